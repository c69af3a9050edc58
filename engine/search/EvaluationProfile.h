#pragma once
// Where a search's evaluations spend their time (issue 34: "evaluations per second per core, and
// where each evaluation's time goes, so that any later change is judged by it"). Thread time,
// summed over the threads that evaluated: moving the scene and cropping the camera (set-up),
// rendering the candidate (render), its footprint mask (footprint), and the similarity against
// the reference (similarity). Registration fills it (search/Registration.h); the commands print it.
#include <string>

namespace fm {

struct EvaluationProfile {
    int evaluations = 0;     // cost evaluations (each may hold several views)
    double wallSeconds = 0.0;
    double setupSeconds = 0.0, renderSeconds = 0.0, footprintSeconds = 0.0, similaritySeconds = 0.0;

    double threadSeconds() const { return setupSeconds + renderSeconds + footprintSeconds + similaritySeconds; }
    EvaluationProfile& operator+=(const EvaluationProfile& o);
};

// "806 evaluations in 0.268 s on 2 threads: 3007 per second, 1504 per core-second; each 0.52 ms
// of thread time: render 0.31, footprint 0.05, similarity 0.12, set-up 0.04". `threads`: the
// threads the search could use (0 = all cores).
std::string describeEvaluations(const EvaluationProfile& profile, int threads);

}  // namespace fm
