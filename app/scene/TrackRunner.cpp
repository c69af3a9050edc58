#include "scene/TrackRunner.h"

#include <chrono>
#include <cmath>
#include <exception>
#include <limits>

#include "core/Error.h"
#include "track/SegmentTracking.h"

namespace fm::app {

std::vector<int> framesFrom(int from, int frameCount, bool backwards) {
    if (from < 0 || from >= frameCount)
        throw Error("track: frame " + std::to_string(from) + " is not one of the trial's 0.." +
                    std::to_string(frameCount - 1));
    std::vector<int> frames;
    if (backwards)
        for (int f = from; f >= 0; --f) frames.push_back(f);
    else
        for (int f = from; f < frameCount; ++f) frames.push_back(f);
    return frames;
}

TrackRequest trackRequestFrom(const std::string& bone, const BonePoses& poses, int from,
                              bool backwards, int threads) {
    TrackRequest r;
    r.bone = bone;
    r.frames = framesFrom(from, poses.frameCount(), backwards);
    r.keyframes = poses.keyframes();
    if (!poses.isKeyframe(from))
        if (const auto p = poses.pose(from)) r.keyframes[from] = *p;
    r.settings.registration.seed = 1;
    r.settings.registration.threads = threads;
    return r;
}

int TrackSnapshot::framesDone() const {
    int n = 0;
    for (const FrameRecord& r : records) n += r.status == FrameRecord::Status::Stopped ? 0 : 1;
    return n;
}

double TrackSnapshot::secondsPerFrame() const {
    double total = 0.0;
    int n = 0;
    for (const FrameRecord& r : records)
        if (r.status != FrameRecord::Status::Stopped) {
            total += r.seconds;
            ++n;
        }
    return n > 0 ? total / n : 0.0;
}

double TrackSnapshot::lastCost() const {
    for (auto r = records.rbegin(); r != records.rend(); ++r) {
        if (r->status != FrameRecord::Status::Tracked) continue;
        double cost = 0.0;
        for (double c : r->viewCost)
            if (!std::isnan(c)) cost += c;
        return cost;
    }
    return std::numeric_limits<double>::quiet_NaN();
}

TrackRunner::~TrackRunner() {
    stop();
}

void TrackRunner::stop() {
    stopFlag_ = true;
    if (worker_.joinable()) worker_.join();
}

bool TrackRunner::running() const {
    std::lock_guard lock(mutex_);
    return snapshot_.running;
}

TrackSnapshot TrackRunner::snapshot() const {
    std::lock_guard lock(mutex_);
    return snapshot_;
}

void TrackRunner::start(std::shared_ptr<const TrialScene> trial, TrackRequest request) {
    if (!trial) throw Error("track: no trial loaded");
    Scene alone = sceneOfBoneAlone(*trial, request.bone);  // fm::Error for a bone not loaded
    if (request.frames.empty()) throw Error("track: no frames to track");
    for (int f : request.frames)
        if (f < 0 || f >= trial->frameCount)
            throw Error("track: frame " + std::to_string(f) + " is not one of the trial's 0.." +
                        std::to_string(trial->frameCount - 1));
    for (const auto& [f, pose] : request.keyframes)
        if (f < 0 || f >= trial->frameCount)
            throw Error("track: keyframe at frame " + std::to_string(f) + " is outside the trial");
    // Built here, so that a bad request fails before the running run is stopped.
    auto tracker = std::make_shared<const Tracker>(
        std::move(alone), request.bone, trialFrameViews(*trial),
        request.settings);

    stop();
    stopFlag_ = false;
    {
        std::lock_guard lock(mutex_);
        TrackSnapshot fresh;
        fresh.running = true;
        fresh.bone = request.bone;
        fresh.frames = request.frames;
        fresh.currentFrame = request.frames.front();
        fresh.run = snapshot_.run + 1;
        fresh.version = snapshot_.version + 1;
        snapshot_ = std::move(fresh);
    }
    worker_ = std::thread([this, trial = std::move(trial), tracker = std::move(tracker),
                           request = std::move(request)]() {
        const auto began = std::chrono::steady_clock::now();
        const auto elapsed = [&] {
            return std::chrono::duration<double>(std::chrono::steady_clock::now() - began).count();
        };
        try {
            for (const TrackSegment& segment : splitAtKeyframes(request.frames, request.keyframes)) {
                if (stopFlag_) break;
                trackSegment(
                    *tracker, segment, {},
                    [&](const RigidTransform& pose) {
                        return storedObjectPose(*trial, request.bone, pose);
                    },
                    [&](const FrameRecord& record) {
                        std::lock_guard lock(mutex_);
                        snapshot_.records.push_back(record);
                        const std::size_t next = snapshot_.records.size();
                        snapshot_.currentFrame =
                            next < snapshot_.frames.size() && !stopFlag_ ? snapshot_.frames[next] : -1;
                        snapshot_.elapsedSeconds = elapsed();
                        ++snapshot_.version;
                    },
                    &stopFlag_);
            }
        } catch (const std::exception& e) {
            std::lock_guard lock(mutex_);
            snapshot_.error = e.what();
        }
        std::lock_guard lock(mutex_);
        snapshot_.running = false;
        snapshot_.stopped = stopFlag_.load() &&
                            (snapshot_.records.size() < snapshot_.frames.size() ||
                             snapshot_.records.back().status == FrameRecord::Status::Stopped);
        snapshot_.finished = snapshot_.error.empty();
        snapshot_.currentFrame = -1;
        snapshot_.elapsedSeconds = elapsed();
        ++snapshot_.version;
    });
}

}  // namespace fm::app
