#pragma once
// Structural check of a DICOM file before GDCM parses it. Debian's GDCM is built with
// assertions enabled, and some corruptions (an element header cut off by the end of the file, a
// garbage VR) make its parser abort the whole process. This walk over the byte structure
// (preamble, meta group, every element length, sequences, items, encapsulated fragments)
// refuses such files first, so only well-formed files reach GDCM.
#include <cstddef>
#include <filesystem>
#include <string>

namespace fm {

struct DicomFileCheck {
    bool hasMagic = false;    // "DICM" at byte 128
    bool wellFormed = false;  // every element fits in its container, in the declared encoding
    std::string transferSyntax;
    std::string problem;  // why it is not well formed (with a byte offset)
};

// Reads `file` and checks its structure. Never throws for bad content (only reports).
DicomFileCheck checkDicomFile(const std::filesystem::path& file);

// The same on bytes in memory (for tests).
DicomFileCheck checkDicomBytes(const unsigned char* data, std::size_t size);

}  // namespace fm
