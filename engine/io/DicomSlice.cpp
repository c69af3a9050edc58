#include "io/DicomSlice.h"

#include <gdcmImage.h>
#include <gdcmImageReader.h>
#include <gdcmReader.h>
#include <gdcmSequenceOfFragments.h>
#include <gdcmTrace.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <limits>
#include <mutex>
#include <set>
#include <sstream>

#include "core/Error.h"
#include "io/DicomFileCheck.h"

namespace fm {
namespace {

const gdcm::Tag kPixelDataTag(0x7fe0, 0x0010);

// Absurdity bounds for geometry: no scanner writes these; a file that does is corrupt.
constexpr double kMaxPixelSpacingMm = 500.0;     // a whole body on a 1x1 image
constexpr double kMaxCoordinateMm = 1.0e6;       // 1 km from the scanner origin
constexpr double kUnitVectorTolerance = 1.0e-2;  // IOP cosines are stored with ~6 digits
constexpr double kPerpendicularTolerance = 1.0e-2;

std::string fileLabel(const std::filesystem::path& file) {
    return file.string();
}

[[noreturn]] void fail(const std::filesystem::path& file, const std::string& why) {
    throw Error(fileLabel(file) + ": " + why);
}

// What GDCM parses: the checked bytes, without the trailing padding DicomFileCheck ignores
// (from memory, so that what GDCM reads is what was checked).
std::istringstream checkedBytes(const std::vector<unsigned char>& content,
                                const DicomFileCheck& check) {
    const auto end = content.begin() + static_cast<std::ptrdiff_t>(check.contentBytes);
    return std::istringstream(std::string(content.begin(), end));
}

std::string trim(std::string s) {
    const auto isPad = [](char c) {
        return c == ' ' || c == '\0' || c == '\t' || c == '\r' || c == '\n';
    };
    while (!s.empty() && isPad(s.back())) s.pop_back();
    std::size_t start = 0;
    while (start < s.size() && isPad(s[start])) ++start;
    return s.substr(start);
}

// Text value of an element: nullopt when absent, "" when present but empty.
std::optional<std::string> textValue(const gdcm::DataSet& ds, const gdcm::Tag& tag) {
    if (!ds.FindDataElement(tag)) return std::nullopt;
    const gdcm::DataElement& de = ds.GetDataElement(tag);
    const gdcm::ByteValue* bv = de.GetByteValue();
    if (!bv || !bv->GetPointer()) return std::string();
    return trim(std::string(bv->GetPointer(), bv->GetLength()));
}

std::string textOrEmpty(const gdcm::DataSet& ds, const gdcm::Tag& tag) {
    return textValue(ds, tag).value_or(std::string());
}

// Backslash-separated decimal strings (DS, IS). Tokens that are not numbers become NaN so
// that validation can name the field instead of silently using a default.
std::optional<std::vector<double>> decimals(const gdcm::DataSet& ds, const gdcm::Tag& tag) {
    const auto text = textValue(ds, tag);
    if (!text || text->empty()) return std::nullopt;
    std::vector<double> values;
    std::size_t start = 0;
    while (start <= text->size()) {
        std::size_t end = text->find('\\', start);
        if (end == std::string::npos) end = text->size();
        const std::string token = trim(text->substr(start, end - start));
        double v = std::numeric_limits<double>::quiet_NaN();
        if (!token.empty()) {
            char* stop = nullptr;
            const double parsed = std::strtod(token.c_str(), &stop);
            if (stop && *stop == '\0') v = parsed;
        }
        values.push_back(v);
        start = end + 1;
        if (values.size() > 64) break;  // garbage, not a value list
    }
    return values;
}

std::optional<double> decimal(const gdcm::DataSet& ds, const gdcm::Tag& tag) {
    const auto values = decimals(ds, tag);
    if (!values || values->empty()) return std::nullopt;
    return values->front();
}

// A 16-bit binary value (US/SS), in the data set's byte order.
std::optional<std::uint16_t> uint16Value(const gdcm::DataSet& ds, const gdcm::Tag& tag,
                                         bool bigEndian) {
    if (!ds.FindDataElement(tag)) return std::nullopt;
    const gdcm::ByteValue* bv = ds.GetDataElement(tag).GetByteValue();
    if (!bv || !bv->GetPointer() || bv->GetLength() < 2) return std::nullopt;
    const auto* p = reinterpret_cast<const unsigned char*>(bv->GetPointer());
    return bigEndian ? static_cast<std::uint16_t>((p[0] << 8) | p[1])
                     : static_cast<std::uint16_t>(p[0] | (p[1] << 8));
}

int uint16OrZero(const gdcm::DataSet& ds, const gdcm::Tag& tag, bool bigEndian) {
    return uint16Value(ds, tag, bigEndian).value_or(0);
}

bool isFiniteVector(const std::vector<double>& v) {
    for (double x : v)
        if (!std::isfinite(x)) return false;
    return true;
}

std::string joinValues(const std::vector<double>& v) {
    std::ostringstream out;
    for (std::size_t i = 0; i < v.size(); ++i) out << (i ? "\\" : "") << v[i];
    return out.str();
}

}  // namespace

void silenceGdcmTrace() {
    // GDCM switches its warning flag back on internally, so the flags alone do not hold:
    // route all three streams into a buffer that drops everything (stateless, so concurrent
    // writes from decoding threads are harmless).
    struct DiscardBuffer : std::streambuf {
        int overflow(int c) override { return traits_type::not_eof(c); }
        std::streamsize xsputn(const char*, std::streamsize n) override { return n; }
    };
    static DiscardBuffer buffer;
    static std::ostream discard(&buffer);
    static std::once_flag once;
    std::call_once(once, [] {
        gdcm::Trace::SetStream(discard);
        gdcm::Trace::DebugOff();
        gdcm::Trace::WarningOff();
        gdcm::Trace::ErrorOff();
    });
}

namespace {

std::uint32_t bigEndian32(const unsigned char* p) {
    return (std::uint32_t(p[0]) << 24) | (std::uint32_t(p[1]) << 16) | (std::uint32_t(p[2]) << 8) |
           std::uint32_t(p[3]);
}

// The SIZ marker of a JPEG 2000 code stream (ISO 15444-1 A.5.1) against the DICOM header.
void checkJpeg2000Size(const DicomSliceHeader& h, const unsigned char* data, std::size_t size) {
    // The code stream starts with SOC (FF4F) then SIZ (FF51); a JP2 file wrapper puts boxes
    // first, so the pair is searched near the start of the fragment.
    const std::size_t searchEnd = std::min<std::size_t>(size, 4096);
    std::size_t at = 0;
    while (at + 4 <= searchEnd &&
           !(data[at] == 0xff && data[at + 1] == 0x4f && data[at + 2] == 0xff && data[at + 3] == 0x51))
        ++at;
    if (at + 4 > searchEnd) fail(h.file, "JPEG 2000 pixel data without a SIZ header");
    const unsigned char* siz = data + at + 4;  // Lsiz follows the marker
    if (at + 4 + 41 > size) fail(h.file, "JPEG 2000 SIZ header cut off");
    const std::uint32_t xsiz = bigEndian32(siz + 4), ysiz = bigEndian32(siz + 8);
    const std::uint32_t x0 = bigEndian32(siz + 12), y0 = bigEndian32(siz + 16);
    const std::uint32_t tileW = bigEndian32(siz + 20), tileH = bigEndian32(siz + 24);
    const unsigned components = (unsigned(siz[36]) << 8) | siz[37];
    const int depth = (siz[38] & 0x7f) + 1;
    const bool sizeAgrees = xsiz > x0 && ysiz > y0 && xsiz - x0 == std::uint32_t(h.columns) &&
                            ysiz - y0 == std::uint32_t(h.rows);
    if (!sizeAgrees || components != 1 || tileW == 0 || tileH == 0 ||
        (h.bitsAllocated > 0 && depth > h.bitsAllocated))
        fail(h.file, "JPEG 2000 code stream claims " + std::to_string(xsiz) + " x " +
                         std::to_string(ysiz) + " (offset " + std::to_string(x0) + ", " +
                         std::to_string(y0) + "), " + std::to_string(components) +
                         " component(s) of " + std::to_string(depth) + " bits, tiles " +
                         std::to_string(tileW) + " x " + std::to_string(tileH) +
                         "; the header says " + std::to_string(h.columns) + " x " +
                         std::to_string(h.rows) + ", 1 component of up to " +
                         std::to_string(h.bitsAllocated) + " bits");
}

void checkClaimedImageSize(const DicomSliceHeader& h, const DicomFileCheck& check,
                           const std::vector<unsigned char>& content) {
    if (h.rows <= 0 || h.columns <= 0 || !check.hasPixelData) return;  // refused when decoded
    if (!check.encapsulated) {
        const std::size_t bytesPerPixel = std::max(1, h.bitsAllocated / 8);
        // One frame's worth (multi-frame files are refused, with their own message, later).
        const std::size_t need = std::size_t(h.rows) * std::size_t(h.columns) * bytesPerPixel;
        if (need > check.pixelDataLength)
            fail(h.file, "pixel data is " + std::to_string(check.pixelDataLength) +
                             " bytes, but Rows x Columns x BitsAllocated (" +
                             std::to_string(h.rows) + " x " + std::to_string(h.columns) + " x " +
                             std::to_string(h.bitsAllocated) + ") promise " +
                             std::to_string(need) + " (corrupt header or truncated file)");
        return;
    }
    const bool jpeg2000 = h.transferSyntax == "1.2.840.10008.1.2.4.90" ||
                          h.transferSyntax == "1.2.840.10008.1.2.4.91";
    if (jpeg2000 && check.firstFragmentLength > 0 &&
        check.firstFragmentOffset + check.firstFragmentLength <= content.size())
        checkJpeg2000Size(h, content.data() + check.firstFragmentOffset,
                          check.firstFragmentLength);
}

}  // namespace

std::optional<DicomSliceHeader> readDicomSliceHeader(const std::filesystem::path& file) {
    silenceGdcmTrace();
    // GDCM only sees files whose byte structure is sound (see DicomFileCheck.h).
    std::vector<unsigned char> content;
    const DicomFileCheck check = checkDicomFile(file, &content);
    if (!check.wellFormed) {
        if (check.hasMagic) fail(file, "corrupt DICOM file: " + check.problem);
        return std::nullopt;  // not DICOM: README, licence text, ...
    }
    gdcm::Reader reader;
    std::istringstream stream = checkedBytes(content, check);
    reader.SetStream(stream);
    bool ok = false;
    try {
        // Stop at the pixel data without loading it: the header pass must stay cheap on large
        // folders.
        ok = reader.ReadUpToTag(kPixelDataTag, std::set<gdcm::Tag>{kPixelDataTag});
    } catch (const std::exception&) {
        ok = false;
    }
    if (!ok) {
        if (check.hasMagic) fail(file, "corrupt DICOM file: its header cannot be parsed");
        return std::nullopt;  // not DICOM: README, licence text, ...
    }
    const gdcm::DataSet& ds = reader.GetFile().GetDataSet();
    const gdcm::TransferSyntax& ts = reader.GetFile().GetHeader().GetDataSetTransferSyntax();
    const bool bigEndian = ts == gdcm::TransferSyntax::ExplicitVRBigEndian;

    DicomSliceHeader h;
    h.file = file;
    h.rows = uint16OrZero(ds, gdcm::Tag(0x0028, 0x0010), bigEndian);
    h.columns = uint16OrZero(ds, gdcm::Tag(0x0028, 0x0011), bigEndian);
    if (!ds.FindDataElement(gdcm::Tag(0x0028, 0x0010)) &&
        !ds.FindDataElement(gdcm::Tag(0x0028, 0x0011)))
        return std::nullopt;  // a DICOM object that is not an image (DICOMDIR, SR, ...)

    // The UID as written (GDCM maps unknown ones to an invalid value; we want to name it).
    h.transferSyntax = !check.transferSyntax.empty() ? check.transferSyntax
                       : ts.IsValid()                ? ts.GetString()
                                                     : "";
    h.seriesInstanceUid = textOrEmpty(ds, gdcm::Tag(0x0020, 0x000e));
    h.studyInstanceUid = textOrEmpty(ds, gdcm::Tag(0x0020, 0x000d));
    h.frameOfReferenceUid = textOrEmpty(ds, gdcm::Tag(0x0020, 0x0052));
    h.seriesNumber = textOrEmpty(ds, gdcm::Tag(0x0020, 0x0011));
    h.modality = textOrEmpty(ds, gdcm::Tag(0x0008, 0x0060));
    h.seriesDescription = textOrEmpty(ds, gdcm::Tag(0x0008, 0x103e));
    h.rescaleType = textOrEmpty(ds, gdcm::Tag(0x0028, 0x1054));
    if (const auto n = decimal(ds, gdcm::Tag(0x0020, 0x0013));
        n && std::isfinite(*n) && std::abs(*n) < 1e15)
        h.instanceNumber = static_cast<long>(*n);

    if (const auto frames = decimal(ds, gdcm::Tag(0x0028, 0x0008))) {
        h.numberOfFrames = (std::isfinite(*frames) && *frames >= 0 && *frames < 1e9)
                               ? static_cast<int>(*frames)
                               : -1;
    }
    h.samplesPerPixel = uint16Value(ds, gdcm::Tag(0x0028, 0x0002), bigEndian).value_or(1);
    h.bitsAllocated = uint16OrZero(ds, gdcm::Tag(0x0028, 0x0100), bigEndian);
    h.bitsStored = uint16OrZero(ds, gdcm::Tag(0x0028, 0x0101), bigEndian);
    h.pixelRepresentation = uint16OrZero(ds, gdcm::Tag(0x0028, 0x0103), bigEndian);
    if (const auto highBit = uint16Value(ds, gdcm::Tag(0x0028, 0x0102), bigEndian))
        h.highBit = *highBit;
    h.photometricInterpretation = textOrEmpty(ds, gdcm::Tag(0x0028, 0x0004));

    h.imageOrientation = decimals(ds, gdcm::Tag(0x0020, 0x0037));
    h.imagePosition = decimals(ds, gdcm::Tag(0x0020, 0x0032));
    h.pixelSpacing = decimals(ds, gdcm::Tag(0x0028, 0x0030));
    h.sliceThickness = decimal(ds, gdcm::Tag(0x0018, 0x0050));
    h.gantryTilt = decimal(ds, gdcm::Tag(0x0018, 0x1120));

    if (const auto slope = decimal(ds, gdcm::Tag(0x0028, 0x1053))) {
        if (!std::isfinite(*slope) || *slope == 0.0 || std::abs(*slope) > 1e6)
            fail(file,
                 "absurd RescaleSlope (0028,1053): " + textOrEmpty(ds, gdcm::Tag(0x0028, 0x1053)));
        h.rescaleSlope = *slope;
    }
    if (const auto intercept = decimal(ds, gdcm::Tag(0x0028, 0x1052))) {
        if (!std::isfinite(*intercept) || std::abs(*intercept) > 1e9)
            fail(file, "absurd RescaleIntercept (0028,1052): " +
                           textOrEmpty(ds, gdcm::Tag(0x0028, 0x1052)));
        h.rescaleIntercept = *intercept;
    }
    // PixelPaddingValue has the pixels' signedness (US or SS).
    const auto asStored = [&](std::uint16_t raw) -> long {
        return h.pixelRepresentation == 1 ? static_cast<long>(static_cast<std::int16_t>(raw))
                                          : static_cast<long>(raw);
    };
    if (const auto pad = uint16Value(ds, gdcm::Tag(0x0028, 0x0120), bigEndian))
        h.pixelPaddingValue = asStored(*pad);
    if (const auto limit = uint16Value(ds, gdcm::Tag(0x0028, 0x0121), bigEndian))
        h.pixelPaddingRangeLimit = asStored(*limit);
    h.encapsulated = check.encapsulated;
    h.pixelDataLength = check.pixelDataLength;
    h.contentBytes = check.contentBytes;
    h.trailingBytes = check.trailingBytes;
    checkClaimedImageSize(h, check, content);
    return h;
}

DicomSliceGeometry dicomSliceGeometry(const DicomSliceHeader& h) {
    DicomSliceGeometry g;
    if (!h.imagePosition) fail(h.file, "missing ImagePositionPatient (0020,0032)");
    if (!h.imageOrientation) fail(h.file, "missing ImageOrientationPatient (0020,0037)");
    if (!h.pixelSpacing) fail(h.file, "missing PixelSpacing (0028,0030)");
    const auto& ipp = *h.imagePosition;
    const auto& iop = *h.imageOrientation;
    const auto& ps = *h.pixelSpacing;
    if (ipp.size() != 3 || !isFiniteVector(ipp))
        fail(h.file,
             "ImagePositionPatient (0020,0032) must be 3 numbers, got '" + joinValues(ipp) + "'");
    for (double x : ipp)
        if (std::abs(x) > kMaxCoordinateMm)
            fail(h.file, "absurd ImagePositionPatient (0020,0032): " + joinValues(ipp));
    if (iop.size() != 6 || !isFiniteVector(iop))
        fail(h.file, "ImageOrientationPatient (0020,0037) must be 6 numbers, got '" +
                         joinValues(iop) + "'");
    if (ps.size() != 2 || !isFiniteVector(ps) || ps[0] <= 0.0 || ps[1] <= 0.0 ||
        ps[0] > kMaxPixelSpacingMm || ps[1] > kMaxPixelSpacingMm)
        fail(h.file, "absurd PixelSpacing (0028,0030): '" + joinValues(ps) +
                         "' (expected two positive spacings in mm)");

    glm::dvec3 row(iop[0], iop[1], iop[2]);
    glm::dvec3 col(iop[3], iop[4], iop[5]);
    if (std::abs(glm::length(row) - 1.0) > kUnitVectorTolerance ||
        std::abs(glm::length(col) - 1.0) > kUnitVectorTolerance ||
        std::abs(glm::dot(row, col)) > kPerpendicularTolerance)
        fail(h.file, "ImageOrientationPatient (0020,0037) is not two perpendicular unit vectors: " +
                         joinValues(iop));
    // Gram-Schmidt: files store cosines with ~6 digits; the volume wants orthonormal axes.
    row = glm::normalize(row);
    col = glm::normalize(col - glm::dot(col, row) * row);
    g.rowDirection = row;
    g.columnDirection = col;
    g.position = glm::dvec3(ipp[0], ipp[1], ipp[2]);
    // PixelSpacing is (between rows, between columns) = (along col dir, along row dir).
    g.spacing = glm::dvec2(ps[1], ps[0]);
    return g;
}

namespace {

// Stored integer value of one pixel from the decoded buffer, honouring BitsStored/HighBit and
// the sign bit (GDCM hands back whole allocated words; unused high bits may hold overlays).
template <typename Word>
long storedValue(Word word, int shift, int bitsStored, bool isSigned) {
    using Unsigned = std::make_unsigned_t<Word>;
    std::uint64_t u = static_cast<Unsigned>(word);
    u >>= shift;
    if (bitsStored < 64) u &= (std::uint64_t{1} << bitsStored) - 1;
    if (isSigned && bitsStored < 64 && ((u >> (bitsStored - 1)) & 1u))
        return static_cast<long>(static_cast<std::int64_t>(u) - (std::int64_t{1} << bitsStored));
    return static_cast<long>(u);
}

template <typename Word>
void convertPixels(const char* buffer, std::size_t count, int shift, int bitsStored, bool isSigned,
                   const DicomSliceHeader& h, float paddingValue, std::vector<float>& out) {
    out.resize(count);
    const bool hasPadding = h.pixelPaddingValue.has_value();
    long padLow = 0, padHigh = 0;
    if (hasPadding) {
        padLow = *h.pixelPaddingValue;
        padHigh = h.pixelPaddingRangeLimit.value_or(padLow);
        if (padHigh < padLow) std::swap(padLow, padHigh);
    }
    for (std::size_t n = 0; n < count; ++n) {
        Word word;
        std::memcpy(&word, buffer + n * sizeof(Word), sizeof(Word));
        const long stored = storedValue(word, shift, bitsStored, isSigned);
        if (hasPadding && stored >= padLow && stored <= padHigh) {
            out[n] = paddingValue;
        } else {
            out[n] = static_cast<float>(static_cast<double>(stored) * h.rescaleSlope +
                                        h.rescaleIntercept);
        }
    }
}

}  // namespace

std::vector<float> readDicomSlicePixels(const DicomSliceHeader& h, float paddingValue) {
    silenceGdcmTrace();
    if (h.rows <= 0 || h.columns <= 0)
        fail(h.file, "image size is " + std::to_string(h.columns) + " x " + std::to_string(h.rows) +
                         " (Rows/Columns missing or zero)");
    if (h.numberOfFrames != 1)
        fail(h.file,
             "has NumberOfFrames " + std::to_string(h.numberOfFrames) +
                 ": multi-frame (enhanced) DICOM is not supported, only one slice per file");
    if (h.samplesPerPixel != 1)
        fail(h.file, "has " + std::to_string(h.samplesPerPixel) +
                         " samples per pixel: only greyscale images are supported");
    if (h.bitsAllocated != 8 && h.bitsAllocated != 16 && h.bitsAllocated != 32)
        fail(h.file, "BitsAllocated " + std::to_string(h.bitsAllocated) +
                         " is not supported (8, 16 or 32 expected)");
    // Checked before GDCM interprets them: its pixel-format code asserts on some nonsense.
    if (h.bitsStored < 1 || h.bitsStored > h.bitsAllocated || h.highBit >= h.bitsAllocated ||
        (h.highBit >= 0 && h.highBit + 1 < h.bitsStored))
        fail(h.file,
             "inconsistent BitsAllocated/BitsStored/HighBit: " + std::to_string(h.bitsAllocated) +
                 "/" + std::to_string(h.bitsStored) + "/" + std::to_string(h.highBit));
    if (h.pixelRepresentation != 0 && h.pixelRepresentation != 1)
        fail(h.file, "PixelRepresentation " + std::to_string(h.pixelRepresentation) +
                         " is neither 0 (unsigned) nor 1 (signed)");
    if (h.photometricInterpretation != "MONOCHROME1" &&
        h.photometricInterpretation != "MONOCHROME2")
        fail(h.file, "photometric interpretation '" + h.photometricInterpretation +
                         "' is not supported (greyscale MONOCHROME1/2 expected)");
    if (!h.transferSyntax.empty() &&
        gdcm::TransferSyntax::GetTSType(h.transferSyntax.c_str()) == gdcm::TransferSyntax::TS_END)
        fail(h.file, "unknown transfer syntax " + h.transferSyntax);

    // The file is checked again, and GDCM parses exactly those bytes: the file may have
    // changed since its header was read.
    std::istringstream stream;
    {
        std::vector<unsigned char> content;
        const DicomFileCheck check = checkDicomFile(h.file, &content);
        if (!check.wellFormed) fail(h.file, "corrupt DICOM file: " + check.problem);
        if (check.contentBytes != h.contentBytes || check.encapsulated != h.encapsulated ||
            check.pixelDataLength != h.pixelDataLength)
            fail(h.file, "changed since its header was read");
        checkClaimedImageSize(h, check, content);
        stream = checkedBytes(content, check);
    }
    gdcm::ImageReader reader;
    reader.SetStream(stream);
    bool ok = false;
    try {
        ok = reader.Read();
    } catch (const std::exception& e) {
        fail(h.file, std::string("cannot read the file: ") + e.what());
    }
    const gdcm::DataSet& ds = reader.GetFile().GetDataSet();
    if (!ds.FindDataElement(kPixelDataTag)) fail(h.file, "has no pixel data (7FE0,0010)");
    if (!ok) fail(h.file, "GDCM cannot read this image (transfer syntax " + h.transferSyntax + ")");

    const gdcm::Image& image = reader.GetImage();
    const unsigned int dimensions = image.GetNumberOfDimensions();
    if (dimensions < 2 || dimensions > 3 || image.GetDimension(0) != unsigned(h.columns) ||
        image.GetDimension(1) != unsigned(h.rows) ||
        (dimensions == 3 && image.GetDimension(2) != 1))
        fail(h.file, "image dimensions disagree with Rows/Columns");
    const gdcm::PixelFormat& pf = image.GetPixelFormat();
    if (pf.GetSamplesPerPixel() != 1) fail(h.file, "only greyscale images are supported");
    const auto pi = image.GetPhotometricInterpretation();
    if (pi != gdcm::PhotometricInterpretation::MONOCHROME1 &&
        pi != gdcm::PhotometricInterpretation::MONOCHROME2)
        fail(h.file, std::string("photometric interpretation ") +
                         gdcm::PhotometricInterpretation::GetPIString(pi) +
                         " is not supported (greyscale MONOCHROME1/2 expected)");

    const int bitsAllocated = pf.GetBitsAllocated();
    const int bitsStored = pf.GetBitsStored();
    const int highBit = pf.GetHighBit();
    const int shift = highBit + 1 - bitsStored;
    if (bitsStored < 1 || bitsStored > bitsAllocated || shift < 0 || highBit >= bitsAllocated)
        fail(h.file,
             "inconsistent BitsAllocated/BitsStored/HighBit: " + std::to_string(bitsAllocated) +
                 "/" + std::to_string(bitsStored) + "/" + std::to_string(highBit));

    const std::size_t count =
        static_cast<std::size_t>(h.rows) * static_cast<std::size_t>(h.columns);
    const std::size_t bytesPerPixel = static_cast<std::size_t>(bitsAllocated) / 8;
    const std::size_t expected = count * bytesPerPixel;
    if (image.GetBufferLength() != expected)
        fail(h.file, "decoded size " + std::to_string(image.GetBufferLength()) +
                         " bytes disagrees with the header (" + std::to_string(expected) + ")");

    // Validate what is on disk before any codec touches it: a short native buffer or an empty
    // fragment sequence is reported here rather than handed to the decoder.
    const gdcm::DataElement& pixelData = image.GetDataElement();
    if (image.GetTransferSyntax().IsEncapsulated()) {
        const gdcm::SequenceOfFragments* fragments = pixelData.GetSequenceOfFragments();
        if (!fragments || fragments->GetNumberOfFragments() == 0)
            fail(h.file, "compressed pixel data has no fragments");
    } else {
        const gdcm::ByteValue* bv = pixelData.GetByteValue();
        const std::size_t have = bv ? static_cast<std::size_t>(bv->GetLength()) : 0;
        if (!bv || have < expected)
            fail(h.file, "pixel data is " + std::to_string(have) + " bytes, but " +
                             std::to_string(h.columns) + " x " + std::to_string(h.rows) + " x " +
                             std::to_string(bitsAllocated) + " bits promise " +
                             std::to_string(expected) + " (truncated file?)");
    }

    std::vector<char> buffer(expected);
    bool decoded = false;
    try {
        decoded = image.GetBuffer(buffer.data());
    } catch (const std::exception& e) {
        fail(h.file, std::string("pixel data cannot be decoded: ") + e.what());
    }
    if (!decoded)
        fail(h.file, "pixel data cannot be decoded (transfer syntax " + h.transferSyntax +
                         ", corrupt or unsupported compression)");

    const bool isSigned = pf.GetPixelRepresentation() == 1;
    std::vector<float> out;
    switch (bitsAllocated) {
        case 8:
            convertPixels<std::uint8_t>(buffer.data(), count, shift, bitsStored, isSigned, h,
                                        paddingValue, out);
            break;
        case 16:
            convertPixels<std::uint16_t>(buffer.data(), count, shift, bitsStored, isSigned, h,
                                         paddingValue, out);
            break;
        default:
            convertPixels<std::uint32_t>(buffer.data(), count, shift, bitsStored, isSigned, h,
                                         paddingValue, out);
            break;
    }
    return out;
}

}  // namespace fm
