#pragma once
// How far an answer can be trusted, from evidence measured without the truth: searches from
// independent starts that end at the same pose, the silhouette IoU against a label mask, the
// answer's similarity against a reference (tracking: what the bone scored in its last good
// frames; evaluate: what a perfect match scores), and how well the images fix each coordinate
// (search/PoseUncertainty). The verdict is the worst the evidence says, and "ok" needs at least
// one piece that confirms the answer: nothing unconfirmed is shown or written as right.
// xray/AnswerCheck adds the check that the model covers valid pixels at all.
#include <array>
#include <optional>
#include <string>

#include "search/PoseUncertainty.h"

namespace fm {

// Silhouette IoU against the mask from which an answer counts as confirmed, and below which it is
// lost rather than doubtful.
inline constexpr double kConfirmedIoU = 0.9;
inline constexpr double kLostIoU = 0.5;
// Tracking: the frame's similarity over the bone's in its last good frames. The JTML misses
// scored 0.82-0.96 of the right pose's; a tracked bone's similarity varies a few per cent
// from frame to frame (docs/tracking.md, "Verdicts").
inline constexpr double kConfirmedSimilarityRatio = 0.9;
inline constexpr double kLostSimilarityRatio = 0.5;
// Evaluate: against a perfect match on a reference the model rendered, right answers score
// nearly 1 (the knee phantom, cmaes with small budgets: every success at 0.958 or more, misses of
// 1.2-3.3 mm at 0.92-0.958; docs/search.md, "Verdicts").
inline constexpr double kConfirmedPerfectMatchRatio = 0.96;
// The same for a pose found with no start (find/ViewFinder, `register --reference-pose` with no
// --start), whose confirming searches all start in its basin: right answers after the full
// registration scored 0.99998 (the knee phantom) and 0.995-0.999 (example_ct, its finest level
// left out); a pose of the analytic cylinder 43 mm mTRE off, on which both confirming searches
// agreed, 0.97 (docs/find.md).
inline constexpr double kConfirmedFoundPerfectMatchRatio = 0.99;
// Real radiographs, edge distance: a perfect outline match scores 1 (every outline pixel on an
// image edge). On the JTML frames every start that ended within 1 mm / 2 deg scored at least
// 0.90 and every miss at most 0.913, from starts 2.5x the range (docs/real-xray.md,
// "Verdicts").
inline constexpr double kConfirmedOutlineRatio = 0.92;

// A pose found with no start (find/PoseFinder): a different answer of the search (beyond the
// registration's start radius) whose shortfall from a perfect match (1 - similarity for edge
// distance) is at most this many times the answer's is a rival the image cannot rule out - a
// near-symmetric outline's mirror pose. A box's half turn: 1.0; the JTML tray's mirror tilt 1.5
// (its outline 50 % further from the image's edges), the femoral component's mirror 4-5
// (docs/find.md).
inline constexpr double kRivalShortfallRatio = 1.25;
// Shortfalls below this count as this (a mean outline distance of 0.16 px at the 8 px cap):
// differences among near-perfect fits are rounding, not evidence.
inline constexpr double kShortfallFloor = 0.02;

enum class AnswerVerdict { Ok, Doubtful, Lost };
const char* toString(AnswerVerdict verdict);  // "ok", "doubtful", "lost"

struct AnswerEvidence {
    std::optional<double> iou;  // silhouette IoU against the object's mask
    int runs = 0;               // searches from independent starts (0: not run)
    int agreeing = 0;           // of them, those that ended at the answer
    // Whether their agreement confirms the answer. Not for a pose found with no start under a
    // measure with no ceiling (gradient NCC): the searches start around the found pose and share
    // its basin, right or wrong; an outline's ratio, a mask or a second camera must confirm it.
    bool agreementConfirms = true;
    std::optional<PoseUncertainty> uncertainty;
    // The names of its coordinates in the reasons (null: the camera frame's, searchCoordinateName).
    const std::array<const char*, 6>* coordinateNames = nullptr;
    // The answer's similarity over a reference: tracking's last good frames, evaluate's
    // perfect match (Registration::referenceSelfSimilarity). Named in the text.
    std::optional<double> similarityRatio;
    std::string similarityReference = "the last good frames'";
    double confirmedRatio = kConfirmedSimilarityRatio;  // ok from this ratio on
    bool stopped = false;                   // the search was stopped before it ended
    // The best different answer of a search with no start: its shortfall from a perfect match over
    // the answer's, and how far it is (as the camera sees it).
    struct Rival {
        double shortfallRatio = 0.0;
        double inPlaneMm = 0.0;
        double rotationDeg = 0.0;
    };
    std::optional<Rival> rival;
};

struct AnswerCheck {
    AnswerVerdict verdict = AnswerVerdict::Doubtful;
    // "ok: 2 of 2 searches from different starts end here" or "doubtful: ...; ..." (every reason).
    std::string text;
};

// The answer's similarity judged against a perfect match's (`ceiling`: the reference against
// itself, for references the model rendered or sliced itself): ok from `confirmedFrom`
// (kConfirmedFoundPerfectMatchRatio for a pose found with no start). A ceiling that is not
// positive says nothing (left unset).
void judgeAgainstPerfectMatch(AnswerEvidence& evidence, double similarity, double ceiling,
                              double confirmedFrom = kConfirmedPerfectMatchRatio);

// A candidate `inPlaneMm` / `rotationDeg` from the answer (as the camera sees them) is a different
// answer, not the answer's own basin, when it lies beyond the search's start radius (`radius`:
// RegistrationSettings::searchRadius, u, v, depth mm, three angles deg): a search from it would
// not end at the answer.
bool beyondSearchRadius(const std::array<double, 6>& radius, double inPlaneMm, double rotationDeg);
// Its evidence as a rival: its shortfall from `ceiling` over the answer's, each at least
// kShortfallFloor.
AnswerEvidence::Rival rivalEvidence(double answerSimilarity, double rivalSimilarity, double ceiling,
                                    double inPlaneMm, double rotationDeg);

// The verdict of the evidence alone.
AnswerCheck judgeEvidence(const AnswerEvidence& evidence);

}  // namespace fm
