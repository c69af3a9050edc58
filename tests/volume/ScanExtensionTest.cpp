// The body continued past a scan's cut faces (volume/ScanExtension.h): a CT whose body touches
// only its last slice grows only there, by the margin in whole voxels, each new slice a copy of
// that face; every voxel of the CT keeps its value at its world position (oblique axes,
// anisotropic spacing); a CT in air all round, or a margin of 0, comes back unchanged.
#include <gtest/gtest.h>

#include <cmath>

#include "core/Error.h"
#include "volume/ScanExtension.h"

namespace {

// Air all round; a body block that reaches the last slice (k = dims.z - 1) and no other face.
fm::Volume cutScan() {
    fm::Volume v = fm::Volume::allocate({6, 5, 4}, -1000.0f);
    v.spacing = {0.8, 1.2, 3.0};
    v.origin = {12.0, -7.0, 40.0};
    const double c = std::cos(0.3), s = std::sin(0.3);
    v.direction = glm::dmat3(glm::dvec3(c, 0, s), glm::dvec3(0, 1, 0), glm::dvec3(-s, 0, c));
    for (int k = 1; k < 4; ++k)
        for (int j = 1; j < 4; ++j)
            for (int i = 1; i < 5; ++i) v.at(i, j, k) = static_cast<float>(10 * i + j + 100 * k);
    return v;
}

TEST(ScanExtension, ACutFaceGrowsByTheMarginInWholeVoxelsAndOnlyIt) {
    const fm::Volume ct = cutScan();
    const fm::Volume out = fm::extendedAcrossCutFaces(ct, 7.0);  // 7 mm of 3 mm slices: 3 slices
    ASSERT_EQ(out.dims, glm::ivec3(6, 5, 7));
    EXPECT_EQ(out.spacing, ct.spacing);
    for (int k = 0; k < ct.dims.z; ++k)
        for (int j = 0; j < ct.dims.y; ++j)
            for (int i = 0; i < ct.dims.x; ++i) {
                const glm::dvec3 p = out.worldToIndex(ct.indexToWorld({i, j, k}));
                EXPECT_NEAR(p.x, i, 1e-9);
                EXPECT_NEAR(p.y, j, 1e-9);
                EXPECT_NEAR(p.z, k, 1e-9);
                EXPECT_EQ(out.at(i, j, k), ct.at(i, j, k));
            }
    for (int k = 4; k < 7; ++k)
        for (int j = 0; j < 5; ++j)
            for (int i = 0; i < 6; ++i) EXPECT_EQ(out.at(i, j, k), ct.at(i, j, 3)) << i << "," << j << "," << k;
}

TEST(ScanExtension, AScanInAirOrNoMarginComesBackUnchanged) {
    fm::Volume air = cutScan();
    for (float& v : air.values) v = std::min(v, -600.0f);  // lung-like air on every face: not body
    const fm::Volume same = fm::extendedAcrossCutFaces(air, 50.0);
    EXPECT_EQ(same.dims, air.dims);
    EXPECT_EQ(same.origin, air.origin);
    const fm::Volume ct = cutScan();
    EXPECT_EQ(fm::extendedAcrossCutFaces(ct, 0.0).dims, ct.dims);
    EXPECT_THROW(fm::extendedAcrossCutFaces(ct, 1e6), fm::Error);
}

TEST(ScanExtension, EveryFaceThatCutsTheBodyGrows) {
    fm::Volume ct = cutScan();
    ct.at(0, 2, 2) = 50.0f;  // the first i face cuts the body too
    const fm::Volume out = fm::extendedAcrossCutFaces(ct, 1.0);  // 2 voxels of 0.8 mm, 1 of 3 mm
    EXPECT_EQ(out.dims, glm::ivec3(8, 5, 5));
    EXPECT_EQ(out.at(0, 2, 2), 50.0f);
    EXPECT_EQ(out.at(1, 2, 2), 50.0f);
    EXPECT_EQ(out.at(2, 2, 2), 50.0f);
    EXPECT_EQ(out.at(3, 2, 2), ct.at(1, 2, 2));
    const glm::dvec3 first = ct.indexToWorld({-2.0, 0.0, 0.0});
    EXPECT_NEAR(glm::length(out.origin - first), 0.0, 1e-9);
}

}  // namespace
