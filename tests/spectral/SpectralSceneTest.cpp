// Realistic radiographs (spectral/SpectralScene.h) against arithmetic done here: one energy
// through a box of water-like tissue is exp(-mu L) with the exact chords (sources outside and
// inside the box); a spectrum through a wedge of bone (a mesh: exact chords) is the spectrum-
// weighted sum of Beer-Lambert terms, and its effective attenuation falls with thickness (beam
// hardening); bone and soft tissue of a CT are told apart by HU and density from HU.
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
    EXPECT_NEAR(densityFromHU(-1000.0), 0.001, 1e-12);  // the formula; decomposeMaterials leaves air out
    EXPECT_NEAR(densityFromHU(0.0), 1.030, 1e-12);
    EXPECT_NEAR(densityFromHU(1500.0), 0.0005886 * 1500 + 1.030, 1e-12);
    EXPECT_EQ(densityFromHU(-2000.0), 0.0);
    Volume ct = Volume::allocate({3, 1, 1}, 0.0f);
    ct.values = {-1000.0f, 40.0f, 1200.0f};
    const MaterialVolumes m = decomposeMaterials(ct);
    EXPECT_EQ(m.softTissue.values, (std::vector<float>{0.0f, std::round(1000.0f * float(densityFromHU(40.0))), 0.0f}));
    EXPECT_EQ(m.bone.values, (std::vector<float>{0.0f, 0.0f, std::round(1000.0f * float(densityFromHU(1200.0)))}));
    Volume mask = Volume::allocate({3, 1, 1}, 0.0f);
    mask.values = {0.0f, 1.0f, 0.0f};  // a label map: the middle voxel is the bone
    const MaterialVolumes byLabel = decomposeMaterials(ct, &mask);
    EXPECT_GT(byLabel.bone.values[1], 0.0f);
    EXPECT_EQ(byLabel.bone.values[2], 0.0f);
}

}  // namespace
}  // namespace fm::test
