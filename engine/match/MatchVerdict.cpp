#include "match/MatchVerdict.h"

#include <cmath>
#include <cstdint>
#include <cstdio>
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
}

Closeness parameterCloseness(double error, double tolerance) {
    const double ratio = std::abs(error) / tolerance;
    if (ratio <= kVeryCloseTolerances) return Closeness::VeryClose;
    if (ratio <= kCloseTolerances) return Closeness::Close;
    return Closeness::Far;
}

Closeness poseCloseness(double mtreMm) {
    if (mtreMm < kVeryCloseMtreMm) return Closeness::VeryClose;
    if (mtreMm < kCloseMtreMm) return Closeness::Close;
    return Closeness::Far;
}

const char* closenessName(Closeness c) {
    switch (c) {
        case Closeness::VeryClose:
            return "very close";
        case Closeness::Close:
            return "close";
        default:
            return "far";
    }
}

MatchVerdict judgeMatch(const Pose& reference, const Pose& user, double mtreMm,
                        const MatchTolerances& tolerances) {
    validateTolerances(tolerances);
    for (double v : reference.toArray())
        if (!std::isfinite(v)) throw Error("match: the reference pose is not finite");
    for (double v : user.toArray())
        if (!std::isfinite(v)) throw Error("match: the pose to judge is not finite");
    if (!std::isfinite(mtreMm) || mtreMm < 0.0)
        throw Error("match: the target registration error is not a finite distance");

    MatchVerdict verdict;
    verdict.mtreMm = mtreMm;
    verdict.closeness = poseCloseness(mtreMm);
    verdict.match = true;
    const auto error = poseDifference(reference, user);
    double worstRatio = -1.0;
    for (int i = 0; i < kPoseParameterCount; ++i) {
        ParameterHint& h = verdict.hints[i];
        h.error = error[i];
        h.tolerance = tolerances.forParameter(i);
        h.closeness = parameterCloseness(h.error, h.tolerance);
        const char* word = "OK";
        if (h.error > h.tolerance) {
            h.status = ParameterStatus::TooHigh;
            word = "too high";
        } else if (h.error < -h.tolerance) {
            h.status = ParameterStatus::TooLow;
            word = "too low";
        }
        if (h.status != ParameterStatus::Ok) verdict.match = false;
        h.text = std::string(poseParameterName(i)) + " " + word;
        const double ratio = std::abs(h.error) / h.tolerance;
        if (ratio > worstRatio) {
            worstRatio = ratio;
            verdict.worstParameter = i;
        }
    }
    return verdict;
}

std::string hintText(const ParameterHint& h, int parameter, HintWording wording,
                     bool showNumbers) {
    std::string text = h.status == ParameterStatus::TooHigh  ? "too high"
                       : h.status == ParameterStatus::TooLow ? "too low"
                                                             : "ok";
    if (wording == HintWording::Bands && h.status != ParameterStatus::Ok)
        text += std::string(", ") + closenessName(h.closeness);
    if (showNumbers) {
        char number[48];
        std::snprintf(number, sizeof(number), " (%+.1f %s)", h.error, poseParameterUnit(parameter));
        text += number;
    }
    return text;
}

std::string verdictMessage(const MatchVerdict& v, HintWording wording, bool showNumbers) {
    std::ostringstream msg;
    msg.setf(std::ios::fixed);
    msg.precision(1);
    const ParameterHint& worst = v.hints[v.worstParameter];
    const char* unit = poseParameterUnit(v.worstParameter);
    if (v.match) {
        msg << "Match! Every parameter is within tolerance (mTRE " << v.mtreMm << " mm).";
        return msg.str();
    }
    msg << "No match yet: " << worst.text << " is furthest off";
    if (showNumbers) {
        msg << " (by " << std::abs(worst.error) << " " << unit << ", tolerance "
            << worst.tolerance << " " << unit << "); mTRE " << v.mtreMm << " mm.";
    } else if (wording == HintWording::Bands) {
        msg << " (" << closenessName(worst.closeness) << "); the pose as a whole is "
            << closenessName(v.closeness) << ".";
    } else {
        msg << ".";
    }
    return msg.str();
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
