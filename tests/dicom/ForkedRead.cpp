#include "dicom/ForkedRead.h"

#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>
#include <csignal>
#include <cstdlib>
#include <cstring>
#include <exception>
#include <vector>

#include "core/Error.h"
#include "io/DicomSlice.h"

namespace fm::test {
namespace {

// The child's report, sent through a pipe: fixed fields, then the message bytes.
struct Report {
    int outcome = 0;
    int rows = 0, columns = 0;
    std::uint64_t pixelHash = 0;
    long baselineKb = 0;
    std::size_t messageLength = 0;
};

void writeAll(int fd, const void* data, std::size_t size) {
    const char* p = static_cast<const char*>(data);
    while (size > 0) {
        const ssize_t n = ::write(fd, p, size);
        if (n < 0 && errno == EINTR) continue;
        if (n <= 0) return;
        p += n;
        size -= std::size_t(n);
    }
}

std::uint64_t hashOf(const std::vector<float>& values) {
    std::uint64_t hash = 14695981039346656037ull;
    for (float v : values) {
        std::uint32_t bits;
        std::memcpy(&bits, &v, sizeof bits);
        for (int b = 0; b < 4; ++b) hash = (hash ^ ((bits >> (8 * b)) & 0xffu)) * 1099511628211ull;
    }
    return hash;
}

// The read itself: its outcome, size and pixel hash in `report`, the exception's text in `message`.
void readSlice(const std::filesystem::path& file, Report& report, std::string& message) {
    try {
        const auto header = readDicomSliceHeader(file);
        if (!header) {
            report.outcome = int(ForkedRead::Outcome::NotAnImage);
        } else {
            const std::vector<float> pixels = readDicomSlicePixels(*header, -1.0e30f);
            report.outcome = int(ForkedRead::Outcome::Loaded);
            report.rows = header->rows;
            report.columns = header->columns;
            report.pixelHash = hashOf(pixels);
        }
    } catch (const Error& e) {
        report.outcome = int(ForkedRead::Outcome::Refused);
        message = e.what();
    } catch (const std::exception& e) {
        report.outcome = int(ForkedRead::Outcome::OtherException);
        message = e.what();
    } catch (...) {
        report.outcome = int(ForkedRead::Outcome::OtherException);
        message = "a non-standard exception";
    }
}

[[noreturn]] void childRead(const std::filesystem::path& file, int fd) {
    rusage usage{};
    getrusage(RUSAGE_SELF, &usage);
    Report report;
    report.baselineKb = usage.ru_maxrss;
    std::string message;
    readSlice(file, report, message);
    report.messageLength = message.size();
    writeAll(fd, &report, sizeof report);
    writeAll(fd, message.data(), message.size());
    ::close(fd);
    _exit(0);  // no atexit handlers, no gtest teardown, no leak check in the child
}

}  // namespace

ForkedRead readSliceInChild(const std::filesystem::path& file) {
    ForkedRead result;
    if (!memoryGrowthIsMeaningful()) {
        // Under the sanitizers there is no growth to measure, and a fork copies the page tables
        // of their shadow memory (the JPEG 2000 sweep 14.0 -> 8.4 s under ASan);
        // a crash aborts the test process either way (abort_on_error), which fails the test.
        Report report;
        readSlice(file, report, result.message);
        result.outcome = static_cast<ForkedRead::Outcome>(report.outcome);
        result.rows = report.rows;
        result.columns = report.columns;
        result.pixelHash = report.pixelHash;
        return result;
    }
    int fds[2];
    if (::pipe(fds) != 0) {
        result.message = "pipe failed";
        return result;
    }
    const pid_t pid = ::fork();
    if (pid < 0) {
        result.message = "fork failed";
        ::close(fds[0]);
        ::close(fds[1]);
        return result;
    }
    if (pid == 0) {
        ::close(fds[0]);
        childRead(file, fds[1]);
    }
    ::close(fds[1]);
    std::string received;  // read to the end before waiting: a full pipe would block the child
    char buffer[4096];
    for (;;) {
        const ssize_t n = ::read(fds[0], buffer, sizeof buffer);
        if (n < 0 && errno == EINTR) continue;
        if (n <= 0) break;
        received.append(buffer, std::size_t(n));
    }
    ::close(fds[0]);
    int status = 0;
    rusage usage{};
    while (::wait4(pid, &status, 0, &usage) < 0 && errno == EINTR) {
    }
    Report report;
    if (!WIFEXITED(status) || WEXITSTATUS(status) != 0 || received.size() < sizeof report) {
        result.outcome = ForkedRead::Outcome::Crashed;
        result.message =
            WIFSIGNALED(status)
                ? "child killed by signal " + std::to_string(WTERMSIG(status)) + " (" +
                      strsignal(WTERMSIG(status)) + ")"
                : "child ended without a report (status " + std::to_string(status) + ")";
        result.peakGrowthKb = usage.ru_maxrss;
        return result;
    }
    std::memcpy(&report, received.data(), sizeof report);
    result.outcome = static_cast<ForkedRead::Outcome>(report.outcome);
    result.message = received.substr(sizeof report, report.messageLength);
    result.rows = report.rows;
    result.columns = report.columns;
    result.pixelHash = report.pixelHash;
    result.peakGrowthKb = usage.ru_maxrss - report.baselineKb;
    return result;
}

bool memoryGrowthIsMeaningful() {
#if defined(__SANITIZE_ADDRESS__)
    return false;
#else
    return std::getenv("FM_SANITIZE_BUILD") == nullptr;
#endif
}

}  // namespace fm::test
