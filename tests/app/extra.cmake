# tests/app: the app's drawing and UI code (fm_appcore: OSMesa, ImGui, GL loader) and the
# golden images in data/golden/.
target_link_libraries(fm_test_${name} PRIVATE fm_appcore)
target_compile_definitions(fm_test_${name} PRIVATE
    FM_GOLDEN_DIR="${PROJECT_SOURCE_DIR}/data/golden")
# The track runner's poses are compared with the fluoromatch CLI's (TrackRunnerTest).
if(TARGET fluoromatch)
    add_dependencies(fm_test_${name} fluoromatch)
    target_compile_definitions(fm_test_${name} PRIVATE FM_FLUOROMATCH_EXE="$<TARGET_FILE:fluoromatch>")
endif()
