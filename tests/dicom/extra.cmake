# The DICOM tests write their own synthetic series with GDCM (the engine links it privately).
target_link_libraries(fm_test_${name} PRIVATE gdcmMSFF gdcmDSED gdcmCommon)
# Under the sanitizers: every length field of real slices read in a forked child.
set(FM_TEST_SANITIZED_SECONDS 90)
