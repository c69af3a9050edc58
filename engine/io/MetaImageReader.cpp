#include "io/MetaImageReader.h"

#include <algorithm>
#include <cmath>
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

// Headers are a few hundred bytes; anything without ElementDataFile in the first MiB is not
// a MetaImage header.
constexpr std::size_t kMaxMetaHeaderBytes = 1 << 20;
// More slice files than this is a corrupt header, not a CT.
constexpr long long kMaxMetaDataFiles = 1 << 20;

ScalarType metaScalarType(const std::string& name, const std::string& what) {
    static const std::map<std::string, ScalarType> kTypes = {
        {"MET_UCHAR", ScalarType::U8},       {"MET_CHAR", ScalarType::I8},
        {"MET_USHORT", ScalarType::U16},     {"MET_SHORT", ScalarType::I16},
        {"MET_UINT", ScalarType::U32},       {"MET_INT", ScalarType::I32},
        {"MET_ULONG", ScalarType::U32},      {"MET_LONG", ScalarType::I32},  // 4 bytes in MetaIO
        {"MET_ULONG_LONG", ScalarType::U64}, {"MET_LONG_LONG", ScalarType::I64},
        {"MET_FLOAT", ScalarType::F32},      {"MET_DOUBLE", ScalarType::F64},
    };
    const auto it = kTypes.find(name);
    if (it == kTypes.end())
        throw Error(what + ": unsupported ElementType '" + name + "' (need a scalar MET_ type)");
    return it->second;
}

bool parseBool(const std::string& value, const std::string& what) {
    if (equalsIgnoreCase(value, "true") || value == "1") return true;
    if (equalsIgnoreCase(value, "false") || value == "0") return false;
    throw Error(what + ": '" + value + "' is not True or False");
}

}  // namespace

