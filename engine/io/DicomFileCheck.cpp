#include "io/DicomFileCheck.h"

#include <gdcmDicts.h>
#include <gdcmGlobal.h>
#include <gdcmTag.h>
#include <gdcmVR.h>

#include <cstdint>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <iterator>
#include <sstream>
#include <vector>

namespace fm {
namespace {

constexpr std::uint32_t kUndefinedLength = 0xffffffffu;
constexpr int kMaxNesting = 16;  // real files nest sequences a few levels deep

struct Encoding {
    bool explicitVr = true;
    bool bigEndian = false;
};

bool isLongFormVr(const char vr[2]) {
    static const char* const kLong[] = {"OB", "OD", "OF", "OL", "OV", "OW", "SQ",
                                        "SV", "UC", "UN", "UR", "UT", "UV"};
    for (const char* v : kLong)
        if (vr[0] == v[0] && vr[1] == v[1]) return true;
    return false;
}

bool isKnownVr(const char vr[2]) {
    static const char* const kAll[] = {"AE", "AS", "AT", "CS", "DA", "DS", "DT", "FL", "FD",
                                       "IS", "LO", "LT", "OB", "OD", "OF", "OL", "OV", "OW",
                                       "PN", "SH", "SL", "SQ", "SS", "ST", "SV", "TM", "UC",
                                       "UI", "UL", "UN", "UR", "US", "UT", "UV"};
    for (const char* v : kAll)
        if (vr[0] == v[0] && vr[1] == v[1]) return true;
    return false;
}

// GDCM reads the image-related modules through gdcm::Attribute, which asserts that the stored
// VR is compatible with the dictionary's. Such files are refused here instead. Only the groups
// GDCM interprets for images are checked: elsewhere a wrong VR is harmless and common.
bool vrIsCheckedFor(std::uint16_t group) {
    return group == 0x0002 || group == 0x0008 || group == 0x0018 || group == 0x0020 ||
           group == 0x0028;
}

// Empty when fine, else the reason.
std::string vrProblem(std::uint16_t group, std::uint16_t element, const char vr[2],
                      std::uint32_t length) {
    if (!vrIsCheckedFor(group)) return {};
    const char text[3] = {vr[0], vr[1], 0};
    const gdcm::VR stored(gdcm::VR::GetVRType(text));
    const gdcm::VR expected =
        gdcm::Global::GetInstance().GetDicts().GetDictEntry(gdcm::Tag(group, element)).GetVR();
    char tag[16];
    std::snprintf(tag, sizeof tag, "(%04X,%04X)", group, element);
    if (expected != gdcm::VR::INVALID && !expected.Compatible(stored))
        return std::string("element ") + tag + " has VR " + text + ", the dictionary says " +
               gdcm::VR::GetVRString(expected);
    // Binary numbers must come whole.
    unsigned size = 0;
    if (stored == gdcm::VR::US || stored == gdcm::VR::SS) size = 2;
    if (stored == gdcm::VR::UL || stored == gdcm::VR::SL || stored == gdcm::VR::FL ||
        stored == gdcm::VR::AT)
        size = 4;
    if (stored == gdcm::VR::FD) size = 8;
    if (size && length % size != 0)
        return std::string("element ") + tag + " has a length of " + std::to_string(length) +
               ", not a multiple of its " + std::to_string(size) + "-byte values";
    return {};
}

class Walker {
  public:
    Walker(const unsigned char* data, std::size_t size) : data_(data), size_(size) {}

    std::string problem;
    std::string transferSyntax;
    // Filled by the top-level walk (see DicomFileCheck).
    bool hasPixelData = false, encapsulated = false;
    std::size_t pixelDataLength = 0, firstFragmentOffset = 0, firstFragmentLength = 0;
    std::size_t pixelDataEnd = 0;  // byte after the top-level pixel data element

    std::uint16_t u16(std::size_t at, bool bigEndian) const {
        return bigEndian ? std::uint16_t((data_[at] << 8) | data_[at + 1])
                         : std::uint16_t(data_[at] | (data_[at + 1] << 8));
    }
    std::uint32_t u32(std::size_t at, bool bigEndian) const {
        const std::uint32_t b0 = data_[at], b1 = data_[at + 1], b2 = data_[at + 2],
                            b3 = data_[at + 3];
        return bigEndian ? (b0 << 24) | (b1 << 16) | (b2 << 8) | b3
                         : b0 | (b1 << 8) | (b2 << 16) | (b3 << 24);
    }

    bool fail(std::size_t at, const std::string& why) {
        std::ostringstream out;
        out << why << " at byte " << at;
        problem = out.str();
        return false;
    }

