#pragma once
// Finding the 2011 scene's six numbers with no start (issue 29): where the camera stood around
// the CT for a reference image, on a CPU, with no training.
//   1. templates: the CT's DRR from every direction of a grid (find/ViewTemplates), at the
//      scan's pitch, through the CT's block means;
//   2. scan: every template turned through every film rotation and scaled through every depth,
//      correlated with the reference at every shift on a 1/16 image, the best `rescored` of
//      them again on the 1/8 image (find/ViewScan); the best `hypotheses` distinct ones kept;
//   3. refine: each hypothesis, as a pose (the offset CT seen along the template's direction),
//      polished by the registration's own search at 1/8 and 1/4, side by side one per core;
//   4. finish: the best `finalists` registered fully (the registration `register --start`
//      runs), answers that agree merged, best first.
// Deterministic for a given input, whatever the thread count.
#include <atomic>
#include <functional>
#include <vector>

#include "core/Image.h"
#include "drr/Drr.h"
#include "find/FindStage.h"
#include "find/ViewScan.h"
#include "find/ViewSpace.h"
#include "geometry/Pose.h"
#include "search/Registration.h"

namespace fm {

struct ViewFindSettings {
    ViewSpace space;
    double templateStepDeg = 10.0;  // azimuth and elevation grid of the templates
    double rollStepDeg = 7.5;
    double scaleStep = 1.05;        // between neighbouring depths of the scan
    int scanPixels = 32;            // the finer scan image spans at least this many pixels (the coarser half)
    int rescored = 400;             // placements of the coarser scan scored again on the finer image
    int hypotheses = 16;            // distinct ones refined in stage 3
    int refineEvaluations = 80;     // per hypothesis
    int finalists = 2;              // registered fully in stage 4
    int threads = 0;                // 0 = all cores
};

struct ViewCandidate {
    Pose pose;
    double similarity = 0.0;  // at the finest level of the finish
    int hypothesis = 0;       // rank of the scan hypothesis it came from (0 = the scan's best)
    int evaluations = 0;
};

struct FoundView {
    // Distinct answers of stage 4, best first; when stopped earlier, the best of the last stage
    // that ended (empty only if stopped before the scan ended with a hypothesis).
    std::vector<ViewCandidate> candidates;
    std::vector<FindStage> stages;
    bool stopped = false;
};

// The CT `volume` (centre `volumeCenter`) in the 2011 scene of `setup`; `reference` has the film's
// size. `finish` is the registration of stage 4 (`register`'s). Setting *stop ends it after the
// current stage's searches (the candidates so far, `stopped` set). Throws fm::Error for a
// reference of another size or settings out of range.
FoundView findScenePose(const DrrVolumePtr& volume, const SceneSetup& setup, const glm::dvec3& volumeCenter,
                        const Image& reference, const RegistrationSettings& finish, const ViewFindSettings& settings,
                        const std::atomic<bool>* stop = nullptr, const FindStageCallback& onStage = {});

// The pose whose image is `placement` of template `view`: the camera turned about its axis by the
// roll, moved along it for the scale and sideways for the shift, then turned about the source so
// that the CT is seen along the template's direction again (the parallax of an offset CT).
Pose placementPose(const ViewTemplate& view, const ViewPlacement& placement, const SceneSetup& setup,
                   const glm::dvec3& volumeCenter);

}  // namespace fm
