#include "io/AtomicFile.h"

#include <atomic>
#include <fstream>
#include <string>
#include <system_error>

#include <unistd.h>

#include "core/Error.h"
#include "io/ByteSource.h"

namespace fm::io {

namespace fs = std::filesystem;

namespace {

fs::path temporaryBeside(const fs::path& path) {
    static std::atomic<unsigned> counter{0};
    std::string name(1, '.');  // piecewise: GCC 12 warns falsely on "." + string
    name += path.filename().string();
    name += ".partial-" + std::to_string(::getpid()) + "-" + std::to_string(counter++);
    return path.parent_path() / name;
}

}  // namespace

void writeViaTemporary(const fs::path& path, const std::function<bool(const fs::path&)>& writeTo) {
    if (path.filename().empty()) throw Error("cannot write " + quoted(path) + ": not a file name");
    const fs::path parent = path.parent_path();
    std::error_code ec;
    if (!parent.empty() && !fs::is_directory(parent, ec))
        throw Error("cannot write " + quoted(path) + ": folder " + quoted(parent) +
                    " does not exist");
    if (fs::is_directory(path, ec))
        throw Error("cannot write " + quoted(path) + ": it is a folder");
    const fs::path temp = temporaryBeside(path);
    bool ok = false;
    try {
        ok = writeTo(temp);
    } catch (...) {
        fs::remove(temp, ec);
        throw;
    }
    if (!ok) {
        fs::remove(temp, ec);
        throw Error("cannot write " + quoted(path) + " (disk full or no permission?)");
    }
    fs::rename(temp, path, ec);
    if (ec) {
        std::error_code ignore;
        fs::remove(temp, ignore);
        throw Error("cannot write " + quoted(path) + ": " + ec.message());
    }
}

void writeFileAtomically(const fs::path& path, const std::vector<std::uint8_t>& bytes) {
    writeViaTemporary(path, [&](const fs::path& temp) {
        std::ofstream out(temp, std::ios::binary | std::ios::trunc);
        if (!out) return false;
        out.write(reinterpret_cast<const char*>(bytes.data()),
                  static_cast<std::streamsize>(bytes.size()));
        out.flush();
        return static_cast<bool>(out);
    });
}

}  // namespace fm::io