    // File meta group (always explicit VR little endian); records the transfer syntax.
    bool metaGroup(std::size_t& pos) {
        while (pos + 8 <= size_ && u16(pos, false) == 0x0002) {
            const std::uint16_t element = u16(pos + 2, false);
            const char vr[2] = {char(data_[pos + 4]), char(data_[pos + 5])};
            if (!isKnownVr(vr)) return fail(pos, "invalid VR in the file meta group");
            std::size_t header = 8;
            std::uint32_t length = u16(pos + 6, false);
            if (isLongFormVr(vr)) {
                if (pos + 12 > size_) return fail(pos, "file meta element cut off");
                header = 12;
                length = u32(pos + 8, false);
            }
            if (length == kUndefinedLength || pos + header + length > size_)
                return fail(pos, "file meta element longer than the file");
            if (const std::string why = vrProblem(0x0002, element, vr, length); !why.empty())
                return fail(pos, why);
            if (element == 0x0010) {
                std::string ts(reinterpret_cast<const char*>(data_ + pos + header), length);
                while (!ts.empty() && (ts.back() == '\0' || ts.back() == ' ')) ts.pop_back();
                transferSyntax = ts;
            }
            pos += header + length;
        }
        return true;
    }

    // Elements from pos up to end; with `toDelimiter` until an item delimiter instead.
    bool dataSet(std::size_t& pos, std::size_t end, Encoding enc, bool toDelimiter, int depth) {
        if (depth > kMaxNesting) return fail(pos, "sequences nested too deeply");
        while (pos < end) {
            if (pos + 8 > end) return fail(pos, "element header cut off");
            const std::uint16_t group = u16(pos, enc.bigEndian);
            const std::uint16_t element = u16(pos + 2, enc.bigEndian);
            if (group == 0xfffe) {
                if (element == 0xe00d && toDelimiter) {
                    pos += 8;
                    return true;
                }
                return fail(pos, "misplaced item or delimiter tag");
            }
            std::size_t header = 8;
            std::uint32_t length = 0;
            char vr[2] = {0, 0};
            if (enc.explicitVr) {
                vr[0] = char(data_[pos + 4]);
                vr[1] = char(data_[pos + 5]);
                if (!isKnownVr(vr)) return fail(pos, "invalid value representation");
                if (isLongFormVr(vr)) {
                    if (pos + 12 > end) return fail(pos, "element header cut off");
                    header = 12;
                    length = u32(pos + 8, enc.bigEndian);
                } else {
                    length = u16(pos + 6, enc.bigEndian);
                }
                if (length != kUndefinedLength)
                    if (const std::string why = vrProblem(group, element, vr, length); !why.empty())
                        return fail(pos, why);
            } else {
                length = u32(pos + 4, enc.bigEndian);
            }
            const std::size_t start = pos;
            pos += header;
            const bool isPixelData = group == 0x7fe0 && element == 0x0010;
            const bool isSq = enc.explicitVr && vr[0] == 'S' && vr[1] == 'Q';
            const bool isUn = enc.explicitVr && vr[0] == 'U' && vr[1] == 'N';
            if (length == kUndefinedLength) {
                if (isPixelData && depth == 0) {
                    if (!fragments(pos, end, enc)) return false;
                    hasPixelData = encapsulated = true;
                    pixelDataEnd = pos;
                    continue;
                }
                if (enc.explicitVr && !isSq && !isUn)
                    return fail(start, "undefined length on a non-sequence element");
                // CP-246: an undefined-length UN holds an implicit VR little endian sequence.
                const Encoding inner = isUn ? Encoding{false, false} : enc;
                if (!sequence(pos, end, inner, true, depth + 1)) return false;
                continue;
            }
            if (length > end - pos) {
                char tag[16];
                std::snprintf(tag, sizeof tag, "(%04X,%04X)", group, element);
                return fail(start, std::string("element ") + tag +
                                       " runs past the end of its container (truncated)");
            }
            const bool looksLikeItems = !enc.explicitVr && length >= 8 &&
                                        u16(pos, enc.bigEndian) == 0xfffe &&
                                        u16(pos + 2, enc.bigEndian) == 0xe000;
            if (isSq || looksLikeItems) {
                std::size_t inner = pos;
                if (!sequence(inner, pos + length, enc, false, depth + 1)) return false;
            }
            pos += length;
            if (isPixelData && depth == 0) {
                hasPixelData = true;
                pixelDataLength = length;
                pixelDataEnd = pos;
            }
        }
        if (toDelimiter) return fail(pos, "item delimiter missing");
        return true;
    }

    // Items of a sequence: up to `end` (defined length) or up to the sequence delimiter.
    bool sequence(std::size_t& pos, std::size_t end, Encoding enc, bool undefined, int depth) {
        while (pos < end || undefined) {
            if (pos + 8 > end) return fail(pos, "sequence item cut off");
            const std::uint16_t group = u16(pos, enc.bigEndian);
            const std::uint16_t element = u16(pos + 2, enc.bigEndian);
            const std::uint32_t length = u32(pos + 4, enc.bigEndian);
            if (group == 0xfffe && element == 0xe0dd && undefined) {
                pos += 8;
                return true;
            }
            if (group != 0xfffe || element != 0xe000) return fail(pos, "expected a sequence item");
            pos += 8;
            if (length == kUndefinedLength) {
                if (!dataSet(pos, end, enc, true, depth)) return false;
            } else {
                if (length > end - pos) return fail(pos, "sequence item runs past the end");
                std::size_t inner = pos;
                if (!dataSet(inner, pos + length, enc, false, depth)) return false;
                pos += length;
            }
        }
        return true;
    }

