// Registration on the knee phantom, the geometry helpers it relies on, and the target error.
#include <cmath>
#include <string>

#include <gtest/gtest.h>

#include "core/Error.h"
#include "drr/Drr.h"
#include "geometry/DetectorCrop.h"
#include "match/PoseError.h"
#include "scene/SceneParameterization.h"
#include "scene/VolumeScene.h"
#include "search/Evaluation.h"
#include "search/Registration.h"
#include "search/RegistrationTargets.h"
#include "source/VolumeSource.h"

namespace fm {
namespace {

// Geometry built from the same doubles along two routes agrees to rounding (~1e-13 mm at
// these magnitudes); 1e-9 mm leaves room and still catches any real mistake.
constexpr double kGeometryToleranceMm = 1e-9;
// Success in the van de Kraats protocol: final mTRE below 1 mm.
constexpr double kSuccessMtreMm = 1.0;

struct Knee {
    Volume volume = loadVolume("phantom:knee");
    DrrVolumePtr prepared = prepareDrrVolume(volume, {});
    SceneSetup setup = defaultSceneSetup();
    std::shared_ptr<const Pose2011Parameterization> parameterization =
        std::make_shared<Pose2011Parameterization>(setup, volume.center());
    ProjectionGeometry model(const Pose& pose) const { return parameterization->geometry(pose); }
    Registration registration(const Image& reference, const RegistrationSettings& s) const {
        return {volumeScene(prepared), parameterization, {{0, reference, {}}}, s};
    }
};

const Knee& knee() {
    static const Knee k;
    return k;
}

Image render(const ProjectionGeometry& g, int threads = 0) {
    DrrRenderOptions o;
    o.threads = threads;
    return renderDrr(*knee().prepared, g, o);
}

void expectNearPoint(const glm::dvec3& a, const glm::dvec3& b, double tol) {
    EXPECT_NEAR(a.x, b.x, tol);
    EXPECT_NEAR(a.y, b.y, tol);
    EXPECT_NEAR(a.z, b.z, tol);
}

TEST(TargetRegistrationError, CameraTranslationsSplitIntoInPlaneAndDepth) {
    const ProjectionGeometry truth = sceneGeometry(Pose{}, defaultSceneSetup(), glm::dvec3(0.0));
    const std::vector<glm::dvec3> targets{{0, 0, 0}, {10, 20, -30}, {-40, 5, 12}};
    // Moving the camera by d along its own axes moves every target by -d in camera coordinates:
    // |d| exactly, split by direction.
    ProjectionGeometry shifted = truth;
    const glm::dvec3 d = 3.0 * truth.detector.u + 4.0 * truth.detector.normal();
    shifted.source += d;
    shifted.detector.origin += d;
    const TargetRegistrationError e = targetRegistrationError(truth, shifted, targets);
    EXPECT_NEAR(e.meanMm, 5.0, 1e-9);
    EXPECT_NEAR(e.meanInPlaneMm, 3.0, 1e-9);
    EXPECT_NEAR(e.meanDepthMm, 4.0, 1e-9);
    EXPECT_NEAR(targetRegistrationError(truth, truth, targets).meanMm, 0.0, 1e-12);
    EXPECT_THROW(targetRegistrationError(truth, truth, {}), Error);
}

TEST(FixedCamera2011Parameterization, ZeroPoseIsTheGivenGeometryAndMovesLikeTheScene) {
    const SceneSetup setup = defaultSceneSetup();
    const glm::dvec3 center{5.0, -7.0, 12.0};
    // When the given geometry is the scene's zero-pose geometry, both models must agree at
    // every pose.
    const Pose2011Parameterization scene(setup, center);
    const FixedCamera2011Parameterization fixed(scene.geometry(Pose{}), setup, center);
    for (const Pose& p : {Pose{}, parsePose("3,-2,5,20,-10,7"), parsePose("-8,1,0,-95,45,-30")}) {
        const ProjectionGeometry a = scene.geometry(p), b = fixed.geometry(p);
        expectNearPoint(a.source, b.source, kGeometryToleranceMm);
        expectNearPoint(a.detector.origin, b.detector.origin, kGeometryToleranceMm);
        expectNearPoint(a.detector.u, b.detector.u, kGeometryToleranceMm);
        expectNearPoint(a.detector.v, b.detector.v, kGeometryToleranceMm);
    }
}

TEST(DetectorCrop, CroppedDetectorRendersExactlyThoseDrrPixels) {
    const ProjectionGeometry g = knee().model(Pose{}).downsampled(4);
    const Image full = render(g, 1);
    const ProjectionGeometry crop = cropDetector(g, 10, 7, 30, 41);
    const Image part = render(crop, 1);
    ASSERT_EQ(part.width, 30);
    ASSERT_EQ(part.height, 41);
    // Each pixel is one ray from the same source to the same point: the same line integral up
    // to the rounding of the moved origin (relative 1e-12 of a ~10 line integral).
    for (int r = 0; r < 41; ++r)
        for (int c = 0; c < 30; ++c) EXPECT_NEAR(part.at(c, r), full.at(c + 10, r + 7), 1e-4);
    EXPECT_THROW(cropDetector(g, 60, 0, 10, 10), Error);
    EXPECT_THROW(cropDetector(g, 0, 0, 0, 10), Error);
}

TEST(SearchCoordinates, TranslationsFollowTheStartCamera) {
    const Pose start = parsePose("1,2,3,30,10,5");
    const ProjectionGeometry g = knee().model(start);
    const Pose moved = poseFromSearchPoint(start, g, {2.0, 0.0, 0.0, 0.0, 0.0, 0.0});
    // Moving the CT by 2 mm along film u moves its projection along u and not along v.
    const glm::dvec3 c = knee().volume.center();
    const auto before = g.projectToPixel(c), after = knee().model(moved).projectToPixel(c);
    ASSERT_TRUE(before && after);
    EXPECT_GT(std::abs(after->x - before->x), 0.5);  // 2 mm x magnification 2 / 2.5 mm pixels
    EXPECT_NEAR(after->y, before->y, 1e-9);
    const Pose turned = poseFromSearchPoint(start, g, {0, 0, 0, 1.5, -2.0, 0.5});
    EXPECT_NEAR(turned.azimuthDeg, 31.5, 1e-12);
    EXPECT_NEAR(turned.elevationDeg, 8.0, 1e-12);
    EXPECT_NEAR(turned.rotationDeg, 5.5, 1e-12);
}

TEST(Registration, CostIsLowestAtTheTruthAlongEachParameter) {
    const Pose truth = parsePose("0,0,0,10,5,0");
    const Image reference = render(knee().model(truth));
    RegistrationSettings s;
    s.levelFactors = {4};
    const Registration reg = knee().registration(reference, s);
    const double atTruth = reg.cost(truth.toArray(), 0);
    EXPECT_LT(atTruth, -0.95);  // a DRR against itself (up to pyramid averaging)
    for (int p = 0; p < 6; ++p)
        for (double step : {-3.0, 3.0}) {
            auto a = truth.toArray();
            a[p] += step;
            EXPECT_GT(reg.cost(a, 0), atTruth) << "parameter " << p;
        }
}

TEST(Registration, RecoversThePhantomPoseFromA5mm5DegStart) {
    const Pose truth = parsePose("0,0,0,10,5,0");
    const Image reference = render(knee().model(truth));
    const Pose start = parsePose("3,-3,2,13.5,2,-3");  // 3-3.5 mm and deg off per parameter
    const auto targets = registrationTargets(knee().volume);
    const double startMtre =
        targetRegistrationError(knee().model(truth), knee().model(start), targets).meanMm;
    EXPECT_GT(startMtre, 4.0);  // the start really is that far off
    for (SearchMethod m : globalSearchMethods()) {
        RegistrationSettings s;
        s.method = m;
        // Kept fast (it runs under the sanitizers too): 64 and 128 pixel levels only, which
        // already reach about 0.5 mm; the full-resolution level is measured by `evaluate`.
        s.levelFactors = {4, 2};
        s.globalEvaluations = 400;
        s.polishEvaluations = 120;
        const Registration reg = knee().registration(reference, s);
        const RegistrationResult r = reg.run(start.toArray());
        const TargetRegistrationError e =
            targetRegistrationError(knee().model(truth), knee().model(r.pose()), targets);
        EXPECT_LT(e.meanMm, kSuccessMtreMm) << toString(m) << " ended at " << formatPose(r.pose());
        EXPECT_LE(r.evaluations, reg.totalBudget());
        EXPECT_FALSE(r.stopped);
    }
}

TEST(Registration, RefinesDepthAlongTheCameraAsFound) {
    // A start 10 deg off in azimuth: the start camera's depth axis is 10 deg off the true one,
    // so a depth step along it also moves the image sideways by sin(10 deg) of the step. When
    // the refinements searched along the start's axes, CMA-ES ended here at 1.79 mm mTRE, 1.79
    // mm of it along the beam; the refinements now search around the pose found so far.
    const Pose truth{};
    const Image reference = render(knee().model(truth));
    const Pose start = parsePose("10,0,0,10,0,0");
    const auto targets = registrationTargets(knee().volume);
    RegistrationSettings s;  // the defaults, full resolution included
    const RegistrationResult r = knee().registration(reference, s).run(start.toArray());
    const TargetRegistrationError e =
        targetRegistrationError(knee().model(truth), knee().model(r.pose()), targets);
    EXPECT_LT(e.meanMm, kSuccessMtreMm) << formatPose(r.pose());
    EXPECT_LT(e.meanDepthMm, 0.5) << formatPose(r.pose());
}

TEST(Registration, CoarseLevelsTraceBlockMeansAndStillPeakAtTheTruth) {
    const Pose truth = parsePose("0,0,0,10,5,0");
    const Image reference = render(knee().model(truth));
    RegistrationSettings s;
    s.levelFactors = {4, 1};
    s.coarseVolumeRatio = 1.25;  // what register / evaluate use on a CT
    const Registration coarse = knee().registration(reference, s);
    s.coarseVolumeRatio = 0.0;
    const Registration full = knee().registration(reference, s);
    const double atTruth = coarse.cost(truth.toArray(), 0);
    // Level 0 (rays 5.5 mm apart at the knee, voxels 1.7-2 mm) traces 2x2x2 block means: a
    // different image from the full volume's, at the finest level the same one.
    EXPECT_NE(atTruth, full.cost(truth.toArray(), 0));
    EXPECT_EQ(coarse.cost(truth.toArray(), 1), full.cost(truth.toArray(), 1));
    EXPECT_LT(atTruth, -0.95);
    for (int p = 0; p < 6; ++p)
        for (double step : {-3.0, 3.0}) {
            auto a = truth.toArray();
            a[p] += step;
            EXPECT_GT(coarse.cost(a, 0), atTruth) << "parameter " << p;
        }
}

TEST(Registration, LeavesOutLevelsFinerThanTheVoxels) {
    const Image reference = render(knee().model(Pose{}));
    RegistrationSettings s;  // levels 4, 2, 1: rays 5.5, 2.7 and 1.4 mm apart at the knee
    s.dropLevelsFinerThanVoxels = true;  // what register / evaluate use on a CT
    EXPECT_EQ(knee().registration(reference, s).settings().levelFactors,
              (std::vector<int>{4, 2, 1}));  // 1.72 mm voxels: every level resolves more
    // The knee in 3.44 x 3.44 x 3.99 mm voxels: 2.7 mm rays already sample every voxel.
    const Scene coarse = volumeScene(coarsenDrrVolume(*knee().prepared, 2));
    const Registration dropped(coarse, knee().parameterization, {{0, reference, {}}}, s);
    EXPECT_EQ(dropped.settings().levelFactors, (std::vector<int>{4, 2}));
    EXPECT_EQ(dropped.levelCount(), 2);
    s.dropLevelsFinerThanVoxels = false;
    const Registration kept(coarse, knee().parameterization, {{0, reference, {}}}, s);
    EXPECT_EQ(kept.settings().levelFactors, (std::vector<int>{4, 2, 1}));
}

TEST(Registration, DeterministicForASeedAndStoppable) {
    const Pose truth{};
    const Image reference = render(knee().model(truth));
    RegistrationSettings s;
    s.method = SearchMethod::ParticleSwarm;
    s.levelFactors = {4, 2};
    s.globalEvaluations = 120;
    s.polishEvaluations = 30;
    s.seed = 5;
    const Registration reg = knee().registration(reference, s);
    const Pose start = parsePose("2,1,-2,2,-1,1");
    const RegistrationResult a = reg.run(start.toArray()), b = reg.run(start.toArray());
    EXPECT_EQ(a.params, b.params);
    EXPECT_EQ(a.costHistory, b.costHistory);

    std::atomic<bool> stop{false};
    int calls = 0;
    int lastEvaluations = 0;
    const RegistrationResult c = reg.run(
        start.toArray(),
        [&](const RegistrationProgress& p) {
            EXPECT_GE(p.evaluations, lastEvaluations);
            EXPECT_LE(p.evaluations, p.evaluationBudget);
            lastEvaluations = p.evaluations;
            if (++calls == 2) stop = true;
        },
        &stop);
    EXPECT_TRUE(c.stopped);
    EXPECT_EQ(calls, 2);
    EXPECT_LT(c.evaluations, a.evaluations);
}

TEST(Registration, OutOfPlaneHypothesesKeepTheSearchDeterministicAndInBudget) {
    // The hypotheses (realXraySettings turns them on) on the knee: the same result for 1 and 2
    // threads, the evaluations within totalBudget, the stage reported, the truth still found.
    const Pose truth = parsePose("0,0,0,10,5,0");
    const Image reference = render(knee().model(truth));
    const Pose start = parsePose("3,-3,2,13.5,2,-3");
    RegistrationSettings s;
    s.levelFactors = {4, 2};
    s.globalEvaluations = 200;
    s.polishEvaluations = 60;
    s.hypothesisTiltDeg = 6.0;
    s.hypothesisEvaluations = 20;
    std::vector<RegistrationResult> runs;
    int hypothesisReports = 0;
    for (int threads : {1, 2}) {
        s.threads = threads;
        const Registration reg = knee().registration(reference, s);
        runs.push_back(reg.run(start.toArray(), [&](const RegistrationProgress& p) {
            hypothesisReports += std::string(p.stage) == "hypothesis";
            EXPECT_LE(p.evaluations, p.evaluationBudget);
        }));
        EXPECT_LE(runs.back().evaluations, reg.totalBudget());
        // At least the 4 hypotheses' polishes and the 5 scores more than without them.
        RegistrationSettings off = s;
        off.hypothesisTiltDeg = 0.0;
        EXPECT_GT(reg.totalBudget(), knee().registration(reference, off).totalBudget() + 4 * 20 + 5);
    }
    EXPECT_EQ(runs[0].params, runs[1].params);
    EXPECT_EQ(runs[0].costHistory, runs[1].costHistory);
    EXPECT_GT(hypothesisReports, 0);
    const double mtre = targetRegistrationError(knee().model(truth), knee().model(runs[0].pose()),
                                                registrationTargets(knee().volume))
                            .meanMm;
    EXPECT_LT(mtre, kSuccessMtreMm) << formatPose(runs[0].pose());
}

TEST(Registration, RejectsBadInput) {
    const Image reference = render(knee().model(Pose{}));
    RegistrationSettings s;
    EXPECT_THROW(knee().registration(Image(), s), Error);
    EXPECT_THROW(knee().registration(Image(100, 100, 1.0f), s), Error);
    s.coarseVolumeRatio = -1.0;
    EXPECT_THROW(knee().registration(reference, s), Error);
    s.coarseVolumeRatio = 1.25;
    s.levelFactors = {2, 4};
    EXPECT_THROW(knee().registration(reference, s), Error);
    s.levelFactors = {3};
    EXPECT_THROW(knee().registration(reference, s), Error);
    s.levelFactors = {4, 2};
    for (double tilt : {-1.0, std::nan(""), HUGE_VAL}) {
        RegistrationSettings h = s;
        h.hypothesisTiltDeg = tilt;
        EXPECT_THROW(knee().registration(reference, h), Error) << tilt;
    }
    RegistrationSettings h = s;
    h.hypothesisTiltDeg = 6.0;
    h.hypothesesKept = 0;
    EXPECT_THROW(knee().registration(reference, h), Error);
    s.searchRadius[2] = 0.0;
    EXPECT_THROW(knee().registration(reference, s), Error);
}

TEST(Evaluation, StartPosesLandInTheirBins) {
    const auto targets = registrationTargets(knee().volume);
    const Pose truth = parsePose("0,0,0,10,5,0");
    const EvaluationScene scene{volumeScene(knee().prepared), knee().parameterization, 0};
    Rng rng(3);
    for (const StartBin& bin : standardStartBins())
        for (int i = 0; i < 5; ++i) {
            const Pose p = Pose::fromArray(startInBin(truth.toArray(), scene, targets, bin, rng));
            const double e =
                targetRegistrationError(knee().model(truth), knee().model(p), targets).meanMm;
            EXPECT_GE(e, bin.lowMm);
            EXPECT_LE(e, bin.highMm);
        }
}

TEST(Evaluation, SummariesFollowTheDefinitions) {
    EvaluationSettings s;
    s.methods = {SearchMethod::CmaEs, SearchMethod::MonteCarlo};
    s.bins = {{0, 2}, {2, 5}, {5, 10}};
    std::vector<EvaluationTrial> trials;
    auto add = [&](SearchMethod m, int bin, double mtre, double seconds) {
        EvaluationTrial t;
        t.method = m;
        t.bin = bin;
        t.final.meanMm = mtre;
        t.seconds = seconds;
        t.success = mtre < s.successMm;
        trials.push_back(t);
    };
    // cmaes: all succeed in bins 0 and 1, half in bin 2 -> capture range 5 mm.
    add(SearchMethod::CmaEs, 0, 0.2, 1.0), add(SearchMethod::CmaEs, 0, 0.4, 3.0);
    add(SearchMethod::CmaEs, 1, 0.3, 2.0), add(SearchMethod::CmaEs, 1, 0.5, 2.0);
    add(SearchMethod::CmaEs, 2, 0.6, 1.0), add(SearchMethod::CmaEs, 2, 7.0, 1.0);
    // mc: fails in bin 0 already -> capture range 0, even though bin 1 succeeds.
    add(SearchMethod::MonteCarlo, 0, 3.0, 1.0), add(SearchMethod::MonteCarlo, 0, 0.1, 1.0);
    add(SearchMethod::MonteCarlo, 1, 0.1, 1.0);
    const auto bins = summarizeBins(trials, s);
    ASSERT_EQ(bins.size(), 5u);  // mc has no trial in bin 2
    EXPECT_DOUBLE_EQ(bins[0].medianMtreMm, 0.3);
    EXPECT_DOUBLE_EQ(bins[0].medianSeconds, 2.0);
    EXPECT_DOUBLE_EQ(bins[2].successRate, 0.5);
    const auto methods = summarizeMethods(trials, s);
    ASSERT_EQ(methods.size(), 2u);
    EXPECT_DOUBLE_EQ(methods[0].captureRangeMm, 5.0);
    EXPECT_DOUBLE_EQ(methods[0].successRate, 5.0 / 6.0);
    EXPECT_DOUBLE_EQ(methods[1].captureRangeMm, 0.0);
    EXPECT_TRUE(std::isnan(median({})));
    EXPECT_DOUBLE_EQ(median({3.0, 1.0, 2.0}), 2.0);
}

}  // namespace
}  // namespace fm

