#include "io/DicomFileCheck.h"

#include <gdcmDicts.h>
#include <gdcmGlobal.h>
#include <gdcmTag.h>
#include <gdcmVR.h>

#include <algorithm>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <iterator>
#include <sstream>
#include <vector>

#include "io/DicomEncoding.h"

namespace fm {
namespace {

constexpr std::uint32_t kUndefinedLength = 0xffffffffu;
constexpr int kMaxNesting = 16;  // real files nest sequences a few levels deep

bool isLongFormVr(const char vr[2]) {
    static const char* const kLong[] = {"OB", "OD", "OF", "OL", "OV", "OW", "SQ",
                                        "SV", "UC", "UN", "UR", "UT", "UV"};
    for (const char* v : kLong)
        if (vr[0] == v[0] && vr[1] == v[1]) return true;
    return false;
}

bool isVr(const char vr[2], const char* name) {
    return vr[0] == name[0] && vr[1] == name[1];
}

bool dictionarySaysSequence(std::uint16_t group, std::uint16_t element) {
    return gdcm::Global::GetInstance().GetDicts().GetDictEntry(gdcm::Tag(group, element)).GetVR() ==
           gdcm::VR::SQ;
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
    const std::string tag = tagText(group, element);
    if (expected != gdcm::VR::INVALID && !expected.Compatible(stored))
        return "element " + tag + " has VR " + text + ", the dictionary says " +
               gdcm::VR::GetVRString(expected);
    // Binary numbers must come whole.
    unsigned size = 0;
    if (stored == gdcm::VR::US || stored == gdcm::VR::SS) size = 2;
    if (stored == gdcm::VR::UL || stored == gdcm::VR::SL || stored == gdcm::VR::FL ||
        stored == gdcm::VR::AT)
        size = 4;
    if (stored == gdcm::VR::FD) size = 8;
    if (size && length % size != 0)
        return "element " + tag + " has a length of " + std::to_string(length) +
               ", not a multiple of its " + std::to_string(size) + "-byte values";
    return {};
}

// GDCM's parser special-cases a few lengths for files of particular vendors and then reads
// other bytes than the walk would (gdcmExplicitDataElement.txx, gdcmImplicitDataElement.txx,
// GDCM_SUPPORT_BROKEN_IMPLEMENTATION, on in Debian's build). Empty when GDCM reads the element
// as written.
std::string workaroundProblem(std::uint16_t group, std::uint16_t element, bool explicitVr,
                              const char vr[2], std::uint32_t length) {
    const std::string tag = tagText(group, element);
    if (explicitVr && group == 0x00ff && element == 0x4aa5)
        return "element " + tag + ", which GDCM reads as pixel data up to the end of the file";
    if (explicitVr && group == 0x0009 && isVr(vr, "UL") && length == 6)
        return "element " + tag + " (UL, length 6), which GDCM reads as 4 bytes";
    if (!explicitVr && length == 13 &&
        !(group == 0x0008 && (element == 0x0070 || element == 0x0080)))
        return "element " + tag + " has a length of 13, which GDCM reads as 10";
    if (!explicitVr && group == 0x031e && element == 0x0324 && length == 0x31f031cu)
        return "element " + tag + " has the length GDCM replaces for a Papyrus file";
    return {};
}

class Walker {
  public:
    Walker(const unsigned char* data, std::size_t size) : data_(data), size_(size) {}

    std::string problem;
    std::string transferSyntax;  // as GDCM reads it (gdcmTransferSyntaxUid)
    bool hasTransferSyntax = false;
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

    // A length that does not fit: the message names the element, what it claims and what is
    // left, so a corrupt length is told from a cut file.
    bool failLength(std::size_t at, const std::string& what, std::uint32_t length,
                    std::size_t left) {
        return fail(at, what + " claims " + std::to_string(length) + " bytes, but only " +
                            std::to_string(left) +
                            " are left in its container (corrupt length or "
                            "truncated file)");
    }

    // GDCM takes a printable unknown VR for UN, whose length is the 4 bytes after the 2
    // reserved ones: the message says what GDCM would have allocated.
    bool failVr(std::size_t pos, std::size_t end, std::uint16_t group, std::uint16_t element,
                const char vr[2], DicomEncoding enc) {
        std::string why =
            "element " + tagText(group, element) + " has an invalid value representation";
        const auto printable = [](char c) { return c >= ' ' && c <= '~'; };
        if (printable(vr[0]) && printable(vr[1])) {
            why += " '" + std::string(vr, 2) + "'";
            if (pos + 12 <= end)
                why += " (GDCM would read it as UN and allocate the " +
                       std::to_string(u32(pos + 8, enc.bigEndian)) + " bytes it then claims)";
        }
        return fail(pos, why);
    }

