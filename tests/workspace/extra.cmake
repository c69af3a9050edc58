# tests/workspace: the real X-ray workspace's scene part (no GL: app/workspace/WorkspaceModel,
# WorkspacePose, WorkspaceImages), compiled into fm_appcore.
target_link_libraries(fm_test_${name} PRIVATE fm_appcore)
