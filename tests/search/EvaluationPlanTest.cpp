// The evaluation plan: the job list a distributed evaluate splits over ranks. Its order and its
// starts must be those of the one-process protocol (methods, then bins, then starts; one
// stream of starts from the seed, shared by every method), so that results do not change.
#include <gtest/gtest.h>

#include "core/Random.h"
#include "drr/Drr.h"
#include "geometry/Pose.h"
#include "scene/SceneParameterization.h"
#include "scene/VolumeScene.h"
#include "search/Evaluation.h"
#include "search/RegistrationTargets.h"
#include "source/VolumeSource.h"

namespace fm {
namespace {

TEST(EvaluationPlan, MethodsThenBinsThenStartsFromOneStream) {
    const Volume volume = loadVolume("phantom:knee");
    const auto parameterization =
        std::make_shared<Pose2011Parameterization>(defaultSceneSetup(), volume.center());
    const EvaluationScene scene{volumeScene(prepareDrrVolume(volume, {})), parameterization, 0};
    const auto targets = registrationTargets(volume);
    const SceneParams truth = parsePose("0,0,0,10,5,0").toArray();
    EvaluationSettings s;
    s.methods = {SearchMethod::CmaEs, SearchMethod::MonteCarlo};
    s.startsPerBin = 3;
    s.seed = 11;
    const auto plan = evaluationPlan(truth, scene, targets, s);
    ASSERT_EQ(plan.size(), 2u * 4u * 3u);

    // The starts drawn directly, bin by bin, from one generator seeded with the seed.
    Rng rng(s.seed);
    std::vector<SceneParams> direct;
    for (const StartBin& bin : s.bins)
        for (int i = 0; i < s.startsPerBin; ++i)
            direct.push_back(startInBin(truth, scene, targets, bin, rng));

    std::size_t k = 0;
    for (SearchMethod m : s.methods)
        for (int b = 0; b < 4; ++b)
            for (int i = 0; i < 3; ++i, ++k) {
                EXPECT_EQ(plan[k].method, m);
                EXPECT_EQ(plan[k].bin, b);
                EXPECT_EQ(plan[k].start, i);
                EXPECT_EQ(plan[k].params, direct[b * 3 + i]) << "job " << k;
            }
    // The same inputs give the same plan (every rank computes its own copy).
    const auto again = evaluationPlan(truth, scene, targets, s);
    for (std::size_t j = 0; j < plan.size(); ++j) EXPECT_EQ(again[j].params, plan[j].params);
}

}  // namespace
}  // namespace fm
