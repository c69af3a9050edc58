#include "track/FrameRecordBytes.h"

#include <algorithm>
#include <cstdint>
#include <cstring>
#include <string>

#include "core/Error.h"

namespace fm {

namespace {

struct Fixed {  // the part every record has, whatever the camera count
    std::int32_t frame = 0;
    std::int32_t status = 0;
    std::int32_t camerasUsed = 0;
    std::int32_t evaluations = 0;
    std::int32_t hasPose = 0;
    std::int32_t noteLength = 0;
    double seconds = 0.0;
    double pose[12] = {};  // rotation column by column, then translation
    double profile[4] = {};  // thread seconds: set-up, render, footprint, similarity
    double profileWall = 0.0;  // (its evaluations are the record's)
    std::int32_t verdict = 0;
    std::int32_t searches = 0;
    std::int32_t hasUncertainty = 0;
    std::int32_t uncertaintyBounded = 0;
    std::int32_t uncertaintyEvaluations = 0;
    std::int32_t hasRatio = 0;
    double sd[6] = {};
    double step[6] = {};
    double boneSd[6] = {};
    double ratio = 0.0;
    std::int32_t verdictLength = 0;
    std::int32_t foundLength = -1;  // -1: the frame was not searched for with no start
};

constexpr int kLastStatus = static_cast<int>(FrameRecord::Status::Stopped);
constexpr int kLastVerdict = static_cast<int>(AnswerVerdict::Lost);

}  // namespace

std::size_t frameRecordBytes(std::size_t cameras) {
    return sizeof(Fixed) + cameras * sizeof(double) + kFrameNoteBytes + kFrameVerdictBytes + kFrameFoundBytes;
}

void encodeFrameRecord(const FrameRecord& r, std::span<std::byte> out) {
    if (out.size() != frameRecordBytes(r.viewCost.size()))
        throw Error("frame record: " + std::to_string(out.size()) + " bytes for " +
                    std::to_string(r.viewCost.size()) + " cameras");
    Fixed f;
    f.frame = r.frame;
    f.status = static_cast<std::int32_t>(r.status);
    f.camerasUsed = r.camerasUsed;
    f.evaluations = r.evaluations;
    f.hasPose = r.worldFromBone ? 1 : 0;
    f.seconds = r.seconds;
    f.profile[0] = r.profile.setupSeconds;
    f.profile[1] = r.profile.renderSeconds;
    f.profile[2] = r.profile.footprintSeconds;
    f.profile[3] = r.profile.similaritySeconds;
    f.profileWall = r.profile.wallSeconds;
    if (r.worldFromBone) {
        for (int c = 0; c < 3; ++c)
            for (int row = 0; row < 3; ++row)
                f.pose[3 * c + row] = r.worldFromBone->rotation[c][row];
        for (int i = 0; i < 3; ++i) f.pose[9 + i] = r.worldFromBone->translation[i];
    }
    f.verdict = static_cast<std::int32_t>(r.verdict);
    f.searches = r.searches;
    if (const auto& u = r.evidence.uncertainty) {
        f.hasUncertainty = 1;
        f.uncertaintyBounded = u->bounded ? 1 : 0;
        f.uncertaintyEvaluations = u->evaluations;
        for (int i = 0; i < 6; ++i) f.sd[i] = u->sd[i], f.step[i] = u->step[i], f.boneSd[i] = r.boneFrameSd[i];
    }
    if (r.evidence.similarityRatio) {
        f.hasRatio = 1;
        f.ratio = *r.evidence.similarityRatio;
    }
    f.verdictLength = static_cast<std::int32_t>(std::min(r.verdictText.size(), kFrameVerdictBytes - 1));
    f.noteLength = static_cast<std::int32_t>(std::min(r.note.size(), kFrameNoteBytes - 1));
    if (r.found) f.foundLength = static_cast<std::int32_t>(std::min(r.found->size(), kFrameFoundBytes - 1));
    std::fill(out.begin(), out.end(), std::byte{0});
    std::memcpy(out.data(), &f, sizeof f);
    std::memcpy(out.data() + sizeof f, r.viewCost.data(), r.viewCost.size() * sizeof(double));
    std::memcpy(out.data() + sizeof f + r.viewCost.size() * sizeof(double), r.note.data(),
                static_cast<std::size_t>(f.noteLength));
    std::memcpy(out.data() + sizeof f + r.viewCost.size() * sizeof(double) + kFrameNoteBytes, r.verdictText.data(),
                static_cast<std::size_t>(f.verdictLength));
    if (r.found)
        std::memcpy(out.data() + sizeof f + r.viewCost.size() * sizeof(double) + kFrameNoteBytes + kFrameVerdictBytes,
                    r.found->data(), static_cast<std::size_t>(f.foundLength));
}

FrameRecord decodeFrameRecord(std::span<const std::byte> in, std::size_t cameras) {
    if (in.size() != frameRecordBytes(cameras))
        throw Error("frame record: " + std::to_string(in.size()) + " bytes, expected " +
                    std::to_string(frameRecordBytes(cameras)) + " for " + std::to_string(cameras) +
                    " cameras");
    Fixed f;
    std::memcpy(&f, in.data(), sizeof f);
    if (f.status < 0 || f.status > kLastStatus)
        throw Error("frame record: status " + std::to_string(f.status) + " is not a status");
    if (f.verdict < 0 || f.verdict > kLastVerdict)
        throw Error("frame record: verdict " + std::to_string(f.verdict) + " is not a verdict");
    if (f.verdictLength < 0 || static_cast<std::size_t>(f.verdictLength) >= kFrameVerdictBytes)
        throw Error("frame record: verdict length " + std::to_string(f.verdictLength) + " out of range");
    if (f.foundLength < -1 || (f.foundLength >= 0 && static_cast<std::size_t>(f.foundLength) >= kFrameFoundBytes))
        throw Error("frame record: found length " + std::to_string(f.foundLength) + " out of range");
    if (f.noteLength < 0 || static_cast<std::size_t>(f.noteLength) >= kFrameNoteBytes)
        throw Error("frame record: note length " + std::to_string(f.noteLength) + " out of range");
    if (f.camerasUsed < 0 || static_cast<std::size_t>(f.camerasUsed) > cameras)
        throw Error("frame record: " + std::to_string(f.camerasUsed) + " cameras used of " +
                    std::to_string(cameras));
    FrameRecord r;
    r.frame = f.frame;
    r.status = static_cast<FrameRecord::Status>(f.status);
    r.camerasUsed = f.camerasUsed;
    r.evaluations = f.evaluations;
    r.seconds = f.seconds;
    r.profile.setupSeconds = f.profile[0];
    r.profile.renderSeconds = f.profile[1];
    r.profile.footprintSeconds = f.profile[2];
    r.profile.similaritySeconds = f.profile[3];
    r.profile.wallSeconds = f.profileWall;
    r.profile.evaluations = f.evaluations;
    if (f.hasPose) {
        RigidTransform p;
        for (int c = 0; c < 3; ++c)
            for (int row = 0; row < 3; ++row) p.rotation[c][row] = f.pose[3 * c + row];
        for (int i = 0; i < 3; ++i) p.translation[i] = f.pose[9 + i];
        r.worldFromBone = p;
    }
    r.viewCost.resize(cameras);
    std::memcpy(r.viewCost.data(), in.data() + sizeof f, cameras * sizeof(double));
    const char* note =
        reinterpret_cast<const char*>(in.data() + sizeof f + cameras * sizeof(double));
    r.note.assign(note, static_cast<std::size_t>(f.noteLength));
    r.verdict = static_cast<AnswerVerdict>(f.verdict);
    r.verdictText.assign(note + kFrameNoteBytes, static_cast<std::size_t>(f.verdictLength));
    if (f.foundLength >= 0) r.found.emplace(note + kFrameNoteBytes + kFrameVerdictBytes, static_cast<std::size_t>(f.foundLength));
    r.searches = f.searches;
    if (f.hasUncertainty) {
        PoseUncertainty u;
        u.bounded = f.uncertaintyBounded != 0;
        u.evaluations = f.uncertaintyEvaluations;
        for (int i = 0; i < 6; ++i) u.sd[i] = f.sd[i], u.step[i] = f.step[i], r.boneFrameSd[i] = f.boneSd[i];
        r.evidence.uncertainty = u;
    }
    if (f.hasRatio) r.evidence.similarityRatio = f.ratio;
    return r;
}

}  // namespace fm
