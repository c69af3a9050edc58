#pragma once
// The trial controls of the workspace (docs/app.md, "Tracking a trial"), as plain data: play /
// pause over the frames, the keyframes of every object, the Track forward / back run as the UI
// shows it (copied from the TrackRunner every frame), the selected object's six pose curves, and
// the requests the Track pane makes. WorkspaceTracking carries the requests out; nothing here
// draws or computes.
#include <cmath>
#include <map>
#include <string>
#include <vector>

#include "scene/PoseCurves.h"
#include "scene/RigidTransform.h"
#include "search/AnswerVerdict.h"

namespace fm::app {

struct TrackRequests {
    bool togglePlay = false;
    bool setKeyframe = false, clearKeyframe = false;  // the selected object, the current frame
    bool forward = false, back = false, stop = false;  // Track from the current frame
    bool saveTra = false;                              // the selected object's .tra
    bool saveKeyframes = false;                        // the trial JSON with every keyframe
};

// The running (or last) Track run.
struct TrackRunView {
    bool running = false, finished = false, stopped = false;
    std::string error;
    std::string object;
    bool backwards = false;
    int done = 0, total = 0;
    double secondsPerFrame = 0.0;
    double lastCost = std::nan("");  // summed over the cameras, of the last tracked frame
    int currentFrame = -1;           // being tracked
    std::string lastNote;            // the last frame's: "cameras 1, 2", "bad frame: ..."
    // How sure the run's frames are (search/AnswerVerdict): counts, the frames not ok, the worst.
    int ok = 0, doubtful = 0, lost = 0;
    std::vector<int> notOk;
    AnswerVerdict worst = AnswerVerdict::Ok;
};

struct TrackState {
    bool playing = false;
    double playFramesPerSecond = 5.0;
    // Per object: frame -> pose (worldFromObject) the tracker starts from there.
    std::vector<std::map<int, RigidTransform>> keyframes;
    TrackRunView run;
    // The selected object's curves over the frames (refreshed when its poses change).
    PoseCurves curves;
    std::string traPath;       // the selected object's .tra: empty = <trial>_<object>.tra
    std::string keyframesPath;  // empty = <trial>_keyframes.json beside the trial
    std::string message;
    bool messageFailed = false;
    TrackRequests requests;
};

}  // namespace fm::app
