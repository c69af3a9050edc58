#pragma once
// One camera's frames: a folder of TIFF files sorted by name (as Autoscoper's Video does), or a
// single multi-page TIFF (one page per frame). This lists and names the frames; reading a
// frame's pixels is the TIFF reader's job.
#include <filesystem>
#include <string>
#include <vector>

namespace fm {

struct ImageSequence {
    std::filesystem::path source;               // the folder or the multi-page file
    bool multiPage = false;                     // one file, frames are its pages
    std::vector<std::filesystem::path> frames;  // folder: one file per frame, sorted by name
    int pageCount = 0;                          // multi-page: pages (set by the caller)

    int frameCount() const { return multiPage ? pageCount : static_cast<int>(frames.size()); }
    // "file.0099.tif" or "stack.tif page 99"; throws fm::Error for a frame out of range.
    std::string frameName(int frame) const;
};

// Lists the .tif/.tiff files (case-insensitive) of `folder`, sorted by name (byte order, as
// Autoscoper sorts). Throws fm::Error naming the folder if it is missing or holds no TIFF.
ImageSequence listImageFolder(const std::filesystem::path& folder);

// The frame number in a name like "xr_rad_uln_cam01_UND.0099.tif" (the last run of digits
// before the extension), or -1 when there is none. Lets a trial check that two cameras'
// frames are simultaneous (same numbers) and report a gap in a sequence.
int frameNumberInName(const std::filesystem::path& file);

}  // namespace fm