    // File meta group (always explicit VR little endian); records the transfer syntax.
    bool metaGroup(std::size_t& pos) {
        while (pos + 8 <= size_ && u16(pos, false) == 0x0002) {
            const std::uint16_t element = u16(pos + 2, false);
            const char vr[2] = {char(data_[pos + 4]), char(data_[pos + 5])};
            if (!isKnownVr(vr)) return fail(pos, "invalid VR in the file meta group");
            // GDCM asserts on a sequence in the meta group.
            if (isVr(vr, "SQ")) return fail(pos, "a sequence in the file meta group");
            std::size_t header = 8;
            std::uint32_t length = u16(pos + 6, false);
            if (isLongFormVr(vr)) {
                if (pos + 12 > size_) return fail(pos, "file meta element cut off");
                header = 12;
                length = u32(pos + 8, false);
            }
            if (length == kUndefinedLength || length > size_ - pos - header)
                return failLength(pos, "file meta element " + tagText(0x0002, element), length,
                                  size_ - std::min(size_, pos + header));
            if (const std::string why = vrProblem(0x0002, element, vr, length); !why.empty())
                return fail(pos, why);
            if (element == 0x0010) {
                transferSyntax = gdcmTransferSyntaxUid(
                    reinterpret_cast<const char*>(data_ + pos + header), length);
                hasTransferSyntax = true;
            }
            pos += header + length;
        }
        return true;
    }

