#pragma once
// The 2011 matching game's judge: the user turns six knobs to reproduce a reference X-ray; after
// each attempt the program says "match" or gives a hint per parameter ("x offset too high",
// "azimuth too low"), naming the one furthest off. Attempts are counted by the caller.
//
// Rule: a match needs every parameter within its tolerance (offsets in mm, angles in degrees,
// angle differences wrapped so that azimuth -179 is 2 degrees from 179). Nothing else decides.
// The image similarity is not part of the rule: the NCC of two knee DRRs stays above 0.9 with
// the azimuth 45 degrees off, so it never decided and read as "nearly there" when it was not.
// How close the whole pose is, is said by the mTRE over the bone (mm on the bone itself) in
// coarse bands (poseCloseness), which mean the same thing on every CT.
//
// What the user is told depends on the hint mode (HintWording) and on whether the numbers may
// be shown (after a match or once the reference is revealed): before that, a hint gives a
// direction (and, in the Bands mode, a coarse band), never the signed error, which would let a
// student match by subtraction without looking at the images.
#include <array>
#include <string>

#include "core/Image.h"
#include "geometry/Pose.h"
#include "match/PoseError.h"

namespace fm {

struct MatchTolerances {
    double offsetMm = 2.0;  // per offset (x, y, z)
    double angleDeg = 2.0;  // per angle (azimuth, elevation, rotation)

    double forParameter(int index) const { return isAngleParameter(index) ? angleDeg : offsetMm; }
};

// Throws fm::Error if a tolerance is not positive and finite.
void validateTolerances(const MatchTolerances& tolerances);

enum class ParameterStatus { Ok, TooHigh, TooLow };

// Coarse distance bands. Per parameter in units of its tolerance: very close up to 3
// tolerances (6 mm / 6 deg by default), close up to 10 (20 mm / 20 deg), far beyond. For the
// whole pose by the mTRE: very close below 3 mm, close below 10 mm, far from 10 mm.
enum class Closeness { VeryClose, Close, Far };
inline constexpr double kVeryCloseTolerances = 3.0, kCloseTolerances = 10.0;
inline constexpr double kVeryCloseMtreMm = 3.0, kCloseMtreMm = 10.0;
Closeness parameterCloseness(double error, double tolerance);
Closeness poseCloseness(double mtreMm);
const char* closenessName(Closeness closeness);  // "very close", "close", "far"

// How much a hint says before the numbers may be shown.
enum class HintWording {
    Direction,  // "too high" / "too low" / "ok" (the default, as in 2011)
    Bands,      // ... plus the band: "too high, far"
};

struct ParameterHint {
    ParameterStatus status = ParameterStatus::Ok;
    double error = 0.0;      // user - reference (mm or deg, angles wrapped)
    double tolerance = 0.0;  // the tolerance it was judged against
    Closeness closeness = Closeness::VeryClose;
    std::string text;  // "x offset too high", "azimuth OK", ... (direction only)
};

struct MatchVerdict {
    bool match = false;
    std::array<ParameterHint, kPoseParameterCount> hints;
    int worstParameter = 0;  // largest |error| / tolerance (Pose::toArray() order)
    double mtreMm = 0.0;     // mean target registration error over the bone (given)
    Closeness closeness = Closeness::VeryClose;  // poseCloseness(mtreMm)
};

// `mtreMm`: targetRegistrationError(reference, user, ...).meanMm (0 when the scene has no bone
// points). Throws fm::Error for a non-finite pose or mTRE, or bad tolerances.
MatchVerdict judgeMatch(const Pose& reference, const Pose& user, double mtreMm,
                        const MatchTolerances& tolerances = {});

// The hint cell of one parameter: "too high", "too low, far", "ok"; with numbers, the signed
// error too ("too high (+4.0 mm)").
std::string hintText(const ParameterHint& hint, int parameter, HintWording wording,
                     bool showNumbers);
// One line for the user. Without numbers: "No match yet: elevation too low is furthest off."
// (Bands: "... (far); the pose as a whole is close."); with numbers the error, its tolerance
// and the mTRE follow.
std::string verdictMessage(const MatchVerdict& verdict, HintWording wording, bool showNumbers);

// NCC of two line-integral DRRs (DrrOutput::LineIntegral: 0 where a ray meets nothing) of the
// same size over the union of their footprints (pixels above zero in either): the empty
// background would otherwise inflate the correlation. Shown for information only (see the
// rule above). Throws fm::Error if the sizes differ.
double imageAgreement(const Image& reference, const Image& user);

}  // namespace fm
