#include "dicom/LengthFields.h"

#include <algorithm>
#include <cstdio>

namespace fm::test {
namespace {

constexpr std::uint32_t kUndefined = 0xffffffffu;

class Lister {
  public:
    explicit Lister(const std::string& bytes) : b_(bytes) {}
    std::vector<LengthField> fields;

    std::uint16_t u16(std::size_t at) const {
        return std::uint16_t(byte(at) | (byte(at + 1) << 8));
    }
    std::uint32_t u32(std::size_t at) const {
        return std::uint32_t(byte(at)) | (std::uint32_t(byte(at + 1)) << 8) |
               (std::uint32_t(byte(at + 2)) << 16) | (std::uint32_t(byte(at + 3)) << 24);
    }
    std::size_t size() const { return b_.size(); }

    void add(std::size_t offset, int width, std::uint32_t value, const std::string& what,
             std::size_t at) {
        fields.push_back({offset, width, value, what + " at byte " + std::to_string(at)});
    }

    static bool longForm(const std::string& vr) {
        for (const char* v :
             {"OB", "OD", "OF", "OL", "OV", "OW", "SQ", "SV", "UC", "UN", "UR", "UT", "UV"})
            if (vr == v) return true;
        return false;
    }

    static std::string tag(std::uint16_t g, std::uint16_t e) {
        char text[16];
        std::snprintf(text, sizeof text, "(%04X,%04X)", g, e);
        return text;
    }

    // Elements from pos to end, or to an item delimiter; returns the position after them.
    std::size_t elements(std::size_t pos, std::size_t end, bool explicitVr) {
        while (pos + 8 <= end) {
            const std::uint16_t g = u16(pos), e = u16(pos + 2);
            if (g == 0xfffe && e == 0xe00d) {
                add(pos + 4, 4, u32(pos + 4), "item delimiter", pos);
                return pos + 8;
            }
            std::string vr;
            std::size_t lengthAt = pos + 4, header = 8;
            int width = 4;
            if (explicitVr || g == 0x0002) {
                vr = b_.substr(pos + 4, 2);
                if (longForm(vr)) {
                    lengthAt = pos + 8;
                    header = 12;
                } else {
                    lengthAt = pos + 6;
                    width = 2;
                }
            }
            const std::uint32_t length = width == 2 ? u16(lengthAt) : u32(lengthAt);
            add(lengthAt, width, length, tag(g, e) + (vr.empty() ? "" : " " + vr), pos);
            pos += header;
            if (length == kUndefined) {
                if (g == 0x7fe0 && e == 0x0010)
                    pos = fragments(pos, end);
                else
                    pos = items(pos, end, vr == "UN" ? false : explicitVr);
                continue;
            }
            const bool startsWithItem = length >= 8 && u16(pos) == 0xfffe && u16(pos + 2) == 0xe000;
            if (vr == "SQ" || (!explicitVr && startsWithItem && !(g == 0x7fe0 && e == 0x0010)))
                items(pos, std::min(end, pos + length), explicitVr);
            else if (vr == "UN" && startsWithItem)  // CP-246: an implicit VR sequence
                items(pos, std::min(end, pos + length), false);
            pos += length;
        }
        return pos;
    }

    std::size_t items(std::size_t pos, std::size_t end, bool explicitVr) {
        while (pos + 8 <= end) {
            const std::uint16_t g = u16(pos), e = u16(pos + 2);
            const std::uint32_t length = u32(pos + 4);
            if (g == 0xfffe && e == 0xe0dd) {
                add(pos + 4, 4, length, "sequence delimiter", pos);
                return pos + 8;
            }
            if (g != 0xfffe || e != 0xe000) return end;  // not items: nothing more to list
            add(pos + 4, 4, length, "item", pos);
            pos += 8;
            if (length == kUndefined) {
                pos = elements(pos, end, explicitVr);
            } else {
                elements(pos, std::min(end, pos + length), explicitVr);
                pos += length;
            }
        }
        return pos;
    }

    std::size_t fragments(std::size_t pos, std::size_t end) {
        while (pos + 8 <= end) {
            const std::uint16_t e = u16(pos + 2);
            const std::uint32_t length = u32(pos + 4);
            add(pos + 4, 4, length, e == 0xe0dd ? "pixel data sequence delimiter" : "fragment",
                pos);
            pos += 8;
            if (e == 0xe0dd) return pos;
            pos += length;
        }
        return pos;
    }

  private:
    unsigned byte(std::size_t at) const { return at < b_.size() ? (unsigned char)b_[at] : 0u; }
    const std::string& b_;
};

}  // namespace

std::vector<LengthField> lengthFields(const std::string& bytes) {
    Lister lister(bytes);
    std::size_t pos = 132;
    // File meta group, noting the transfer syntax.
    bool explicitVr = true;
    while (pos + 8 <= bytes.size() && lister.u16(pos) == 0x0002) {
        const std::string vr = bytes.substr(pos + 4, 2);
        const bool longForm = Lister::longForm(vr);
        const std::size_t lengthAt = longForm ? pos + 8 : pos + 6;
        const std::uint32_t length = longForm ? lister.u32(lengthAt) : lister.u16(lengthAt);
        const std::size_t header = longForm ? 12 : 8;
        lister.add(lengthAt, longForm ? 4 : 2, length,
                   Lister::tag(0x0002, lister.u16(pos + 2)) + " " + vr, pos);
        if (lister.u16(pos + 2) == 0x0010) {
            std::string uid = bytes.substr(pos + header, length);
            while (!uid.empty() && (uid.back() == '\0' || uid.back() == ' ')) uid.pop_back();
            explicitVr = uid != "1.2.840.10008.1.2";
        }
        pos += header + length;
    }
    lister.elements(pos, bytes.size(), explicitVr);
    return lister.fields;
}

std::vector<std::uint32_t> claimedLengths(const LengthField& field, std::size_t fileSize) {
    std::vector<std::uint32_t> claims;
    const std::size_t valueStart = field.offset + std::size_t(field.width);
    const std::size_t pastEnd = fileSize > valueStart ? fileSize - valueStart + 1 : 1;
    if (field.width == 2) {
        claims = {0xffffu, 0xfffeu, std::uint32_t(std::min<std::size_t>(pastEnd, 0xffff)),
                  std::uint32_t((field.value + 2) & 0xffffu)};
    } else {
        claims = {0xffffffffu,
                  0xfffffff0u,
                  0x7ffffff0u,
                  1000000000u,
                  std::uint32_t(std::min<std::size_t>(pastEnd, 0xffffffffu)),
                  field.value + 2};
    }
    std::sort(claims.begin(), claims.end());
    claims.erase(std::unique(claims.begin(), claims.end()), claims.end());
    claims.erase(std::remove(claims.begin(), claims.end(), field.value), claims.end());
    return claims;
}

std::string withLength(std::string bytes, const LengthField& field, std::uint32_t value) {
    for (int b = 0; b < field.width; ++b)
        bytes[field.offset + std::size_t(b)] = char((value >> (8 * b)) & 0xffu);
    return bytes;
}

}  // namespace fm::test
