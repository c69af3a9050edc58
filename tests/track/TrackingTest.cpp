// Tracking through biplane sequences with real geometry: the radius of Autoscoper's sample
// wrist seen through the two real wrist calibrations (their 1760-pixel images at 512 x 512, the
// trial's RenderResolution, as tracking renders them), moving along a smooth known trajectory
// with noise. Every frame must come back within 0.25 mm (bone centre) and 0.25 deg; a stretch
// where the bone leaves one camera's view is tracked on the other and reported as single-view;
// a resumed run gives the same poses as an uninterrupted one.
#include <cmath>

#include <gtest/gtest.h>

#include "camera/CameraFile.h"
#include "camera/PinholeCamera.h"
#include "common/SanitizerBuild.h"
#include "common/TestData.h"
#include "core/Error.h"
#include "core/Random.h"
#include "drr/Drr.h"
#include "io/TiffVolume.h"
#include "scene/XrayModel.h"
#include "search/Registration.h"
#include "track/PoseErrors.h"
#include "track/Tracker.h"
#include "scene/ObjectPoseParameterization.h"

namespace {

using fm::RigidTransform;

// The accuracy for synthetic sequences with real geometry.
constexpr double kMaxCentreErrorMm = 0.25;
constexpr double kMaxAngleErrorDeg = 0.25;
// Noise added to the rendered frames, as a fraction of the brightest pixel.
constexpr double kNoiseFraction = 0.02;
// Frames of the biplane sequence (Release only: tests/track/extra.cmake).
constexpr int kFrames = 20;
// The wrist images (1760 pixels square) at the shipped trial's RenderResolution, as tracking
// renders them (trialRenderSize).
constexpr int kRenderSize = 512;

struct Wrist {
    fm::Scene scene;
    glm::dvec3 centre{0.0};  // bone centre, object frame

    Wrist() {
        const auto dir = fm::test::sharedDataDir() / "autoscoper-bvr";
        for (const char* cam : {"Calibration/xr_calib_wrist_cam01.txt", "Calibration/xr_calib_wrist_cam02.txt"})
            scene.cameras.push_back(fm::toProjectionGeometry(
                fm::resizedCamera(fm::readCameraFile(dir / cam).camera, {kRenderSize, kRenderSize})));
        const fm::Volume v = fm::io::readTiffVolume(dir / "Models/rad_dcm_cropped.tif", {0.39625, 0.39625, 0.625});
        fm::DrrValueOptions raw;
        raw.values = fm::DrrValues::Raw;
        auto model = std::make_shared<fm::VolumeXrayModel>(fm::prepareDrrVolume(v, raw));
        const fm::Box3 box = model->bounds();
        centre = 0.5 * (box.lower + box.upper);
        scene.objects.push_back({"radius", model, {}, true});
        // Where the two image centres' rays pass closest: in the middle of both views.
        const fm::ProjectionGeometry& a = scene.cameras[0];
        const fm::ProjectionGeometry& b = scene.cameras[1];
        const glm::dvec3 da = glm::normalize(a.detector.center() - a.source);
        const glm::dvec3 db = glm::normalize(b.detector.center() - b.source);
        const glm::dvec3 r = a.source - b.source;
        const double k = glm::dot(da, db), d = glm::dot(da, r), e = glm::dot(db, r);
        const double ta = (k * e - d) / (1.0 - k * k), tb = (e - k * d) / (1.0 - k * k);
        middle = 0.5 * (a.source + ta * da + b.source + tb * db);
    }
    glm::dvec3 middle{0.0};  // world point seen at the centre of both images

    // A smooth trajectory around the calibration origin (seen by both cameras): 1.5-3 mm and
    // 2-3 deg per frame, not constant velocity (so the extrapolated start is off every frame).
    RigidTransform truth(int k, glm::dvec3 drift = glm::dvec3(0.0)) const {
        const double s = k;
        const glm::dvec3 c{2.0 * s + 2.0 * std::sin(s / 2.0), 1.5 * s, -s + 3.0 * std::cos(s / 3.0) - 3.0};
        return RigidTransform::translate(middle + c + s * drift) *
               fm::rotationAbout({0.3, 1.0, 0.2}, 2.0 * s, glm::dvec3(0.0)) *
               fm::rotationAbout({1.0, 0.0, 0.5}, 3.0 * std::sin(s / 3.0), glm::dvec3(0.0)) *
               RigidTransform::translate(-centre);
    }

