# The io tests write their own gzip/zlib inputs with zlib and decode PNGs with stb_image
# (independent of the code under test).
target_link_libraries(fm_test_io PRIVATE ZLIB::ZLIB stb)
