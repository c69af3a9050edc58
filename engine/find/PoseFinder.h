#pragma once
// Finding a model's pose in one radiograph with no start (issue 29), on a CPU, with no training:
//   1. templates: the model's outline rendered once per pair of tilts (find/OutlineTemplates);
//   2. scan: every template turned through every roll and scaled through every depth, chamfer-
//      matched (directional, with polarity) at every position of a coarse image (1/8 or 1/16,
//      find/TemplateScan); the best `hypotheses` distinct ones kept;
//   3. refine: each hypothesis, as a pose, polished by the registration's own search at a
//      coarse level (exact renders, edge distance), side by side one per core;
//   4. finish: the best `finalists` registered fully (xray/ObjectRegistration, the search
//      `register --start` runs), and the best one's look-alikes (its mirror images through the
//      film plane, one per model axis, and its tilts reversed: poses one view can barely tell from
//      it), answers that agree merged, best first.
// The answer is then confirmed like any other (xray/ConfirmedRegistration: more searches from
// independent starts around it); a different pose that scores nearly as well is a rival
// (the mirror-image silhouette of a symmetric implant): the verdict says so (search/AnswerVerdict).
// Deterministic for a given input, whatever the thread count.
#include <atomic>
#include <string>
#include <vector>

#include "find/FindSpace.h"
#include "find/FindStage.h"
#include "search/Registration.h"
#include "scene/Scene.h"

namespace fm {

struct FindSettings {
    FindSpace space;
    // The scan's detector downsampling: the coarsest power of two up to maxScanFactor at which the
    // model spans minScanSpanPixels at the far end of the depth band (JTML: the femoral component
    // 1/16, the tibial tray 1/8; at 1/16 the tray's plate is one pixel thick and its edges merge
    // with the femoral component's). Templates and edges at half its pixel.
    int maxScanFactor = 16;
    double minScanSpanPixels = 12.0;
    double tiltStepDeg = 14.0;   // template grid
    double rollStepDeg = 12.0;
    double scaleStep = 1.12;     // ratio between neighbouring depths of the scan
    double capPixels = 4.0;      // the scan's distance cap (scan pixels)
    int hypotheses = 24;         // kept by the scan, refined in stage 3
    int perPlace = 3;            // of them at most this many within 2 scan pixels of one another
    int refineFactor = 8;        // level of the refinement
    int refineEvaluations = 60;  // per hypothesis
    int finalists = 3;           // registered fully in stage 4
    int threads = 0;             // 0 = all cores
};

struct FoundCandidate {
    RigidTransform worldFromObject;
    double similarity = 0.0;  // at the finest level (edge distance: against a perfect outline's 1)
    int hypothesis = 0;       // rank of the scan hypothesis it came from (0 = the scan's best)
    int evaluations = 0;
};

struct FoundPose {
    std::vector<FoundCandidate> candidates;  // distinct answers of stage 4, best first
    std::vector<FindStage> stages;
    int scanFactor = 0;  // the scan's detector downsampling
    bool stopped = false;
    double seconds() const;
};

// Object `object` of `scene` in `view`, the others hidden (as registerObject). `finish` is the
// registration of stage 4 (realXraySettings). Throws fm::Error as registerObject, and for
// settings out of range.
FoundPose findObjectPose(const Scene& scene, std::size_t object, const RegistrationView& view,
                         const RegistrationSettings& finish, const FindSettings& settings,
                         const std::atomic<bool>* stop = nullptr);

}  // namespace fm
