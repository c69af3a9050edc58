# tests/app: the app's drawing and UI code (fm_appcore: OSMesa, ImGui, GL loader) and the
# golden images in data/golden/.
target_link_libraries(fm_test_${name} PRIVATE fm_appcore)
# Paths go to the few files that use them (not the whole target): the other files' compile lines
# stay the same in every checkout, so ccache shares them between worktrees.
set_property(SOURCE ${dir}/GoldenImage.cpp APPEND PROPERTY COMPILE_DEFINITIONS
    FM_GOLDEN_DIR="${PROJECT_SOURCE_DIR}/data/golden")
# The track runner's poses are compared with the fluoromatch CLI's (TrackRunnerTest, TrackUiTest); the
# biplane Find's trial is simulated by it (WorkspaceBiplaneFindTest).
if(TARGET fluoromatch)
    add_dependencies(fm_test_${name} fluoromatch)
    set_property(SOURCE ${dir}/TrackRunnerTest.cpp ${dir}/TrackUiTest.cpp ${dir}/WorkspaceBiplaneFindTest.cpp APPEND PROPERTY COMPILE_DEFINITIONS
        FM_FLUOROMATCH_EXE="$<TARGET_FILE:fluoromatch>")
endif()
# The longest executable under the sanitizers (144 s alone, 300 s beside another test at -j2):
# two ctest tests there, the Track pane, its runner and the workspace's UI, biplane Find included
# (162 s in the last full pass, without that Find), and the rest (265 s), started first.
set(FM_TEST_SANITIZED_SPLIT "TrackUi.*:TrackRunner.*:WorkspaceUi.*:WorkspaceBiplaneFind.*")
set(FM_TEST_SANITIZED_SECONDS 200 260)
# Heavy under the sanitizers (the two entries 160-270 s there: tracking and finds at the wrist
# trial's 512 pixels behind the UI): left out of the quick sanitizer pass (scripts/test --skip-heavy).
set(FM_TEST_SANITIZED_HEAVY ON)
