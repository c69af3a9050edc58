#pragma once
// Structural check of a DICOM file before GDCM parses it. Debian's GDCM is built with
// assertions enabled, and some corruptions (an element header cut off by the end of the file, a
// garbage VR) make its parser abort the whole process. This walk over the byte structure
// (preamble, meta group, every element length, sequences, items, encapsulated fragments)
// refuses such files first, so only well-formed files reach GDCM.
// GDCM allocates every value at the length its header claims before reading it, so the check
// is also what keeps a corrupt length from allocating gigabytes. It holds only if the walk
// sees the elements GDCM will parse: the data set is walked in the encoding GDCM chooses
// (DicomEncoding.h), GDCM's vendor workarounds that read other lengths than written are
// refused, and so is anything GDCM may later re-parse as a sequence unless it is a well-formed
// one. GDCM then parses the checked bytes from memory, not the file again.
#include <cstddef>
#include <filesystem>
#include <string>
#include <vector>

namespace fm {

struct DicomFileCheck {
    bool hasMagic = false;       // "DICM" at byte 128
    bool wellFormed = false;     // every element fits in its container, in GDCM's encoding
    std::string transferSyntax;  // (0002,0010) as GDCM reads it; empty without a meta group
    std::string problem;         // why it is not well formed (with a byte offset)

    // Where the top-level pixel data (7FE0,0010) is, as the walk found it (lengths checked
    // against the file): native data has `pixelDataLength` bytes; encapsulated data has its
    // first image fragment (after the offset table) at `firstFragmentOffset`, of
    // `firstFragmentLength` bytes. The readers check image sizes against these before GDCM
    // allocates anything.
    bool hasPixelData = false;
    bool encapsulated = false;
    std::size_t pixelDataLength = 0;
    std::size_t firstFragmentOffset = 0, firstFragmentLength = 0;

    // Bytes after the last element that do not form elements (zero padding after the pixel
    // data, as some scanners write): legal in practice, ignored. `contentBytes` is where the
    // well-formed content ends; only that prefix is handed to GDCM.
    std::size_t contentBytes = 0;
    std::size_t trailingBytes = 0;
};

// Reads `file` and checks its structure. Never throws for bad content (only reports). When
// `bytes` is given it receives the file's content (so the caller need not read it again).
DicomFileCheck checkDicomFile(const std::filesystem::path& file,
                              std::vector<unsigned char>* bytes = nullptr);

// The same on bytes in memory (for tests).
DicomFileCheck checkDicomBytes(const unsigned char* data, std::size_t size);

}  // namespace fm
