#include "io/VtkReader.h"

#include <map>

#include "core/Error.h"
#include "io/ByteSource.h"
#include "io/HeaderText.h"
#include "io/RawVolume.h"

namespace fm {

using namespace fm::io;
namespace fs = std::filesystem;

namespace {

constexpr std::size_t kMaxVtkHeaderBytes = 1 << 16;  // the header is ~10 short lines

ScalarType vtkScalarType(const std::string& name, const std::string& what) {
    static const std::map<std::string, ScalarType> kTypes = {
        {"unsigned_char", ScalarType::U8},   {"char", ScalarType::I8},
        {"signed_char", ScalarType::I8},     {"short", ScalarType::I16},
        {"unsigned_short", ScalarType::U16}, {"int", ScalarType::I32},
        {"unsigned_int", ScalarType::U32},   {"float", ScalarType::F32},
        {"double", ScalarType::F64},         {"vtktypeint64", ScalarType::I64},
        {"vtktypeuint64", ScalarType::U64},
    };
    const auto it = kTypes.find(toLower(name));
    if (it == kTypes.end())
        throw Error(what + ": unsupported VTK scalar type '" + name +
                    "' ('long' has no fixed size in legacy VTK)");
    return it->second;
}

}  // namespace

Volume readLegacyVtk(const fs::path& path) {
    const std::string what = quoted(path);
    const Bytes head = readFilePrefix(path, kMaxVtkHeaderBytes);
    const std::string_view text(reinterpret_cast<const char*>(head.data()), head.size());
    std::size_t pos = 0;
    std::string line;
    if (!nextLine(text, pos, line) || !startsWith(line, "# vtk DataFile"))
        throw Error(what + ": not a legacy VTK file (no '# vtk DataFile' line)");
    std::string title;
    if (!nextLine(text, pos, title)) throw Error(what + ": truncated VTK header");
    if (!nextLine(text, pos, line)) throw Error(what + ": truncated VTK header");
    const std::string format = toLower(trim(line));
    if (format != "binary" && format != "ascii")
        throw Error(what + ": third line must be ASCII or BINARY, got '" +
                    trim(line).substr(0, 40) + "'");
    const bool binary = format == "binary";

    bool sawDataset = false;
    long long dimsIn[3] = {0, 0, 0};
    bool haveDims = false;
    glm::dvec3 spacing{1.0}, origin{0.0};
    glm::dmat3 direction{1.0};
    long long pointCount = -1;
    std::string typeName;
    bool done = false;
    while (!done && nextLine(text, pos, line)) {
        const auto words = splitWords(line);
        if (words.empty()) continue;
        const std::string key = toLower(words[0]);
        auto numbers = [&](std::size_t count) {
            if (words.size() != count + 1)
                throw Error(what + ": " + words[0] + " needs " + std::to_string(count) + " values");
            std::vector<double> v;
            for (std::size_t i = 1; i <= count; ++i)
                v.push_back(parseFinite(words[i], what + ": " + words[0]));
            return v;
        };
        if (key == "dataset") {
            if (words.size() != 2 || toLower(words[1]) != "structured_points")
                throw Error(what + ": only DATASET STRUCTURED_POINTS is supported, got '" +
                            line.substr(0, 60) + "'");
            sawDataset = true;
        } else if (key == "dimensions") {
            for (int a = 0; a < 3; ++a) {
                if (words.size() != 4) throw Error(what + ": DIMENSIONS needs 3 values");
                dimsIn[a] = parseInteger(words[a + 1], what + ": DIMENSIONS");
            }
            haveDims = true;
        } else if (key == "spacing" || key == "aspect_ratio") {
            const auto v = numbers(3);
            spacing = {v[0], v[1], v[2]};
        } else if (key == "origin") {
            const auto v = numbers(3);
            origin = {v[0], v[1], v[2]};
        } else if (key == "direction") {
            const auto v = numbers(9);  // row-major 3x3; columns are the axes
            for (int r = 0; r < 3; ++r)
                for (int c = 0; c < 3; ++c) direction[c][r] = v[r * 3 + c];
        } else if (key == "point_data") {
            if (words.size() != 2) throw Error(what + ": POINT_DATA needs a count");
            pointCount = parseInteger(words[1], what + ": POINT_DATA");
        } else if (key == "cell_data") {
            throw Error(what + ": CELL_DATA is not supported (need point scalars)");
        } else if (key == "scalars") {
            if (words.size() < 3 || words.size() > 4)
                throw Error(what + ": SCALARS needs a name, a type and optionally 1 component");
            typeName = words[2];
            if (words.size() == 4 && parseInteger(words[3], what + ": SCALARS components") != 1)
                throw Error(what + ": only one scalar component per point is supported");
            // LOOKUP_TABLE follows (may be absent in some writers: then data starts here).
            std::size_t peek = pos;
            std::string next;
            if (nextLine(text, peek, next) && startsWith(toLower(trim(next)), "lookup_table"))
                pos = peek;
            done = true;
        } else if (key == "color_scalars" || key == "vectors" || key == "field" ||
                   key == "tensors" || key == "normals") {
            throw Error(what + ": " + words[0] + " data is not supported (need SCALARS)");
        } else {
            throw Error(what + ": unexpected VTK header line '" + line.substr(0, 60) + "'");
        }
    }
    if (!sawDataset) throw Error(what + ": no DATASET STRUCTURED_POINTS line");
    if (!haveDims) throw Error(what + ": no DIMENSIONS line");
    if (!done) throw Error(what + ": no SCALARS line (truncated header?)");
    const glm::ivec3 dims = checkedDims(dimsIn[0], dimsIn[1], dimsIn[2], what);
    const long long voxels = static_cast<long long>(dims.x) * dims.y * dims.z;
    if (pointCount != voxels)
        throw Error(what + ": POINT_DATA " + std::to_string(pointCount) +
                    " does not match DIMENSIONS (" + std::to_string(voxels) + " points)");
    const ScalarType type = vtkScalarType(typeName, what);

    Volume v;
    if (binary) {
        // Legacy VTK binary data is always big-endian.
        const Bytes raw = readFileRange(path, pos, rawByteCount(dims, type));
        v = volumeFromRaw(dims, raw, 0, type, hostIsLittleEndian(), what);
    } else {
        const std::uintmax_t size = fileSize(path);
        if (size > (std::uintmax_t{1} << 34)) throw Error(what + " is too large");
        const Bytes rest = readFileRange(path, pos, static_cast<std::size_t>(size - pos));
        v = volumeFromText(
            dims, std::string_view(reinterpret_cast<const char*>(rest.data()), rest.size()), what);
    }
    v.spacing = spacing;
    v.origin = origin;
    v.direction = direction;
    v.meta.source = path.string();
    v.meta.description = "legacy VTK, " + std::string(toString(type));
    if (!trim(title).empty()) v.meta.description += ": " + trim(title);
    v.validate(what);
    return v;
}

}  // namespace fm