    // The frames the cameras would record, with noise (seeded).
    fm::FrameViews frames(std::function<RigidTransform(int)> pose) const {
        return [this, pose](int k) {
            fm::Scene s = scene;
            s.objects[0].worldFromObject = pose(k);
            fm::Rng rng(1000 + k);
            std::vector<fm::RegistrationView> views;
            for (std::size_t c = 0; c < s.cameras.size(); ++c) {
                fm::Image img = fm::renderView(s, c, {});
                float peak = 0.0f;
                for (float p : img.pixels) peak = std::max(peak, p);
                for (float& p : img.pixels) p += static_cast<float>(kNoiseFraction * peak * rng.normal());
                views.push_back({c, std::move(img), std::nullopt});
            }
            return views;
        };
    }
};

using fm::test::angleErrorDeg;
using fm::test::centreError;

TEST(Tracking, RecoversEveryFrameOfABiplaneSequenceThroughTheRealWristCameras) {
    FM_REQUIRE_SHARED_DATA("autoscoper-bvr/Models/rad_dcm_cropped.tif");
    const Wrist w;
    const auto truth = [&](int k) { return w.truth(k); };
    ASSERT_GT(centreError(truth(0), truth(1), w.centre), 1.5);  // the motion is several mm per frame
    ASSERT_GT(angleErrorDeg(truth(0), truth(1)), 2.0);
    const fm::Tracker tracker(w.scene, "radius", w.frames(truth), {});
    for (std::size_t c = 0; c < 2; ++c)
        for (int k = 0; k < kFrames; ++k) ASSERT_GT(tracker.inViewFraction(c, truth(k)), 0.99);

    std::vector<int> frames;
    for (int k = 1; k < kFrames; ++k) frames.push_back(k);
    std::map<int, RigidTransform> tracked;
    std::vector<fm::FrameRecord> records;
    tracker.run(frames, {{0, truth(0)}}, tracked, [&](const fm::FrameRecord& r) { records.push_back(r); });
    ASSERT_EQ(records.size(), frames.size());
    for (const fm::FrameRecord& r : records) {
        ASSERT_EQ(r.status, fm::FrameRecord::Status::Tracked) << "frame " << r.frame << ": " << r.note;
        EXPECT_EQ(r.camerasUsed, 2);
        EXPECT_TRUE(std::isfinite(r.viewCost[0]) && std::isfinite(r.viewCost[1]));
        EXPECT_LT(centreError(*r.worldFromBone, truth(r.frame), w.centre), kMaxCentreErrorMm) << "frame " << r.frame;
        EXPECT_LT(angleErrorDeg(*r.worldFromBone, truth(r.frame)), kMaxAngleErrorDeg) << "frame " << r.frame;
    }
}

// trackFrame's progress (what the app's biplane Solve shows): over both searches, evaluations
// never go back, end at the record's count within one budget, and the levels run from the
// coarsest to the full-resolution one (the coarse levels, then one more).
TEST(Tracking, ReportsProgressOverTheCoarseAndTheFullResolutionSearch) {
    FM_REQUIRE_SHARED_DATA("autoscoper-bvr/Models/rad_dcm_cropped.tif");
    const Wrist w;
    const auto truth = [&](int k) { return w.truth(k); };
    fm::TrackSettings settings;
    settings.confirmWithoutReference = false;  // the confirming search reports no progress
    const fm::Tracker tracker(w.scene, "radius", w.frames(truth), settings);
    std::vector<fm::RegistrationProgress> seen;
    const fm::FrameRecord r =
        tracker.trackFrame(1, truth(0), nullptr, [&](const fm::RegistrationProgress& p) { seen.push_back(p); });
    ASSERT_EQ(r.status, fm::FrameRecord::Status::Tracked) << r.note;
    ASSERT_GT(seen.size(), 10u);
    const int levels = static_cast<int>(tracker.settings().registration.levelFactors.size()) + 1;
    for (std::size_t i = 0; i < seen.size(); ++i) {
        EXPECT_EQ(seen[i].levelCount, levels);
        EXPECT_EQ(seen[i].evaluationBudget, seen[0].evaluationBudget);
        EXPECT_LE(seen[i].evaluations, seen[i].evaluationBudget);
        if (i > 0) {
            EXPECT_GE(seen[i].evaluations, seen[i - 1].evaluations) << i;
            EXPECT_GE(seen[i].level, seen[i - 1].level) << i;
        }
    }
    EXPECT_EQ(seen.front().level, 0);
    EXPECT_EQ(seen.back().level, levels - 1);
    EXPECT_EQ(seen.back().factor, 1);
    EXPECT_EQ(seen.back().evaluations, r.evaluations);
}

// Step 5: each frame judged against the last good one (frame 0 against its keyframe); a frame
// whose images hold no bone (noise only) is lost whatever the search finds, its pose is never a
// later frame's start, and the run stops there, searches it again or goes on as onLost says.
TEST(Tracking, VerdictsJudgeEveryFrameAndALostFrameStopsOrIsSearchedAgainOrSkipped) {
    FM_REQUIRE_SHARED_DATA("autoscoper-bvr/Models/rad_dcm_cropped.tif");
    const Wrist w;
    const auto truth = [&](int k) { return w.truth(k); };
    const fm::FrameViews real = w.frames(truth);
    const fm::FrameViews withBlank = [&](int k) {
        std::vector<fm::RegistrationView> views = real(k);
        if (k != 2) return views;
        fm::Rng rng(7);
        for (fm::RegistrationView& v : views)
            for (float& p : v.reference.pixels) p = static_cast<float>(rng.normal());
        return views;
    };
    const std::map<int, RigidTransform> keyframes{{0, truth(0)}};
    const auto runWith = [&](fm::OnLost onLost) {
        fm::TrackSettings settings;
        settings.onLost = onLost;
        const fm::Tracker tracker(w.scene, "radius", withBlank, settings);
        std::map<int, RigidTransform> tracked;
        std::vector<fm::FrameRecord> records;
        tracker.run({0, 1, 2, 3}, keyframes, tracked, [&](const fm::FrameRecord& r) { records.push_back(r); });
        return std::make_pair(records, tracked);
    };
    const auto [records, tracked] = runWith(fm::OnLost::Continue);
    ASSERT_EQ(records.size(), 4u);
    for (int k : {0, 1, 3}) {
        const fm::FrameRecord& r = records[static_cast<std::size_t>(k)];
        EXPECT_EQ(r.verdict, fm::AnswerVerdict::Ok) << k << ": " << r.verdictText;
        ASSERT_TRUE(r.evidence.similarityRatio) << k;
        EXPECT_GT(*r.evidence.similarityRatio, fm::kConfirmedSimilarityRatio) << k;
        ASSERT_TRUE(r.evidence.uncertainty) << k;
        EXPECT_EQ(r.evidence.uncertainty->evaluations, 73);
        EXPECT_LT(centreError(*r.worldFromBone, truth(k), w.centre), 0.5) << k;
        EXPECT_EQ(tracked.count(k), 1u) << k;
    }
    const fm::FrameRecord& blank = records[2];
    EXPECT_EQ(blank.status, fm::FrameRecord::Status::Tracked);
    EXPECT_EQ(blank.verdict, fm::AnswerVerdict::Lost) << blank.verdictText;
    EXPECT_LT(*blank.evidence.similarityRatio, fm::kLostSimilarityRatio);
    EXPECT_FALSE(blank.answered());
    EXPECT_EQ(blank.searches, 1) << "continue: not searched again";
    EXPECT_EQ(tracked.count(2), 0u) << "a lost pose is kept as a start";

    const auto [stopped, stoppedTracked] = runWith(fm::OnLost::Stop);
    ASSERT_EQ(stopped.size(), 3u) << "stop: the run ends at the lost frame";
    EXPECT_EQ(stopped[2].verdict, fm::AnswerVerdict::Lost);

    const auto [searched, searchedTracked] = runWith(fm::OnLost::Search);
    ASSERT_EQ(searched.size(), 4u);
    EXPECT_EQ(searched[2].searches, 2) << "search: the lost frame searched again, wider";
    EXPECT_GT(searched[2].evaluations, blank.evaluations);
    EXPECT_EQ(searched[2].verdict, fm::AnswerVerdict::Lost);
    EXPECT_EQ(searched[3].verdict, fm::AnswerVerdict::Ok) << searched[3].verdictText;
}

// Frames far apart (the real wrist's are 59-97 frames apart): the bone jumps 33 mm and 35 deg
// between frames 0 and 1, so frame 1 tracked from frame 0 is not ok even when searched again (a
// 16 mm, 20 deg jump was recovered by the wider search).
// With OnLost::Find the tracker then asks its finder (here a stand-in that answers 1 mm and 2 deg
// from the truth, as a find does before registration) and registers the frame from that answer:
// within the tracking bounds, ok. Frame 2 jumps again and the finder says its find is not ok: the
// frame keeps its searched record, not answered, with the find's line. A keyframe's frame is
// never found again.
TEST(Tracking, AFrameNotOkIsFoundWithNoStartAndRegisteredFromThere) {
    FM_REQUIRE_SHARED_DATA("autoscoper-bvr/Models/rad_dcm_cropped.tif");
    const Wrist w;
    // Jumps from frame 0 about the bone's centre; each frame starts from the previous one's pose.
    const glm::dvec3 c0 = w.truth(0).applyToPoint(w.centre);
    const auto truth = [&](int k) {
        if (k == 1) return RigidTransform::translate({20.0, -25.0, 8.0}) * fm::rotationAbout({0.2, 0.4, 1.0}, 35.0, c0) * w.truth(0);
        if (k == 2) return RigidTransform::translate({-12.0, 10.0, -8.0}) * fm::rotationAbout({1.0, 0.3, 0.2}, -20.0, c0) * w.truth(0);
        return w.truth(0);
    };
    std::vector<int> asked;
    fm::TrackSettings settings;
    settings.onLost = fm::OnLost::Find;
    settings.init = fm::InitMode::Previous;
    settings.findFrame = [&](int frame, const std::atomic<bool>*) {
        asked.push_back(frame);
        fm::FrameFind f;
        f.verdictText = frame == 1 ? "ok: a stand-in find" : "doubtful: a stand-in find";
        if (frame == 1)
            f.pose = RigidTransform::translate({0.6, -0.5, 0.6}) *
                     fm::rotationAbout({1.0, 1.0, 0.0}, 2.0, truth(1).applyToPoint(w.centre)) * truth(1);
        return f;
    };
    // A finder only with OnLost::Find, and OnLost::Find only with a finder.
    EXPECT_THROW(fm::Tracker(w.scene, "radius", w.frames(truth), [&] {
                     fm::TrackSettings s = settings;
                     s.onLost = fm::OnLost::Search;
                     return s;
                 }()),
                 fm::Error);
    EXPECT_THROW(fm::Tracker(w.scene, "radius", w.frames(truth), [] {
                     fm::TrackSettings s;
                     s.onLost = fm::OnLost::Find;
                     return s;
                 }()),
                 fm::Error);
    EXPECT_EQ(fm::parseOnLost("find", "--on-lost"), fm::OnLost::Find);
    EXPECT_STREQ(fm::toString(fm::OnLost::Find), "find");
    const fm::Tracker tracker(w.scene, "radius", w.frames(truth), settings);
    std::map<int, RigidTransform> tracked;
    std::vector<fm::FrameRecord> records;
    // Under the sanitizers (18 s here, four times that there) frames 0 and 1 only.
    const std::vector<int> frames = fm::test::kSanitizerBuild ? std::vector<int>{0, 1} : std::vector<int>{0, 1, 2};
    tracker.run(frames, {{0, truth(0)}}, tracked, [&](const fm::FrameRecord& r) { records.push_back(r); });
    ASSERT_EQ(records.size(), frames.size());
    EXPECT_EQ(asked, std::vector<int>(frames.begin() + 1, frames.end())) << "found only where not ok after the searches";
    EXPECT_FALSE(records[0].found);
    const fm::FrameRecord& found = records[1];
    ASSERT_TRUE(found.found);
    EXPECT_EQ(*found.found, "ok: a stand-in find");
    EXPECT_EQ(found.searches, 3) << "searched, searched again wider, registered from the find";
    EXPECT_EQ(found.verdict, fm::AnswerVerdict::Ok) << found.verdictText;
    ASSERT_TRUE(found.worldFromBone);
    EXPECT_LT(centreError(*found.worldFromBone, truth(1), w.centre), kMaxCentreErrorMm);
    EXPECT_LT(angleErrorDeg(*found.worldFromBone, truth(1)), kMaxAngleErrorDeg);
    EXPECT_EQ(tracked.count(1), 1u);
    if (frames.size() < 3) return;
    const fm::FrameRecord& notFound = records[2];
    ASSERT_TRUE(notFound.found);
    EXPECT_EQ(*notFound.found, "doubtful: a stand-in find");
    EXPECT_EQ(notFound.searches, 2) << "no pose from the find: nothing registered from it";
    EXPECT_NE(notFound.verdict, fm::AnswerVerdict::Ok) << notFound.verdictText;

    // A keyframe's own frame is not found again, however it ends: its start is the user's pose
    // (here frame 0's, 33 mm from frame 1's truth) or a find's.
    asked.clear();
    records.clear();
    std::map<int, RigidTransform> fresh;  // frame 1 not tracked yet (a frame in `tracked` is kept)
    tracker.run({1}, {{1, truth(0)}}, fresh, [&](const fm::FrameRecord& r) { records.push_back(r); });
    ASSERT_EQ(records.size(), 1u);
    EXPECT_NE(records[0].verdict, fm::AnswerVerdict::Ok) << records[0].verdictText;
    EXPECT_TRUE(asked.empty());
    EXPECT_FALSE(records[0].found);
}

TEST(Tracking, ContinuesOnOneCameraWhileTheBoneLeavesTheOther) {
    FM_REQUIRE_SHARED_DATA("autoscoper-bvr/Models/rad_dcm_cropped.tif");
    Wrist w;
    const RigidTransform pose0 = w.truth(0);
    fm::ProjectionGeometry& cam2 = w.scene.cameras[1];
    // Camera 2 sees only a window around the bone at the start (a collimated view).
    const fm::PixelRect box = fm::projectedBox(cam2, {"radius", w.scene.objects[0].model, pose0, true}, 8);
    ASSERT_FALSE(box.empty());
    cam2.detector.origin = cam2.detector.pixelCenter(box.col0, box.row0);
    cam2.detector.size = {box.cols, box.rows};
    // The bone slides in camera 1's image plane along camera 2's columns, out of that window by
    // a whole window width and back, smoothly (so the extrapolated start stays within reach).
    const fm::ProjectionGeometry& cam1 = w.scene.cameras[0];
    const glm::dvec3 n1 = glm::normalize(cam1.detector.center() - cam1.source);
    // Along camera 2's columns or rows, whichever lies more in camera 1's image plane.
    const auto inPlane = [&](const glm::dvec3& a) { return a - glm::dot(a, n1) * n1; };
    const bool useRows = glm::length(inPlane(cam2.detector.v)) > glm::length(inPlane(cam2.detector.u));
    const glm::dvec3 axis = useRows ? cam2.detector.v : cam2.detector.u;
    const glm::dvec3 d = glm::normalize(inPlane(axis));
    const glm::dvec3 centre0 = pose0.applyToPoint(w.centre);
    const double mmPerPixel = glm::length(centre0 - cam2.source) /
                              glm::length(cam2.detector.center() - cam2.source) * cam2.detector.spacing.x;
    const double reach = (useRows ? box.rows : box.cols) * mmPerPixel / std::abs(glm::dot(d, axis));
    constexpr int kPeriod = 20;
    ASSERT_LT(reach, 120.0) << "the slide would be too fast to follow";
    const auto truth = [&](int k) {
        const double out = reach * 0.5 * (1.0 - std::cos(2.0 * M_PI * k / kPeriod));
        return RigidTransform::translate(out * d) * pose0;
    };
    fm::TrackSettings s;
    s.registration.globalEvaluations = 120;
    s.registration.polishEvaluations = 60;
    s.refineEvaluations = 80;
    const fm::Tracker tracker(w.scene, "radius", w.frames(truth), s);
    std::vector<int> frames;
    for (int k = 1; k <= kPeriod; ++k) frames.push_back(k);
    std::map<int, RigidTransform> tracked;
    std::vector<fm::FrameRecord> records;
    tracker.run(frames, {{0, truth(0)}}, tracked, [&](const fm::FrameRecord& r) { records.push_back(r); });
    int single = 0;
    for (const fm::FrameRecord& r : records) {
        ASSERT_EQ(r.status, fm::FrameRecord::Status::Tracked) << "frame " << r.frame << ": " << r.note;
        if (r.camerasUsed == 1) {
            ++single;
            EXPECT_EQ(r.note, "single view: camera 1");
            EXPECT_TRUE(std::isnan(r.viewCost[1]));
        } else {
            EXPECT_EQ(r.note, "cameras 1, 2");
        }
        // Depth along camera 1's view is the weak part of one view: in-plane apart.
        const glm::dvec3 e = r.worldFromBone->applyToPoint(w.centre) - truth(r.frame).applyToPoint(w.centre);
        const double inPlane = glm::length(e - glm::dot(e, n1) * n1);
        EXPECT_LT(inPlane, 1.0) << "frame " << r.frame;
    }
    EXPECT_GE(single, 3);
    EXPECT_LE(single, kPeriod - 4);  // and it came back to both views
    // Back in both views at the end: biplane accuracy again.
    EXPECT_LT(centreError(*records.back().worldFromBone, truth(kPeriod), w.centre), kMaxCentreErrorMm);
}

TEST(Tracking, AResumedRunGivesTheSamePosesAndVerdicts) {
    FM_REQUIRE_SHARED_DATA("autoscoper-bvr/Models/rad_dcm_cropped.tif");
    const Wrist w;
    const auto truth = [&](int k) { return w.truth(k); };
    fm::TrackSettings s;
    s.registration.globalEvaluations = 120;
    s.registration.polishEvaluations = 40;
    const fm::Tracker tracker(w.scene, "radius", w.frames(truth), s);
    const std::map<int, RigidTransform> keys{{0, truth(0)}};
    // Frames 1-4 (1-3 under the sanitizers), and the same resumed after frame 2: the second run
    // is given every frame, frames 1-2 kept (their poses in `resumed`, their records in `kept`),
    // as `track --resume` gives them from the .tra and the CSV.
    const std::vector<int> frames = fm::test::kSanitizerBuild ? std::vector<int>{1, 2, 3} : std::vector<int>{1, 2, 3, 4};
    std::map<int, RigidTransform> whole, resumed;
    std::map<int, fm::FrameRecord> wholeRecords, kept, resumedRecords;
    tracker.run(frames, keys, whole, [&](const fm::FrameRecord& r) { wholeRecords[r.frame] = r; });
    tracker.run({1, 2}, keys, resumed, [&](const fm::FrameRecord& r) { kept[r.frame] = r; });
    // The kept frames' verdicts and costs as the CSV holds them (what --resume reads back).
    for (auto& [frame, r] : kept)
        for (double& c : r.viewCost) c = fm::storedCost(c);
    tracker.run(frames, keys, resumed, [&](const fm::FrameRecord& r) { resumedRecords[r.frame] = r; }, nullptr, kept);
    ASSERT_EQ(whole.size(), frames.size());
    ASSERT_EQ(resumed.size(), whole.size());
    ASSERT_EQ(resumedRecords.size(), frames.size() - 2) << "the kept frames are not tracked again";
    for (const auto& [frame, pose] : whole)
        EXPECT_EQ(pose.toRowMajor4x4(), resumed.at(frame).toRowMajor4x4()) << "frame " << frame;
    // Judged as in the uninterrupted run: frame 3 against frame 2's similarity (ok), with the same
    // searches, not as a frame with nothing before it (a confirming second search).
    for (const auto& [frame, r] : resumedRecords) {
        EXPECT_EQ(r.verdictText, wholeRecords.at(frame).verdictText) << "frame " << frame;
        EXPECT_EQ(r.evaluations, wholeRecords.at(frame).evaluations) << "frame " << frame;
        EXPECT_EQ(r.viewCost, wholeRecords.at(frame).viewCost) << "frame " << frame;
    }
    EXPECT_EQ(resumedRecords.at(3).verdict, fm::AnswerVerdict::Ok) << resumedRecords.at(3).verdictText;
}

}  // namespace
