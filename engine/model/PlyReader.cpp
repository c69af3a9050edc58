// PLY (Turk 1994): a text header of elements and properties, then the data in ASCII or binary
// (little or big endian). Reads element "vertex" (properties x, y, z of any scalar type) and
// element "face" (list property "vertex_indices" or "vertex_index"); every other element and
// property is read past. Counts are checked against the bytes left before anything is sized.
#include <cmath>
#include <cstring>
#include <optional>
#include <string_view>

#include "core/Error.h"
#include "model/MeshFile.h"
#include "model/MeshText.h"

namespace fm {
namespace {

enum class Format { Ascii, BinaryLE, BinaryBE };

struct ScalarKind {
    int bytes = 0;
    bool isFloat = false;
    bool isSigned = false;
};

std::optional<ScalarKind> scalarKind(std::string_view name) {
    if (name == "char" || name == "int8") return ScalarKind{1, false, true};
    if (name == "uchar" || name == "uint8") return ScalarKind{1, false, false};
    if (name == "short" || name == "int16") return ScalarKind{2, false, true};
    if (name == "ushort" || name == "uint16") return ScalarKind{2, false, false};
    if (name == "int" || name == "int32") return ScalarKind{4, false, true};
    if (name == "uint" || name == "uint32") return ScalarKind{4, false, false};
    if (name == "float" || name == "float32") return ScalarKind{4, true, true};
    if (name == "double" || name == "float64") return ScalarKind{8, true, true};
    return std::nullopt;
}

struct Property {
    std::string name;
    ScalarKind type;
    bool isList = false;
    ScalarKind countType;
};

struct Element {
    std::string name;
    std::size_t count = 0;
    std::vector<Property> properties;
};

// Reads one scalar of the data section, ASCII or binary, bounds-checked.
class DataReader {
  public:
    DataReader(const std::vector<std::uint8_t>& bytes, std::size_t offset, Format format,
               int line, const std::string& what)
        : bytes_(bytes),
          format_(format),
          pos_(offset),
          text_(std::string_view(reinterpret_cast<const char*>(bytes.data()), bytes.size()), what,
                offset, line),
          what_(what) {}

    double value(const ScalarKind& kind, const std::string& field) {
        if (format_ == Format::Ascii) {
            // Integers are read as numbers too: their range check is the caller's.
            return text_.number(field);
        }
        if (pos_ + kind.bytes > bytes_.size())
            throw Error(what_ + ": the data ends inside " + field + " (truncated)");
        std::uint8_t raw[8];
        std::memcpy(raw, bytes_.data() + pos_, kind.bytes);
        pos_ += kind.bytes;
        if (format_ == Format::BinaryBE)
            for (int a = 0, b = kind.bytes - 1; a < b; ++a, --b) std::swap(raw[a], raw[b]);
        double out = 0.0;
        if (kind.isFloat) {
            if (kind.bytes == 4) {
                float f;
                std::memcpy(&f, raw, 4);
                out = f;
            } else {
                std::memcpy(&out, raw, 8);
            }
            if (!std::isfinite(out)) throw Error(what_ + ": " + field + " is not finite");
            return out;
        }
        std::uint64_t u = 0;
        for (int i = kind.bytes - 1; i >= 0; --i) u = (u << 8) | raw[i];
        if (kind.isSigned) {
            const int shift = 64 - 8 * kind.bytes;
            return static_cast<double>(static_cast<std::int64_t>(u << shift) >> shift);
        }
        return static_cast<double>(u);
    }

    std::size_t bytesLeft() const {
        const std::size_t at = format_ == Format::Ascii ? text_.offset() : pos_;
        return at < bytes_.size() ? bytes_.size() - at : 0;
    }
    bool ascii() const { return format_ == Format::Ascii; }

