#include "match/MatchVerdict.h"

#include <cmath>
#include <cstdint>
#include <sstream>
#include <vector>

#include "core/Error.h"
#include "similarity/Ncc.h"

namespace fm {

void validateTolerances(const MatchTolerances& t) {
    auto positive = [](double v) { return std::isfinite(v) && v > 0.0; };
    if (!positive(t.offsetMm))
        throw Error("match tolerance for offsets must be positive, got " +
                    std::to_string(t.offsetMm) + " mm");
    if (!positive(t.angleDeg))
        throw Error("match tolerance for angles must be positive, got " +
                    std::to_string(t.angleDeg) + " deg");
    if (!std::isfinite(t.minNcc) || t.minNcc < -1.0 || t.minNcc > 1.0)
        throw Error("match minimum NCC must be in -1..1, got " + std::to_string(t.minNcc));
}

MatchVerdict judgeMatch(const Pose& reference, const Pose& user, double ncc,
                        const MatchTolerances& tolerances) {
    validateTolerances(tolerances);
    for (double v : reference.toArray())
        if (!std::isfinite(v)) throw Error("match: the reference pose is not finite");
    for (double v : user.toArray())
        if (!std::isfinite(v)) throw Error("match: the pose to judge is not finite");
    if (!std::isfinite(ncc)) throw Error("match: the image similarity (NCC) is not finite");

    MatchVerdict verdict;
    verdict.ncc = ncc;
    verdict.imagesAgree = ncc >= tolerances.minNcc;
    verdict.parametersWithinTolerance = true;
    const auto error = poseDifference(reference, user);
    double worstRatio = -1.0;
    for (int i = 0; i < kPoseParameterCount; ++i) {
        ParameterHint& h = verdict.hints[i];
        h.error = error[i];
        h.tolerance = tolerances.forParameter(i);
        const char* word = "OK";
        if (h.error > h.tolerance) {
            h.status = ParameterStatus::TooHigh;
            word = "too high";
        } else if (h.error < -h.tolerance) {
            h.status = ParameterStatus::TooLow;
            word = "too low";
        }
        if (h.status != ParameterStatus::Ok) verdict.parametersWithinTolerance = false;
        h.text = std::string(poseParameterName(i)) + " " + word;
        const double ratio = std::abs(h.error) / h.tolerance;
        if (ratio > worstRatio) {
            worstRatio = ratio;
            verdict.worstParameter = i;
        }
    }
    verdict.match = verdict.parametersWithinTolerance && verdict.imagesAgree;

    std::ostringstream msg;
    msg.setf(std::ios::fixed);
    msg.precision(1);
    const ParameterHint& worst = verdict.hints[verdict.worstParameter];
    const char* unit = poseParameterUnit(verdict.worstParameter);
    if (verdict.match) {
        msg << "Match! Every parameter is within tolerance; the images correlate at ";
        msg.precision(3);
        msg << ncc << ".";
    } else if (!verdict.parametersWithinTolerance) {
        msg << "No match yet: " << worst.text << " (off by " << std::abs(worst.error) << " " << unit
            << ", tolerance " << worst.tolerance << " " << unit << ").";
    } else {
        msg << "No match: the parameters are within tolerance but the images differ (NCC ";
        msg.precision(3);
        msg << ncc << " < " << tolerances.minNcc << ").";
    }
    verdict.message = msg.str();
    return verdict;
}

double imageAgreement(const Image& reference, const Image& user) {
    if (reference.width != user.width || reference.height != user.height)
        throw Error("image agreement: the images differ in size (" +
                    std::to_string(reference.width) + "x" + std::to_string(reference.height) +
                    " vs " + std::to_string(user.width) + "x" + std::to_string(user.height) + ")");
    std::vector<std::uint8_t> mask(reference.pixels.size());
    for (std::size_t i = 0; i < mask.size(); ++i)
        mask[i] = (reference.pixels[i] > 0.0f || user.pixels[i] > 0.0f) ? 1 : 0;
    return nccValues(reference.pixels.data(), user.pixels.data(), mask.data(), mask.size());
}

}  // namespace fm
