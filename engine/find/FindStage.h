#pragma once
// One stage of a search with no start (find/PoseFinder.h, find/ViewFinder.h): its name, wall
// time, work and what it hands on, printed one line each.
#include <chrono>
#include <functional>
#include <string>
#include <vector>

namespace fm {

struct FindStage {
    std::string name;     // "templates", "scan", "glance", "refine", "finish"
    double seconds = 0.0; // wall
    long long evaluations = 0;  // renders (templates), template placements (scan), searches' evaluations
    int kept = 0;         // what goes on to the next stage
};

// Told the name of each stage as it starts ("templates", "scan", "glance", "refine", "finish"), on the
// calling thread: what a progress display shows.
using FindStageCallback = std::function<void(const char* stage)>;

using FindClock = std::chrono::steady_clock;
// Wall seconds from `start` to now: a stage's time.
inline double secondsSince(FindClock::time_point start) {
    return std::chrono::duration<double>(FindClock::now() - start).count();
}

// The stages' wall times summed.
double findSeconds(const std::vector<FindStage>& stages);

// One line per stage: "scan        0.41 s   52992 placements -> 24 hypotheses".
std::vector<std::string> describeFindStages(const std::vector<FindStage>& stages);

}  // namespace fm
