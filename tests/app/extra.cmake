# tests/app: the app's drawing and UI code (fm_appcore: OSMesa, ImGui, GL loader) and the
# golden images in data/golden/.
target_link_libraries(fm_test_${name} PRIVATE fm_appcore)
# Paths go to the few files that use them (not the whole target): the other files' compile lines
# stay the same in every checkout, so ccache shares them between worktrees.
set_property(SOURCE ${dir}/GoldenImage.cpp APPEND PROPERTY COMPILE_DEFINITIONS
    FM_GOLDEN_DIR="${PROJECT_SOURCE_DIR}/data/golden")
# The track runner's poses are compared with the fluoromatch CLI's (TrackRunnerTest, TrackUiTest).
if(TARGET fluoromatch)
    add_dependencies(fm_test_${name} fluoromatch)
    set_property(SOURCE ${dir}/TrackRunnerTest.cpp ${dir}/TrackUiTest.cpp APPEND PROPERTY COMPILE_DEFINITIONS
        FM_FLUOROMATCH_EXE="$<TARGET_FILE:fluoromatch>")
endif()
# The longest executable under the sanitizers (307 s as one process, 2026-12-03): started first.
set(FM_TEST_SANITIZED_SECONDS 310)
