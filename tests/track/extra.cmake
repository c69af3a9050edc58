# tests/track: the longest executable under the sanitizers after fm_test_app (tracking at the
# wrist trial's 512 pixels): started first among the others (tests/CMakeLists.txt).
set(FM_TEST_SANITIZED_SECONDS 200)
# Release only (FM_TEST_RELEASE_ONLY, tests/CMakeLists.txt): the 20-frame accuracy proof, whose
# path (tracker.run from a keyframe) the verdict, one-camera and resume tests take there; the real
# wrist's biplane answer, registered on the same frames by app_cli_track and the Track pane's tests;
# RealWrist.* holds the wrist's finds with no start too (~1.5 minutes a bone), whose path
# (findTrialBone -> the biplane finder) cli_track_test.sh and the finder's own tests take there on
# smaller spaces.
set(FM_TEST_RELEASE_ONLY "Tracking.RecoversEveryFrameOfABiplaneSequenceThroughTheRealWristCameras:RealWrist.*")
# Heavy under the sanitizers (410 s there, 194 s with the Release-only tests out): left out of the quick sanitizer pass (scripts/test
# --skip-heavy).
set(FM_TEST_SANITIZED_HEAVY ON)