namespace fm {
namespace {

TEST(Registration, ItsProfileAccountsForItsOwnEvaluations) {
    // search/EvaluationProfile.h: the run's evaluations and wall time, and thread time in each
    // stage (all measured, none zero), adding up to no more than its threads could give.
    const Pose truth = parsePose("0,0,0,10,5,0");
    const Image reference = render(knee().model(truth));
    RegistrationSettings s;
    s.levelFactors = {4, 2};
    s.globalEvaluations = 100;
    s.polishEvaluations = 40;
    s.threads = 2;
    const Registration reg = knee().registration(reference, s);
    const RegistrationResult first = reg.run(parsePose("2,-2,1,12,4,1").toArray());
    const RegistrationResult second = reg.run(parsePose("2,-2,1,12,4,1").toArray());
    for (const RegistrationResult* r : {&first, &second}) {
        const EvaluationProfile& p = r->profile;
        EXPECT_EQ(p.evaluations, r->evaluations);
        EXPECT_EQ(p.wallSeconds, r->seconds);
        EXPECT_GT(p.setupSeconds, 0.0);
        EXPECT_GT(p.renderSeconds, 0.0);
        EXPECT_GT(p.footprintSeconds, 0.0);
        EXPECT_GT(p.similaritySeconds, 0.0);
        EXPECT_LE(p.threadSeconds(), 2.0 * p.wallSeconds * 1.05 + 1e-3);
    }
    // The second run reports its own time, not the first's too.
    EXPECT_LT(second.profile.threadSeconds(), 1.5 * first.profile.threadSeconds() + 0.05);
    const std::string line = describeEvaluations(first.profile, 2);
    EXPECT_NE(line.find(std::to_string(first.evaluations) + " evaluations in"), std::string::npos) << line;
    EXPECT_NE(line.find("per core-second"), std::string::npos) << line;
    EvaluationProfile sum = first.profile;
    sum += second.profile;
    EXPECT_EQ(sum.evaluations, first.evaluations + second.evaluations);
}

}  // namespace
}  // namespace fm
