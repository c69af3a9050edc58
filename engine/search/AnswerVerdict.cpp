#include "search/AnswerVerdict.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace fm {

const char* toString(AnswerVerdict verdict) {
    switch (verdict) {
        case AnswerVerdict::Ok: return "ok";
        case AnswerVerdict::Lost: return "lost";
        default: return "doubtful";
    }
}

namespace {

struct Judgement {
    AnswerVerdict verdict = AnswerVerdict::Ok;
    bool confirmed = false;
    std::string reasons;
    void add(AnswerVerdict says, const std::string& reason, bool confirms = false) {
        if (static_cast<int>(says) > static_cast<int>(verdict)) verdict = says;
        confirmed = confirmed || confirms;
        reasons += (reasons.empty() ? "" : "; ") + reason;
    }
};

std::string format(const char* pattern, double a, double b = 0.0, double c = 0.0, double d = 0.0) {
    char text[300];
    std::snprintf(text, sizeof text, pattern, a, b, c, d);
    return text;
}

}  // namespace

void judgeAgainstPerfectMatch(AnswerEvidence& evidence, double similarity, double ceiling, double confirmedFrom) {
    if (!(ceiling > 0.0)) return;
    evidence.similarityRatio = similarity / ceiling;
    evidence.similarityReference = "a perfect match's";
    evidence.confirmedRatio = confirmedFrom;
}

bool beyondSearchRadius(const std::array<double, 6>& radius, double inPlaneMm, double rotationDeg) {
    return inPlaneMm > std::max(radius[0], radius[1]) || rotationDeg > std::max({radius[3], radius[4], radius[5]});
}

AnswerEvidence::Rival rivalEvidence(double answerSimilarity, double rivalSimilarity, double ceiling,
                                    double inPlaneMm, double rotationDeg) {
    return {std::max(ceiling - rivalSimilarity, kShortfallFloor) / std::max(ceiling - answerSimilarity, kShortfallFloor),
            inPlaneMm, rotationDeg};
}

AnswerCheck judgeEvidence(const AnswerEvidence& evidence) {
    using V = AnswerVerdict;
    Judgement j;
    // 2. Searches from independent starts: the answer is confirmed when another ends there too.
    if (evidence.runs >= 2) {
        const std::string counted = std::to_string(evidence.agreeing) + " of " + std::to_string(evidence.runs) +
                                    " searches from different starts end here";
        if (evidence.agreeing >= 2) j.add(V::Ok, counted, evidence.agreementConfirms);
        else j.add(V::Doubtful, "no other search from a different start ends here (" + counted + ")");
    }
    // 3. The mask, where there is one: the silhouette must cover it.
    if (evidence.iou) {
        const double iou = *evidence.iou;
        if (iou >= kConfirmedIoU) j.add(V::Ok, format("silhouette IoU %.3f against the mask (at least %.2f)", iou, kConfirmedIoU), true);
        else if (iou >= kLostIoU) j.add(V::Doubtful, format("silhouette IoU %.3f against the mask (below %.2f)", iou, kConfirmedIoU));
        else j.add(V::Lost, format("silhouette IoU %.3f against the mask (below %.2f)", iou, kLostIoU));
    }
    // 4. Tracking: the similarity against what the bone scored in its last good frames.
    if (evidence.similarityRatio) {
        const double r = *evidence.similarityRatio;
        const std::string of = "similarity %.2f of " + evidence.similarityReference;
        const double confirmed = evidence.confirmedRatio;
        if (r >= confirmed) j.add(V::Ok, format((of + " (at least %.2f)").c_str(), r, confirmed), true);
        else if (r >= kLostSimilarityRatio) j.add(V::Doubtful, format((of + " (below %.2f)").c_str(), r, confirmed));
        else j.add(V::Lost, format((of + " (below %.2f)").c_str(), r, kLostSimilarityRatio));
    }
    // 5. A direction along which the cost does not rise: the images do not fix the pose.
    if (evidence.uncertainty && evidence.uncertainty->measured() && !evidence.uncertainty->bounded) {
        std::string unfixed;
        for (int i = 0; i < 6; ++i)
            if (!std::isfinite(evidence.uncertainty->sd[i]))
                unfixed += (unfixed.empty() ? "" : ", ") +
                           std::string(evidence.coordinateNames ? (*evidence.coordinateNames)[static_cast<std::size_t>(i)]
                                                                : searchCoordinateName(i));
        j.add(V::Doubtful, "the cost does not rise along " + (unfixed.empty() ? std::string("some direction") : unfixed));
    }
    // 6. A pose found with no start: a different pose that scores nearly as well.
    if (evidence.rival && evidence.rival->shortfallRatio <= kRivalShortfallRatio)
        j.add(V::Doubtful, format("a different pose %.1f mm / %.1f deg away fits nearly as well (its shortfall from "
                                  "a perfect match %.2fx the answer's, at most %.2fx): the image cannot tell them "
                                  "apart (a near-symmetric outline?)",
                                  evidence.rival->inPlaneMm, evidence.rival->rotationDeg,
                                  evidence.rival->shortfallRatio, kRivalShortfallRatio));
    if (evidence.stopped) j.add(V::Doubtful, "stopped before the search ended");
    if (!j.confirmed && j.verdict == V::Ok)
        j.add(V::Doubtful, "nothing confirms it (no second search, mask or earlier frame): check the outline");
    return {j.verdict, std::string(toString(j.verdict)) + ": " + j.reasons};
}

}  // namespace fm
