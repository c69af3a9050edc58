// gzip/zlib streams whose checksum (CRC-32 / Adler-32), length or end is wrong are refused with
// the file and the reason, for every reader that inflates: NIfTI .nii.gz, MetaImage
// CompressedData and NRRD gzip. The corrupt streams are made here from real files in
// ../shared/data; the unchanged stream loads to the same voxels as the original.
#include <gtest/gtest.h>

#include <string>

#include "IoTestFiles.h"
#include "TestExpect.h"
#include "common/TestData.h"
#include "io/ReadVolume.h"
#include "io/VolumeWriter.h"

namespace {

namespace fs = std::filesystem;
using fm::test::Bytes;
using fm::test::expectError;

// Writes `bytes` with byte `at` (counted from the end when negative) xor-ed with 0x5a.
fs::path withFlippedByte(const fs::path& dir, const std::string& name, Bytes bytes, long at) {
    const std::size_t index = at < 0 ? bytes.size() + at : static_cast<std::size_t>(at);
    bytes.at(index) ^= 0x5a;
    fm::test::writeFile(dir / name, bytes);
    return dir / name;
}

TEST(CompressedChecksum, RealNiftiGzWithBadCrcOrLengthIsRefused) {
    FM_REQUIRE_SHARED_DATA("totalseg-example-ct/example_ct.nii.gz");
    const fs::path original = fm::test::sharedDataDir() / "totalseg-example-ct/example_ct.nii.gz";
    const fs::path dir = fm::test::scratchDir("checksum_nifti");
    const Bytes gz = fm::test::readFile(original);
    ASSERT_GT(gz.size(), 1000u);
    // RFC 1952: the member ends with CRC-32 (4 bytes) then ISIZE (4 bytes), little-endian.
    expectError([&] { fm::readVolume(withFlippedByte(dir, "crc.nii.gz", gz, -6)); }, "crc.nii.gz",
                "incorrect data check");
    expectError([&] { fm::readVolume(withFlippedByte(dir, "len.nii.gz", gz, -2)); }, "len.nii.gz",
                "incorrect length check");
    // The trailer cut off: all voxels are there, the checksum is not.
    fm::test::writeFile(dir / "cut.nii.gz", Bytes(gz.begin(), gz.end() - 8));
    expectError([&] { fm::readVolume(dir / "cut.nii.gz"); }, "cut.nii.gz", "before its checksum");
    // A byte changed inside the deflate data: refused, whichever check catches it first.
    for (const double where : {0.3, 0.5, 0.7, 0.9}) {
        const fs::path p =
            withFlippedByte(dir, "mid.nii.gz", gz, static_cast<long>(gz.size() * where));
        EXPECT_THROW(fm::readVolume(p), fm::Error) << "byte at " << where << " of the stream";
    }
    // Unchanged bytes in a new place still load.
    fm::test::writeFile(dir / "same.nii.gz", gz);
    EXPECT_EQ(fm::readVolume(dir / "same.nii.gz").values, fm::readVolume(original).values);
}

TEST(CompressedChecksum, RealVolumeAsMetaImageWithBadAdlerIsRefused) {
    FM_REQUIRE_SHARED_DATA("vtk-headsq-quarter/quarter.nhdr");
    const fm::Volume real =
        fm::readVolume(fm::test::sharedDataDir() / "vtk-headsq-quarter/quarter.nhdr");
    const fs::path dir = fm::test::scratchDir("checksum_mha");
    fm::writeMetaImage(real, dir / "ct.mha", true);
    const Bytes mha = fm::test::readFile(dir / "ct.mha");
    // RFC 1950: the zlib stream (the file's tail) ends with Adler-32, big-endian.
    expectError([&] { fm::readVolume(withFlippedByte(dir, "adler.mha", mha, -1)); }, "adler.mha",
                "incorrect data check");
    fm::test::writeFile(dir / "cut.mha", Bytes(mha.begin(), mha.end() - 4));
    expectError([&] { fm::readVolume(dir / "cut.mha"); }, "cut.mha", "before its checksum");
    EXPECT_EQ(fm::readVolume(dir / "ct.mha").values, real.values);
}

TEST(CompressedChecksum, RealSlicesAsGzipNrrdWithBadCrcAreRefused) {
    FM_REQUIRE_SHARED_DATA("vtk-headsq-quarter/quarter.nhdr");
    const fs::path source = fm::test::sharedDataDir() / "vtk-headsq-quarter";
    Bytes raw;
    for (int k = 1; k <= 93; ++k)
        raw = fm::test::concat(raw, fm::test::readFile(source / ("quarter." + std::to_string(k))));
    const std::string header =
        "NRRD0004\ndimension: 3\nsizes: 64 64 93\nspacings: 3.2 3.2 1.5\nendian: little\n"
        "type: short\nencoding: gzip\nspace: 3D-left-handed\n\n";
    const Bytes nrrd = fm::test::concat(fm::test::toBytes(header), fm::test::gzipBytes(raw));
    const fs::path dir = fm::test::scratchDir("checksum_nrrd");
    fm::test::writeFile(dir / "good.nrrd", nrrd);
    EXPECT_EQ(fm::readVolume(dir / "good.nrrd").values,
              fm::readVolume(source / "quarter.nhdr").values);
    expectError([&] { fm::readVolume(withFlippedByte(dir, "crc.nrrd", nrrd, -7)); }, "crc.nrrd",
                "incorrect data check");
    // A stream holding far more than the header promises (a zip bomb) is refused, not inflated
    // to its end.
    const Bytes bomb =
        fm::test::concat(fm::test::toBytes(header), fm::test::gzipBytes(Bytes(raw.size() * 20, 0)));
    fm::test::writeFile(dir / "bomb.nrrd", bomb);
    expectError([&] { fm::readVolume(dir / "bomb.nrrd"); }, "bomb.nrrd", "far beyond");
}

}  // namespace
