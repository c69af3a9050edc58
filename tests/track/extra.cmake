# tests/track: the longest executable under the sanitizers after fm_test_app (tracking at the
# wrist trial's 512 pixels): started first among the others (tests/CMakeLists.txt).
set(FM_TEST_SANITIZED_SECONDS 200)