    // Encapsulated pixel data: an offset table item, then fragments, then the delimiter.
    bool fragments(std::size_t& pos, std::size_t end, Encoding enc) {
        int items = 0;
        for (;;) {
            if (pos + 8 > end) return fail(pos, "compressed pixel data cut off");
            const std::uint16_t group = u16(pos, enc.bigEndian);
            const std::uint16_t element = u16(pos + 2, enc.bigEndian);
            const std::uint32_t length = u32(pos + 4, enc.bigEndian);
            pos += 8;
            if (group == 0xfffe && element == 0xe0dd) {
                if (items < 2) return fail(pos, "compressed pixel data without fragments");
                return true;
            }
            if (group != 0xfffe || element != 0xe000 || length == kUndefinedLength)
                return fail(pos - 8, "expected a pixel data fragment");
            if (length > end - pos) return fail(pos - 8, "pixel data fragment runs past the end");
            if (items == 1) {  // item 0 is the basic offset table
                firstFragmentOffset = pos;
                firstFragmentLength = length;
            }
            pos += length;
            ++items;
        }
    }

  private:
    const unsigned char* data_;
    std::size_t size_;
};

}  // namespace

DicomFileCheck checkDicomBytes(const unsigned char* data, std::size_t size) {
    DicomFileCheck check;
    Walker walker(data, size);
    check.hasMagic = size >= 132 && std::memcmp(data + 128, "DICM", 4) == 0;
    std::size_t pos = check.hasMagic ? 132 : 0;
    if (!walker.metaGroup(pos)) {
        check.problem = walker.problem;
        return check;
    }
    check.transferSyntax = walker.transferSyntax;
    Encoding enc;
    const std::string& ts = check.transferSyntax;
    if (ts.empty()) {
        // No meta group: GDCM guesses; accept only what looks like a plain data set.
        if (pos + 6 > size) {
            check.problem = "too short for a DICOM data set";
            return check;
        }
        const char vr[2] = {char(data[pos + 4]), char(data[pos + 5])};
        enc.explicitVr = isKnownVr(vr);
    } else if (ts == "1.2.840.10008.1.2") {
        enc.explicitVr = false;
    } else if (ts == "1.2.840.10008.1.2.2") {
        enc.bigEndian = true;
    } else if (ts == "1.2.840.10008.1.2.1.99") {
        check.problem = "deflated transfer syntax is not supported";
        return check;
    }
    if (pos >= size) {
        check.problem = "no data set after the file meta group";
        return check;
    }
    bool ok = walker.dataSet(pos, size, enc, false, 0);
    if (!ok && walker.hasPixelData) {
        // Bytes after the pixel data that are not elements (zero padding, scanner leftovers):
        // legal in practice. The content ends with the pixel data; the rest is ignored.
        check.contentBytes = walker.pixelDataEnd;
        check.trailingBytes = size - walker.pixelDataEnd;
        ok = true;
    } else {
        check.contentBytes = size;
    }
    if (!ok) {
        check.problem = walker.problem;
        return check;
    }
    check.hasPixelData = walker.hasPixelData;
    check.encapsulated = walker.encapsulated;
    check.pixelDataLength = walker.pixelDataLength;
    check.firstFragmentOffset = walker.firstFragmentOffset;
    check.firstFragmentLength = walker.firstFragmentLength;
    check.wellFormed = true;
    return check;
}

DicomFileCheck checkDicomFile(const std::filesystem::path& file,
                              std::vector<unsigned char>* content) {
    std::ifstream in(file, std::ios::binary);
    DicomFileCheck check;
    if (!in) {
        check.problem = "cannot open the file";
        return check;
    }
    // Without the DICM magic, only a data set starting with group 0002 or 0008 (as raw DICOM
    // files do) is worth reading whole: a large non-DICOM file in the folder is not loaded.
    unsigned char head[132] = {};
    in.read(reinterpret_cast<char*>(head), sizeof head);
    const std::size_t got = static_cast<std::size_t>(in.gcount());
    const bool magic = got == sizeof head && std::memcmp(head + 128, "DICM", 4) == 0;
    const unsigned group = got >= 2 ? unsigned(head[0] | (head[1] << 8)) : 0u;
    if (!magic && group != 0x0002 && group != 0x0008) {
        check.problem = "not a DICOM file";
        return check;
    }
    in.clear();
    in.seekg(0);
    std::vector<unsigned char> bytes((std::istreambuf_iterator<char>(in)),
                                     std::istreambuf_iterator<char>());
    DicomFileCheck result = checkDicomBytes(bytes.data(), bytes.size());
    if (content) *content = std::move(bytes);
    return result;
}

}  // namespace fm
