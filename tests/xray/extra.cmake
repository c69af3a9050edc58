# Release only (FM_TEST_RELEASE_ONLY, tests/CMakeLists.txt): registration from ten perturbed
# starts against the .jts pose; the same prepared registration runs there in
# RealXray.OnePreparedRegistrationServesEverySearchAndTheUncertainty and app_cli_xray_register.
set(FM_TEST_RELEASE_ONLY "RealXray.RegistrationFromPerturbedStartsReachesTheJtsPose")
