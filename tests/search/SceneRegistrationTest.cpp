// Registration on the general scene model: the cost of several views is the sum of the
// views' costs, valid-pixel masks limit what is compared, and an object's pose in a camera's
// frame is recovered from one and from two views (biplane is the same code).
#include <gtest/gtest.h>

#include "core/Error.h"
#include "match/PoseError.h"
#include "scene/ObjectPoseParameterization.h"
#include "scene/VolumeScene.h"
#include "search/Registration.h"
#include "source/VolumeSource.h"

namespace fm {
namespace {

struct KneeScene {
    Volume volume = loadVolume("phantom:knee");
    DrrVolumePtr prepared = prepareDrrVolume(volume, {});
    SceneSetup setup = defaultSceneSetup();
    Scene scene;
    SceneParameterizationPtr parameterization;
    std::vector<Image> references;  // each camera's image at the truth
    SceneParams truth;
    KneeScene() {
        scene = volumeScene(prepared);
        scene.cameras = {sceneGeometry(parsePose("0,0,0,10,5,0"), setup, volume.center()),
                         sceneGeometry(parsePose("0,0,0,100,-5,0"), setup, volume.center())};
        // The truth: the CT turned and moved away from where its file puts it.
        const RigidTransform moved = rotationAbout({0.2, 1.0, -0.3}, 8.0, volume.center()) *
                                     RigidTransform::translate({4.0, -3.0, 2.0});
        auto p = std::make_shared<ObjectPoseParameterization>("ct", scene.cameras[0], moved,
                                                              volume.center());
        truth = p->referenceParams();
        parameterization = p;
        const Scene atTruth = sceneAt(scene, *p, truth);
        for (std::size_t c = 0; c < 2; ++c) references.push_back(renderView(atTruth, c, {}));
    }
    std::vector<RegistrationView> views(std::vector<std::size_t> cameras) const {
        std::vector<RegistrationView> out;
        for (std::size_t c : cameras) out.push_back({c, references[c], {}});
        return out;
    }
};

const KneeScene& kneeScene() {
    static const KneeScene k;
    return k;
}

RegistrationSettings quickSettings() {
    RegistrationSettings s;
    s.levelFactors = {4, 2};
    s.globalEvaluations = 300;
    s.polishEvaluations = 100;
    s.searchRadius = {5.0, 5.0, 10.0, 5.0, 5.0, 5.0};
    return s;
}

SceneParams offset(const SceneParams& p, const SceneParams& d) {
    SceneParams out;
    for (int i = 0; i < 6; ++i) out[i] = p[i] + d[i];
    return out;
}

TEST(SceneRegistration, CostOfTwoViewsIsTheSumOfTheirCosts) {
    const KneeScene& k = kneeScene();
    const RegistrationSettings s = quickSettings();
    const Registration both(k.scene, k.parameterization, k.views({0, 1}), s);
    const Registration first(k.scene, k.parameterization, k.views({0}), s);
    const Registration second(k.scene, k.parameterization, k.views({1}), s);
    const SceneParams off = offset(k.truth, {2, -1, 5, 1, 2, -1});
    for (int level = 0; level < 2; ++level) {
        EXPECT_DOUBLE_EQ(both.cost(off, level), first.cost(off, level) + second.cost(off, level));
        EXPECT_LT(both.cost(k.truth, level), both.cost(off, level));
    }
    EXPECT_LT(first.cost(k.truth, 1), -0.95);  // a DRR against itself
}

TEST(SceneRegistration, ValidPixelMasksLimitWhatIsCompared) {
    const KneeScene& k = kneeScene();
    const RegistrationSettings s = quickSettings();
    std::vector<RegistrationView> views = k.views({0});
    const Registration plain(k.scene, k.parameterization, views, s);
    const glm::ivec2 size = k.scene.cameras[0].detector.size;
    views[0].valid = Mask(size.x, size.y, true);
    const Registration allValid(k.scene, k.parameterization, views, s);
    const SceneParams off = offset(k.truth, {1, 1, 0, 1, 0, 0});
    EXPECT_EQ(allValid.cost(off, 1), plain.cost(off, 1));
    views[0].valid = Mask(size.x, size.y, false);
    const Registration noneValid(k.scene, k.parameterization, views, s);
    EXPECT_EQ(noneValid.cost(off, 1), 0.0);  // nothing to compare: no evidence
    // The left half valid: the cost is that of the comparison on the left half only, which
    // differs from the whole-image cost.
    Mask left(size.x, size.y, false);
    for (int r = 0; r < size.y; ++r)
        for (int c = 0; c < size.x / 2; ++c) left.inside[std::size_t(r) * size.x + c] = 1;
    views[0].valid = left;
    const Registration leftValid(k.scene, k.parameterization, views, s);
    EXPECT_NE(leftValid.cost(off, 1), plain.cost(off, 1));
    views[0].valid = Mask(size.x + 1, size.y, true);
    EXPECT_THROW(Registration(k.scene, k.parameterization, views, s), Error);
    const std::vector<RegistrationView> noSuchCamera{{2, k.references[0], {}}};
    EXPECT_THROW(Registration(k.scene, k.parameterization, noSuchCamera, s), Error);
    EXPECT_THROW(Registration(k.scene, k.parameterization, {}, s), Error);
}

TEST(SceneRegistration, RecoversAnObjectPoseFromOneAndFromTwoViews) {
    const KneeScene& k = kneeScene();
    const SceneParams start = offset(k.truth, {3, -2.5, 6, 3, -2, 2.5});
    const auto* p = static_cast<const ObjectPoseParameterization*>(k.parameterization.get());
    const auto targets = boneTargetPoints(k.volume, 300.0, 300);
    // Error in camera 0's frame: targets in the CT frame moved by both poses.
    auto errorOf = [&](const SceneParams& params) {
        const RigidTransform truthPose = p->worldFromObject(k.truth);
        const RigidTransform pose = p->worldFromObject(params);
        return targetRegistrationError(transformGeometry(truthPose.inverse(), k.scene.cameras[0]),
                                       transformGeometry(pose.inverse(), k.scene.cameras[0]),
                                       targets);
    };
    EXPECT_GT(errorOf(start).meanMm, 4.0);
    for (const auto& cameras : {std::vector<std::size_t>{0}, std::vector<std::size_t>{0, 1}}) {
        const Registration reg(k.scene, k.parameterization, k.views(cameras), quickSettings());
        const RegistrationResult r = reg.run(start);
        const TargetRegistrationError e = errorOf(r.params);
        EXPECT_LT(e.meanInPlaneMm, 0.5) << cameras.size() << " view(s)";
        EXPECT_LT(e.meanMm, 1.0) << cameras.size() << " view(s)";
    }
}

}  // namespace
}  // namespace fm
