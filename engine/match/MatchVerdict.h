#pragma once
// The 2011 matching game's judge: the user turns six knobs to reproduce a reference X-ray; after
// each attempt the program says "match" or gives a hint per parameter ("x offset too high",
// "azimuth too low"), naming the one furthest off. Attempts are counted by the caller.
//
// Rule: a match needs every parameter within its tolerance (offsets in mm, angles in degrees,
// angle differences wrapped so that azimuth -179 is 2 degrees from 179) AND the two DRRs to
// agree (NCC at least minNcc). The image check guards against declaring a match while the
// images differ for another reason (a different volume, threshold or render setting); within
// the default tolerances the DRRs of the same scene correlate far above it.
#include <array>
#include <string>

#include "core/Image.h"
#include "geometry/Pose.h"
#include "match/PoseError.h"

namespace fm {

struct MatchTolerances {
    double offsetMm = 2.0;  // per offset (x, y, z)
    double angleDeg = 2.0;  // per angle (azimuth, elevation, rotation)
    double minNcc = 0.9;    // the DRRs must correlate at least this much

    double forParameter(int index) const { return isAngleParameter(index) ? angleDeg : offsetMm; }
};

// Throws fm::Error if a tolerance is not positive and finite or minNcc is outside -1..1.
void validateTolerances(const MatchTolerances& tolerances);

enum class ParameterStatus { Ok, TooHigh, TooLow };

struct ParameterHint {
    ParameterStatus status = ParameterStatus::Ok;
    double error = 0.0;      // user - reference (mm or deg, angles wrapped)
    double tolerance = 0.0;  // the tolerance it was judged against
    std::string text;        // "x offset too high", "azimuth OK", ...
};

struct MatchVerdict {
    bool match = false;
    bool parametersWithinTolerance = false;
    bool imagesAgree = false;  // ncc >= minNcc
    double ncc = 0.0;
    std::array<ParameterHint, kPoseParameterCount> hints;
    int worstParameter = 0;  // largest |error| / tolerance (Pose::toArray() order)
    std::string message;     // one line for the user
};

// `ncc` is the similarity of the reference and the user's DRR (see imageAgreement()).
// Throws fm::Error for a non-finite pose or NCC, or bad tolerances.
MatchVerdict judgeMatch(const Pose& reference, const Pose& user, double ncc,
                        const MatchTolerances& tolerances = {});

// NCC of two line-integral DRRs (DrrOutput::LineIntegral: 0 where a ray meets nothing) of the
// same size over the union of their footprints (pixels above zero in either): the empty
// background would otherwise inflate the correlation. Throws fm::Error if
// the sizes differ.
double imageAgreement(const Image& reference, const Image& user);

}  // namespace fm