Volume readMetaImage(const fs::path& path) {
    const std::string what = quoted(path);
    const Bytes head = readFilePrefix(path, kMaxMetaHeaderBytes);
    const std::string_view text(reinterpret_cast<const char*>(head.data()), head.size());

    // Key = Value lines up to ElementDataFile, which ends the header.
    std::map<std::string, std::string> fields;  // lower-case key -> value
    std::size_t pos = 0, dataStart = 0;
    std::string line;
    bool ended = false;
    while (nextLine(text, pos, line)) {
        const std::string trimmed = trim(line);
        if (trimmed.empty()) continue;
        const std::size_t eq = trimmed.find('=');
        if (eq == std::string::npos)
            throw Error(what + ": malformed MetaImage header line '" + trimmed.substr(0, 80) + "'");
        const std::string key = toLower(trim(std::string_view(trimmed).substr(0, eq)));
        fields[key] = trim(std::string_view(trimmed).substr(eq + 1));
        if (key == "elementdatafile") {
            ended = true;
            dataStart = pos;
            break;
        }
    }
    if (!ended) throw Error(what + ": not a MetaImage header (no ElementDataFile line)");
    auto field = [&](const char* key) -> const std::string* {
        const auto it = fields.find(key);
        return it == fields.end() ? nullptr : &it->second;
    };
    auto fieldFirst = [&](std::initializer_list<const char*> keys) -> const std::string* {
        for (const char* k : keys)
            if (const std::string* v = field(k)) return v;
        return nullptr;
    };

    if (const std::string* type = field("objecttype"); type && !equalsIgnoreCase(*type, "Image"))
        throw Error(what + ": ObjectType '" + *type + "' is not an Image");
    const std::string* ndimsText = field("ndims");
    if (!ndimsText) throw Error(what + ": NDims is missing");
    const long long ndims = parseInteger(*ndimsText, what + ": NDims");
    if (ndims < 1 || ndims > 4) throw Error(what + ": NDims " + *ndimsText + " must be 1..4");
    const auto nd = static_cast<std::size_t>(ndims);

    const std::string* dimText = field("dimsize");
    if (!dimText) throw Error(what + ": DimSize is missing");
    const auto dimValues = parseNumbers(*dimText, nd, what + ": DimSize");
    long long n[4] = {1, 1, 1, 1};
    for (std::size_t a = 0; a < nd; ++a) {
        if (dimValues[a] != std::floor(dimValues[a]) || dimValues[a] < 1 || dimValues[a] > 2e9)
            throw Error(what + ": DimSize '" + *dimText + "' must hold positive integers");
        n[a] = static_cast<long long>(dimValues[a]);
    }
    if (n[3] != 1) throw Error(what + ": 4D images (DimSize " + *dimText + ") are not supported");
    const glm::ivec3 dims = checkedDims(n[0], n[1], n[2], what);
    const std::size_t spatial = std::min<std::size_t>(nd, 3);

    if (const std::string* ch = field("elementnumberofchannels");
        ch && parseInteger(*ch, what + ": ElementNumberOfChannels") != 1)
        throw Error(what + ": ElementNumberOfChannels " + *ch + " is not supported (need 1)");
    const std::string* typeText = field("elementtype");
    if (!typeText) throw Error(what + ": ElementType is missing");
    const ScalarType type = metaScalarType(*typeText, what);

    glm::dvec3 spacing{1.0}, origin{0.0};
    glm::dmat3 direction{1.0};
    if (const std::string* s = fieldFirst({"elementspacing", "elementsize"})) {
        const auto v = parseNumbers(*s, nd, what + ": ElementSpacing");
        for (std::size_t a = 0; a < spatial; ++a) spacing[a] = v[a];
    }
    if (const std::string* o = fieldFirst({"offset", "position", "origin"})) {
        const auto v = parseNumbers(*o, nd, what + ": Offset");
        for (std::size_t a = 0; a < spatial; ++a) origin[a] = v[a];
    }
    if (const std::string* m =
            fieldFirst({"transformmatrix", "rotation", "orientation", "direction"})) {
        // nd x nd values; each consecutive group of nd is one axis direction (as ITK writes).
        const auto v = parseNumbers(*m, nd * nd, what + ": TransformMatrix");
        for (std::size_t a = 0; a < spatial; ++a)
            for (std::size_t w = 0; w < spatial; ++w) direction[a][w] = v[a * nd + w];
    }

    const bool binary =
        !field("binarydata") || parseBool(*field("binarydata"), what + ": BinaryData");
    bool msb = false;
    if (const std::string* b = fieldFirst({"binarydatabyteordermsb", "elementbyteordermsb"}))
        msb = parseBool(*b, what + ": BinaryDataByteOrderMSB");
    const bool compressed =
        field("compresseddata") && parseBool(*field("compresseddata"), what + ": CompressedData");
    long long headerSize = 0;
    if (const std::string* hs = field("headersize"))
        headerSize = parseInteger(*hs, what + ": HeaderSize");
    if (headerSize < -1)
        throw Error(what + ": HeaderSize " + std::to_string(headerSize) + " is invalid");

    const std::size_t totalBytes = rawByteCount(dims, type);
    const std::string dataFile = *field("elementdatafile");
    const fs::path folder = path.parent_path();

    // The list of data files and how many bytes each holds.
    std::vector<fs::path> files;
    const auto words = splitWords(dataFile);
    if (dataFile.empty()) throw Error(what + ": ElementDataFile is empty");
    long long subdim = static_cast<long long>(spatial) - 1;
    if (equalsIgnoreCase(dataFile, "LOCAL")) {
        subdim = static_cast<long long>(spatial);
        files.push_back(path);
    } else if (equalsIgnoreCase(words[0], "LIST")) {
        if (words.size() > 1) {  // "LIST 2D" (MetaIO's form) or "LIST 2"
            std::string d = words[1];
            if (!d.empty() && (d.back() == 'D' || d.back() == 'd')) d.pop_back();
            subdim = parseInteger(d, what + ": LIST dimension");
        }
        std::string name;
        while (nextLine(text, pos, name)) {
            if (!trim(name).empty()) files.push_back(folder / trim(name));
        }
    } else if (words.size() >= 4 && dataFile.find('%') != std::string::npos) {
        const long long first = parseInteger(words[1], what + ": file list start");
        const long long last = parseInteger(words[2], what + ": file list end");
        const long long step = parseInteger(words[3], what + ": file list step");
        if (words.size() > 4) subdim = parseInteger(words[4], what + ": file list dimension");
        // Checked against the volume before any name is made: a corrupt range cannot loop long.
        for (long long k : numberRange(first, last, step, std::min(n[0] * n[1] * n[2], kMaxMetaDataFiles), what))
            files.push_back(folder / formatFileNumber(words[0], k, what));
    } else {
        subdim = static_cast<long long>(spatial);
        files.push_back(folder / dataFile);
    }
    if (subdim < 1 || subdim > static_cast<long long>(spatial))
        throw Error(what + ": file list dimension " + std::to_string(subdim) + " is invalid");
    if (files.empty()) throw Error(what + ": ElementDataFile lists no files");
    // Each file holds the first `subdim` axes; the files stack along the rest.
    long long expectedFiles = 1;
    for (long long a = subdim; a < static_cast<long long>(spatial); ++a) expectedFiles *= n[a];
    if (static_cast<long long>(files.size()) != expectedFiles)
        throw Error(what + ": ElementDataFile lists " + std::to_string(files.size()) +
                    " files, the dimensions need " + std::to_string(expectedFiles));

    const bool local = files.size() == 1 && files[0] == path;
    const std::size_t perFile = totalBytes / files.size();
    // Where a file's samples start: after the header in the .mha itself, after HeaderSize bytes
    // in a data file, or (HeaderSize -1) the last perFile bytes of it.
    auto dataOffset = [&](const fs::path& file) {
        std::uintmax_t offset =
            local ? dataStart : static_cast<std::uintmax_t>(std::max<long long>(headerSize, 0));
        if (!local && headerSize == -1 && !compressed) {
            const std::uintmax_t size = fileSize(file);
            if (size < perFile)
                throw Error(quoted(file) + " is truncated: " + std::to_string(perFile) +
                            " bytes of data expected, the file has " + std::to_string(size));
            offset = size - perFile;
        }
        return offset;
    };
    const bool swapBytes = msb == hostIsLittleEndian();
    Bytes raw;
    std::string asciiText;
    std::optional<Volume> streamed;
    if (binary && !compressed && files.size() == 1) {
        // The usual case: one uncompressed run of samples, converted as it is read.
        streamed = volumeFromFile(dims, files[0], dataOffset(files[0]), type, swapBytes, what);
    } else if (binary) {
        raw.reserve(std::min<std::size_t>(totalBytes, 1 << 26));
        for (const fs::path& file : files) {
            const Bytes part = readSampleBytes(file, dataOffset(file), perFile, compressed);
            raw.insert(raw.end(), part.begin(), part.end());
        }
    } else {
        if (compressed) throw Error(what + ": compressed ASCII data is not supported");
        for (const fs::path& file : files) {
            const std::uintmax_t offset = local ? dataStart : 0;
            const std::uintmax_t size = fileSize(file);
            if (size > (std::uintmax_t{1} << 34)) throw Error(quoted(file) + " is too large");
            const Bytes part =
                readFileRange(file, std::min(offset, size), size - std::min(offset, size));
            asciiText.append(part.begin(), part.end());
        }
    }

    Volume v = streamed ? std::move(*streamed)
               : binary ? volumeFromRaw(dims, raw, 0, type, swapBytes, what)
                        : volumeFromText(dims, asciiText, what);
    v.spacing = spacing;
    v.origin = origin;
    v.direction = direction;
    v.meta.source = path.string();
    if (const std::string* mod = field("modality")) {
        if (*mod == "MET_MOD_CT")
            v.meta.modality = "CT";
        else if (*mod == "MET_MOD_MR")
            v.meta.modality = "MR";
    }
    v.meta.description = std::string("MetaImage, ") + toString(type);
    // AnatomicalOrientation is informative only: the direction matrix is what ITK uses.
    if (const std::string* ao = field("anatomicalorientation"))
        v.meta.description += ", AnatomicalOrientation " + *ao;
    v.validate(what);
    return v;
}

}  // namespace fm
