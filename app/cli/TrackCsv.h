#pragma once
// `track --csv`: one row per tracked frame (status, cost per camera, evaluations, time). The
// CSV is resumed as the .tra is: --resume keeps the rows of the frames it keeps.
#include <filesystem>
#include <map>
#include <set>
#include <string>

#include "track/SegmentTracking.h"

namespace fm::cli {

std::string trackCsvHeader(std::size_t cameras);  // ends in '\n'
std::string trackCsvRow(const FrameRecord& r, const std::string& bone);  // ends in '\n'

// --resume: the rows of `csv` (written by an earlier run with the same cameras) for `bone`
// whose frame is in `kept`, by frame, each ending in '\n'. A missing file gives none; a file
// with another header or a malformed row is refused (fm::Error naming the file and line), so a
// CSV of another trial is never merged into this one.
std::map<int, std::string> keptTrackCsvRows(const std::filesystem::path& csv, std::size_t cameras,
                                            const std::string& bone, const std::set<int>& kept);

// What a kept row tells the frames after it (Tracker::run's `kept`): its frame, status, cost per
// camera (an empty field: NaN) and verdict. fm::Error naming `where` (the file) and the frame
// for a field that does not parse.
FrameRecord keptFrameRecord(const std::string& row, std::size_t cameras, const std::string& where);

}  // namespace fm::cli
