#pragma once
// Reads one DICOM slice (header, then pixels) in a forked child and reports the outcome and how
// much the child's peak resident memory grew. A library allocates (and zero-fills) a value at
// the length its header claims before reading it, so a corrupt length shows up as growth even
// when the read then fails; the child keeps that, and a crash, out of the test process.
// Where growth is not measured (memoryGrowthIsMeaningful: the sanitizer builds) the read runs in
// the test process instead, with the same outcome, and peakGrowthKb stays 0.
#include <cstdint>
#include <filesystem>
#include <string>

namespace fm::test {

struct ForkedRead {
    enum class Outcome { Loaded, NotAnImage, Refused, OtherException, Crashed };
    Outcome outcome = Outcome::Crashed;
    std::string message;  // fm::Error's or the exception's text, or how the child ended
    int rows = 0, columns = 0;
    std::uint64_t pixelHash = 0;  // FNV-1a over the decoded floats' bits
    long peakGrowthKb = 0;        // child's peak RSS minus its RSS when it started reading
};

ForkedRead readSliceInChild(const std::filesystem::path& file);

// Peak RSS is not a measure of the reader under the sanitizers (shadow memory, quarantine).
bool memoryGrowthIsMeaningful();

}  // namespace fm::test
