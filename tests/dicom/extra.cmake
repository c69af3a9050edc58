# The DICOM tests write their own synthetic series with GDCM (the engine links it privately).
target_link_libraries(fm_test_${name} PRIVATE gdcmMSFF gdcmDSED gdcmCommon)
