// Trials: Autoscoper .cfg files read as Autoscoper reads them (checked against its Trial.cpp
// rules), our JSON form, the shipped wrist trial on the real data, and bad input.
#include <fstream>

#include <gtest/gtest.h>

#include "common/ErrorText.h"
#include "common/TestData.h"
#include "core/Error.h"
#include "trial/AutoscoperConfig.h"
#include "trial/ImageSequence.h"
#include "trial/Trial.h"

namespace {

namespace fs = std::filesystem;

fs::path writeText(const fs::path& dir, const std::string& name, const std::string& text) {
    const fs::path p = dir / name;
    std::ofstream(p) << text;
    return p;
}

using fm::test::errorOf;

using fm::test::sharedDataBesideRepo;

TEST(WristTrial, ShippedCfgNamesTheRealFilesAndFrames) {
    FM_REQUIRE_SHARED_DATA("autoscoper-bvr");
    if (!sharedDataBesideRepo()) {
        if (fm::test::underCI()) FAIL() << "under CI the shared data must be ../shared/data beside the repository";
        GTEST_SKIP() << "FM_DATA_DIR is not ../shared/data beside the repository";
    }
    const fm::Trial t = fm::readTrial(fm::test::repoDir() / "data/trials/wrist.cfg");
    EXPECT_TRUE(t.warnings.empty());
    ASSERT_EQ(t.cameras.size(), 2u);
    ASSERT_EQ(t.bones.size(), 3u);
    EXPECT_EQ(t.bones[0].name, "rad_dcm_cropped");
    EXPECT_EQ(t.bones[2].voxelSize, glm::dvec3(0.39625, 0.39625, 0.625));
    EXPECT_EQ(t.renderResolution, glm::ivec2(512, 512));
    EXPECT_NO_THROW(fm::checkTrialFiles(t));
    // Both cameras hold the same three simultaneous frames.
    const fm::ImageSequence a = fm::listImageFolder(t.cameras[0].frames);
    const fm::ImageSequence b = fm::listImageFolder(t.cameras[1].frames);
    ASSERT_EQ(a.frameCount(), 3);
    ASSERT_EQ(b.frameCount(), 3);
    const int expected[] = {2, 99, 158};
    for (int i = 0; i < 3; ++i) {
        EXPECT_EQ(fm::frameNumberInName(a.frames[i]), expected[i]);
        EXPECT_EQ(fm::frameNumberInName(b.frames[i]), expected[i]);
    }
    EXPECT_EQ(a.frameName(1), "xr_rad_uln_cam01_UND.0099.tif");
}

TEST(WristTrial, ShippedJsonIsTheSameTrialWithBoneNames) {
    FM_REQUIRE_SHARED_DATA("autoscoper-bvr");
    if (!sharedDataBesideRepo()) {
        if (fm::test::underCI()) FAIL() << "under CI the shared data must be ../shared/data beside the repository";
        GTEST_SKIP() << "FM_DATA_DIR is not ../shared/data beside the repository";
    }
    const fm::Trial cfg = fm::readTrial(fm::test::repoDir() / "data/trials/wrist.cfg");
    const fm::Trial json = fm::readTrial(fm::test::repoDir() / "data/trials/wrist.json");
    EXPECT_TRUE(json.warnings.empty());
    ASSERT_EQ(json.bones.size(), cfg.bones.size());
    EXPECT_EQ(json.bone("radius").volume, cfg.bones[0].volume);
    EXPECT_EQ(json.bone("ulna").volume, cfg.bones[1].volume);
    EXPECT_EQ(json.bone("mc3").volume, cfg.bones[2].volume);
    for (std::size_t i = 0; i < 2; ++i) {
        EXPECT_EQ(json.cameras[i].calibration, cfg.cameras[i].calibration);
        EXPECT_EQ(json.cameras[i].frames, cfg.cameras[i].frames);
    }
    EXPECT_NO_THROW(fm::checkTrialFiles(json));
    EXPECT_NE(errorOf([&] { json.bone("femur"); }).find("radius, ulna, mc3"), std::string::npos);
}

TEST(AutoscoperConfig, FollowsAutoscopersParsingRules) {
    const fs::path dir = fm::test::scratchDir("cfg_rules");
    // Comments and blank lines skipped, key = text before the first space, backslashes become
    // slashes, relative paths resolved against the file's folder from 1.1 on, defaults for
    // RenderResolution / OptimizationOffsets.
    const fs::path p = writeText(dir, "t.cfg",
                                 "# a comment\n\nVersion 1.1\r\nmayaCam_csv cal\\cam1.txt\n"
                                 "CameraRootDir frames/cam1/\nVolumeFile vol.tif\nVoxelSize 0.5 0.5 1\n");
    const fm::AutoscoperConfig c = fm::readAutoscoperConfig(p);
    EXPECT_EQ(c.versionMinor, 1);
    ASSERT_EQ(c.calibrations.size(), 1u);
    EXPECT_EQ(c.calibrations[0], dir / "cal/cam1.txt");
    EXPECT_EQ(c.cameraRootDirs[0], dir / "frames/cam1");
    EXPECT_EQ(c.volumes[0].voxelSize, glm::dvec3(0.5, 0.5, 1.0));
    EXPECT_EQ(c.volumes[0].flip, glm::ivec3(0));
    EXPECT_EQ(c.renderResolution, glm::ivec2(512, 512));
    EXPECT_EQ(c.optimizationOffsets[3], 0.1);
}

TEST(AutoscoperConfig, WriteThenReadGivesTheSameTrial) {
    const fs::path dir = fm::test::scratchDir("cfg_roundtrip");
    fm::AutoscoperConfig c;
    c.calibrations = {dir / "cal/a.txt", dir / "cal/b.txt"};
    c.cameraRootDirs = {dir / "img/a", dir / "img/b"};
    c.volumes = {{dir / "v/rad.tif", {1, 0, 1}, {0.39625, 0.39625, 0.625}}};
    c.renderResolution = {256, 384};
    c.optimizationOffsets = {0.2, 0.3, 0.4, 0.5, 0.6, 0.7};
    fm::writeAutoscoperConfig(dir / "t.cfg", c);
    std::ifstream in(dir / "t.cfg");
    const std::string text((std::istreambuf_iterator<char>(in)), {});
    EXPECT_NE(text.find("mayaCam_csv cal/a.txt"), std::string::npos) << text;  // relative
    const fm::AutoscoperConfig back = fm::readAutoscoperConfig(dir / "t.cfg");
    EXPECT_EQ(back.calibrations, c.calibrations);
    EXPECT_EQ(back.cameraRootDirs, c.cameraRootDirs);
    EXPECT_EQ(back.volumes[0].file, c.volumes[0].file);
    EXPECT_EQ(back.volumes[0].flip, c.volumes[0].flip);
    EXPECT_EQ(back.volumes[0].voxelSize, c.volumes[0].voxelSize);
    EXPECT_EQ(back.renderResolution, c.renderResolution);
    EXPECT_EQ(back.optimizationOffsets, c.optimizationOffsets);
}

TEST(AutoscoperConfig, RefusesBrokenFilesNamingLineAndKey) {
    const fs::path dir = fm::test::scratchDir("cfg_bad");
    const std::string good = "mayaCam_csv /a.txt\nCameraRootDir /f\nVolumeFile /v.tif\n";
    struct Case {
        const char* text;
        const char* expect;
    } cases[] = {
        {"Version 1.1\nmayaCam_csv a.txt\nmayaCam_csv b.txt\nCameraRootDir f\nVolumeFile v.tif\nVoxelSize 1 1 1\n",
         "2 cameras (mayaCam_csv) but 1 image folders"},
        {"Version 1.1\nCameraRootDir f\nVolumeFile v.tif\nVoxelSize 1 1 1\n", "no camera"},
        {"Version 1.1\nmayaCam_csv a.txt\nCameraRootDir f\nVoxelSize 1 1 1\n", "no volume"},
        {"Version 1.1\nmayaCam_csv a.txt\nCameraRootDir f\nVolumeFile v.tif\n", "1 volumes but 0 VoxelSize"},
        {"Version 1.1\nmayaCam_csv a.txt\nCameraRootDir f\nVolumeFile v.tif\nVoxelSize 1 x 1\n", "line 5 (VoxelSize)"},
        {"Version 1.1\nmayaCam_csv a.txt\nCameraRootDir f\nVolumeFile v.tif\nVoxelSize 1 -1 1\n", "positive"},
        {"Version 1.1\nmayaCam_csv a.txt\nCameraRootDir f\nVolumeFile v.tif\nVoxelSize 1 1 1\nVolumeFlip 0 2 0\n", "0 or 1"},
        {"Version 1.1\nmayaCam_csv a.txt\nCameraRootDir f\nVolumeFile v.tif\nVoxelSize 1 1 1\nRenderResolution 0 512\n", "RenderResolution"},
        {"Version 3.0\n", "not 1.0, 1.1 or 1.2"},
        {"Version 1.0\nmayaCam_csv a.txt\nCameraRootDir /f\nVolumeFile /v.tif\nVoxelSize 1 1 1\n", "Version 1.0 does not allow"},
        {"Version 1.2\nmayaCam_csv /a\nCameraRootDir /f\nVolumeFile /v\nVolumeFile /w\nVoxelSize 1 1 1\nVoxelSize 1 1 1\nMeshFile /m.stl\n", "one MeshFile per volume"},
    };
    for (const Case& c : cases) {
        const fs::path p = writeText(dir, "bad.cfg", c.text);
        const std::string e = errorOf([&] { fm::readAutoscoperConfig(p); });
        EXPECT_NE(e.find(c.expect), std::string::npos) << "case:\n" << c.text << "error: " << e;
        EXPECT_NE(e.find("bad.cfg"), std::string::npos) << e;
    }
    // Unknown keys and a missing Version are reported, not silently dropped.
    const fm::AutoscoperConfig w =
        fm::readAutoscoperConfig(writeText(dir, "w.cfg", good + "VoxelSize 1 1 1\nVolumeFilp 0 0 1\n"));
    ASSERT_EQ(w.warnings.size(), 2u);
    EXPECT_NE(w.warnings[0].find("VolumeFilp"), std::string::npos);
    EXPECT_NE(w.warnings[1].find("no Version"), std::string::npos);
    EXPECT_NE(errorOf([&] { fm::readAutoscoperConfig(dir / "missing.cfg"); }).find("missing.cfg"),
              std::string::npos);
}

TEST(TrialJson, RoundTripWithKeyframesAndStrictReading) {
    const fs::path dir = fm::test::scratchDir("trial_json");
    fm::Trial t;
    t.name = "knee";
    t.source = dir / "t.json";
    t.cameras = {{"left", dir / "c1.txt", dir / "f1"}, {"right", dir / "c2.txt", dir / "f2"}};
    t.bones = {{"femur", dir / "fem.tif", {0.4, 0.4, 0.6}, {0, 1, 0}, {}},
               {"tibia", dir / "tib.tif", {0.4, 0.4, 0.6}, {0, 0, 0}, dir / "tib.stl"}};
    fm::TrialPose k0{3, fm::rotationAbout({0, 0, 1}, 30.0, {1, 2, 3}), fm::VolumeFrame::Autoscoper};
    fm::TrialPose k1{0, fm::RigidTransform::translate({5, 6, 7}), fm::VolumeFrame::Fluoromatch};
    t.keyframes["femur"] = {k1, k0};
    fm::writeTrialJson(t.source, t);
    const fm::Trial back = fm::readTrial(t.source);
    EXPECT_TRUE(back.warnings.empty());
    EXPECT_EQ(back.name, "knee");
    EXPECT_EQ(back.cameras[1].name, "right");
    EXPECT_EQ(back.cameras[1].frames, dir / "f2");
    EXPECT_EQ(back.bone("femur").flip, glm::ivec3(0, 1, 0));
    EXPECT_EQ(back.bone("tibia").mesh, dir / "tib.stl");
    ASSERT_EQ(back.keyframes.at("femur").size(), 2u);
    const fm::TrialPose& b1 = back.keyframes.at("femur")[1];
    EXPECT_EQ(b1.frame, 3);
    EXPECT_EQ(b1.volumeFrame, fm::VolumeFrame::Autoscoper);
    for (int i = 0; i < 16; ++i)
        EXPECT_NEAR(b1.worldFromVolume.toRowMajor4x4()[i], k0.worldFromVolume.toRowMajor4x4()[i], 1e-15);
    EXPECT_THROW(fm::checkTrialFiles(back), fm::Error);  // none of these files exist

    struct Case {
        const char* text;
        const char* expect;
    } cases[] = {
        {"{\"cameras\": [], \"bones\": []}", "\"cameras\" must be a non-empty array"},
        {"{\"cameras\": [{\"calibration\": \"c\", \"frames\": \"f\"}], \"bones\": [{\"name\": \"a\", \"volume\": \"v.tif\"}]}",
         "bones[0].voxel_size\" is missing"},
        {"{\"cameras\": [{\"calibration\": \"c\", \"frames\": \"f\"}], \"bones\": [{\"name\": \"a\", \"volume\": \"v.tif\", "
         "\"voxel_size\": [1,1,1]}], \"keyframes\": {\"b\": []}}",
         "no bone \"b\""},
        {"{\"cameras\": [{\"calibration\": \"c\", \"frames\": \"f\"}], \"bones\": [{\"name\": \"a\", \"volume\": \"v.tif\", "
         "\"voxel_size\": [1,1,1]}], \"keyframes\": {\"a\": [{\"frame\": 0, \"volume_frame\": \"autoscoper\", "
         "\"world_from_volume\": [2,0,0,0, 0,2,0,0, 0,0,2,0, 0,0,0,1]}]}}",
         "not orthonormal"},
        {"{\"name\": \"a\", \"name\": \"b\"}", "duplicate key \"name\""},
        {"{\"name\": ", "not valid JSON"},
        {"{\"cameras\": [{\"calibration\": \"c\", \"frames\": \"f\"}], \"bones\": [{\"name\": \"a\", \"volume\": \"v.tif\", "
         "\"voxel_size\": [1,1,1]}, {\"name\": \"a\", \"volume\": \"w.tif\", \"voxel_size\": [1,1,1]}]}",
         "repeats the bone name"},
        {"{\"cameras\": [{\"name\": \"c\", \"calibration\": \"a\", \"frames\": \"f\"}, {\"name\": \"c\", "
         "\"calibration\": \"b\", \"frames\": \"g\"}], \"bones\": [{\"name\": \"a\", \"volume\": \"v.tif\", "
         "\"voxel_size\": [1,1,1]}]}",
         "cameras 1 and 2 are both named \"c\""},
        // Another volume format has its own geometry: a voxel size is refused, not ignored.
        {"{\"cameras\": [{\"calibration\": \"c\", \"frames\": \"f\"}], \"bones\": [{\"name\": \"a\", "
         "\"volume\": \"v.nii.gz\", \"voxel_size\": [1,1,1]}]}",
         "belongs to a TIFF stack: v.nii.gz is placed by its own spacing, origin and direction"},
        {"{\"cameras\": [{\"calibration\": \"a\", \"frames\": \"f\"}, {\"calibration\": \"./a\", "
         "\"frames\": \"f/\"}], \"bones\": [{\"name\": \"a\", \"volume\": \"v.tif\", \"voxel_size\": [1,1,1]}]}",
         "cameras cam1 and cam2 are the same camera"},
    };
    for (const Case& c : cases) {
        const fs::path p = writeText(dir, "bad.json", c.text);
        const std::string e = errorOf([&] { fm::readTrial(p); });
        EXPECT_NE(e.find(c.expect), std::string::npos) << c.text << "\nerror: " << e;
        EXPECT_NE(e.find("bad.json"), std::string::npos) << e;
    }
    EXPECT_NE(errorOf([&] { fm::readTrial(dir / "t.txt"); }).find(".cfg or a fluoromatch .json"),
              std::string::npos);
}

// A .cfg listing the same calibration and frame folder twice is one camera counted twice.
TEST(AutoscoperConfig, TheSameCameraTwiceIsRefused) {
    const fs::path dir = fm::test::scratchDir("cfg_same_camera");
    const fs::path p = writeText(dir, "twice.cfg",
                                 "Version 1.1\nmayaCam_csv a.txt\nmayaCam_csv a.txt\nCameraRootDir f\n"
                                 "CameraRootDir f\nVolumeFile v.tif\nVoxelSize 1 1 1\n");
    const std::string e = errorOf([&] { fm::readTrial(p); });
    EXPECT_NE(e.find("twice.cfg"), std::string::npos) << e;
    EXPECT_NE(e.find("the same camera"), std::string::npos) << e;
}

// A folder or a device where a file belongs is named as such, not as missing.
TEST(TrialJson, AFolderOrDeviceGivenAsAFileIsNamedAsSuch) {
    const fs::path dir = fm::test::scratchDir("trial_not_a_file");
    fs::create_directories(dir / "calib");
    fm::Trial t;
    t.source = dir / "t.json";
    t.cameras.push_back({"cam1", dir / "calib", dir});
    EXPECT_NE(errorOf([&] { fm::checkTrialFiles(t); }).find("is a folder, not a file"), std::string::npos);
    t.cameras[0].calibration = "/dev/zero";
    EXPECT_NE(errorOf([&] { fm::checkTrialFiles(t); }).find("not a regular file"), std::string::npos);
    t.cameras[0].calibration = dir / "none.txt";
    EXPECT_NE(errorOf([&] { fm::checkTrialFiles(t); }).find("does not exist"), std::string::npos);
}

TEST(ImageSequence, SortsByNameAndRefusesEmptyFolders) {
    const fs::path dir = fm::test::scratchDir("sequence");
    for (const char* n : {"b.0010.tif", "b.0002.TIF", "b.0100.tiff", "notes.txt"}) writeText(dir, n, "x");
    const fm::ImageSequence s = fm::listImageFolder(dir);
    ASSERT_EQ(s.frameCount(), 3);
    EXPECT_EQ(s.frames[0].filename(), "b.0002.TIF");
    EXPECT_EQ(s.frames[2].filename(), "b.0100.tiff");
    EXPECT_EQ(fm::frameNumberInName(s.frames[2]), 100);
    EXPECT_EQ(fm::frameNumberInName("nodigits.tif"), -1);
    EXPECT_THROW(s.frameName(3), fm::Error);
    fs::create_directories(dir / "empty");
    EXPECT_NE(errorOf([&] { fm::listImageFolder(dir / "empty"); }).find("holds no TIFF"), std::string::npos);
    EXPECT_NE(errorOf([&] { fm::listImageFolder(dir / "nope"); }).find("does not exist"), std::string::npos);
}

}  // namespace
