#include "io/OutputPath.h"

#include <unistd.h>

#include <system_error>

#include "core/Error.h"
#include "io/AtomicFile.h"
#include "io/ByteSource.h"

namespace fm::io {

void checkOutputPath(const std::filesystem::path& path, const std::string& option) {
    if (path.empty()) return;
    namespace fs = std::filesystem;
    std::error_code ec;
    const std::string what = option + " " + quoted(path);
    if (fs::is_directory(path, ec)) throw Error(what + ": is a folder, not a file name");
    if (fs::exists(path, ec) && writesThrough(path)) return;  // a pipe, /dev/null
    const fs::path folder = path.parent_path().empty() ? fs::path(".") : path.parent_path();
    if (!fs::exists(folder, ec))
        throw Error(what + ": the folder " + quoted(folder) + " does not exist");
    if (!fs::is_directory(folder, ec))
        throw Error(what + ": " + quoted(folder) + " is not a folder");
    // The file is written beside itself first (AtomicFile): the folder must take new files.
    if (::access(folder.c_str(), W_OK | X_OK) != 0)
        throw Error(what + ": the folder " + quoted(folder) + " is not writable");
}

}  // namespace fm::io
