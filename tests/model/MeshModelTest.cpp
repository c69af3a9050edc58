// Welding, the closed-surface check and the outward winding of loaded models.
#include <gtest/gtest.h>

#include <cmath>

#include "common/TestData.h"
#include "common/TestMeshes.h"
#include "core/Error.h"
#include "model/MeshModel.h"
#include "model/MeshWriter.h"

namespace {

namespace fs = std::filesystem;

// Every triangle with its own three vertices, as an STL stores it.
fm::Mesh unshared(const fm::Mesh& m) {
    fm::Mesh s;
    for (const auto& t : m.triangles) {
        const auto i = static_cast<unsigned>(s.positions.size());
        for (int k = 0; k < 3; ++k) s.positions.push_back(m.positions[t[k]]);
        s.triangles.push_back(glm::uvec3(i, i + 1, i + 2));
    }
    return s;
}

TEST(MeshModel, WeldingRestoresSharedVerticesOfABox) {
    const fm::Mesh box = unshared(fm::test::boxMesh({0, 0, 0}, {1, 2, 3}));
    ASSERT_EQ(box.positions.size(), 36u);
    const fm::MeshModel m = fm::makeMeshModel(box, "box");
    EXPECT_EQ(m.weld.verticesBefore, 36u);
    EXPECT_EQ(m.weld.verticesAfter, 8u);
    EXPECT_TRUE(m.closed);
    EXPECT_FALSE(m.flipped);
    EXPECT_EQ(m.topology.edges, 18u);  // 12 box edges + 6 face diagonals
    EXPECT_NEAR(m.topology.signedVolume, 6.0, 1e-12);
    EXPECT_NEAR(m.topology.area, 2 * (2 + 6 + 3), 1e-12);
    EXPECT_EQ(m.topology.boundsMax, glm::dvec3(1, 2, 3));
}

TEST(MeshModel, ToleranceWeldsNearbyVerticesOnly) {
    fm::Mesh box = unshared(fm::test::boxMesh({0, 0, 0}, {10, 10, 10}));
    // Jitter every copy by up to 1e-4 mm: exact welding leaves the surface open...
    for (std::size_t i = 0; i < box.positions.size(); ++i)
        box.positions[i] += glm::vec3(1e-4f * float(i % 3), -1e-4f * float(i % 2), 0.f);
    EXPECT_THROW(fm::makeMeshModel(box, "jittered"), fm::Error);
    // ... welding within 1e-3 mm closes it again.
    fm::ModelLoadOptions o;
    o.weldToleranceMm = 1e-3;
    const fm::MeshModel m = fm::makeMeshModel(box, "jittered", o);
    EXPECT_EQ(m.weld.verticesAfter, 8u);
    EXPECT_TRUE(m.closed);
    o.weldToleranceMm = -1;
    EXPECT_THROW(fm::makeMeshModel(box, "jittered", o), fm::Error);
}

TEST(MeshModel, InsideOutModelIsFlipped) {
    const fm::MeshModel m =
        fm::makeMeshModel(fm::test::flippedMesh(fm::test::uvSphereMesh({0, 0, 0}, 5, 10, 16)), "s");
    EXPECT_TRUE(m.flipped);
    EXPECT_GT(m.topology.signedVolume, 0.0);
    // Flipping back gives the writer's winding again: the first triangle as the generator made it.
    const fm::Mesh original = fm::test::uvSphereMesh({0, 0, 0}, 5, 10, 16);
    for (int k = 0; k < 3; ++k)
        EXPECT_EQ(m.mesh.positions[m.mesh.triangles[0][k]], original.positions[original.triangles[0][k]]);
}

TEST(MeshModel, OpenSurfaceIsRefusedWithEdgeCountUnlessSilhouetteOnly) {
    fm::Mesh box = fm::test::boxMesh({0, 0, 0}, {1, 1, 1});
    box.triangles.pop_back();  // one triangle missing: a hole with 3 rim edges
    try {
        fm::makeMeshModel(box, "'holey.stl'");
        ADD_FAILURE() << "open mesh accepted";
    } catch (const fm::Error& e) {
        const std::string msg = e.what();
        EXPECT_NE(msg.find("holey.stl"), std::string::npos) << msg;
        EXPECT_NE(msg.find("3 boundary edges"), std::string::npos) << msg;
    }
    fm::ModelLoadOptions o;
    o.silhouetteOnly = true;
    const fm::MeshModel m = fm::makeMeshModel(box, "holey", o);
    EXPECT_FALSE(m.closed);
    EXPECT_EQ(m.topology.boundaryEdges, 3u);
}

TEST(MeshModel, NonManifoldAndMisorientedEdgesAreCounted) {
    // Two boxes sharing one edge: that edge has four triangles.
    const fm::Mesh two = fm::test::mergeMeshes(fm::test::boxMesh({0, 0, 0}, {1, 1, 1}),
                                               fm::test::boxMesh({1, 1, 0}, {2, 2, 1}));
    fm::ModelLoadOptions o;
    o.silhouetteOnly = true;
    const fm::MeshModel m = fm::makeMeshModel(two, "two", o);
    EXPECT_EQ(m.topology.nonManifoldEdges, 1u);
    EXPECT_FALSE(m.closed);
    // One triangle wound the wrong way: its three edges run in the same direction as a neighbour's.
    fm::Mesh bad = fm::test::boxMesh({0, 0, 0}, {1, 1, 1});
    std::swap(bad.triangles[0].y, bad.triangles[0].z);
    const fm::MeshModel b = fm::makeMeshModel(bad, "bad", o);
    EXPECT_EQ(b.topology.misorientedEdges, 3u);
    EXPECT_THROW(fm::makeMeshModel(bad, "bad"), fm::Error);
}

TEST(MeshModel, CoordinatesBeyondTheWorldLimitAreRefused) {
    fm::Mesh box = fm::test::boxMesh({0, 0, 0}, {1, 1, 1});
    box.positions[5].y = -3e20f;
    try {
        fm::makeMeshModel(box, "'far.stl'");
        ADD_FAILURE() << "accepted";
    } catch (const fm::Error& e) {
        EXPECT_NE(std::string(e.what()).find("vertex 5 coordinate 1"), std::string::npos) << e.what();
    }
}

TEST(MeshModel, CollapsedTrianglesAreDropped) {
    fm::Mesh box = fm::test::boxMesh({0, 0, 0}, {1, 1, 1});
    box.triangles.push_back(glm::uvec3(0, 0, 1));  // degenerate: two corners the same vertex
    const fm::MeshModel m = fm::makeMeshModel(box, "box");
    EXPECT_EQ(m.weld.collapsedTriangles, 1u);
    EXPECT_EQ(m.mesh.triangles.size(), 12u);
    EXPECT_TRUE(m.closed);
}

TEST(MeshModel, LoadsEachFormatFromDisk) {
    const fs::path dir = fm::test::scratchDir("mesh_model_formats");
    const fm::Mesh torus = fm::test::squareFrameMesh(4, 2, -1, 1);
    for (const char* ext : {".stl", ".ply", ".obj"}) {
        const fs::path p = dir / (std::string("frame") + ext);
        fm::writeMesh(torus, p);
        const fm::MeshModel m = fm::loadMeshModel(p);
        EXPECT_TRUE(m.closed) << ext;
        EXPECT_EQ(m.mesh.positions.size(), 16u) << ext;
        EXPECT_NEAR(m.topology.signedVolume, (64.0 - 16.0) * 2.0, 1e-9) << ext;
        // Euler characteristic V - E + F = 0 for a torus.
        EXPECT_EQ(long(m.mesh.positions.size()) - long(m.topology.edges) +
                      long(m.mesh.triangles.size()),
                  0)
            << ext;
    }
}

}  // namespace
