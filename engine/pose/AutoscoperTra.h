#pragma once
// Autoscoper tracking results (.tra), docs/real-xray.md "Files":
//   one text line per frame; per tracked object either 16 numbers, the row-major 4x4
//   [R t; 0 0 0 1] (mm), or 6 numbers x, y, z, yaw, pitch, roll (mm, degrees) with
//   R = Rz(yaw) Ry(pitch) Rx(roll); objects follow each other on the line; comma or white space
//   separated; NaN (all numbers of an object) for a frame that object was not tracked in.
// A pose is worldFromVolume: from Autoscoper's corner frame of the volume (pose/AutoscoperVolumeFrame.h)
// to the calibration's world (the MayaCam cube frame). Only mm, degrees and row order are read:
// Autoscoper's cm / radian / column-order exports are not recognisable from the numbers (a
// column-order matrix is refused by its last row).
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "scene/RigidTransform.h"

namespace fm {

enum class TraForm {
    Auto,     // deduce from the count of numbers per line (refused when 16k and 6k both fit)
    Matrix,   // 16 numbers per object
    Xyzypr,   // 6 numbers per object
};

struct TraFile {
    TraForm form = TraForm::Matrix;  // Matrix or Xyzypr after reading
    int objects = 1;
    // frames[frame][object]; nullopt = not tracked (NaN)
    std::vector<std::vector<std::optional<RigidTransform>>> frames;
};

// x, y, z, yaw, pitch, roll <-> transform (Autoscoper's CoordFrame::from_xyzypr / to_xyzypr).
RigidTransform transformFromXyzypr(const double xyzypr[6]);
void xyzyprFromTransform(const RigidTransform& t, double xyzypr[6]);

// fm::Error "<what>: line N, object K, value V: ..." for wrong counts, non-numbers, partial
// NaN, a matrix that is not rigid. `objects` (0: unknown) is how many objects the file is
// expected to hold: with TraForm::Auto it decides a count that both forms divide (48 numbers:
// 3 matrices, or 8 xyzypr rows); the file may still hold one object.
// `howToSay`: what the refusal of an undecided line suggests (the caller's option, e.g. "give
// --tra-form matrix or xyzypr"); empty: the general advice.
TraFile parseTra(const std::string& text, const std::string& what, TraForm form = TraForm::Auto,
                 int objects = 0, const std::string& howToSay = {});
TraFile readTra(const std::filesystem::path& path, TraForm form = TraForm::Auto, int objects = 0,
                const std::string& howToSay = {});
// "matrix" or "xyzypr" (an option's value); fm::Error naming `option` otherwise.
TraForm parseTraForm(const std::string& text, const std::string& option);

// What Autoscoper reads back (its own backup format): per object 16 comma-separated numbers in
// row order (or 6 for Xyzypr), fixed-point with 16 decimals, "NaN" x 16 for untracked frames.
std::string traText(const TraFile& tra);
void writeTra(const std::filesystem::path& path, const TraFile& tra);

// `pose` as a .tra file holds it (the 16 fixed-point decimals of traText, read back): a run that
// starts later frames from this computes the same numbers as one resumed from the file.
RigidTransform asWrittenInTra(const RigidTransform& pose);

}  // namespace fm
