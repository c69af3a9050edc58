# The io tests write their own gzip/zlib inputs with zlib, decode PNGs with stb_image, and
# cross-check NIfTI files with the reference nifti1_io library (libnifti2-dev): all
# independent of the code under test. (Debian's NIFTIConfig.cmake points at wrong paths, so
# the library is found directly.)
find_library(FM_NIFTIIO_LIBRARY niftiio REQUIRED)
find_library(FM_ZNZ_LIBRARY znz REQUIRED)
find_path(FM_NIFTI_INCLUDE_DIR nifti1_io.h PATH_SUFFIXES nifti REQUIRED)
target_include_directories(fm_test_io SYSTEM PRIVATE ${FM_NIFTI_INCLUDE_DIR})
target_link_libraries(fm_test_io PRIVATE ZLIB::ZLIB stb ${FM_NIFTIIO_LIBRARY} ${FM_ZNZ_LIBRARY} m)
# TIFF files written by io/ImageFileWriter are decoded with libtiff (libtiff-dev), independently.
find_package(TIFF REQUIRED)
target_link_libraries(fm_test_io PRIVATE TIFF::TIFF)