    // Elements from pos up to end; with `toDelimiter` until an item delimiter instead.
    bool dataSet(std::size_t& pos, std::size_t end, DicomEncoding enc, bool toDelimiter,
                 int depth) {
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
                if (!isKnownVr(vr)) return failVr(pos, end, group, element, vr, enc);
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
            if (const std::string why =
                    workaroundProblem(group, element, enc.explicitVr, vr, length);
                !why.empty())
                return fail(pos, why);
            const std::size_t start = pos;
            const std::string tag = tagText(group, element);
            pos += header;
            const bool isPixelData = group == 0x7fe0 && element == 0x0010;
            const bool isSq = enc.explicitVr && isVr(vr, "SQ");
            const bool isUn = enc.explicitVr && isVr(vr, "UN");
            // GDCM asserts on both.
            if (isPixelData && isSq) return fail(start, "pixel data " + tag + " with VR SQ");
            if (length == kUndefinedLength) {
                // GDCM reads undefined-length pixel data as fragments at any depth (an icon's
                // too), whatever the transfer syntax.
                if (isPixelData) {
                    if (enc.explicitVr && !isVr(vr, "OB") && !isVr(vr, "OW") && !isUn)
                        return fail(start, "compressed pixel data " + tag + " with VR " +
                                               std::string(vr, 2));
                    if (!fragments(pos, end, enc, depth == 0)) return false;
                    if (depth == 0) {
                        hasPixelData = encapsulated = true;
                        pixelDataEnd = pos;
                    }
                    continue;
                }
                if (enc.explicitVr && !isSq && !isUn)
                    return fail(start, "undefined length on a non-sequence element " + tag);
                // CP-246: an undefined-length UN holds an implicit VR sequence (GDCM keeps the
                // data set's byte order).
                const DicomEncoding inner = isUn ? DicomEncoding{false, enc.bigEndian} : enc;
                if (!sequence(pos, end, inner, true, depth + 1)) return false;
                continue;
            }
            if (length > end - pos) return failLength(start, "element " + tag, length, end - pos);
            if (isSq) {
                std::size_t inner = pos;
                if (!sequence(inner, pos + length, enc, false, depth + 1)) return false;
            } else if (!isPixelData &&
                       !valueAsSequence(pos, length, enc, vr, group, element, depth)) {
                return false;
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

    // A defined-length value that GDCM may parse as a sequence later: every element of an
    // implicit VR data set, and an explicit UN, OB or OW one whose tag is a sequence in the
    // dictionary (gdcm::DataElement::GetValueAsSQ, which GDCM's image reader calls on the icon,
    // the functional groups, ...). GetValueAsSQ parses it as implicit VR little endian, and on
    // failure retries as explicit VR in both byte orders: lengths nobody checked, allocated
    // before they are read. So whatever starts like items must be a well-formed implicit VR
    // little endian sequence, and byte-swapped items are refused.
    bool valueAsSequence(std::size_t pos, std::uint32_t length, DicomEncoding enc, const char vr[2],
                         std::uint16_t group, std::uint16_t element, int depth) {
        if (length < 4) return true;  // GDCM's item read fails on the tag, before any length
        const bool sequenceTag = dictionarySaysSequence(group, element);
        const bool bulkVr = isVr(vr, "UN") || isVr(vr, "OB") || isVr(vr, "OW");
        if (enc.explicitVr && !(sequenceTag && bulkVr)) return true;
        // Raw bytes, little endian: GetValueAsSQ reads with GDCM's no-swap swapper.
        const std::uint16_t firstGroup = u16(pos, false), firstElement = u16(pos + 2, false);
        const std::string tag = tagText(group, element);
        if (sequenceTag && firstGroup == 0xfeff &&
            (firstElement == 0x00e0 || firstElement == 0xdde0))
            return fail(pos, "element " + tag + " holds byte-swapped sequence items");
        const bool item = firstGroup == 0xfffe && firstElement == 0xe000;
        const bool delimiter = firstGroup == 0xfffe && firstElement == 0xe0dd;
        // Implicit VR values of other tags are checked when they start like items (GDCM leaves
        // them alone; a value that merely looks like items is rare).
        if (!item && !(delimiter && sequenceTag)) return true;
        std::size_t inner = pos;
        if (sequence(inner, pos + length, DicomEncoding{false, false}, false, depth + 1))
            return true;
        problem = "element " + tag + " holds what GDCM parses as a sequence: " + problem;
        return false;
    }

    // Items of a sequence: up to `end` (defined length) or up to the sequence delimiter.
    bool sequence(std::size_t& pos, std::size_t end, DicomEncoding enc, bool undefined, int depth) {
        const std::size_t start = pos;
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
            const std::size_t item = pos;
            pos += 8;
            if (length == kUndefinedLength) {
                if (!dataSet(pos, end, enc, true, depth)) return false;
            } else {
                if (length > end - pos) return failLength(item, "sequence item", length, end - pos);
                std::size_t inner = pos;
                if (!dataSet(inner, pos + length, enc, false, depth)) return false;
                pos += length;
            }
            // GDCM's workarounds for two Philips files end a defined-length sequence early at
            // these lengths (gdcmSequenceOfItems.h): it would read the rest as elements.
            const std::size_t total = end - start, read = pos - start;
            if (!undefined && ((total == 778 && read == 774) || (total == 444 && read == 213)))
                return fail(item, "a sequence of " + std::to_string(total) +
                                      " bytes that GDCM ends after " + std::to_string(read));
        }
        return true;
    }

    // Encapsulated pixel data: an offset table item, then fragments, then the delimiter.
    // `record` for the top-level pixel data (an icon's is only checked).
    bool fragments(std::size_t& pos, std::size_t end, DicomEncoding enc, bool record) {
        int items = 0;
        for (;;) {
            if (pos + 8 > end) return fail(pos, "compressed pixel data cut off");
            const std::uint16_t group = u16(pos, enc.bigEndian);
            const std::uint16_t element = u16(pos + 2, enc.bigEndian);
            const std::uint32_t length = u32(pos + 4, enc.bigEndian);
            pos += 8;
            if (group == 0xfffe && element == 0xe0dd) {
                // GDCM allocates and reads the delimiter's length as if it were a fragment.
                if (length != 0)
                    return fail(pos - 8, "pixel data sequence delimiter claims " +
                                             std::to_string(length) + " bytes (0 expected)");
                if (items < 2) return fail(pos, "compressed pixel data without fragments");
                return true;
            }
            if (group != 0xfffe || element != 0xe000 || length == kUndefinedLength)
                return fail(pos - 8, "expected a pixel data fragment");
            if (length > end - pos)
                return failLength(pos - 8, "pixel data fragment", length, end - pos);
            if (items == 1 && record) {  // item 0 is the basic offset table
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
    // The data set is walked in the encoding GDCM will parse it in (DicomEncoding.h): from
    // the file meta group's transfer syntax when the file starts with group 0002 (GDCM reads
    // such a group with or without its group length), else by GDCM's guess.
    DicomEncodingChoice choice;
    std::string guessed;  // how the encoding was guessed, for the message
    if (size >= pos + 8 && walker.u16(pos, false) == 0x0002) {
        if (!walker.metaGroup(pos)) {
            check.problem = walker.problem;
            return check;
        }
        check.transferSyntax = walker.transferSyntax;
        if (!walker.hasTransferSyntax) {
            check.problem = "the file meta group has no transfer syntax (0002,0010)";
            return check;
        }
        choice = encodingOfTransferSyntax(walker.transferSyntax);
    } else {
        choice = guessedEncoding(data + pos, size - std::min(size, pos));
        guessed = "no file meta group: read as GDCM guesses from its first element, " +
                  describe(choice.encoding) + ": ";
    }
    if (!choice.problem.empty()) {
        check.problem = choice.problem;
        return check;
    }
    if (pos >= size) {
        check.problem = "no data set after the file meta group";
        return check;
    }
    bool ok = walker.dataSet(pos, size, choice.encoding, false, 0);
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
        check.problem = guessed + walker.problem;
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
