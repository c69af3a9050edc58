// Realistic radiographs (spectral/SpectralScene.h) against arithmetic done here: one energy
// through a box of water-like tissue is exp(-mu L) with the exact chords (sources outside and
// inside the box); a spectrum through a wedge of bone (a mesh: exact chords) is the spectrum-
// weighted sum of Beer-Lambert terms, and its effective attenuation falls with thickness (beam
// hardening); bone and soft tissue of a CT are told apart by HU and density from HU, and their
// masses (one walk for both) are their densities times their exact chords.
#include <gtest/gtest.h>

#include <cmath>

#include "meshdrr/MeshDrr.h"
#include "core/Error.h"
#include "spectral/MaterialDecomposition.h"
#include "spectral/SpectralScene.h"

namespace fm::test {
namespace {

// Length of the segment a -> b inside the convex region {x : n_i . x <= d_i}.
double convexChord(const glm::dvec3& a, const glm::dvec3& b, const std::vector<std::pair<glm::dvec3, double>>& planes) {
    double t0 = 0.0, t1 = 1.0;
    const glm::dvec3 d = b - a;
    for (const auto& [n, dist] : planes) {
        const double num = dist - glm::dot(n, a), den = glm::dot(n, d);
        if (den == 0.0) {
            if (num < 0.0) return 0.0;
            continue;
        }
        const double t = num / den;
        if (den > 0.0) t1 = std::min(t1, t);
        else t0 = std::max(t0, t);
    }
    return std::max(0.0, t1 - t0) * glm::length(d);
}

ProjectionGeometry lookingAt(const glm::dvec3& source, const glm::dvec3& target, int pixels, double pitch) {
    ProjectionGeometry g;
    g.source = source;
    const glm::dvec3 n = glm::normalize(target - source);
    glm::dvec3 u = glm::normalize(glm::cross(n, glm::dvec3(0.3, 0.2, 1.0)));
    const glm::dvec3 v = glm::cross(n, u);
    g.detector.size = {pixels, pixels};
    g.detector.spacing = {pitch, pitch};
    g.detector.u = u;
    g.detector.v = v;
    const glm::dvec3 centre = source + 2.0 * (target - source);
    g.detector.origin = centre - pitch * (pixels - 1) / 2.0 * (u + v);
    return g;
}

TEST(SpectralScene, OneEnergyThroughTissueIsExpOfMuTimesTheExactChords) {
    // A box of 0 HU: soft tissue of 1.030 g/cm^3 (spectral/MaterialDecomposition.h).
    Volume box = Volume::allocate({12, 10, 8}, 0.0f);
    box.spacing = {2.0, 3.0, 2.5};
    box.origin = {-11.0, -13.5, -8.75};
    box.meta.units = ValueUnit::HounsfieldUnits;
    const glm::dvec3 lower = box.origin - 0.5 * box.spacing, upper = lower + glm::dvec3(box.dims) * box.spacing;
    const std::vector<std::pair<glm::dvec3, double>> planes{
        {{1, 0, 0}, upper.x}, {{-1, 0, 0}, -lower.x}, {{0, 1, 0}, upper.y},
        {{0, -1, 0}, -lower.y}, {{0, 0, 1}, upper.z}, {{0, 0, -1}, -lower.z}};
    SpectralScene scene;
    addCtLayers(scene, box, nullptr, "box", RigidTransform::identity(), 1);
    const double mu = materialTable("soft_tissue").muRhoAt(60.0) * 1.030 / 10.0;  // 1/mm
    for (const glm::dvec3 source : {glm::dvec3(-200.0, 30.0, 40.0), glm::dvec3(3.0, -2.0, 1.0)}) {
        const ProjectionGeometry g = lookingAt(source, glm::dvec3(0.5, 0.2, -0.3), 24, 4.0);
        const Image t = transmissionImage(renderMassImages(scene, g, 1), monoenergetic(60.0), DetectorResponse::Counting, 1);
        double longest = 0.0;
        for (int r = 0; r < 24; ++r)
            for (int c = 0; c < 24; ++c) {
                const double chord = convexChord(source, g.detector.pixelCenter(c, r), planes);
                longest = std::max(longest, chord);
                EXPECT_NEAR(t.at(c, r), std::exp(-mu * chord), 2e-6) << c << "," << r;
            }
        EXPECT_GT(longest, 10.0);
    }
}

// A CT of a soft-tissue box (40 HU) beside a bone box (1200 HU), air elsewhere: its one layer
// (addCtLayers: one walk for both materials) gives each material's mass as its density times its
// box's exact chord, from sources outside and inside the CT.
TEST(SpectralScene, ACtsTwoMaterialsMassesAreTheirDensitiesTimesTheExactChords) {
    Volume ct = Volume::allocate({20, 12, 10}, -1000.0f);
    ct.spacing = {2.0, 2.5, 3.0};
    ct.origin = {-19.0, -13.75, -13.5};
    ct.meta.units = ValueUnit::HounsfieldUnits;
    for (int k = 1; k < 9; ++k)
        for (int j = 2; j < 10; ++j) {
            for (int i = 1; i < 9; ++i) ct.at(i, j, k) = 40.0f;
            for (int i = 11; i < 19; ++i) ct.at(i, j, k) = 1200.0f;
        }
    // The boxes' planes in the world (identity direction): voxel i spans origin + (i -+ 0.5) s.
    const auto boxPlanes = [&](int i0, int i1) {
        const glm::dvec3 lo = ct.origin + (glm::dvec3(i0, 2, 1) - 0.5) * ct.spacing,
                         hi = ct.origin + (glm::dvec3(i1, 10, 9) - 0.5) * ct.spacing;
        return std::vector<std::pair<glm::dvec3, double>>{{{1, 0, 0}, hi.x},  {{-1, 0, 0}, -lo.x}, {{0, 1, 0}, hi.y},
                                                          {{0, -1, 0}, -lo.y}, {{0, 0, 1}, hi.z}, {{0, 0, -1}, -lo.z}};
    };
    const auto softPlanes = boxPlanes(1, 9), bonePlanes = boxPlanes(11, 19);
    SpectralScene scene;
    addCtLayers(scene, ct, nullptr, "ct", RigidTransform::identity(), 1);
    const double soft = std::round(1000.0 * densityFromHU(40.0)) / 1e4,  // g/cm^3 -> g/cm^2 per mm
        bone = std::round(1000.0 * densityFromHU(1200.0)) / 1e4;
    for (const glm::dvec3 source : {glm::dvec3(-150.0, 60.0, 35.0), glm::dvec3(0.5, 1.0, -0.7)}) {
        const ProjectionGeometry g = lookingAt(source, glm::dvec3(2.0, -1.0, 0.5), 28, 3.0);
        const MassImages masses = renderMassImages(scene, g, 1);
        ASSERT_EQ(masses.materials.size(), 2u);
        EXPECT_EQ(masses.materials[0], &materialTable("soft_tissue"));
        EXPECT_EQ(masses.materials[1], &materialTable("cortical_bone"));
        int softMet = 0, boneMet = 0, both = 0;
        for (int r = 0; r < 28; ++r)
            for (int c = 0; c < 28; ++c) {
                const double s = convexChord(source, g.detector.pixelCenter(c, r), softPlanes),
                             b = convexChord(source, g.detector.pixelCenter(c, r), bonePlanes);
                softMet += s > 2.0;
                boneMet += b > 2.0;
                both += s > 2.0 && b > 2.0;
                EXPECT_NEAR(masses.mass[0].at(c, r), soft * s, 1e-6 + 1e-5 * soft * s) << c << "," << r;
                EXPECT_NEAR(masses.mass[1].at(c, r), bone * b, 1e-6 + 1e-5 * bone * b) << c << "," << r;
            }
        EXPECT_GT(std::min(softMet, boneMet), 10) << "rays through each box";
        if (source.x < -100.0) {
            EXPECT_GT(both, 10) << "rays through both boxes (the source outside)";
        }
    }
}

TEST(SpectralScene, ASpectrumThroughAWedgeOfBoneIsTheWeightedSumAndHardens) {
    // A wedge (triangular prism) of cortical bone as a closed mesh: 40 mm along x, thickness
    // along z growing from 0 to 40 mm over y 0..40, 40 mm deep along x.
    Mesh wedge;
    wedge.positions = {{0, 0, 0}, {0, 40, 0}, {0, 40, 40}, {40, 0, 0}, {40, 40, 0}, {40, 40, 40}};
    wedge.triangles = {{0, 2, 1}, {3, 4, 5}, {0, 1, 4}, {0, 4, 3}, {1, 2, 5}, {1, 5, 4}, {0, 3, 5}, {0, 5, 2}};
    const std::vector<std::pair<glm::dvec3, double>> planes{
        {{-1, 0, 0}, 0.0}, {{1, 0, 0}, 40.0}, {{0, 0, -1}, 0.0}, {{0, 1, 0}, 40.0},
        {glm::normalize(glm::dvec3(0, -1, 1)), 0.0}};
    const MaterialTable& bone = materialTable("cortical_bone");
    SpectralScene scene;
    addMeshLayer(scene, prepareMeshDrr(wedge, true), bone, "wedge", RigidTransform::identity());
    const Spectrum spectrum = makeSpectrum(parseSpectrumSpec("80,filter=2.5,bin=2"));
    ProjectionGeometry g;  // rays along z, through the wedge's thickness
    g.source = {20.0, 20.0, 1000.0};
    g.detector.size = {1, 33};
    g.detector.spacing = {1.0, 1.25};
    g.detector.origin = {20.0, 0.0, -1000.0};
    g.detector.u = {1, 0, 0};
    g.detector.v = {0, 1, 0};
    const Image t = transmissionImage(renderMassImages(scene, g, 1), spectrum, DetectorResponse::Integrating, 1);
    double previousMu = INFINITY, weights = 0.0;
    for (std::size_t b = 0; b < spectrum.photons.size(); ++b) weights += spectrum.photons[b] * spectrum.energyKeV[b];
    for (int r = 1; r < 33; ++r) {
        const double chord = convexChord(g.source, g.detector.pixelCenter(0, r), planes);  // mm
        double expected = 0.0;
        for (std::size_t b = 0; b < spectrum.photons.size(); ++b)
            expected += spectrum.photons[b] * spectrum.energyKeV[b] / weights *
                        std::exp(-bone.muRhoAt(spectrum.energyKeV[b]) * bone.densityGPerCm3 * chord / 10.0);
        EXPECT_NEAR(t.at(0, r), expected, 2e-6 + 1e-5 * expected) << r;
        // Beam hardening: the effective mu = -ln(I)/L falls as the bone thickens.
        const double effective = -std::log(t.at(0, r)) / chord;
        if (chord > 2.0) {
            EXPECT_LT(effective, previousMu) << r;
            previousMu = effective;
        }
    }
    // The thinnest and thickest effective mu differ clearly, and both lie between the spectrum's
    // extreme energies' mu.
    EXPECT_LT(previousMu, bone.muRhoAt(spectrum.meanEnergyKeV()) * bone.densityGPerCm3 / 10.0 * 1.5);
}

TEST(SpectralScene, BoneAndSoftTissueByHUWithDensityFromHU) {
    EXPECT_NEAR(densityFromHU(-1000.0), 0.001, 1e-12);  // the formula; signedMaterialDensity leaves air out
    EXPECT_NEAR(densityFromHU(0.0), 1.030, 1e-12);
    EXPECT_NEAR(densityFromHU(1500.0), 0.0005886 * 1500 + 1.030, 1e-12);
    EXPECT_EQ(densityFromHU(-2000.0), 0.0);
    Volume ct = Volume::allocate({3, 1, 1}, 0.0f);
    ct.values = {-1000.0f, 40.0f, 1200.0f};
    // Soft tissue positive, bone negative.
    const float soft40 = std::round(1000.0f * float(densityFromHU(40.0))),
                bone1200 = std::round(1000.0f * float(densityFromHU(1200.0)));
    EXPECT_EQ(signedMaterialDensity(ct).values, (std::vector<float>{0.0f, soft40, -bone1200}));
    Volume mask = Volume::allocate({3, 1, 1}, 0.0f);
    mask.values = {0.0f, 1.0f, 0.0f};  // a label map: the middle voxel is the bone
    const Volume byLabel = signedMaterialDensity(ct, &mask);
    EXPECT_EQ(byLabel.values, (std::vector<float>{0.0f, -soft40, bone1200}));
    const Volume otherGrid = Volume::allocate({2, 1, 1}, 1.0f);
    EXPECT_THROW(signedMaterialDensity(ct, &otherGrid), Error);
}

}  // namespace
}  // namespace fm::test
