#pragma once
// A tracked frame's record (track/Tracker.h FrameRecord) as a fixed number of bytes, for the
// fixed-size records a distributed run gathers to rank 0 (distributed/JobRunner.h). The size
// depends only on the trial's camera count; doubles are copied bit for bit, so a pose decoded
// on rank 0 is the one the tracking rank found. The note, the verdict's text and the find's line
// are cut to kFrameNoteBytes - 1, kFrameVerdictBytes - 1 and kFrameFoundBytes - 1 bytes (the
// uncertainty's Hessian is not sent).
#include <cstddef>
#include <span>

#include "track/Tracker.h"

namespace fm {

inline constexpr std::size_t kFrameNoteBytes = 200;
inline constexpr std::size_t kFrameVerdictBytes = 300;  // the verdict's text, cut likewise
inline constexpr std::size_t kFrameFoundBytes = 300;    // the find's verdict line (OnLost::Find)

std::size_t frameRecordBytes(std::size_t cameras);

// `out` must hold frameRecordBytes(record.viewCost.size()) bytes.
void encodeFrameRecord(const FrameRecord& record, std::span<std::byte> out);

// The record of `cameras` cameras in `in`; fm::Error for bytes no encoder wrote (a status or
// note length out of range, a size that does not match).
FrameRecord decodeFrameRecord(std::span<const std::byte> in, std::size_t cameras);

}  // namespace fm
