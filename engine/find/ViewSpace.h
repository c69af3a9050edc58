#pragma once
// Where the 2011 scene's pose is looked for when nobody gives a start (issue 29): the source
// anywhere around the CT in azimuth, its elevation within +-elevation, the film turned within
// +-rotation, and the CT's centre within +-offset mm of the isocenter along each world axis.
// The defaults hold the app's hard reference draws (engine/match/ReferenceDraw.h: the clinical
// views' azimuths +-30 deg, elevations -45 to 30 deg, rotation +-30 deg, offsets +-40 mm).
#include <string>

namespace fm {

struct ViewSpace {
    double elevationDeg = 45.0;  // +- this (0-90)
    double rotationDeg = 30.0;   // +- this (0-90)
    double offsetMm = 40.0;      // +- this along x, y and z (> 0)
};

// "elevation=45,rotation=30,offset=40" (any subset, any order) over the defaults. Throws
// fm::Error naming `option` and the key for an unknown key, a value that is not a number or one
// out of range.
ViewSpace parseViewSpace(const std::string& text, const std::string& option = "--find-space");

// "azimuth any, elevation +-45 deg, rotation +-30 deg, offsets +-40 mm"
std::string describeViewSpace(const ViewSpace& space);

}  // namespace fm
