// makePhantom / loadVolume("phantom:...") name and option parsing.
#include <cmath>
#include <numbers>
#include <string>

#include <gtest/gtest.h>

#include "core/Error.h"
#include "phantom/AnalyticObjects.h"
#include "phantom/Phantoms.h"
#include "source/VolumeSource.h"

namespace {

constexpr double kPiRad = std::numbers::pi;
constexpr double kMm = 1e-9;  // spacing/extent arithmetic in double precision

double phantomMass(const fm::Volume& v) {
    double sum = 0.0;
    for (float x : v.values) sum += x;
    return sum * v.spacing.x * v.spacing.y * v.spacing.z;
}

glm::dvec3 centreOfMass(const fm::Volume& v) {
    glm::dvec3 sum{0.0};
    double mass = 0.0;
    for (int k = 0; k < v.dims.z; ++k)
        for (int j = 0; j < v.dims.y; ++j)
            for (int i = 0; i < v.dims.x; ++i) {
                sum += static_cast<double>(v.at(i, j, k)) * v.indexToWorld({i, j, k});
                mass += v.at(i, j, k);
            }
    return sum / mass;
}

// Parsing checks, not accuracy ones (AnalyticObjectsTest bounds the voxelizer's error, here up
// to ~8e-3 for the cylinder whose sampling error is coherent along its axis): 1 % still
// catches any wrong size (a 1 mm radius error is >= 10 % of these volumes).
constexpr double kMassRel = 1e-2;

TEST(Phantoms, DefaultSceneIsTheKnee) {
    const fm::Volume v = fm::loadVolume(fm::kDefaultVolumeSpec);
    EXPECT_EQ(v.dims, glm::ivec3(128, 128, 141));
    EXPECT_EQ(v.meta.source, "phantom:knee");
    EXPECT_EQ(v.meta.units, fm::ValueUnit::HounsfieldUnits);
}

TEST(Phantoms, KneeOptions) {
    const fm::Volume a = fm::makePhantom("knee, flexion=30, size=64x64x70, field=200x210x220");
    EXPECT_EQ(a.dims, glm::ivec3(64, 64, 70));
    EXPECT_NEAR(a.extent().x, 200.0, kMm);
    EXPECT_NEAR(a.extent().y, 210.0, kMm);
    EXPECT_NEAR(a.extent().z, 220.0, kMm);
    EXPECT_NE(a.meta.description.find("flexion 30"), std::string::npos);
    // size alone keeps the 2011 voxel spacing.
    const fm::Volume b = fm::makePhantom("knee,size=64x64x70");
    EXPECT_NEAR(b.spacing.x, 220.0 / 128.0, kMm);
    EXPECT_NEAR(b.spacing.z, 281.0 / 141.0, kMm);
    const fm::Volume c = fm::makePhantom("knee,size=50,spacing=2");
    EXPECT_EQ(c.dims, glm::ivec3(50));
    EXPECT_NEAR(c.spacing.y, 2.0, kMm);
    const fm::Volume left = fm::makePhantom("knee,size=32,side=left");
    EXPECT_NE(left.meta.description.find("left"), std::string::npos);
}

TEST(Phantoms, SphereDefaultsAndOptions) {
    const fm::Volume v = fm::makePhantom("sphere");
    EXPECT_EQ(v.dims, glm::ivec3(64));
    EXPECT_EQ(v.meta.units, fm::ValueUnit::Unknown);
    EXPECT_EQ(v.meta.source, "phantom:sphere");
    EXPECT_NEAR(phantomMass(v) / (4.0 / 3.0 * kPiRad * 8000.0), 1.0, kMassRel);  // radius 20
    // Centred in the grid (symmetric sampling: the centre of mass is the grid centre).
    EXPECT_NEAR(glm::length(centreOfMass(v) - v.center()), 0.0, 1e-6);

    const fm::Volume s = fm::makePhantom("sphere,radius=10,size=48,spacing=0.5");
    EXPECT_EQ(s.dims, glm::ivec3(48));
    EXPECT_NEAR(s.spacing.x, 0.5, kMm);
    EXPECT_NEAR(phantomMass(s) / (4.0 / 3.0 * kPiRad * 1000.0), 1.0, kMassRel);
}

TEST(Phantoms, OtherShapesHaveTheirExactVolumes) {
    // The box is voxelized by exact overlap: its mass is exact up to float storage.
    EXPECT_NEAR(phantomMass(fm::makePhantom("box,extent=10x20x30")) / 6000.0, 1.0, 1e-6);
    EXPECT_NEAR(
        phantomMass(fm::makePhantom("box,extent=9.3x17.1x25.5,spacing=1.3")) / (9.3 * 17.1 * 25.5),
        1.0, 1e-6);
    EXPECT_NEAR(phantomMass(fm::makePhantom("cylinder,radius=8,height=20")) / (kPiRad * 64.0 * 20.0),
                1.0, kMassRel);
    EXPECT_NEAR(
        phantomMass(fm::makePhantom("ellipsoid,axes=20x15x10")) / (4.0 / 3.0 * kPiRad * 20 * 15 * 10),
        1.0, kMassRel);
}

TEST(Phantoms, InsideAndOutsideValues) {
    const fm::Volume v = fm::makePhantom("sphere,radius=5,size=16,inside=1000,outside=-1000");
    EXPECT_EQ(v.at(0, 0, 0), -1000.0f);
    EXPECT_EQ(v.at(8, 8, 8), 1000.0f);
}

void expectErrorMentioning(const std::string& spec, const std::string& words) {
    try {
        fm::makePhantom(spec);
        ADD_FAILURE() << "no error for '" << spec << "'";
    } catch (const fm::Error& e) {
        EXPECT_NE(std::string(e.what()).find(words), std::string::npos)
            << "'" << spec << "' gave: " << e.what();
    }
}

TEST(Phantoms, BadNamesAndOptionsAreErrors) {
    expectErrorMentioning("teapot", "knee, sphere, box, cylinder, ellipsoid");
    expectErrorMentioning("", "valid names");
    expectErrorMentioning("sphere,colour=red", "colour");
    expectErrorMentioning("sphere,radius=-1", "radius");
    expectErrorMentioning("sphere,radius=abc", "radius");
    expectErrorMentioning("sphere,radius=nan", "radius");
    expectErrorMentioning("sphere,radius=1,radius=2", "twice");
    expectErrorMentioning("sphere,radius", "key=value");
    expectErrorMentioning("sphere,supersample=0", "supersample");
    expectErrorMentioning("sphere,spacing=0", "spacing");
    expectErrorMentioning("box,extent=1x2", "extent");
    expectErrorMentioning("ellipsoid,axes=1x0x2", "semi-axes");
    expectErrorMentioning("knee,flexion=500", "flexion");
    expectErrorMentioning("knee,size=0x10x10", "size");
    expectErrorMentioning("knee,size=12.5x10x10", "size");
    expectErrorMentioning("knee,size=100000", "size");
    expectErrorMentioning("knee,field=1x2", "field");
    expectErrorMentioning("knee,field=100x100x100,spacing=1", "not both");
    expectErrorMentioning("knee,side=up", "side");
    expectErrorMentioning("knee,radius=3", "radius");
    EXPECT_THROW(fm::loadVolume("phantom:teapot"), fm::Error);
}

}  // namespace
