// The trial view's pose table, curves and files, without images: keyframe set/clear and tracking
// results per frame; the six curves are the .tra pose's x, y, z, yaw, pitch, roll that built it,
// angles unwrapped across the +-180 seam but a real jump kept; the saved .tra holds the .tra poses
// (NaN rows where none) and the saved trial JSON the keyframes in Autoscoper's volume frame.
#include <cmath>

#include <gtest/gtest.h>

#include "common/TestData.h"
#include "core/Error.h"
#include "io/TextFile.h"
#include "scene/PoseCurves.h"
#include "scene/TrackRunner.h"
#include "scene/TrialPoseFiles.h"
#include "trial/Trial.h"

namespace fm::app {
namespace {

RigidTransform fromXyzypr(double x, double y, double z, double yaw, double pitch, double roll) {
    const double v[6] = {x, y, z, yaw, pitch, roll};
    return transformFromXyzypr(v);
}

double maxDifference(const RigidTransform& a, const RigidTransform& b) {
    const auto ma = a.toRowMajor4x4(), mb = b.toRowMajor4x4();
    double d = 0.0;
    for (int i = 0; i < 16; ++i) d = std::max(d, std::abs(ma[i] - mb[i]));
    return d;
}

// A trial of `frames` frames with one bone whose volume frame is off Autoscoper's by a known
// rigid motion (no files: the conversions only need autoscoperFromVolume).
TrialScene fakeTrial(int frames) {
    TrialScene t;
    t.trial.name = "fake";
    t.trial.bones.push_back({"radius", "rad.tif", glm::dvec3(0.4, 0.4, 0.6), glm::ivec3(0), {}});
    t.frameCount = frames;
    t.autoscoperFromVolume["radius"] = fromXyzypr(0.0, 34.0, -79.4, 0.0, 180.0, 0.0);
    return t;
}

FrameRecord tracked(int frame, const RigidTransform& pose) {
    FrameRecord r;
    r.frame = frame;
    r.status = FrameRecord::Status::Tracked;
    r.worldFromBone = pose;
    return r;
}

TEST(BonePoses, KeyframesAndTrackedPosesPerFrame) {
    const RigidTransform k0 = RigidTransform::translate({1, 0, 0});
    BonePoses p(5, {{0, k0}});
    EXPECT_TRUE(p.isKeyframe(0));
    ASSERT_TRUE(p.pose(0));
    EXPECT_EQ(p.pose(0)->translation.x, 1.0);
    EXPECT_FALSE(p.hasPose(1));

    // A tracked frame keeps its pose; a keyframe's tracked pose is shown over the keyframe.
    p.apply(tracked(1, RigidTransform::translate({2, 0, 0})));
    p.apply(tracked(0, RigidTransform::translate({1.5, 0, 0})));
    EXPECT_EQ(p.pose(1)->translation.x, 2.0);
    EXPECT_EQ(p.pose(0)->translation.x, 1.5);
    EXPECT_EQ(p.keyframes().at(0).translation.x, 1.0);

    // Frames that were not tracked change nothing.
    FrameRecord bad = tracked(2, RigidTransform::translate({9, 0, 0}));
    bad.status = FrameRecord::Status::Stopped;
    p.apply(bad);
    bad.status = FrameRecord::Status::BadFrame;
    p.apply(bad);
    EXPECT_FALSE(p.hasPose(2));

    // Setting a keyframe puts the bone there (the tracked pose goes); clearing it keeps a
    // tracked pose and leaves none where there was only the keyframe.
    p.setKeyframe(1, RigidTransform::translate({3, 0, 0}));
    EXPECT_EQ(p.pose(1)->translation.x, 3.0);
    EXPECT_TRUE(p.clearKeyframe(1));
    EXPECT_FALSE(p.clearKeyframe(1));
    EXPECT_FALSE(p.hasPose(1));
    EXPECT_TRUE(p.clearKeyframe(0));
    EXPECT_EQ(p.pose(0)->translation.x, 1.5);

    EXPECT_THROW(p.setKeyframe(5, k0), Error);
    EXPECT_THROW(p.pose(-1), Error);
    EXPECT_THROW(BonePoses(3, {{3, k0}}), Error);
}

TEST(TrackRequest, FramesFromTheCurrentFrameWithItsPoseAsAKeyframe) {
    EXPECT_EQ(framesFrom(2, 5, false), (std::vector<int>{2, 3, 4}));
    EXPECT_EQ(framesFrom(2, 5, true), (std::vector<int>{2, 1, 0}));
    EXPECT_THROW(framesFrom(5, 5, false), Error);

    BonePoses p(6, {{0, RigidTransform::translate({1, 0, 0})}});
    p.setPose(3, RigidTransform::translate({4, 0, 0}));
    const TrackRequest r = trackRequestFrom("radius", p, 3, true, 2);
    EXPECT_EQ(r.frames, (std::vector<int>{3, 2, 1, 0}));
    ASSERT_EQ(r.keyframes.size(), 2u);
    EXPECT_EQ(r.keyframes.at(3).translation.x, 4.0);
    EXPECT_EQ(r.settings.registration.seed, 1u);  // the CLI's default
    EXPECT_EQ(r.settings.registration.threads, 2);
    // From a keyframe, the keyframe is the start (as in the CLI), not a tracked pose there.
    p.apply(tracked(0, RigidTransform::translate({1.2, 0, 0})));
    EXPECT_EQ(trackRequestFrom("radius", p, 0, false, 1).keyframes.at(0).translation.x, 1.0);
}

TEST(PoseCurves, TheTraPosesNumbersWithAnglesUnwrappedAndJumpsKept) {
    const TrialScene t = fakeTrial(5);
    BonePoses p(5);
    // yaw crosses the +-180 seam between frames 0 and 1; frame 2 has no pose; frame 4 jumps.
    const double numbers[5][6] = {{10, 20, 30, 175, 10, -5},
                                  {11, 21, 31, -178, 11, -6},
                                  {0, 0, 0, 0, 0, 0},
                                  {13, 23, 33, -170, 12, -7},
                                  {40, 23, 33, -100, 12, -7}};
    for (int f : {0, 1, 3, 4}) {
        const double* n = numbers[f];
        p.setPose(f, objectPoseFromTra(t, "radius", fromXyzypr(n[0], n[1], n[2], n[3], n[4], n[5])));
    }
    const PoseCurves c = poseCurves(t, "radius", p);
    const double yaw[5] = {175, 182, NAN, 190, 260};
    for (int f : {0, 1, 3, 4}) {
        for (int i = 0; i < 3; ++i) EXPECT_NEAR(c.values[i][f], numbers[f][i], 1e-4) << f << " " << i;
        EXPECT_NEAR(c.values[3][f], yaw[f], 1e-4) << "frame " << f;
        EXPECT_NEAR(c.values[4][f], numbers[f][4], 1e-4) << "frame " << f;
        EXPECT_NEAR(c.values[5][f], numbers[f][5], 1e-4) << "frame " << f;
    }
    for (int i = 0; i < PoseCurves::kCount; ++i) EXPECT_TRUE(std::isnan(c.values[i][2]));
    EXPECT_FLOAT_EQ(c.range(0)[0], 10.0f);
    EXPECT_FLOAT_EQ(c.range(0)[1], 40.0f);
    EXPECT_STREQ(PoseCurves::name(3), "yaw (deg)");
}

TEST(TrialPoseFiles, TraRowsAreTheTraPosesAndNaNWhereNone) {
    const TrialScene t = fakeTrial(4);
    BonePoses p(4, {{3, objectPoseFromTra(t, "radius", fromXyzypr(5, 6, 7, 8, 9, 10))}});
    const RigidTransform tra1 = fromXyzypr(101.25, -20.5, 80.125, 30, -12, 175);
    p.setPose(1, objectPoseFromTra(t, "radius", tra1));
    const auto path = fm::test::scratchDir("trial_pose_files") / "radius.tra";
    saveTra(path, t, "radius", p);
    const TraFile back = readTra(path);
    ASSERT_EQ(back.frames.size(), 4u);
    EXPECT_FALSE(back.frames[0][0]);
    EXPECT_FALSE(back.frames[2][0]);
    ASSERT_TRUE(back.frames[1][0] && back.frames[3][0]);
    EXPECT_LT(maxDifference(*back.frames[1][0], tra1), 1e-12);
    EXPECT_LT(maxDifference(*back.frames[3][0], fromXyzypr(5, 6, 7, 8, 9, 10)), 1e-12);
    // The file's text is traText of the rows, NaN x 16 for the frames without a pose.
    const std::string text = io::readTextFile(path, 1 << 20, "tra");
    EXPECT_EQ(text, traText(traFileOf(t, "radius", p)));
    EXPECT_EQ(text.substr(0, 4), "NaN,");

    EXPECT_THROW(saveTra(path, t, "ulna", p), Error);
    EXPECT_THROW(saveTra(path, t, "radius", BonePoses(3)), Error);
}

TEST(TrialPoseFiles, TrialJsonHoldsTheKeyframesInAutoscopersVolumeFrame) {
    TrialScene t = fakeTrial(3);
    t.trial = readTrial(fm::test::repoDir() / "data/trials/wrist.json");  // paths only, not read
    const RigidTransform key = fromXyzypr(120, 116, 90, -160, 18, 5);
    BonePoses radius(3, {{2, objectPoseFromTra(t, "radius", key)}});
    const auto path = fm::test::scratchDir("trial_pose_files_json") / "wrist_keys.json";
    saveTrialJson(path, t, {{"radius", radius}});
    const Trial back = readTrial(path);
    ASSERT_EQ(back.keyframes.at("radius").size(), 1u);
    const TrialPose& k = back.keyframes.at("radius")[0];
    EXPECT_EQ(k.frame, 2);
    EXPECT_EQ(k.volumeFrame, VolumeFrame::Autoscoper);
    EXPECT_LT(maxDifference(k.worldFromVolume, key), 1e-9);
    // The ulna's keyframes were not in the table: the trial's stay; the paths still name the
    // same files from the new folder.
    EXPECT_EQ(back.keyframes.at("ulna").size(), t.trial.keyframes.at("ulna").size());
    EXPECT_EQ(std::filesystem::weakly_canonical(back.bones[0].volume),
              std::filesystem::weakly_canonical(t.trial.bones[0].volume));
}

}  // namespace
}  // namespace fm::app
