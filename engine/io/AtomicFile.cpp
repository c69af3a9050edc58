#include "io/AtomicFile.h"

#include <atomic>
#include <cerrno>
#include <chrono>
#include <cstdlib>
#include <cstring>
#include <mutex>
#include <random>
#include <string>
#include <system_error>

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include "core/Error.h"
#include "io/ByteSource.h"

namespace fm::io {

namespace fs = std::filesystem;

namespace {

// --- the test hook: bytes left before writes fail as on a full disk ---
std::mutex limitMutex;
std::optional<std::uintmax_t> writeBudget;
bool limitFromEnvironmentRead = false;

// How many of `wanted` bytes may be written now (0: fail with ENOSPC).
std::size_t allowedBytes(std::size_t wanted) {
    std::lock_guard lock(limitMutex);
    if (!limitFromEnvironmentRead) {
        limitFromEnvironmentRead = true;
        if (const char* env = std::getenv("FM_TEST_WRITE_LIMIT"); env && *env)
            writeBudget = std::strtoull(env, nullptr, 10);
    }
    if (!writeBudget) return wanted;
    const std::size_t allowed =
        static_cast<std::size_t>(std::min<std::uintmax_t>(*writeBudget, wanted));
    *writeBudget -= allowed;
    return allowed;
}

[[noreturn]] void fail(const fs::path& target, const std::string& step, int error) {
    throw Error("cannot write " + quoted(target) + ": " + step +
                " failed: " + std::strerror(error));
}

// An open file descriptor, closed (unchecked) if still open when an error unwinds.
struct Descriptor {
    int fd = -1;
    ~Descriptor() {
        if (fd >= 0) ::close(fd);
    }
    // The checked close: on NFS and some full disks a failed close is the only sign of loss.
    void close(const fs::path& target) {
        const int rc = ::close(fd);
        fd = -1;
        if (rc != 0 && errno != EINTR) fail(target, "closing", errno);
    }
};

void writeAll(int fd, const void* data, std::size_t size, const fs::path& target) {
    const auto* p = static_cast<const std::uint8_t*>(data);
    while (size > 0) {
        const std::size_t piece = allowedBytes(std::min<std::size_t>(size, 1u << 30));
        if (piece == 0) fail(target, "writing", ENOSPC);
        const ssize_t n = ::write(fd, p, piece);
        if (n < 0) {
            if (errno == EINTR) continue;
            fail(target, "writing", errno);
        }
        if (n == 0) fail(target, "writing", ENOSPC);
        p += n;
        size -= static_cast<std::size_t>(n);
    }
}

// A name no other writer (thread, process, earlier killed run) uses: hidden, pid, counter and
// random bits.
fs::path temporaryName(const fs::path& target) {
    static std::atomic<unsigned> counter{0};
    static const std::uint64_t salt = [] {
        std::random_device device;
        return (std::uint64_t(device()) << 32) ^ device() ^
               std::uint64_t(std::chrono::steady_clock::now().time_since_epoch().count());
    }();
    const std::uint64_t n = counter++;
    const std::uint64_t bits = (salt + n * 0x9E3779B97F4A7C15ull) * 0xBF58476D1CE4E5B9ull;
    char random[17];
    std::snprintf(random, sizeof random, "%016llx", static_cast<unsigned long long>(bits));
    std::string name(1, '.');  // piecewise: GCC 12 warns falsely on "." + string
    name += target.filename().string();
    name += ".tmp-" + std::to_string(::getpid()) + "-" + std::to_string(n) + "-" + random;
    return target.parent_path() / name;
}

// Creates the temporary exclusively (never opens another writer's file).
int createTemporary(const fs::path& target, fs::path& temp) {
    for (int attempt = 0; attempt < 16; ++attempt) {
        temp = temporaryName(target);
        const int fd = ::open(temp.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_CLOEXEC, 0666);
        if (fd >= 0) return fd;
        if (errno != EEXIST) fail(target, "creating a temporary file beside it", errno);
    }
    fail(target, "creating a temporary file beside it", EEXIST);
}

// Follows symbolic links (relative ones from their own folder) to the file to write.
fs::path resolveLinks(const fs::path& path) {
    fs::path p = path;
    for (int depth = 0; depth < 40; ++depth) {
        std::error_code ec;
        if (!fs::is_symlink(fs::symlink_status(p, ec))) return p;
        const fs::path link = fs::read_symlink(p, ec);
        if (ec) return p;
        p = link.is_absolute() ? link : p.parent_path() / link;
    }
    throw Error("cannot write " + quoted(path) + ": too many levels of symbolic links");
}

enum class TargetKind { Replace, WriteThrough };

struct Target {
    fs::path path;  // after links
    TargetKind kind = TargetKind::Replace;
    std::optional<mode_t> keepMode;  // permission bits of the file replaced
};

Target inspect(const fs::path& requested) {
    if (requested.filename().empty())
        throw Error("cannot write " + quoted(requested) + ": not a file name");
    Target t{resolveLinks(requested)};
    const fs::path parent = t.path.parent_path();
    std::error_code ec;
    if (!parent.empty() && !fs::is_directory(parent, ec))
        throw Error("cannot write " + quoted(requested) + ": folder " + quoted(parent) +
                    " does not exist");
    struct stat st {};
    if (::stat(t.path.c_str(), &st) != 0) {
        if (errno == ENOENT) return t;
        fail(requested, "inspecting the target", errno);
    }
    if (S_ISREG(st.st_mode)) {
        t.keepMode = st.st_mode & 07777;
        return t;
    }
    if (S_ISDIR(st.st_mode)) throw Error("cannot write " + quoted(requested) + ": it is a folder");
    if (S_ISFIFO(st.st_mode) || S_ISCHR(st.st_mode)) {
        t.kind = TargetKind::WriteThrough;
        return t;
    }
    throw Error("cannot write " + quoted(requested) +
                ": it is a special file (block device or socket), not a regular file");
}

// A pipe or device: written in place; a FIFO nobody reads is refused rather than waited on.
void writeThrough(const Target& t, const fs::path& requested, const void* data, std::size_t size) {
    Descriptor d;
    d.fd = ::open(t.path.c_str(), O_WRONLY | O_NONBLOCK | O_NOCTTY | O_CLOEXEC);
    if (d.fd < 0) {
        if (errno == ENXIO)
            throw Error("cannot write " + quoted(requested) + ": it is a FIFO with no reader");
        fail(requested, "opening", errno);
    }
    const int flags = ::fcntl(d.fd, F_GETFL);
    if (flags < 0 || ::fcntl(d.fd, F_SETFL, flags & ~O_NONBLOCK) != 0)
        fail(requested, "opening", errno);
    writeAll(d.fd, data, size, requested);
    d.close(requested);
}

// Makes the completed temporary the target: fsync, close, rename, fsync of the folder.
void commit(Descriptor& d, const fs::path& temp, const Target& t, const fs::path& requested) {
    if (t.keepMode && ::fchmod(d.fd, *t.keepMode) != 0) fail(requested, "setting the mode", errno);
    if (::fsync(d.fd) != 0) fail(requested, "flushing to disk (fsync)", errno);
    d.close(requested);
    if (::rename(temp.c_str(), t.path.c_str()) != 0) fail(requested, "renaming into place", errno);
    const fs::path folder = t.path.parent_path().empty() ? fs::path(".") : t.path.parent_path();
    Descriptor dir;
    dir.fd = ::open(folder.c_str(), O_RDONLY | O_DIRECTORY | O_CLOEXEC);
    // The new name is in place; a folder that cannot be fsynced (some file systems) is not an
    // error of this write.
    if (dir.fd >= 0) ::fsync(dir.fd);
}

// Runs `body` with the temporary; removes it on every failure.
template <typename Body>
void withTemporary(const Target& t, Body&& body) {
    fs::path temp;
    Descriptor d;
    d.fd = createTemporary(t.path, temp);
    try {
        body(d, temp);
    } catch (...) {
        ::unlink(temp.c_str());
        throw;
    }
}

}  // namespace

void setWriteLimitForTesting(std::optional<std::uintmax_t> bytes) {
    std::lock_guard lock(limitMutex);
    limitFromEnvironmentRead = true;
    writeBudget = bytes;
}

bool writesThrough(const fs::path& path) {
    struct stat st {};
    if (::stat(path.c_str(), &st) != 0) return false;
    return S_ISFIFO(st.st_mode) || S_ISCHR(st.st_mode);
}

void writeFileAtomically(const fs::path& path, const void* data, std::size_t size) {
    const Target t = inspect(path);
    if (t.kind == TargetKind::WriteThrough) return writeThrough(t, path, data, size);
    withTemporary(t, [&](Descriptor& d, const fs::path& temp) {
        writeAll(d.fd, data, size, path);
        commit(d, temp, t, path);
    });
}

void writeFileAtomically(const fs::path& path, const std::vector<std::uint8_t>& bytes) {
    writeFileAtomically(path, bytes.data(), bytes.size());
}

void writeFileAtomically(const fs::path& path, std::string_view bytes) {
    writeFileAtomically(path, bytes.data(), bytes.size());
}

void writeViaTemporary(const fs::path& path, const std::function<bool(const fs::path&)>& writeTo) {
    const Target t = inspect(path);
    if (t.kind == TargetKind::WriteThrough) {
        // Written to a temporary, then copied through in one checked write.
        const fs::path scratch = fs::temp_directory_path() / "fluoromatch";
        std::error_code ec;
        fs::create_directories(scratch, ec);
        Bytes content;
        withTemporary(Target{scratch / path.filename()}, [&](Descriptor& d, const fs::path& temp) {
            d.close(path);
            if (!writeTo(temp))
                throw Error("cannot write " + quoted(path) + " (disk full or no permission?)");
            content = readFilePrefix(temp, static_cast<std::size_t>(fileSize(temp)));
            ::unlink(temp.c_str());
        });
        return writeThrough(t, path, content.data(), content.size());
    }
    withTemporary(t, [&](Descriptor& d, const fs::path& temp) {
        if (!writeTo(temp))
            throw Error("cannot write " + quoted(path) + " (disk full or no permission?)");
        // The writer used its own handle; ours still refers to the same file for the fsync.
        commit(d, temp, t, path);
    });
}

}  // namespace fm::io
