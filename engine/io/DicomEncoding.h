#pragma once
// How GDCM's reader (gdcm::Reader, 3.0) decides the encoding of a file's data set. The
// structural check (DicomFileCheck.h) must walk the data set in exactly that encoding: a file
// checked in one encoding and parsed by GDCM in another passes the check while GDCM reads
// lengths from the wrong bytes. (A real 526 KB CT slice whose first meta tag (0002,0000) had one
// corrupt byte, (9002,0000), was checked as explicit VR little endian; GDCM, seeing no file
// meta group, guessed big endian from that tag, read a length of 909 MB out of a UID's text and
// allocated it.)
#include <cstddef>
#include <cstdint>
#include <string>

namespace fm {

struct DicomEncoding {
    bool explicitVr = true;
    bool bigEndian = false;
};

// "(0028,0010)": how a tag is named in every message.
std::string tagText(std::uint16_t group, std::uint16_t element);

// "explicit VR little endian", ...
std::string describe(DicomEncoding encoding);

struct DicomEncodingChoice {
    DicomEncoding encoding;
    std::string problem;  // non-empty when GDCM cannot read the data set (or we refuse to)
};

// The transfer syntax UID as GDCM reads it from (0002,0010): the value up to its first NUL,
// trailing spaces dropped (gdcm::FileMetaInformation::ComputeDataSetTransferSyntax).
std::string gdcmTransferSyntaxUid(const char* value, std::size_t length);

// The data set's encoding for transfer syntax `uid` (as gdcmTransferSyntaxUid returns it), by
// GDCM's own table. Unknown UIDs, deflate and implicit big endian are problems.
DicomEncodingChoice encodingOfTransferSyntax(const std::string& uid);

// GDCM's guess for a data set without a file meta group (gdcm::FileMetaInformation::
// ReadCompat), from its first tag and the two bytes after it (at least 6 of `size` bytes at
// `first`). A first tag in group 0002 is a meta group, not a guess: the caller reads it.
// Paths that GDCM itself fails on or asserts in are problems.
DicomEncodingChoice guessedEncoding(const unsigned char* first, std::size_t size);

// Whether two bytes spell one of the value representations GDCM knows (gdcm::VR::IsValid).
bool isKnownVr(const char vr[2]);

}  // namespace fm
