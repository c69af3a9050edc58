// Marching cubes on the knee phantom and on every real CT in ../shared/data that we can read,
// at a bone threshold, checked by CGAL. The larger CTs are meshed in a region of interest so
// that the CGAL checks stay fast (about 100-250k triangles each).
#include <gtest/gtest.h>

#include <algorithm>
#include <optional>

#include "common/TestData.h"
#include "io/ReadVolume.h"
#include "mesh/MarchingCubes.h"
#include "mesh/MeshCheck.h"
#include "mesh/MeshComponents.h"
#include "phantom/Phantoms.h"

namespace {

using fm::Mesh;
using fm::Volume;

struct RealMeshResult {
    Mesh mesh;
    fm::MeshCheckReport report;
    std::vector<std::size_t> componentSizes;
};

RealMeshResult meshAndCheck(const Volume& v, double iso, std::optional<glm::ivec3> roiMin = {},
                            std::optional<glm::ivec3> roiMax = {}) {
    fm::MarchingCubesOptions o;
    o.isoValue = iso;
    o.threads = 2;
    o.roiMin = roiMin;
    o.roiMax = roiMax;
    o.labelComponents = true;
    RealMeshResult r;
    r.mesh = fm::marchingCubes(v, o);
    r.report = fm::checkMesh(r.mesh);
    r.componentSizes = fm::componentSizes(r.mesh);
    return r;
}

void expectWatertight(const RealMeshResult& r, const std::string& what) {
    const auto& c = r.report;
    EXPECT_GT(r.mesh.triangleCount(), 1000u) << what;
    EXPECT_TRUE(c.watertight()) << what << ": " << c.summary();
    // Each closed orientable component has an even Euler characteristic 2 - 2 genus.
    EXPECT_EQ(c.eulerCharacteristic % 2, 0) << what;
    EXPECT_EQ(c.components, r.componentSizes.size()) << what << ": our labels vs CGAL's";
}

// Every vertex lies inside the world box of the (ROI) grid, grown by one voxel for the
// padding layer that closes cut bones: checks the reader's placement reaches the mesh.
void expectInsideGrid(const Mesh& mesh, const Volume& v, glm::ivec3 lo, glm::ivec3 hi,
                      const std::string& what) {
    glm::dvec3 boxMin(1e300), boxMax(-1e300);
    for (int c = 0; c < 8; ++c) {
        const glm::dvec3 ijk((c & 1) ? hi.x + 1.0 : lo.x - 1.0, (c & 2) ? hi.y + 1.0 : lo.y - 1.0,
                             (c & 4) ? hi.z + 1.0 : lo.z - 1.0);
        const glm::dvec3 w = v.indexToWorld(ijk);
        boxMin = glm::min(boxMin, w);
        boxMax = glm::max(boxMax, w);
    }
    constexpr double kFloatSlack = 1e-3;  // float positions at up to ~1000 mm
    std::size_t outside = 0;
    for (const auto& p : mesh.positions)
        if (glm::any(glm::lessThan(glm::dvec3(p), boxMin - kFloatSlack)) ||
            glm::any(glm::greaterThan(glm::dvec3(p), boxMax + kFloatSlack)))
            ++outside;
    EXPECT_EQ(outside, 0u) << what;
}

TEST(RealVolumeMesh, KneePhantomGivesFourClosedBones) {
    // The phantom holds four separate bones (femur, tibia, fibula, patella), each solid above
    // 300 HU (cancellous 350 HU inside a cortical shell): four genus-0 surfaces.
    const Volume v = fm::makePhantom("knee");
    const auto r = meshAndCheck(v, 300.0);
    expectWatertight(r, "knee phantom");
    EXPECT_EQ(r.report.components, 4u);
    EXPECT_EQ(r.report.eulerCharacteristic, 8);
    expectInsideGrid(r.mesh, v, glm::ivec3(0), v.dims - 1, "knee phantom");
}

TEST(RealVolumeMesh, HeadsqQuarterAtVtkBoneLevel) {
    FM_REQUIRE_SHARED_DATA("vtk-headsq-quarter/quarter.nhdr");
    const Volume v = fm::readVolume(fm::test::sharedDataDir() / "vtk-headsq-quarter/quarter.nhdr");
    // Values are not HU; 1150 is the bone level of VTK's Medical examples (data README).
    const auto r = meshAndCheck(v, 1150.0);
    expectWatertight(r, "headsq");
    // The skull is one connected surface: it dominates, with small islands of noise.
    ASSERT_FALSE(r.componentSizes.empty());
    EXPECT_GT(r.componentSizes[0], r.mesh.triangleCount() / 2);
    expectInsideGrid(r.mesh, v, glm::ivec3(0), v.dims - 1, "headsq");
}

TEST(RealVolumeMesh, TotalSegExampleCtAtBoneLevel) {
    FM_REQUIRE_SHARED_DATA("totalseg-example-ct/example_ct.nii.gz");
    const Volume v =
        fm::readVolume(fm::test::sharedDataDir() / "totalseg-example-ct/example_ct.nii.gz");
    const auto r = meshAndCheck(v, 300.0);
    expectWatertight(r, "example_ct");
    // Spine, pelvis and both femurs are separate bones at 3 mm: several large components,
    // plus many small ones (trabecular islands, vessels calcifications, metal streaks).
    const std::size_t big = static_cast<std::size_t>(
        std::count_if(r.componentSizes.begin(), r.componentSizes.end(),
                      [&](std::size_t n) { return n > r.mesh.triangleCount() / 20; }));
    EXPECT_GE(big, 3u);
    expectInsideGrid(r.mesh, v, glm::ivec3(0), v.dims - 1, "example_ct");
}

TEST(RealVolumeMesh, TotalSegExampleCtMetalSitsWhereTheReadmeSaysIt) {
    FM_REQUIRE_SHARED_DATA("totalseg-example-ct/example_ct.nii.gz");
    const Volume v =
        fm::readVolume(fm::test::sharedDataDir() / "totalseg-example-ct/example_ct.nii.gz");
    // Above 2000 HU only the metal object remains (about voxel i 15-34, j 30-45, k 0-16).
    fm::MarchingCubesOptions o;
    o.isoValue = 2000.0;
    o.keepLargestComponents = 1;
    const Mesh metal = fm::marchingCubes(v, o);
    ASSERT_GT(metal.triangleCount(), 0u);
    EXPECT_TRUE(fm::checkMesh(metal).watertight());
    glm::dvec3 centre(0.0);
    for (const auto& p : metal.positions) centre += glm::dvec3(p);
    centre /= static_cast<double>(metal.vertexCount());
    const glm::dvec3 ijk = v.worldToIndex(centre);
    constexpr double kSlack = 3.0;  // voxels: the README gives the box by eye
    EXPECT_GT(ijk.x, 15 - kSlack);
    EXPECT_LT(ijk.x, 34 + kSlack);
    EXPECT_GT(ijk.y, 30 - kSlack);
    EXPECT_LT(ijk.y, 45 + kSlack);
    EXPECT_GT(ijk.z, 0 - kSlack);
    EXPECT_LT(ijk.z, 16 + kSlack);
}

TEST(RealVolumeMesh, TotalSegAortaCropAtBoneLevel) {
    FM_REQUIRE_SHARED_DATA("totalseg-example-ct/ct_cropped_aorta_report.nii.gz");
    const Volume v = fm::readVolume(fm::test::sharedDataDir() /
                                    "totalseg-example-ct/ct_cropped_aorta_report.nii.gz");
    // The lower 60 slices (the full crop gives ~580k triangles: contrast, stent, ribs).
    const glm::ivec3 lo(0), hi(v.dims.x - 1, v.dims.y - 1, 59);
    const auto r = meshAndCheck(v, 300.0, lo, hi);
    expectWatertight(r, "aorta crop");
    expectInsideGrid(r.mesh, v, lo, hi, "aorta crop");
}

TEST(RealVolumeMesh, TotalSegDicomSeriesAtBoneLevel) {
    FM_REQUIRE_SHARED_DATA("totalseg-example-ct/example_ct_dicom");
    const Volume v =
        fm::readVolume(fm::test::sharedDataDir() / "totalseg-example-ct/example_ct_dicom");
    // The central 320 x 320 columns of all 20 slices (vertebra, ribs, no arms).
    const glm::ivec3 lo(96, 96, 0), hi(415, 415, v.dims.z - 1);
    const auto r = meshAndCheck(v, 300.0, lo, hi);
    expectWatertight(r, "dicom series");
    expectInsideGrid(r.mesh, v, lo, hi, "dicom series");
}

TEST(RealVolumeMesh, GantryTiltedHeadAtBoneLevel) {
    FM_REQUIRE_SHARED_DATA("dcmqa-ct-ge-tilt");
    const Volume v = fm::readVolume(fm::test::sharedDataDir() / "dcmqa-ct-ge-tilt");
    // A central block of the (resampled) head: skull cut on all sides, closed by the ROI.
    const glm::ivec3 lo = v.dims / 4, hi = v.dims / 4 + v.dims / 3;
    const auto r = meshAndCheck(v, 300.0, lo, hi);
    expectWatertight(r, "tilted head");
    expectInsideGrid(r.mesh, v, lo, hi, "tilted head");
}

}  // namespace
