# The radiograph tests write TIFFs with libtiff (independent of the reader's code paths) and
# check real files against a small TIFF decoder of their own (MiniTiff).
find_package(TIFF REQUIRED)
target_link_libraries(fm_test_radiograph PRIVATE TIFF::TIFF stb)
