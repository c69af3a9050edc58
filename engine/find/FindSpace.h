#pragma once
// Where a model's pose is looked for when nobody gives a start (issue 29): the model anywhere in
// the image, its pivot's depth within a band of the source-to-detector distance, any turn about
// the ray it is seen along, and the two other rotations within +-tilt of the base orientation.
//
// The base orientation is JointTrack's "as the camera sees it": the model's x along the film's
// columns, its z towards the source, its y completing a right-handed frame (up the film for the
// usual detector whose rows run down). Implant models are drawn in that frame (a lateral knee
// view sees the .jts poses within a few degrees of it); a user with another convention widens
// the tilt. Rotations are relative to the ray through the pivot, so an object seen off the
// optical axis has the same search space as one on it.
#include <functional>
#include <string>

namespace fm {

struct FindSpace {
    double tiltDeg = 35.0;   // about the film's u and v axes, +- this
    double rollDeg = 180.0;  // about the ray, +- this (180: any)
    // The pivot's depth along the optical axis, as fractions of the source-to-detector distance.
    // The issue asks for the middle half at least; fluoroscopy puts the joint near the image
    // intensifier (the JTML knee at 0.86), so the default reaches further.
    double nearFraction = 0.25;
    double farFraction = 0.92;
    // Or in mm from the source (both > 0): a pinhole calibration (MayaCam) has no physical film,
    // its detector plane is a virtual one 10 m away (camera/PinholeCamera.h), and a biplane
    // trial knows better: where its cameras' views cross (track/FoundKeyframe.h).
    double nearMm = 0.0;
    double farMm = 0.0;

    // The band in mm for a camera whose film lies `distance` mm from its source.
    double nearDepth(double distance) const { return nearMm > 0.0 ? nearMm : nearFraction * distance; }
    double farDepth(double distance) const { return farMm > 0.0 ? farMm : farFraction * distance; }
};

// Calls `each(key, value)` for every comma-separated key=value of `text` in order. Throws fm::Error
// naming `option` (and `keysHelp`, what the keys are) for a part without '='.
void forEachKeyValue(const std::string& text, const std::string& option, const std::string& keysHelp,
                     const std::function<void(const std::string& key, const std::string& value)>& each);

// "tilt=35,roll=180,depth=0.25:0.92" (any subset, any order) over `base`; depth in mm as
// "depth=600mm:1400mm". Throws fm::Error naming `option` and the key for an unknown key, a value
// that is not a number or out of range (tilt 0-90, roll 0-180, 0 < near < far < 1, or
// 0 < near mm < far mm).
FindSpace parseFindSpace(const std::string& text, const std::string& option = "--find-space",
                         const FindSpace& base = {});

// "tilt +-35 deg, roll +-180 deg, depth 0.25-0.92 of the source-to-detector distance" (or
// "depth 600-1400 mm from the source")
std::string describeFindSpace(const FindSpace& space);

}  // namespace fm
