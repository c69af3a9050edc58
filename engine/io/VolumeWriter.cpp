#include "io/VolumeWriter.h"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstring>
#include <sstream>

#include "core/Error.h"
#include "io/AtomicFile.h"
#include "io/ByteSource.h"
#include "io/HeaderText.h"
#include "io/PngWriter.h"

namespace fm {

using namespace fm::io;
namespace fs = std::filesystem;

namespace {

// Shortest text that reads back as the same double.
std::string number(double v) {
    char buf[64];
    const auto [end, ec] = std::to_chars(buf, buf + sizeof buf, v);
    return ec == std::errc() ? std::string(buf, end) : std::string("0");
}

void checkWritable(const Volume& v, const std::string& what) {
    v.validate(what);
    if (v.values.size() != v.voxelCount()) throw Error(what + ": the volume has no values");
}

// float32 samples in little-endian order whatever the host.
Bytes littleEndianFloats(const std::vector<float>& values) {
    Bytes out(values.size() * 4);
    std::memcpy(out.data(), values.data(), out.size());
    if (!hostIsLittleEndian())
        for (std::size_t n = 0; n < out.size(); n += 4) {
            std::swap(out[n], out[n + 3]);
            std::swap(out[n + 1], out[n + 2]);
        }
    return out;
}

// Little-endian header fields at fixed offsets.
class HeaderBuilder {
  public:
    explicit HeaderBuilder(std::size_t size) : bytes_(size, 0) {}
    template <typename T>
    void put(std::size_t offset, T value) {
        std::uint8_t b[sizeof(T)];
        std::memcpy(b, &value, sizeof(T));
        if (!hostIsLittleEndian()) std::reverse(b, b + sizeof(T));
        std::memcpy(bytes_.data() + offset, b, sizeof(T));
    }
    void text(std::size_t offset, const std::string& s, std::size_t maxLength) {
        std::memcpy(bytes_.data() + offset, s.data(), std::min(s.size(), maxLength - 1));
    }
    Bytes& bytes() { return bytes_; }

