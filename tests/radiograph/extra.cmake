# The radiograph tests write TIFFs with libtiff (independent of the reader's code paths) and
# check real files against a small TIFF decoder of their own (MiniTiff); they write PNGs with
# libpng's writer or chunk by chunk (zlib), JPEGs with libjpeg's encoder, BMPs with stb.
find_package(TIFF REQUIRED)
find_package(PNG REQUIRED)
find_package(JPEG REQUIRED)
target_link_libraries(fm_test_radiograph PRIVATE TIFF::TIFF PNG::PNG JPEG::JPEG ZLIB::ZLIB stb)
