// The JTML total-knee implant models (ASCII STL from stlwrite.m) load, weld and are closed.
#include <gtest/gtest.h>

#include "common/TestData.h"
#include "model/MeshModel.h"

namespace {

struct Expected {
    const char* file;
    std::size_t facets;
};

TEST(RealModel, JtmlImplantsAreClosedAndOutward) {
    FM_REQUIRE_SHARED_DATA("jtml-kneel-tka-fluoro/KR_right_7_fem.stl");
    for (const Expected e : {Expected{"KR_right_7_fem.stl", 12412}, Expected{"KR_right_6_tib.stl", 15000}}) {
        const fm::MeshModel m =
            fm::loadMeshModel(fm::test::sharedDataDir() / "jtml-kneel-tka-fluoro" / e.file);
        EXPECT_EQ(m.fileTriangles, e.facets) << e.file;
        EXPECT_EQ(m.weld.verticesBefore, 3 * e.facets) << e.file;
        EXPECT_TRUE(m.closed) << e.file << ": " << m.topology.edgeSummary();
        EXPECT_EQ(m.weld.collapsedTriangles, 0u) << e.file;
        EXPECT_GT(m.topology.signedVolume, 0.0) << e.file;
        // Closed triangle mesh: 3F = 2E.
        EXPECT_EQ(3 * m.mesh.triangles.size(), 2 * m.topology.edges) << e.file;
        std::cout << "[ model    ] " << e.file << ": " << m.mesh.triangles.size() << " triangles, "
                  << m.mesh.positions.size() << " vertices, volume " << m.topology.signedVolume
                  << " mm^3, flipped " << m.flipped << ", euler "
                  << long(m.mesh.positions.size()) - long(m.topology.edges) +
                         long(m.mesh.triangles.size())
                  << "\n";
    }
}

}  // namespace
