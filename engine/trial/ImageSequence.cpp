#include "trial/ImageSequence.h"

#include <algorithm>
#include <cctype>
#include <system_error>

#include "core/Error.h"
#include "io/ByteSource.h"
#include "io/TiffReader.h"

namespace fm {

namespace fs = std::filesystem;

std::string ImageSequence::frameName(int frame) const {
    if (frame < 0 || frame >= frameCount())
        throw Error(io::quoted(source) + ": frame " + std::to_string(frame) + " does not exist (" +
                    std::to_string(frameCount()) + " frames)");
    if (multiPage) return source.filename().string() + " page " + std::to_string(frame);
    return frames[static_cast<std::size_t>(frame)].filename().string();
}

ImageSequence listImageFolder(const fs::path& folder) {
    std::error_code ec;
    if (!fs::is_directory(folder, ec))
        throw Error("image folder " + io::quoted(folder) + " does not exist or is not a folder");
    ImageSequence seq;
    seq.source = folder;
    for (const auto& entry : fs::directory_iterator(folder, ec)) {
        if (io::hasTiffExtension(entry.path()) && entry.is_regular_file(ec))
            seq.frames.push_back(entry.path());
    }
    if (ec) throw Error("cannot list image folder " + io::quoted(folder) + ": " + ec.message());
    if (seq.frames.empty()) throw Error("image folder " + io::quoted(folder) + " holds no TIFF file");
    std::sort(seq.frames.begin(), seq.frames.end(),
              [](const fs::path& a, const fs::path& b) {
                  return a.filename().string() < b.filename().string();
              });
    return seq;
}

int frameNumberInName(const fs::path& file) {
    const std::string stem = file.stem().string();
    int end = static_cast<int>(stem.size());
    while (end > 0 && !std::isdigit(static_cast<unsigned char>(stem[end - 1]))) --end;
    int begin = end;
    while (begin > 0 && std::isdigit(static_cast<unsigned char>(stem[begin - 1]))) --begin;
    if (begin == end || end - begin > 9) return -1;
    return std::stoi(stem.substr(begin, end - begin));
}

}  // namespace fm
