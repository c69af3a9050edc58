#pragma once
// A bone volume's pose in two or more calibrated cameras with no start (issue 29), on a CPU, with no
// training. Measured on a simulated example_ct femur trial (docs/find.md, "Biplane"):
//   1. scan: orientations x 3D positions scored by every camera's gradient correlation at once
//      (find/BiplaneScan.h) at the coarsest power of two at which the bone spans minScanSpanPixels,
//      placements at most maxPlacementsPerSide per side;
//   2. refine: the best `refined` hypotheses each polished by the registration's own search at the
//      scan's pixel (Nelder-Mead from the hypothesis, both cameras, exact renders; side by side,
//      one per core): the scan ranks a 10 deg-off truth a few hundred places down, its polish lifts it;
//      a glance first (a few evaluations each) leaves the best quarter to polish in full;
//   3. finish: the best `finalists` polished at 1/2 and 1/4 of the scan's pixel, where the bone's
//      inner edges tell it from the other bones' (femur: the truth 1.10 against 0.79 next, where
//      the scan's pixel had them 1.02 against 0.99); answers that agree merged, best first;
//   then, when no answer is clearly seen and the scan was at 1/8 or coarser, 1-3 once more with the
//      scan at half its pixel and 4x the hypotheses refined (the femur flexed 20 deg: its neighbours
//      ranked 1674th at 1/8; flexed 30 deg, found from the 768th at 1/4).
// How sure: the best answer clearly seen (kBiplaneMinSimilarity) and against the next distinct one
// (kBiplaneRivalRatio); the tracker's registration and verdict follow, as from a keyframe.
// Deterministic whatever the thread count.
#include <atomic>
#include <string>
#include <utility>
#include <vector>

#include "find/BiplaneScan.h"
#include "find/FindStage.h"
#include "search/AnswerVerdict.h"
#include "search/Registration.h"

namespace fm {

// An answer further than kBiplaneRivalMm or kBiplaneRivalDeg from the best one (another basin)
// scoring above kBiplaneRivalRatio of it is a rival the cameras cannot rule out: the find is
// doubtful. (The femur's best other basin scored 0.50 of the truth's; docs/find.md.)
inline constexpr double kBiplaneRivalRatio = 0.9;
inline constexpr double kBiplaneRivalMm = 5.0;
inline constexpr double kBiplaneRivalDeg = 5.0;
// A best answer whose gradient NCC, averaged over the cameras, is below this is doubtful whatever
// its rivals score: the bone is not clearly seen at any pose searched (the truth may lie outside
// the search space). On the simulated femur (scripts/find_biplane_accuracy.sh, 20 finds) the wrong
// best answers scored 0.24-0.32 per camera, one of them called ok by its rivals alone (tilt +-35:
// 0.32, the next basin 0.81 of it, 100 mm off); the right ones 0.39-0.54; the wrist's 0.55-0.64.
inline constexpr double kBiplaneMinSimilarity = 0.35;
// Two answers within these are one (merged).
inline constexpr double kBiplaneSameMm = 2.0;
inline constexpr double kBiplaneSameDeg = 2.0;

struct BiplaneFindSettings {
    // A CT bone's frame says nothing of how a camera sees it: any orientation. Depths: where the
    // cameras' views cross, unless a band in mm is given (fractions of the film distance are not
    // used: a pinhole calibration's film is a virtual plane).
    FindSpace space{90.0, 180.0};
    int maxScanFactor = 16;
    double minScanSpanPixels = 40.0;  // the bone's bounding-box diagonal at the scan's pixel
    // Placements 2, 4, ... scan pixels apart beyond this many per side of the scan image. At 128 the
    // wrist (256 at 1/2) was scanned 2 apart: the radius and the ulna found in 91 and 57 s (1 apart:
    // 149 and 92 s, the machine shared), but mc3 lost (doubtful, 0.95; found ok at 1 apart): not yet the default.
    int maxPlacementsPerSide = 256;
    BiplaneScanSettings scan;         // its factor is chosen as above
    int refined = 400;
    // 2a: each of the `refined` first polished with glanceEvaluations (0: no glance); the best
    // glanceKeptShare of them (at least `finalists`) go on to the refine's refineEvaluations. The
    // flexed femur's frame 6 (docs/find.md): the finer pass's refine 85 -> 18 + 22 s, the same answer.
    int glanceEvaluations = 16;
    double glanceKeptShare = 0.25;
    int refineEvaluations = 80;
    int finalists = 8;
    int finishEvaluations = 80;  // at 1/2 of the scan's pixel (half of it at 1/4)
    // When no answer is clearly seen (kBiplaneMinSimilarity) with the scan at 1/8 or coarser, all
    // of it once more with the scan at half that pixel (the flexed femur, docs/find.md), refining
    // its best refinedWhenFiner hypotheses: the femur flexed 30 deg was found from the finer
    // scan's 768th (of 7776), not within its best 400.
    bool finerScanWhenUnseen = true;
    int refinedWhenFiner = 1600;
    int threads = 0;
};

struct BiplaneCandidate {
    RigidTransform worldFromObject;
    double similarity = 0.0;  // summed over the cameras, at the finish's finest level
    int hypothesis = 0;       // its rank in the scan
};

struct FoundBiplane {
    std::vector<BiplaneCandidate> candidates;  // distinct, best first
    std::vector<FindStage> stages;
    int scanFactor = 0;
    int placementStride = 1;  // scan pixels between placements
    int orientations = 0;
    std::pair<double, double> band{0.0, 0.0};  // depths searched along the first camera
    bool stopped = false;
    // Ok when the best scores at least kBiplaneMinSimilarity per camera and the best rival
    // (kBiplaneRivalMm / kBiplaneRivalDeg away) below kBiplaneRivalRatio of it, or there is none
    // and two or more finalists ended at the best; else doubtful; lost when there is no candidate.
    AnswerVerdict verdict = AnswerVerdict::Lost;
    std::string verdictText;
};

// FoundBiplane::verdict and its text for a find's distinct answers (best first; similarity summed
// over `cameras`), `finalists` of which went into its finish.
std::pair<AnswerVerdict, std::string> judgeBiplaneAnswers(const std::vector<BiplaneCandidate>& candidates,
                                                          std::size_t finalists, std::size_t cameras,
                                                          const glm::dvec3& pivot);

// Object 0 of `scene` (the bone alone) in `views` (two or more cameras). `finish` gives the
// similarity and render settings (gradient NCC; cropToModel for real radiographs); `onStage` is
// told "scan", "refine", "finish" as each starts. Throws
// fm::Error for fewer than two views, cameras that share no depths, settings out of range.
FoundBiplane findBiplanePose(const Scene& scene, const std::vector<RegistrationView>& views,
                             const RegistrationSettings& finish, const BiplaneFindSettings& settings,
                             const std::atomic<bool>* stop = nullptr, const FindStageCallback& onStage = {});

}  // namespace fm
