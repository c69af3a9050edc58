// Cross-checks against the reference NIfTI library (nifti1_io from libnifti2-dev): files we
// write must open there with the same geometry and values, and files it writes or reads must
// give us the same world coordinates.
#include <gtest/gtest.h>

#include <nifti1_io.h>

#include <cmath>
#include <memory>

#include <glm/gtc/matrix_transform.hpp>

#include "TestExpect.h"
#include "common/TestData.h"
#include "io/ReadVolume.h"
#include "io/VolumeWriter.h"

namespace {

namespace fs = std::filesystem;
using fm::test::expectVec;

// Both sides hold the affine as float32 (NIfTI-1): relative ~1e-7 on coordinates up to ~600 mm.
constexpr double kFloat32WorldTol = 2e-4;

struct NiftiImageDeleter {
    void operator()(nifti_image* nim) const { nifti_image_free(nim); }
};
using NiftiImagePtr = std::unique_ptr<nifti_image, NiftiImageDeleter>;

glm::dvec3 apply(const mat44& m, const glm::dvec3& ijk) {
    glm::dvec3 out;
    for (int r = 0; r < 3; ++r)
        out[r] = m.m[r][0] * ijk.x + m.m[r][1] * ijk.y + m.m[r][2] * ijk.z + m.m[r][3];
    return out;
}

glm::dvec3 lpsToRas(const glm::dvec3& p) { return {-p.x, -p.y, p.z}; }

TEST(LibniftiCrossCheck, OurNiftiOpensInLibnifti) {
    const fs::path dir = fm::test::scratchDir("libnifti_ours");
    for (bool mirrored : {false, true}) {
        fm::Volume v = fm::Volume::allocate({6, 5, 4});
        for (std::size_t n = 0; n < v.values.size(); ++n) v.values[n] = 0.25f * n - 7.0f;
        v.spacing = {0.8, 1.1, 2.5};
        v.origin = {-40.0, 25.5, 310.0};
        v.direction = glm::dmat3(
            glm::rotate(glm::dmat4(1.0), 0.7, glm::normalize(glm::dvec3(-1, 2, 0.5))));
        if (mirrored) v.direction[1] = -v.direction[1];
        const fs::path file = dir / "ours.nii.gz";
        fm::writeNifti(v, file);

        NiftiImagePtr nim(nifti_image_read(file.string().c_str(), 1));
        ASSERT_TRUE(nim) << "libnifti could not read " << file;
        SCOPED_TRACE(mirrored ? "mirrored" : "rotation");
        EXPECT_EQ(nim->nx, 6);
        EXPECT_EQ(nim->ny, 5);
        EXPECT_EQ(nim->nz, 4);
        EXPECT_EQ(nim->datatype, DT_FLOAT32);
        const float* data = static_cast<const float*>(nim->data);
        for (std::size_t n = 0; n < v.values.size(); ++n) ASSERT_EQ(data[n], v.values[n]) << n;
        // Both the sform and libnifti's own decoding of our qform put every voxel where our
        // volume says (in RAS).
        for (const glm::dvec3 ijk : {glm::dvec3(0, 0, 0), glm::dvec3(5, 0, 0), glm::dvec3(0, 4, 3),
                                     glm::dvec3(5, 4, 3)}) {
            const glm::dvec3 expected = lpsToRas(v.indexToWorld(ijk));
            expectVec(apply(nim->sto_xyz, ijk), expected, kFloat32WorldTol);
            expectVec(apply(nim->qto_xyz, ijk), expected, kFloat32WorldTol);
        }
    }
}

TEST(LibniftiCrossCheck, LibniftiQformFileReadsTheSame) {
    const fs::path dir = fm::test::scratchDir("libnifti_theirs");
    const int dims[8] = {3, 4, 3, 2, 1, 1, 1, 1};
    NiftiImagePtr nim(nifti_make_new_nim(dims, DT_INT16, 1));
    ASSERT_TRUE(nim);
    auto* samples = static_cast<std::int16_t*>(nim->data);
    for (int n = 0; n < 24; ++n) samples[n] = static_cast<std::int16_t>(n * 37 - 400);
    nim->qform_code = NIFTI_XFORM_SCANNER_ANAT;
    nim->sform_code = 0;
    nim->quatern_b = 0.2f, nim->quatern_c = -0.4f, nim->quatern_d = 0.3f;
    nim->qoffset_x = 12.5f, nim->qoffset_y = -8.0f, nim->qoffset_z = 44.0f;
    nim->qfac = -1.0f;
    nim->dx = nim->pixdim[1] = 0.9f;
    nim->dy = nim->pixdim[2] = 1.7f;
    nim->dz = nim->pixdim[3] = 3.0f;
    nim->xyz_units = NIFTI_UNITS_MM;
    nim->qto_xyz = nifti_quatern_to_mat44(nim->quatern_b, nim->quatern_c, nim->quatern_d,
                                          nim->qoffset_x, nim->qoffset_y, nim->qoffset_z,
                                          nim->dx, nim->dy, nim->dz, nim->qfac);
    const mat44 truth = nim->qto_xyz;
    const fs::path prefix = dir / "theirs.nii.gz";
    ASSERT_EQ(nifti_set_filenames(nim.get(), prefix.string().c_str(), 0, 1), 0);
    nifti_image_write(nim.get());

    const fm::Volume v = fm::readVolume(prefix);
    EXPECT_EQ(v.dims, glm::ivec3(4, 3, 2));
    for (int n = 0; n < 24; ++n) ASSERT_EQ(v.values[n], static_cast<float>(n * 37 - 400));
    for (const glm::dvec3 ijk : {glm::dvec3(0, 0, 0), glm::dvec3(3, 0, 0), glm::dvec3(0, 2, 1),
                                 glm::dvec3(3, 2, 1)})
        expectVec(lpsToRas(v.indexToWorld(ijk)), apply(truth, ijk), kFloat32WorldTol);
}

TEST(LibniftiCrossCheck, RealCtsMatchLibnifti) {
    FM_REQUIRE_SHARED_DATA("totalseg-example-ct/ct_cropped_aorta_report.nii.gz");
    for (const char* name : {"totalseg-example-ct/example_ct.nii.gz",
                             "totalseg-example-ct/ct_cropped_aorta_report.nii.gz"}) {
        const fs::path file = fm::test::sharedDataDir() / name;
        const fm::Volume v = fm::readVolume(file);
        NiftiImagePtr nim(nifti_image_read(file.string().c_str(), 1));
        ASSERT_TRUE(nim);
        SCOPED_TRACE(name);
        ASSERT_EQ(static_cast<std::size_t>(nim->nvox), v.values.size());
        const mat44& affine = nim->sform_code > 0 ? nim->sto_xyz : nim->qto_xyz;
        const glm::dvec3 last = glm::dvec3(v.dims) - 1.0;
        for (const glm::dvec3 ijk : {glm::dvec3(0), last, glm::dvec3(last.x, 0, last.z)})
            expectVec(lpsToRas(v.indexToWorld(ijk)), apply(affine, ijk), kFloat32WorldTol);
        for (std::size_t n = 0; n < v.values.size(); n += 97) {
            double stored = 0;
            if (nim->datatype == DT_INT32) stored = static_cast<const std::int32_t*>(nim->data)[n];
            else if (nim->datatype == DT_INT16) stored = static_cast<const std::int16_t*>(nim->data)[n];
            else FAIL() << "unexpected datatype " << nim->datatype;
            ASSERT_EQ(v.values[n], static_cast<float>(stored)) << n;
        }
    }
}

}  // namespace
