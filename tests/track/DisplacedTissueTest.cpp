// A trial bone's displaced_tissue (trial/Trial.h): the bone is rendered as its attenuation in
// excess of the tissue it displaces. Checked on the values the loaded scene holds, computed here
// from the stored ones: a TIFF stack (raw, air 0) keeps v - tissue, never below 0; a volume in HU
// (air -1000) keeps v - tissue - 1000 (so its attenuation is mu_water (v - tissue) / 1000), never
// below -1000; the field survives the trial's round trip; a tissue above every voxel is refused.
#include <algorithm>
#include <fstream>

#include <gtest/gtest.h>

#include "camera/MayaCam.h"
#include "common/TestData.h"
#include "core/Error.h"
#include "io/AtomicFile.h"
#include "io/ImageFileWriter.h"
#include "io/TiffVolume.h"
#include "io/VolumeWriter.h"
#include "simulate/TrialSimulation.h"
#include "track/TrialScene.h"
#include "trial/Trial.h"

namespace {

namespace fs = std::filesystem;

// Stored values of a 4 x 3 x 2 bone: air, soft tissue and bone of every level.
fm::Volume storedBone(float air) {
    fm::Volume v = fm::Volume::allocate({4, 3, 2}, air);
    const float levels[] = {air, air + 900.0f, air + 1040.0f, air + 1041.0f, air + 1500.0f, air + 2800.0f};
    for (std::size_t n = 0; n < v.values.size(); ++n) v.values[n] = levels[n % 6];
    v.spacing = {1.0, 1.0, 2.0};
    return v;
}

// A one-camera, one-frame trial around `volume` (its file written by the caller).
fm::Trial trialOf(const fs::path& dir, const fs::path& volume, std::optional<double> tissue) {
    fs::create_directories(dir / "frames");
    const auto cameras = fm::camerasAround(glm::dvec3(2.0), 10.0, 1, 80.0, 1000.0, {16, 16});
    fm::writeMayaCam2(dir / "cam.txt", cameras[0]);
    fm::Image frame(16, 16, 1000.0f);
    fm::io::writeFileAtomically(dir / "frames/f0.tif", fm::encodeTiffGrey16(frame, 1.0));
    fm::Trial t;
    t.name = "excess";
    t.source = dir / "t.json";
    t.cameras = {{"cam", dir / "cam.txt", dir / "frames"}};
    fm::TrialBone b;
    b.name = "bone";
    b.volume = volume;
    b.voxelSize = {1.0, 1.0, 2.0};
    b.displacedTissue = tissue;
    t.bones = {b};
    fm::writeTrialJson(t.source, t);
    return fm::readTrial(t.source);  // the written file, read back
}

TEST(DisplacedTissue, AStackKeepsTheExcessOverTheTissueAndNeverLessThanAir) {
    const fs::path dir = fm::test::scratchDir("displaced_stack");
    const fm::Volume stored = storedBone(0.0f);  // HU + 1000: air 0, muscle 1040
    fm::io::writeFileAtomically(dir / "bone.tif", fm::io::encodeTiffStack16(stored, 0.0));
    const fm::Trial trial = trialOf(dir, dir / "bone.tif", 1040.0);
    ASSERT_TRUE(trial.bone("bone").displacedTissue.has_value());
    EXPECT_EQ(*trial.bone("bone").displacedTissue, 1040.0);
    const fm::TrialScene scene = fm::loadTrialScene(trial, {}, 1);
    const fm::Volume& loaded = *scene.volumes.at("bone");
    ASSERT_EQ(loaded.values.size(), stored.values.size());
    for (std::size_t n = 0; n < stored.values.size(); ++n)
        EXPECT_EQ(loaded.values[n], std::max(0.0f, stored.values[n] - 1040.0f)) << n;
    // Without the field, the values as stored.
    const fm::TrialScene plain = fm::loadTrialScene(trialOf(dir, dir / "bone.tif", std::nullopt), {}, 1);
    EXPECT_EQ(plain.volumes.at("bone")->values, stored.values);
}

TEST(DisplacedTissue, AVolumeInHounsfieldUnitsKeepsItsAirAtMinus1000) {
    const fs::path dir = fm::test::scratchDir("displaced_hu");
    const fm::Volume stored = storedBone(-1000.0f);  // HU: air -1000, muscle 40
    fm::writeNifti(stored, dir / "bone.nii");
    const fm::TrialScene scene = fm::loadTrialScene(trialOf(dir, dir / "bone.nii", 40.0), {}, 1);
    const fm::Volume& loaded = *scene.volumes.at("bone");
    ASSERT_EQ(loaded.values.size(), stored.values.size());
    for (std::size_t n = 0; n < stored.values.size(); ++n)
        EXPECT_EQ(loaded.values[n], std::max(-1000.0f, stored.values[n] - 40.0f - 1000.0f)) << n;
}

TEST(DisplacedTissue, ATissueAboveEveryVoxelOrOnAMeshIsRefused) {
    const fs::path dir = fm::test::scratchDir("displaced_refused");
    fm::io::writeFileAtomically(dir / "bone.tif", fm::io::encodeTiffStack16(storedBone(0.0f), 0.0));
    try {
        fm::loadTrialScene(trialOf(dir, dir / "bone.tif", 5000.0), {}, 1);
        ADD_FAILURE() << "a tissue above every voxel was accepted";
    } catch (const fm::Error& e) {
        const std::string m = e.what();
        EXPECT_NE(m.find("t.json"), std::string::npos) << m;
        EXPECT_NE(m.find("displaced_tissue"), std::string::npos) << m;
    }
    std::ofstream(dir / "mesh.json") << R"({"cameras": [{"calibration": "cam.txt", "frames": "frames"}], )"
                                     << R"("bones": [{"name": "a", "mesh": "a.stl", "displaced_tissue": 1040}]})";
    try {
        fm::readTrial(dir / "mesh.json");
        ADD_FAILURE() << "displaced_tissue on a mesh-only bone was accepted";
    } catch (const fm::Error& e) {
        EXPECT_NE(std::string(e.what()).find("bones[0].displaced_tissue"), std::string::npos) << e.what();
    }
}

}  // namespace
