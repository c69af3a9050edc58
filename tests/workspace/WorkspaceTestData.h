#pragma once
// The JTML knee and wrist data as the workspace tests open them.
#include <filesystem>

#include <gtest/gtest.h>

#include "common/TestData.h"
#include "workspace/WorkspaceModel.h"

namespace fm::test {

inline std::filesystem::path jtmlDir() { return sharedDataDir() / "jtml-kneel-tka-fluoro"; }

// The shipped trials name ../shared/data beside the repository.
#define FM_REQUIRE_SHIPPED_TRIAL_DATA(sub)                                                        \
    do {                                                                                         \
        FM_REQUIRE_SHARED_DATA(sub);                                                             \
        if (!::fm::test::sharedDataBesideRepo()) {                                               \
            if (::fm::test::underCI()) FAIL() << "under CI the shared data must be ../shared/data"; \
            GTEST_SKIP() << "FM_DATA_DIR is not ../shared/data beside the repository";           \
        }                                                                                        \
    } while (0)

inline app::WorkspaceSource jtmlTrialSource() {
    app::WorkspaceSource s;
    s.trial = repoDir() / "data/trials/jtml-knee.json";
    return s;
}

// Frame 0160 alone, as `register --reference` takes it (docs/real-xray.md's example flags).
inline app::WorkspaceSource jtmlRadiographSource() {
    app::WorkspaceSource s;
    s.reference = jtmlDir() / "AT_K1_V1_0160.tif";
    s.camera = jtmlDir() / "calibration.txt";
    s.models = {jtmlDir() / "KR_right_7_fem.stl", jtmlDir() / "KR_right_6_tib.stl"};
    s.starts = {(jtmlDir() / "fem.jts").string(), (jtmlDir() / "tib.jts").string()};
    s.masks = {jtmlDir() / "Labels/fem/AT_K1_V1_0160_label_fem.tif", jtmlDir() / "Labels/tib/AT_K1_V1_0160_label_tib.tif"};
    RadiographPreparation p;
    p.invert = true;
    p.excludeBelow = 0.0;
    s.preparation = p;
    return s;
}

}  // namespace fm::test
