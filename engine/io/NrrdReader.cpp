#include "io/NrrdReader.h"

#include <algorithm>
#include <cmath>
#include <fstream>
#include <map>
#include <optional>
#include <sstream>

#include "core/Error.h"
#include "io/ByteSource.h"
#include "io/HeaderText.h"
#include "io/RawVolume.h"

namespace fm {

using namespace fm::io;
namespace fs = std::filesystem;

namespace {

constexpr std::size_t kMaxNrrdHeaderBytes = 1 << 20;  // headers are tiny; a MiB is absurd already
constexpr int kMaxAxes = 16;                      // NRRD_DIM_MAX
// More slice files than this is a corrupt header, not a CT.
constexpr long long kMaxNrrdDataFiles = 1 << 20;

ScalarType nrrdScalarType(const std::string& raw, const std::string& what) {
    // Collapse runs of spaces: "unsigned   short" is the same type.
    const std::string name = [&] {
        std::string out;
        for (const auto& w : splitWords(toLower(raw))) out += (out.empty() ? "" : " ") + w;
        return out;
    }();
    static const std::map<std::string, ScalarType> kTypes = {
        {"signed char", ScalarType::I8},
        {"int8", ScalarType::I8},
        {"int8_t", ScalarType::I8},
        {"uchar", ScalarType::U8},
        {"unsigned char", ScalarType::U8},
        {"uint8", ScalarType::U8},
        {"uint8_t", ScalarType::U8},
        {"short", ScalarType::I16},
        {"short int", ScalarType::I16},
        {"signed short", ScalarType::I16},
        {"signed short int", ScalarType::I16},
        {"int16", ScalarType::I16},
        {"int16_t", ScalarType::I16},
        {"ushort", ScalarType::U16},
        {"unsigned short", ScalarType::U16},
        {"unsigned short int", ScalarType::U16},
        {"uint16", ScalarType::U16},
        {"uint16_t", ScalarType::U16},
        {"int", ScalarType::I32},
        {"signed int", ScalarType::I32},
        {"int32", ScalarType::I32},
        {"int32_t", ScalarType::I32},
        {"uint", ScalarType::U32},
        {"unsigned int", ScalarType::U32},
        {"uint32", ScalarType::U32},
        {"uint32_t", ScalarType::U32},
        {"longlong", ScalarType::I64},
        {"long long", ScalarType::I64},
        {"long long int", ScalarType::I64},
        {"signed long long", ScalarType::I64},
        {"signed long long int", ScalarType::I64},
        {"int64", ScalarType::I64},
        {"int64_t", ScalarType::I64},
        {"ulonglong", ScalarType::U64},
        {"unsigned long long", ScalarType::U64},
        {"unsigned long long int", ScalarType::U64},
        {"uint64", ScalarType::U64},
        {"uint64_t", ScalarType::U64},
        {"float", ScalarType::F32},
        {"double", ScalarType::F64},
    };
    const auto it = kTypes.find(name);
    if (it == kTypes.end()) throw Error(what + ": unsupported NRRD type '" + raw + "'");
    return it->second;
}

// World-frame conversion of a NRRD space to LPS (diagonal signs), or nullopt if unknown.
std::optional<glm::dvec3> spaceToLps(const std::string& space) {
    const std::string s = toLower(trim(space));
    if (s == "right-anterior-superior" || s == "ras" || s == "right-anterior-superior-time" ||
        s == "rast")
        return glm::dvec3(-1, -1, 1);
    if (s == "left-anterior-superior" || s == "las" || s == "left-anterior-superior-time" ||
        s == "last")
        return glm::dvec3(1, -1, 1);
    if (s == "left-posterior-superior" || s == "lps" || s == "left-posterior-superior-time" ||
        s == "lpst")
        return glm::dvec3(1, 1, 1);
    if (s == "scanner-xyz" || s == "scanner-xyz-time" || s == "3d-right-handed" ||
        s == "3d-left-handed" || s == "3d-right-handed-time" || s == "3d-left-handed-time")
        return glm::dvec3(1, 1, 1);
    return std::nullopt;
}

// "(1,0,0)" -> its components; "none" -> empty.
std::vector<double> parseVector(const std::string& token, const std::string& what) {
    if (toLower(token) == "none") return {};
    if (token.size() < 2 || token.front() != '(' || token.back() != ')')
        throw Error(what + ": '" + token + "' is not a vector like (1,0,0)");
    std::vector<double> v;
    std::string inner = token.substr(1, token.size() - 2);
    std::stringstream ss(inner);
    std::string part;
    while (std::getline(ss, part, ',')) v.push_back(parseFinite(trim(part), what));
    return v;
}

// Vectors in a field value, which may hold spaces inside the parentheses.
std::vector<std::string> splitVectors(const std::string& value) {
    std::vector<std::string> out;
    std::string current;
    int depth = 0;
    for (char c : value) {
        if (c == '(') ++depth;
        if (c == ')') --depth;
        if (std::isspace(static_cast<unsigned char>(c)) && depth == 0) {
            if (!current.empty()) out.push_back(current);
            current.clear();
        } else if (!std::isspace(static_cast<unsigned char>(c))) {
            current += c;
        }
    }
    if (!current.empty()) out.push_back(current);
    return out;
}

// Offset just past `lines` newlines counted from `offset`.
std::uintmax_t skipLines(const fs::path& path, std::uintmax_t offset, long long lines) {
    if (lines <= 0) return offset;
    std::ifstream in(path, std::ios::binary);
    if (!in) throw Error("cannot open " + quoted(path));
    in.seekg(static_cast<std::streamoff>(offset));
    std::vector<char> chunk(1 << 16);
    std::uintmax_t pos = offset;
    while (lines > 0) {
        in.read(chunk.data(), static_cast<std::streamsize>(chunk.size()));
        const auto got = static_cast<std::size_t>(in.gcount());
        if (got == 0) throw Error(quoted(path) + " is truncated: it ends before the lines to skip");
        for (std::size_t i = 0; i < got && lines > 0; ++i) {
            ++pos;
            if (chunk[i] == '\n') --lines;
        }
    }
    return pos;
}

}  // namespace

Volume readNrrd(const fs::path& path) {
    const std::string what = quoted(path);
    const Bytes head = readFilePrefix(path, kMaxNrrdHeaderBytes);
    const std::string_view text(reinterpret_cast<const char*>(head.data()), head.size());

    std::size_t pos = 0;
    std::string line;
    if (!nextLine(text, pos, line) || !startsWith(line, "NRRD000") || line.size() != 8 ||
        !std::isdigit(static_cast<unsigned char>(line[7])))
        throw Error(what + ": not a NRRD file (the first line must be NRRD000x)");

    std::map<std::string, std::string> fields;  // key without spaces, lower case -> value
    std::vector<std::string> listedFiles;
    bool listMode = false;
    bool headerEnded = false;
    while (nextLine(text, pos, line)) {
        if (line.empty()) {
            headerEnded = true;
            break;
        }
        if (listMode) {  // after "data file: LIST" every line is a file name
            if (!trim(line).empty()) listedFiles.push_back(trim(line));
            continue;
        }
        if (line[0] == '#') continue;
        if (line.find(":=") != std::string::npos) continue;  // key/value pairs: not needed
        const std::size_t colon = line.find(": ");
        if (colon == std::string::npos)
            throw Error(what + ": malformed NRRD header line '" + line.substr(0, 80) + "'");
        std::string key;
        for (char c : toLower(line.substr(0, colon)))
            if (c != ' ') key += c;
        const std::string value = trim(std::string_view(line).substr(colon + 2));
        if (fields.count(key)) throw Error(what + ": field '" + key + "' appears twice");
        fields[key] = value;
        if (key == "datafile" && !splitWords(value).empty() &&
            equalsIgnoreCase(splitWords(value)[0], "LIST"))
            listMode = true;
    }
    if (!headerEnded && pos < text.size())
        throw Error(what + ": NRRD header is larger than " + std::to_string(kMaxNrrdHeaderBytes) +
                    " bytes");
    const std::size_t attachedStart = pos;
    auto field = [&](const char* key) -> const std::string* {
        const auto it = fields.find(key);
        return it == fields.end() ? nullptr : &it->second;
    };
    auto required = [&](const char* key, const char* name) -> const std::string& {
        const std::string* v = field(key);
        if (!v) throw Error(what + ": required NRRD field '" + name + "' is missing");
        return *v;
    };

    const long long dimension =
        parseInteger(required("dimension", "dimension"), what + ": dimension");
    if (dimension < 1 || dimension > kMaxAxes)
        throw Error(what + ": dimension " + std::to_string(dimension) + " is invalid");
    const auto nd = static_cast<std::size_t>(dimension);
    const ScalarType type = nrrdScalarType(required("type", "type"), what);

    const auto sizeWords = splitWords(required("sizes", "sizes"));
    if (sizeWords.size() != nd)
        throw Error(what + ": 'sizes' needs " + std::to_string(nd) + " values");
    std::vector<long long> sizes;
    for (const auto& w : sizeWords) {
        const long long s = parseInteger(w, what + ": sizes");
        if (s < 1 || s > (1LL << 31)) throw Error(what + ": size " + w + " is invalid");
        sizes.push_back(s);
    }

    // Geometry per axis: a direction vector (space directions) or a spacing.
    const std::string* spaceName = field("space");
    glm::dvec3 toLps{1.0};
    std::size_t spaceDim = 3;
    if (spaceName) {
        const auto conversion = spaceToLps(*spaceName);
        if (!conversion) throw Error(what + ": unsupported NRRD space '" + *spaceName + "'");
        toLps = *conversion;
    } else if (const std::string* sd = field("spacedimension")) {
        const long long d = parseInteger(*sd, what + ": space dimension");
        if (d < 2 || d > 3) throw Error(what + ": space dimension " + *sd + " is not supported");
        spaceDim = static_cast<std::size_t>(d);
    }
    std::vector<std::optional<glm::dvec3>> axisVectors(nd);
    bool haveDirections = false;
    if (const std::string* sd = field("spacedirections")) {
        haveDirections = true;
        const auto vectors = splitVectors(*sd);
        if (vectors.size() != nd)
            throw Error(what + ": 'space directions' needs " + std::to_string(nd) + " entries");
        for (std::size_t a = 0; a < nd; ++a) {
            const auto v = parseVector(vectors[a], what + ": space directions");
            if (v.empty()) continue;  // "none": a non-spatial axis
            if (v.size() != spaceDim)
                throw Error(what + ": space direction '" + vectors[a] + "' has the wrong length");
            axisVectors[a] = glm::dvec3(v[0], v[1], spaceDim == 3 ? v[2] : 0.0);
        }
    }
    std::vector<double> spacings(nd, 1.0);
    std::vector<bool> spatial(nd, true);
    if (haveDirections) {
        for (std::size_t a = 0; a < nd; ++a) spatial[a] = axisVectors[a].has_value();
    } else {
        if (const std::string* sp = field("spacings")) {
            const auto words = splitWords(*sp);
            if (words.size() != nd)
                throw Error(what + ": 'spacings' needs " + std::to_string(nd) + " values");
            for (std::size_t a = 0; a < nd; ++a) {
                if (toLower(words[a]) == "nan") {  // NRRD's way to say "not a spatial axis"
                    spatial[a] = false;
                    continue;
                }
                spacings[a] = parseFinite(words[a], what + ": spacings");
                if (spacings[a] <= 0.0)
                    throw Error(what + ": spacing " + words[a] + " must be positive");
            }
        }
        if (const std::string* kinds = field("kinds")) {
            const auto words = splitWords(*kinds);
            if (words.size() == nd)
                for (std::size_t a = 0; a < nd; ++a) {
                    const std::string k = toLower(words[a]);
                    if (k != "domain" && k != "space" && k != "time" && k != "???" && k != "none")
                        spatial[a] = false;
                }
        }
    }
    // Keep spatial axes; non-spatial ones (vector components, time) must have size 1.
    std::vector<std::size_t> keep;
    for (std::size_t a = 0; a < nd; ++a) {
        if (spatial[a])
            keep.push_back(a);
        else if (sizes[a] != 1)
            throw Error(what + ": axis " + std::to_string(a) + " of size " +
                        std::to_string(sizes[a]) +
                        " is not spatial (multi-component or time data is not supported)");
    }
    while (keep.size() > 3 && sizes[keep.back()] == 1) keep.pop_back();
    if (keep.size() > 3 || keep.empty())
        throw Error(what + ": " + std::to_string(keep.size()) +
                    " spatial axes; only 1D to 3D volumes are supported");
    long long n[3] = {1, 1, 1};
    for (std::size_t a = 0; a < keep.size(); ++a) n[a] = sizes[keep[a]];
    // Axes dropped above all have size 1, so the kept ones keep their storage order.
    const glm::ivec3 dims = checkedDims(n[0], n[1], n[2], what);

    Volume geometry;
    if (haveDirections) {
        // A missing third axis (2D image in 3D space) gets the unit normal of the other two.
        for (std::size_t a = 0; a < keep.size(); ++a) {
            const glm::dvec3 vec = *axisVectors[keep[a]] * toLps;
            const double len = glm::length(vec);
            if (!(len > 0.0) || !std::isfinite(len))
                throw Error(what + ": space direction of axis " + std::to_string(keep[a]) +
                            " has zero length");
            geometry.spacing[static_cast<int>(a)] = len;
            geometry.direction[static_cast<int>(a)] = vec / len;
        }
        if (keep.size() == 2) {
            const glm::dvec3 normal = glm::cross(geometry.direction[0], geometry.direction[1]);
            if (glm::length(normal) > 0) geometry.direction[2] = glm::normalize(normal);
        }
    } else {
        for (std::size_t a = 0; a < keep.size(); ++a)
            geometry.spacing[static_cast<int>(a)] = spacings[keep[a]];
    }
    if (const std::string* so = field("spaceorigin")) {
        const auto v = parseVector(trim(*so), what + ": space origin");
        if (v.size() != spaceDim) throw Error(what + ": 'space origin' has the wrong length");
        geometry.origin = glm::dvec3(v[0], v[1], spaceDim == 3 ? v[2] : 0.0) * toLps;
    }

    // Encoding and byte order.
    const std::string encoding = toLower(required("encoding", "encoding"));
    enum class Encoding { Raw, Gzip, Ascii } enc;
    if (encoding == "raw")
        enc = Encoding::Raw;
    else if (encoding == "gzip" || encoding == "gz")
        enc = Encoding::Gzip;
    else if (encoding == "ascii" || encoding == "text" || encoding == "txt")
        enc = Encoding::Ascii;
    else
        throw Error(what + ": NRRD encoding '" + encoding +
                    "' is not supported (raw, gzip, ascii)");
    bool swap = false;
    if (enc != Encoding::Ascii && scalarSize(type) > 1) {
        const std::string endian = toLower(required("endian", "endian"));
        if (endian != "little" && endian != "big")
            throw Error(what + ": endian '" + endian + "' must be little or big");
        swap = (endian == "little") != hostIsLittleEndian();
    }
    long long lineSkip = 0, byteSkip = 0;
    if (const std::string* ls = field("lineskip"))
        lineSkip = parseInteger(*ls, what + ": line skip");
    if (const std::string* bs = field("byteskip"))
        byteSkip = parseInteger(*bs, what + ": byte skip");
    if (lineSkip < 0) throw Error(what + ": negative line skip");
    if (byteSkip < -1) throw Error(what + ": byte skip must be -1 or more");
    if (byteSkip == -1 && enc != Encoding::Raw)
        throw Error(what + ": byte skip -1 is only allowed with raw encoding");

    // Data files: attached, one detached file, a numbered list, or LIST.
    std::vector<fs::path> files;
    bool attached = false;
    long long subdim = static_cast<long long>(nd);
    if (const std::string* df = field("datafile")) {
        const auto words = splitWords(*df);
        if (words.empty()) throw Error(what + ": empty 'data file'");
        auto resolve = [&](const std::string& name) {
            const fs::path p(name);
            return p.is_absolute() ? p : path.parent_path() / p;
        };
        if (equalsIgnoreCase(words[0], "LIST")) {
            subdim = nd - 1;
            if (words.size() > 1) subdim = parseInteger(words[1], what + ": LIST dimension");
            for (const auto& name : listedFiles) files.push_back(resolve(name));
        } else if (words.size() >= 4 && words[0].find('%') != std::string::npos) {
            const long long first = parseInteger(words[1], what + ": data file start");
            const long long last = parseInteger(words[2], what + ": data file end");
            const long long step = parseInteger(words[3], what + ": data file step");
            subdim = nd - 1;
            if (words.size() > 4) subdim = parseInteger(words[4], what + ": data file dimension");
            for (long long k : numberRange(first, last, step, std::min(n[0] * n[1] * n[2], kMaxNrrdDataFiles), what))
                files.push_back(resolve(formatFileNumber(words[0], k, what)));
        } else {
            files.push_back(resolve(*df));
        }
    } else {
        if (!headerEnded)
            throw Error(what + ": NRRD header has no data (no blank line and no 'data file')");
        attached = true;
        files.push_back(path);
    }
    if (subdim < 1 || subdim > static_cast<long long>(nd))
        throw Error(what + ": data file dimension " + std::to_string(subdim) + " is invalid");
    long long expectedFiles = 1;
    for (std::size_t a = static_cast<std::size_t>(subdim); a < nd; ++a) expectedFiles *= sizes[a];
    if (static_cast<long long>(files.size()) != expectedFiles)
        throw Error(what + ": 'data file' names " + std::to_string(files.size()) +
                    " files, the sizes need " + std::to_string(expectedFiles));

    const std::size_t totalBytes = rawByteCount(dims, type);
    const std::size_t perFile = totalBytes / files.size();
    Bytes raw;
    std::string asciiText;
    std::optional<Volume> streamed;
    for (const fs::path& file : files) {
        std::uintmax_t offset = attached ? attachedStart : 0;
        offset = skipLines(file, offset, lineSkip);
        if (enc == Encoding::Raw) {
            if (byteSkip == -1) {
                const std::uintmax_t size = fileSize(file);
                if (size < perFile + offset)
                    throw Error(quoted(file) + " is truncated: " + std::to_string(perFile) +
                                " bytes of data expected, the file has " + std::to_string(size));
                offset = size - perFile;
            } else {
                offset += static_cast<std::uintmax_t>(byteSkip);
            }
            if (files.size() == 1) {
                // The usual case: one run of raw samples, converted as it is read.
                streamed = volumeFromFile(dims, file, offset, type, swap, what);
                break;
            }
            const Bytes part = readFileRange(file, offset, perFile);
            raw.insert(raw.end(), part.begin(), part.end());
        } else if (enc == Encoding::Gzip) {
            // byte skip counts decompressed bytes (as in teem).
            const auto skip = static_cast<std::size_t>(byteSkip);
            const Bytes part = readSampleBytes(file, offset, perFile + skip, true);
            raw.insert(raw.end(), part.begin() + static_cast<std::ptrdiff_t>(skip), part.end());
        } else {
            const std::uintmax_t size = fileSize(file);
            if (size > (std::uintmax_t{1} << 34)) throw Error(quoted(file) + " is too large");
            offset = std::min(offset + static_cast<std::uintmax_t>(byteSkip), size);
            const Bytes part = readFileRange(file, offset, size - offset);
            asciiText.append(part.begin(), part.end());
            asciiText += '\n';
        }
    }

    Volume v = streamed                  ? std::move(*streamed)
               : enc == Encoding::Ascii ? volumeFromText(dims, asciiText, what)
                                        : volumeFromRaw(dims, raw, 0, type, swap, what);
    v.spacing = geometry.spacing;
    v.direction = geometry.direction;
    v.origin = geometry.origin;
    v.meta.source = path.string();
    v.meta.description = std::string("NRRD, ") + toString(type) + ", " + encoding;
    if (spaceName) v.meta.description += ", space " + *spaceName;
    if (const std::string* content = field("content")) v.meta.description += ": " + *content;
    v.validate(what);
    return v;
}

}  // namespace fm
