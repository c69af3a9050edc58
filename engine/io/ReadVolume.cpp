#include "io/ReadVolume.h"

#include <system_error>

#include "core/Error.h"
#include "io/ByteSource.h"
#include "io/DicomReader.h"
#include "io/HeaderText.h"
#include "io/TiffVolume.h"
#include "io/MetaImageReader.h"
#include "io/NiftiReader.h"
#include "io/NrrdReader.h"
#include "io/VtkReader.h"

namespace fm {

using namespace fm::io;
namespace fs = std::filesystem;

namespace {

constexpr std::size_t kSniffBytes = 548;  // a NIfTI-2 header plus its extension flag

std::string formatFromExtension(const fs::path& path) {
    const std::string name = toLower(path.filename().string());
    for (const char* ext : {".nii", ".nii.gz", ".hdr", ".img", ".img.gz"})
        if (endsWith(name, ext)) return "nifti";
    for (const char* ext : {".mha", ".mhd"})
        if (endsWith(name, ext)) return "metaimage";
    for (const char* ext : {".nrrd", ".nhdr"})
        if (endsWith(name, ext)) return "nrrd";
    if (endsWith(name, ".vtk")) return "vtk";
    for (const char* ext : {".tif", ".tiff"})
        if (endsWith(name, ext)) return "tiff";
    return "";
}

bool looksLikeNifti(const Bytes& b) {
    if (b.size() < 8) return false;
    std::uint32_t size;
    std::memcpy(&size, b.data(), 4);
    const std::uint32_t swapped =
        (size >> 24) | ((size >> 8) & 0xff00u) | ((size << 8) & 0xff0000u) | (size << 24);
    auto magicAt = [&](std::size_t at, const char* m) {
        return b.size() >= at + 4 && std::memcmp(b.data() + at, m, 4) == 0;
    };
    if (size == 348 || swapped == 348) return magicAt(344, "n+1\0") || magicAt(344, "ni1\0");
    if (size == 540 || swapped == 540) return magicAt(4, "n+2\0") || magicAt(4, "ni2\0");
    return false;
}

std::string formatFromContent(const Bytes& b) {
    if (looksLikeNifti(b)) return "nifti";
    const std::string_view text(reinterpret_cast<const char*>(b.data()), b.size());
    if (startsWith(text, "NRRD000")) return "nrrd";
    if (startsWith(text, "# vtk DataFile")) return "vtk";
    if (startsWith(text, std::string_view("II*\0", 4)) || startsWith(text, std::string_view("MM\0*", 4)))
        return "tiff";
    std::size_t pos = 0;
    std::string line;
    for (int n = 0; n < 4 && nextLine(text, pos, line); ++n) {
        const std::string t = trim(line);
        if (startsWith(t, "ObjectType") || startsWith(t, "NDims")) return "metaimage";
    }
    return "";
}

}  // namespace

std::string detectVolumeFormat(const fs::path& path) {
    std::error_code ec;
    if (fs::is_directory(path, ec)) return "dicom";
    fileSize(path);  // "file not found: '...'"
    if (std::string f = formatFromExtension(path); !f.empty()) return f;
    Bytes head = readFilePrefix(path, kSniffBytes);
    if (hasGzipMagic(head.data(), head.size())) {
        head = inflateFile(path, 0, kSniffBytes, io::InflateEnd::PrefixOnly);
        if (looksLikeNifti(head)) return "nifti";
        throw Error(quoted(path) + ": gzip file that does not hold a NIfTI volume");
    }
    if (std::string f = formatFromContent(head); !f.empty()) return f;
    if (head.size() >= 132 && std::memcmp(head.data() + 128, "DICM", 4) == 0)
        throw Error(quoted(path) + " is a single DICOM file: give the folder of its series");
    throw Error(quoted(path) +
                ": unknown volume format (expected a DICOM folder, .nii/.nii.gz, .mha/.mhd, "
                ".nrrd/.nhdr, .vtk or a .tif stack)");
}

Volume readVolume(const fs::path& path, const VolumeReadOptions& options) {
    const std::string format = detectVolumeFormat(path);
    if (format == "tiff") {
        if (!options.spacing)
            throw Error(quoted(path) + ": a TIFF stack holds no voxel size: give it, e.g. " +
                        path.filename().string() + "?spacing=0.39625,0.39625,0.625 (mm)");
        return io::readTiffVolume(path, *options.spacing);
    }
    if (options.spacing)
        throw Error(quoted(path) + ": a voxel size is only given for TIFF stacks (this " + format +
                    " file holds its own)");
    if (format == "dicom") return readDicomSeries(path);
    if (format == "nifti") return readNifti(path);
    if (format == "metaimage") return readMetaImage(path);
    if (format == "nrrd") return readNrrd(path);
    return readLegacyVtk(path);
}

}  // namespace fm