  private:
    const std::vector<std::uint8_t>& bytes_;
    Format format_;
    std::size_t pos_;
    model::TextCursor text_;
    std::string what_;
};

// Smallest number of bytes one instance of `e` can take: the size check before allocating.
std::size_t minimumRecordBytes(const Element& e, bool ascii) {
    std::size_t n = 0;
    for (const Property& p : e.properties) {
        if (ascii)
            n += 2;  // a digit and a separator
        else
            n += static_cast<std::size_t>(p.isList ? p.countType.bytes : p.type.bytes);
    }
    return std::max<std::size_t>(n, 1);
}

std::size_t listCount(double value, const std::string& field, const std::string& what) {
    if (value < 0 || value != std::floor(value) || value > 1e6)
        throw Error(what + ": " + field + " has an invalid list length " + std::to_string(value));
    return static_cast<std::size_t>(value);
}

}  // namespace

Mesh readPlyBytes(const std::vector<std::uint8_t>& bytes, const std::string& what) {
    const std::string_view text(reinterpret_cast<const char*>(bytes.data()), bytes.size());
    model::TextCursor header(text, what);
    if (header.next() != "ply") header.fail("not a PLY file (no 'ply' magic)");
    header.skipLine();
    std::optional<Format> format;
    std::vector<Element> elements;
    for (;;) {
        if (header.atEnd()) header.fail("the header has no 'end_header' (truncated?)");
        const std::string_view key = header.next();
        if (key == "end_header") {
            header.skipLine();
            break;
        }
        if (key == "comment" || key == "obj_info") {
            header.skipLine();
        } else if (key == "format") {
            const std::string_view f = header.nextOnLine();
            if (f == "ascii")
                format = Format::Ascii;
            else if (f == "binary_little_endian")
                format = Format::BinaryLE;
            else if (f == "binary_big_endian")
                format = Format::BinaryBE;
            else
                header.fail("unknown format '" + std::string(f.substr(0, 40)) + "'");
            header.skipLine();
        } else if (key == "element") {
            Element e;
            e.name = std::string(header.nextOnLine());
            std::int64_t count = 0;
            if (!model::parseInteger(header.nextOnLine(), count) || count < 0)
                header.fail("element '" + e.name + "' needs a non-negative count");
            if (static_cast<std::uint64_t>(count) > kMaxModelElements)
                header.fail("element '" + e.name + "' count " + std::to_string(count) +
                            " is more than a model may have");
            e.count = static_cast<std::size_t>(count);
            elements.push_back(std::move(e));
            header.skipLine();
        } else if (key == "property") {
            if (elements.empty()) header.fail("'property' before any 'element'");
            Property p;
            std::string_view type = header.nextOnLine();
            if (type == "list") {
                p.isList = true;
                const auto count = scalarKind(header.nextOnLine());
                if (!count || count->isFloat) header.fail("a list count must be an integer type");
                p.countType = *count;
                type = header.nextOnLine();
            }
            const auto kind = scalarKind(type);
            if (!kind) header.fail("unknown property type '" + std::string(type.substr(0, 40)) + "'");
            p.type = *kind;
            p.name = std::string(header.nextOnLine());
            if (p.name.empty()) header.fail("a property needs a name");
            elements.back().properties.push_back(p);
            header.skipLine();
        } else {
            header.fail("unknown header line '" + std::string(key.substr(0, 40)) + "'");
        }
    }
    if (!format) throw Error(what + ": the PLY header has no 'format' line");

    DataReader data(bytes, header.offset(), *format, header.line(), what);
    Mesh mesh;
    bool haveVertices = false, haveFaces = false;
    for (const Element& e : elements) {
        // The count must fit in what is left of the file before anything is sized by it.
        const std::size_t minBytes = minimumRecordBytes(e, data.ascii());
        if (e.count > data.bytesLeft() / minBytes)
            throw Error(what + ": element '" + e.name + "' count " + std::to_string(e.count) +
                        " needs at least " + std::to_string(minBytes) + " bytes each, only " +
                        std::to_string(data.bytesLeft()) + " bytes are left (truncated or corrupt)");
        const bool isVertex = e.name == "vertex", isFace = e.name == "face";
        int xyz[3] = {-1, -1, -1};
        int indexList = -1;
        for (std::size_t i = 0; i < e.properties.size(); ++i) {
            const Property& p = e.properties[i];
            if (isVertex && !p.isList && p.name.size() == 1 && p.name[0] >= 'x' && p.name[0] <= 'z')
                xyz[p.name[0] - 'x'] = static_cast<int>(i);
            if (isFace && p.isList && (p.name == "vertex_indices" || p.name == "vertex_index"))
                indexList = static_cast<int>(i);
        }
        if (isVertex) {
            if (xyz[0] < 0 || xyz[1] < 0 || xyz[2] < 0)
                throw Error(what + ": element 'vertex' lacks an x, y or z property");
            mesh.positions.resize(e.count);
            haveVertices = true;
        }
        if (isFace) {
            if (indexList < 0)
                throw Error(what + ": element 'face' has no 'vertex_indices' list");
            mesh.triangles.reserve(e.count);
            haveFaces = true;
        }
        std::vector<std::uint32_t> polygon;
        for (std::size_t r = 0; r < e.count; ++r) {
            for (std::size_t i = 0; i < e.properties.size(); ++i) {
                const Property& p = e.properties[i];
                const std::string field = e.name + " " + std::to_string(r) + " '" + p.name + "'";
                if (!p.isList) {
                    const double value = data.value(p.type, field);
                    if (isVertex)
                        for (int a = 0; a < 3; ++a)
                            if (xyz[a] == static_cast<int>(i)) {
                                const float f = static_cast<float>(value);
                                if (!std::isfinite(f))
                                    throw Error(what + ": " + field + " is out of float range");
                                mesh.positions[r][a] = f;
                            }
                    continue;
                }
                const std::size_t n = listCount(data.value(p.countType, field + " count"), field, what);
                const bool indices = isFace && indexList == static_cast<int>(i);
                if (indices) polygon.clear();
                for (std::size_t k = 0; k < n; ++k) {
                    const double value = data.value(p.type, field);
                    if (!indices) continue;
                    if (value < 0 || value != std::floor(value) || value >= 4294967295.0)
                        throw Error(what + ": " + field + " has an invalid vertex index " +
                                    std::to_string(value));
                    polygon.push_back(static_cast<std::uint32_t>(value));
                }
                if (!indices) continue;
                if (polygon.size() < 3)
                    throw Error(what + ": " + field + " has " + std::to_string(polygon.size()) +
                                " vertices (a face needs at least 3)");
                for (std::size_t k = 1; k + 1 < polygon.size(); ++k)  // fan
                    mesh.triangles.push_back(glm::uvec3(polygon[0], polygon[k], polygon[k + 1]));
                if (mesh.triangles.size() > kMaxModelElements)
                    throw Error(what + ": more triangles than a model may have");
            }
        }
    }
    if (!haveVertices) throw Error(what + ": the PLY has no 'vertex' element");
    if (!haveFaces || mesh.triangles.empty()) throw Error(what + ": the PLY has no face");
    for (std::size_t t = 0; t < mesh.triangles.size(); ++t)
        for (int k = 0; k < 3; ++k)
            if (mesh.triangles[t][k] >= mesh.positions.size())
                throw Error(what + ": face triangle " + std::to_string(t) + " uses vertex " +
                            std::to_string(mesh.triangles[t][k]) + " of " +
                            std::to_string(mesh.positions.size()));
    return mesh;
}

}  // namespace fm