  private:
    Bytes bytes_;
};

// NIfTI quaternion of a proper rotation R (columns = axes), as nifti_mat44_to_quatern.
glm::dvec4 rotationToQuaternion(const glm::dmat3& R) {
    auto r = [&](int row, int col) { return R[col][row]; };
    double a = r(0, 0) + r(1, 1) + r(2, 2) + 1.0, b, c, d;
    if (a > 0.5) {
        a = 0.5 * std::sqrt(a);
        b = 0.25 * (r(2, 1) - r(1, 2)) / a;
        c = 0.25 * (r(0, 2) - r(2, 0)) / a;
        d = 0.25 * (r(1, 0) - r(0, 1)) / a;
    } else {
        const double xd = 1.0 + r(0, 0) - (r(1, 1) + r(2, 2));
        const double yd = 1.0 + r(1, 1) - (r(0, 0) + r(2, 2));
        const double zd = 1.0 + r(2, 2) - (r(0, 0) + r(1, 1));
        if (xd > 1.0) {
            b = 0.5 * std::sqrt(xd);
            c = 0.25 * (r(0, 1) + r(1, 0)) / b;
            d = 0.25 * (r(0, 2) + r(2, 0)) / b;
            a = 0.25 * (r(2, 1) - r(1, 2)) / b;
        } else if (yd > 1.0) {
            c = 0.5 * std::sqrt(yd);
            b = 0.25 * (r(0, 1) + r(1, 0)) / c;
            d = 0.25 * (r(1, 2) + r(2, 1)) / c;
            a = 0.25 * (r(0, 2) - r(2, 0)) / c;
        } else {
            d = 0.5 * std::sqrt(zd);
            b = 0.25 * (r(0, 2) + r(2, 0)) / d;
            c = 0.25 * (r(1, 2) + r(2, 1)) / d;
            a = 0.25 * (r(1, 0) - r(0, 1)) / d;
        }
        if (a < 0.0) b = -b, c = -c, d = -d, a = -a;
    }
    return {a, b, c, d};
}

}  // namespace

void writeMetaImage(const Volume& volume, const fs::path& path, bool compress) {
    const std::string what = "MetaImage " + quoted(path);
    checkWritable(volume, what);
    const Bytes raw = littleEndianFloats(volume.values);
    const Bytes data = compress ? deflateBuffer(raw.data(), raw.size(), false) : raw;

    std::ostringstream h;
    h << "ObjectType = Image\nNDims = 3\nBinaryData = True\nBinaryDataByteOrderMSB = False\n";
    h << "CompressedData = " << (compress ? "True" : "False") << "\n";
    if (compress) h << "CompressedDataSize = " << data.size() << "\n";
    // Each group of three is one axis direction (ITK's TransformMatrix layout).
    h << "TransformMatrix =";
    for (int a = 0; a < 3; ++a)
        for (int w = 0; w < 3; ++w) h << " " << number(volume.direction[a][w]);
    h << "\nOffset = " << number(volume.origin.x) << " " << number(volume.origin.y) << " "
      << number(volume.origin.z) << "\n";
    h << "CenterOfRotation = 0 0 0\n";
    h << "ElementSpacing = " << number(volume.spacing.x) << " " << number(volume.spacing.y) << " "
      << number(volume.spacing.z) << "\n";
    h << "DimSize = " << volume.dims.x << " " << volume.dims.y << " " << volume.dims.z << "\n";
    if (volume.meta.modality == "CT") h << "Modality = MET_MOD_CT\n";
    h << "ElementType = MET_FLOAT\nElementDataFile = LOCAL\n";
    const std::string header = h.str();

    Bytes file(header.begin(), header.end());
    file.insert(file.end(), data.begin(), data.end());
    writeFileAtomically(path, file);
}

void writeNifti(const Volume& volume, const fs::path& path) {
    const std::string what = "NIfTI " + quoted(path);
    checkWritable(volume, what);

    // LPS -> RAS: negate the x and y world components.
    glm::dmat3 dirRas = volume.direction;
    for (int a = 0; a < 3; ++a) dirRas[a].x = -dirRas[a].x, dirRas[a].y = -dirRas[a].y;
    const glm::dvec3 originRas(-volume.origin.x, -volume.origin.y, volume.origin.z);

    HeaderBuilder h(352);  // 348-byte header + 4 zero extension bytes
    h.put<std::int32_t>(0, 348);
    h.put<std::uint8_t>(38, 'r');  // "regular", for ANALYZE tools
    const std::int16_t dim[8] = {3,
                                 static_cast<std::int16_t>(volume.dims.x),
                                 static_cast<std::int16_t>(volume.dims.y),
                                 static_cast<std::int16_t>(volume.dims.z),
                                 1,
                                 1,
                                 1,
                                 1};
    for (int a = 1; a <= 3; ++a)
        if (volume.dims[a - 1] > 32767)
            throw Error(what + ": dimension " + std::to_string(volume.dims[a - 1]) +
                        " is too large for NIfTI-1 (max 32767)");
    for (int a = 0; a < 8; ++a) h.put<std::int16_t>(40 + 2 * a, dim[a]);
    h.put<std::int16_t>(70, 16);  // DT_FLOAT32
    h.put<std::int16_t>(72, 32);  // bitpix

    // qform: a proper rotation; a mirrored axis set is stored with qfac = -1 (k axis flipped).
    glm::dmat3 rotation = dirRas;
    double qfac = 1.0;
    if (glm::determinant(rotation) < 0.0) {
        qfac = -1.0;
        rotation[2] = -rotation[2];
    }
    const glm::dvec4 q = rotationToQuaternion(rotation);
    const float pixdim[8] = {static_cast<float>(qfac),
                             static_cast<float>(volume.spacing.x),
                             static_cast<float>(volume.spacing.y),
                             static_cast<float>(volume.spacing.z),
                             1,
                             1,
                             1,
                             1};
    for (int a = 0; a < 8; ++a) h.put<float>(76 + 4 * a, pixdim[a]);
    h.put<float>(108, 352.0f);    // vox_offset
    h.put<float>(112, 1.0f);      // scl_slope
    h.put<float>(116, 0.0f);      // scl_inter
    h.put<std::uint8_t>(123, 2);  // xyzt_units: millimetres
    h.text(148, volume.meta.description, 80);
    h.put<std::int16_t>(252, 1);  // qform_code: scanner anatomical
    h.put<std::int16_t>(254, 1);  // sform_code: scanner anatomical
    h.put<float>(256, static_cast<float>(q[1]));
    h.put<float>(260, static_cast<float>(q[2]));
    h.put<float>(264, static_cast<float>(q[3]));
    for (int w = 0; w < 3; ++w) h.put<float>(268 + 4 * w, static_cast<float>(originRas[w]));
    for (int row = 0; row < 3; ++row) {
        for (int c = 0; c < 3; ++c)
            h.put<float>(280 + 16 * row + 4 * c,
                         static_cast<float>(dirRas[c][row] * volume.spacing[c]));
        h.put<float>(280 + 16 * row + 12, static_cast<float>(originRas[row]));
    }
    h.text(344, std::string("n+1"), 4);

    Bytes file = std::move(h.bytes());
    const Bytes data = littleEndianFloats(volume.values);
    file.insert(file.end(), data.begin(), data.end());
    if (endsWith(toLower(path.filename().string()), ".gz"))
        file = deflateBuffer(file.data(), file.size(), true);
    writeFileAtomically(path, file);
}

void writeVolume(const Volume& volume, const fs::path& path) {
    const std::string name = toLower(path.filename().string());
    if (endsWith(name, ".mha")) return writeMetaImage(volume, path, true);
    if (endsWith(name, ".nii") || endsWith(name, ".nii.gz")) return writeNifti(volume, path);
    throw Error("cannot write volume " + quoted(path) +
                ": unsupported extension (use .mha, .nii or .nii.gz)");
}

Volume imageAsVolume(const Image& image) {
    if (image.width <= 0 || image.height <= 0 ||
        image.pixels.size() != static_cast<std::size_t>(image.width) * image.height)
        throw Error("image is empty or its pixel count does not match its size");
    Volume v = Volume::allocate({image.width, image.height, 1});
    v.values = image.pixels;
    v.spacing = {image.spacing.x, image.spacing.y, 1.0};
    return v;
}

void writeImage(const Image& image, const fs::path& path) {
    const std::string name = toLower(path.filename().string());
    if (endsWith(name, ".png")) {
        float low = 0.0f, high = 0.0f;
        bool any = false;
        for (float v : image.pixels) {
            if (!std::isfinite(v)) continue;
            low = any ? std::min(low, v) : v;
            high = any ? std::max(high, v) : v;
            any = true;
        }
        if (!(high > low)) high = low + 1.0f;  // a flat image: all black
        return writePng(image, path, low, high);
    }
    writeVolume(imageAsVolume(image), path);
}

}  // namespace fm
