// Why the patella's per-bone evaluation fails (docs/bones.md): the phantom's patella is an
// ellipsoid with two equal semi-axes (kPatellaSemiAxes 22, 10.5, 22 mm), a body of revolution
// about its own y axis, and its density depends only on the distance to its surface. A turn
// about that axis leaves its lateral DRR nearly unchanged, yet moves its points: no image can
// tell that rotation (up to voxelisation), and the mTRE over the patella's points counts it.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "bones/BoneMotion.h"
#include "bones/BoneRegistration.h"
#include "bones/BoneVolume.h"
#include "match/PoseError.h"
#include "phantom/ArticulatedKnee.h"

namespace {

// |a - b| / |a| over the pixels (root of the summed squares).
double relativeDifference(const fm::Image& a, const fm::Image& b) {
    double norm = 0.0, diff = 0.0;
    for (std::size_t i = 0; i < a.pixels.size(); ++i) {
        norm += double(a.pixels[i]) * a.pixels[i];
        const double d = double(a.pixels[i]) - double(b.pixels[i]);
        diff += d * d;
    }
    return std::sqrt(diff / norm);
}

struct PatellaAlone {
    fm::KneePhantomParams params;
    fm::Scene scene;
    glm::dvec3 centre;
    std::vector<glm::dvec3> targets;  // the patella's points, its own frame
};

PatellaAlone patellaAlone() {
    PatellaAlone p;
    fm::BoneSceneOptions options;
    options.includeRest = false;
    p.scene = fm::makeArticulatedKnee(p.params, options);
    for (auto& o : p.scene.objects) o.visible = o.name == fm::kKneePatella;
    fm::SceneSetup setup = fm::defaultSceneSetup();
    setup.filmPixels = {128, 128};
    // The lateral view of the per-bone evaluation (--truth 0,0,0,90,0,0).
    p.scene.cameras.push_back(fm::sceneGeometry(fm::Pose{{0, 0, 0}, 90.0, 0.0, 0.0}, setup, {}));
    p.centre = fm::kneeModelToWorld(p.params, fm::KneeSegment::Patella, fm::kPatellaCenter);
    const fm::Volume ct = fm::makeKneePhantom(p.params);
    const fm::Volume labels = fm::makeKneeBoneLabels(p.params);
    const auto bones = fm::kneeBones();
    p.targets = fm::boneTargetPoints(fm::boneVolume(ct, labels, bones[2]), 200.0, 1000);
    return p;
}

double meanPointDistance(const fm::RigidTransform& a, const std::vector<glm::dvec3>& points) {
    double sum = 0.0;
    for (const auto& q : points) sum += glm::length(a.applyToPoint(q) - q);
    return sum / double(points.size());
}

TEST(PatellaSymmetry, ATurnAboutItsOwnYAxisHardlyChangesTheLateralView) {
    PatellaAlone p = patellaAlone();
    // The straight knee's patella frame has the world's axes (kneeAnatomicalFrame).
    const fm::RigidTransform aboutY = fm::rotationAbout({0, 1, 0}, 20.0, p.centre);
    const fm::RigidTransform aboutX = fm::rotationAbout({1, 0, 0}, 20.0, p.centre);
    const fm::RigidTransform aboutZ = fm::rotationAbout({0, 0, 1}, 20.0, p.centre);
    const double moved = meanPointDistance(aboutY, p.targets);
    for (std::size_t c = 0; c < p.scene.cameras.size(); ++c) {
        const fm::Image still = fm::renderView(p.scene, c, {});
        auto turned = [&](const fm::RigidTransform& t) {
            fm::Scene s = p.scene;
            s.object(fm::kKneePatella).worldFromObject = t;
            return relativeDifference(still, fm::renderView(s, c, {}));
        };
        const double y = turned(aboutY), x = turned(aboutX), z = turned(aboutZ);
        std::printf("camera %zu: 20 deg about the patella's y axis changes the DRR by %.4f (RMS, "
                    "relative) (about x %.4f, about z %.4f); its points move by %.2f mm on average\n",
                    c, y, x, z, moved);
        // Voxelisation and the label's cut at the femur break the symmetry a little: the turn
        // about y changes the image a few per cent, the visible turns three to eight times more.
        EXPECT_LT(y, 0.08);
        EXPECT_GT(std::min(x, z), 3.0 * y);
    }
    EXPECT_GT(moved, 4.0);  // yet the mTRE of that invisible turn is several millimetres
}

}  // namespace

namespace {

// The error of a registration as a turn about the patella's centre: its angle (deg) and unit axis.
struct Turn {
    double angleDeg;
    glm::dvec3 axis;
};
Turn turnOf(const glm::dmat3& r) {
    const double angle = std::acos(std::clamp((r[0][0] + r[1][1] + r[2][2] - 1.0) / 2.0, -1.0, 1.0));
    const glm::dvec3 axis(r[1][2] - r[2][1], r[2][0] - r[0][2], r[0][1] - r[1][0]);
    return {glm::degrees(angle), glm::length(axis) > 1e-12 ? glm::normalize(axis) : axis};
}

TEST(PatellaSymmetry, ItsRegistrationErrorIsTheTurnAboutItsSymmetryAxis) {
    // The per-bone evaluation's set-up (lateral view, the other bones and the soft tissue
    // static, default settings), from a start 4 deg about y off. What the search cannot see is
    // what it gets wrong: the final error is a turn about the patella's y axis; without that
    // turn the patella is within about a millimetre (its depth, which one view hardly shows).
    fm::KneePhantomParams params;
    fm::Scene knee = fm::makeArticulatedKnee(params);
    knee.cameras.push_back(
        fm::sceneGeometry(fm::Pose{{0, 0, 0}, 90.0, 0.0, 0.0}, fm::defaultSceneSetup(), {}));
    const fm::Image reference = fm::renderView(knee, 0, {});
    const PatellaAlone p = patellaAlone();
    fm::Scene start = knee;
    start.object(fm::kKneePatella).worldFromObject =
        fm::boneMotionTransform({0, 0, 0, 0, 4, 0}, p.centre);
    const auto r = fm::registerBone(start, fm::kKneePatella, {reference}, fm::RegistrationSettings{});
    const fm::RigidTransform& error = r.worldFromBone;  // the truth is the identity
    const Turn turn = turnOf(error.rotation);
    const double aboutY = turn.angleDeg * turn.axis.y;
    const fm::RigidTransform withoutTheTurn =
        error * fm::rotationAbout({0, 1, 0}, -aboutY, p.centre);
    const double mtre = meanPointDistance(error, p.targets);
    const double rest = meanPointDistance(withoutTheTurn, p.targets);
    std::printf("patella registered from 4 deg about y: mTRE %.2f mm; error %.2f deg about "
                "(%.2f, %.2f, %.2f); without the turn about y %.2f mm\n",
                mtre, turn.angleDeg, turn.axis.x, turn.axis.y, turn.axis.z, rest);
    EXPECT_GT(mtre, 1.0) << "a failure by the evaluation's 1 mm rule";
    EXPECT_GT(std::abs(turn.axis.y), 0.95) << "the error turns about the symmetry axis";
    EXPECT_LT(rest, 1.5);
    EXPECT_LT(rest, 0.6 * mtre);
}

}  // namespace
