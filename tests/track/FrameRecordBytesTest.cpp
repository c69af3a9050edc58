// A frame record survives its fixed-size bytes bit for bit (what rank 0 receives is what the
// tracking rank found), and bytes no encoder wrote are refused.
#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <limits>
#include <vector>

#include "core/Error.h"
#include "track/FrameRecordBytes.h"

namespace fm {
namespace {

FrameRecord sample() {
    FrameRecord r;
    r.frame = 17;
    r.status = FrameRecord::Status::Tracked;
    r.note = "single view: camera 2";
    RigidTransform p;
    p.rotation = glm::dmat3(0.36, 0.48, -0.8, -0.8, 0.6, 0.0, 0.48, 0.64, 0.6);
    p.translation = {1.0 / 3.0, -2.5e-7, 123.456789};
    r.worldFromBone = p;
    r.viewCost = {std::numeric_limits<double>::quiet_NaN(), -0.123456789012345};
    r.camerasUsed = 1;
    r.evaluations = 990;
    r.seconds = 0.731;
    r.profile = {990, 0.73, 0.01, 1.0 / 3.0, 0.2, 0.15};
    r.verdict = AnswerVerdict::Doubtful;
    r.verdictText = "doubtful: similarity 0.87 of the last good frames' (below 0.90)";
    r.searches = 2;
    PoseUncertainty u;
    u.sd = {0.05, 0.07, 1.0 / 3.0, std::numeric_limits<double>::infinity(), 0.2, 0.1};
    u.step = kUncertaintySteps;
    u.bounded = false;
    u.evaluations = 73;
    r.evidence.uncertainty = u;
    r.boneFrameSd = {0.06, 0.05, 0.3, std::numeric_limits<double>::infinity(), 0.25, 0.125};
    r.evidence.similarityRatio = 0.8712345678;
    r.found = "ok: the best answer of another basin scores 0.85 of it (below 0.90)";
    return r;
}

TEST(FrameRecordBytes, RoundTripIsExact) {
    const FrameRecord r = sample();
    std::vector<std::byte> bytes(frameRecordBytes(2));
    encodeFrameRecord(r, bytes);
    const FrameRecord d = decodeFrameRecord(bytes, 2);
    EXPECT_EQ(d.frame, 17);
    EXPECT_EQ(d.status, FrameRecord::Status::Tracked);
    EXPECT_EQ(d.note, r.note);
    EXPECT_EQ(d.camerasUsed, 1);
    EXPECT_EQ(d.evaluations, 990);
    EXPECT_EQ(d.seconds, r.seconds);
    EXPECT_EQ(d.profile.evaluations, 990);
    EXPECT_EQ(d.profile.wallSeconds, r.profile.wallSeconds);
    EXPECT_EQ(d.profile.setupSeconds, r.profile.setupSeconds);
    EXPECT_EQ(d.profile.renderSeconds, r.profile.renderSeconds);
    EXPECT_EQ(d.profile.footprintSeconds, r.profile.footprintSeconds);
    EXPECT_EQ(d.profile.similaritySeconds, r.profile.similaritySeconds);
    ASSERT_TRUE(d.worldFromBone);
    EXPECT_EQ(
        std::memcmp(&d.worldFromBone->rotation, &r.worldFromBone->rotation, sizeof(glm::dmat3)), 0);
    EXPECT_EQ(std::memcmp(&d.worldFromBone->translation, &r.worldFromBone->translation,
                          sizeof(glm::dvec3)),
              0);
    ASSERT_EQ(d.viewCost.size(), 2u);
    EXPECT_TRUE(std::isnan(d.viewCost[0]));
    EXPECT_EQ(d.viewCost[1], r.viewCost[1]);
    // How sure it is travels with it.
    EXPECT_EQ(d.verdict, AnswerVerdict::Doubtful);
    EXPECT_EQ(d.verdictText, r.verdictText);
    EXPECT_EQ(d.searches, 2);
    ASSERT_TRUE(d.evidence.uncertainty);
    for (int i = 0; i < 6; ++i) {
        EXPECT_EQ(d.evidence.uncertainty->sd[i], r.evidence.uncertainty->sd[i]) << i;
        EXPECT_EQ(d.evidence.uncertainty->step[i], r.evidence.uncertainty->step[i]) << i;
        EXPECT_EQ(d.boneFrameSd[i], r.boneFrameSd[i]) << i;
    }
    EXPECT_FALSE(d.evidence.uncertainty->bounded);
    EXPECT_EQ(d.evidence.uncertainty->evaluations, 73);
    EXPECT_EQ(d.evidence.similarityRatio, r.evidence.similarityRatio);
    EXPECT_EQ(d.found, r.found);  // found with no start after it was lost (OnLost::Find)
}

TEST(FrameRecordBytes, NoPoseStaysNoPoseAndLongNotesAreCut) {
    FrameRecord r;
    r.frame = 3;
    r.status = FrameRecord::Status::BadFrame;
    r.note = std::string(500, 'x');
    r.viewCost.assign(3, 0.5);
    std::vector<std::byte> bytes(frameRecordBytes(3));
    encodeFrameRecord(r, bytes);
    const FrameRecord d = decodeFrameRecord(bytes, 3);
    EXPECT_FALSE(d.worldFromBone);
    EXPECT_EQ(d.status, FrameRecord::Status::BadFrame);
    EXPECT_EQ(d.note, std::string(kFrameNoteBytes - 1, 'x'));
    EXPECT_FALSE(d.evidence.uncertainty);
    EXPECT_FALSE(d.evidence.similarityRatio);
    EXPECT_FALSE(d.found);  // not searched for: none, not an empty line
    r.verdictText = std::string(900, 'v');
    r.found = "";
    encodeFrameRecord(r, bytes);
    EXPECT_EQ(decodeFrameRecord(bytes, 3).verdictText, std::string(kFrameVerdictBytes - 1, 'v'));
    EXPECT_EQ(decodeFrameRecord(bytes, 3).found, std::string());
    r.found = std::string(700, 'f');
    encodeFrameRecord(r, bytes);
    EXPECT_EQ(decodeFrameRecord(bytes, 3).found, std::string(kFrameFoundBytes - 1, 'f'));
}

TEST(FrameRecordBytes, RefusesWrongSizesAndBytesNoEncoderWrote) {
    const FrameRecord r = sample();
    std::vector<std::byte> small(frameRecordBytes(2) - 1);
    EXPECT_THROW(encodeFrameRecord(r, small), Error);
    std::vector<std::byte> bytes(frameRecordBytes(2));
    encodeFrameRecord(r, bytes);
    EXPECT_THROW(decodeFrameRecord(bytes, 3), Error);  // another camera count
    std::vector<std::byte> junk(frameRecordBytes(2), std::byte{0xff});
    EXPECT_THROW(decodeFrameRecord(junk, 2), Error);
}

}  // namespace
}  // namespace fm
