# Release only (FM_TEST_RELEASE_ONLY, tests/CMakeLists.txt): issue 29's proofs over seeded draws
# (the 2011 scene's find also runs there in SolveUi.FindReachesTheReferenceFromNothing and
# RealisticReference.FindFindsTheHiddenPoseFromNothingAgainstIt) and on the three JTML frames
# (the same find in app_cli_find and WorkspaceUi.FindPutsAnImplantBack...).
set(FM_TEST_RELEASE_ONLY "ViewFinderProof.*:JtmlFind.*")
