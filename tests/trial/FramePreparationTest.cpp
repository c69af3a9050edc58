// A camera's frame preparation in a trial file: every form round-trips through our JSON and
// Autoscoper's .cfg (read back by readTrial, as every command reads a trial), the .cfg line is
// one Autoscoper's parser skips, and bad values are refused naming the file and the field.
#include <fstream>
#include <set>

#include <gtest/gtest.h>

#include "common/ErrorText.h"
#include "common/TestData.h"
#include "core/Error.h"
#include "trial/AutoscoperConfig.h"
#include "trial/Trial.h"

namespace {

namespace fs = std::filesystem;
using fm::FramePreparation;

using fm::test::errorOf;

// One of each kind: log with I0, inverted with an exclusion and an roi, as stored.
std::vector<FramePreparation> examples() {
    FramePreparation log;
    log.values = FramePreparation::Values::Log;
    log.i0 = 51234.5;
    FramePreparation invert;
    invert.values = FramePreparation::Values::Invert;
    invert.excludeBelow = 0.0;
    invert.erodePixels = 5;
    invert.roi = fm::PixelRect{10, 20, 300, 400};
    FramePreparation stored;
    stored.values = FramePreparation::Values::AsStored;
    stored.excludeBelow = -12.25;
    stored.erodePixels = 0;
    return {log, invert, stored};
}

fm::Trial trialOf(const fs::path& dir, const std::vector<FramePreparation>& preparations) {
    fm::Trial t;
    t.name = "prep";
    for (std::size_t c = 0; c < preparations.size(); ++c) {
        const std::string n = "cam" + std::to_string(c + 1);
        t.cameras.push_back({n, dir / (n + ".txt"), dir / n, preparations[c]});
    }
    t.bones.push_back({"bone", dir / "bone.tif", {0.5, 0.5, 1.0}, {0, 0, 0}, {}, 0.0, {}});
    return t;
}

TEST(FramePreparation, EveryFormRoundTripsThroughTheTrialJson) {
    const fs::path dir = fm::test::scratchDir("prep_json");
    fm::Trial t = trialOf(dir, examples());
    t.cameras.push_back({"cam4", dir / "cam4.txt", dir / "cam4", std::nullopt});  // says nothing
    fm::writeTrialJson(dir / "t.json", t);
    const fm::Trial back = fm::readTrial(dir / "t.json");
    ASSERT_EQ(back.cameras.size(), 4u);
    for (std::size_t c = 0; c < 3; ++c) {
        ASSERT_TRUE(back.cameras[c].preparation) << c;
        EXPECT_EQ(*back.cameras[c].preparation, examples()[c]) << c;
    }
    EXPECT_FALSE(back.cameras[3].preparation);
    EXPECT_TRUE(back.warnings.empty());
}

TEST(FramePreparation, EveryFormRoundTripsThroughTheCfgAndAutoscoperSkipsItsLines) {
    const fs::path dir = fm::test::scratchDir("prep_cfg");
    fm::AutoscoperConfig c;
    for (int k = 1; k <= 3; ++k) {
        c.calibrations.push_back(dir / ("cam" + std::to_string(k) + ".txt"));
        c.cameraRootDirs.push_back(dir / ("cam" + std::to_string(k)));
    }
    c.volumes = {{dir / "bone.tif", {0, 0, 0}, {0.5, 0.5, 1.0}}};
    c.preparations = examples();
    fm::writeAutoscoperConfig(dir / "t.cfg", c);
    const fm::Trial back = fm::readTrial(dir / "t.cfg");
    ASSERT_EQ(back.cameras.size(), 3u);
    for (std::size_t k = 0; k < 3; ++k) {
        ASSERT_TRUE(back.cameras[k].preparation) << k;
        EXPECT_EQ(*back.cameras[k].preparation, examples()[k]) << k;
    }
    EXPECT_TRUE(back.warnings.empty());
    // Autoscoper (libautoscoper Trial::parse at 203b721) takes the text before the first space
    // as the key and compares it with its nine keys; anything else is skipped. Each of our lines
    // has a key outside them, so the file loads there as the trial without preparations.
    const std::set<std::string> autoscoperKeys{"mayaCam_csv",      "CameraRootDir", "VolumeFile",
                                               "VolumeFlip",       "VoxelSize",     "RenderResolution",
                                               "OptimizationOffsets", "MeshFile",   "Version"};
    std::ifstream in(dir / "t.cfg");
    int ours = 0;
    for (std::string line; std::getline(in, line);) {
        const std::string key = line.substr(0, line.find(' '));
        if (key == "RadiographPreparation") ++ours;
        else EXPECT_TRUE(autoscoperKeys.count(key)) << line;
    }
    EXPECT_EQ(ours, 3);
    EXPECT_FALSE(autoscoperKeys.count("RadiographPreparation"));
}

TEST(FramePreparation, BadValuesAreRefusedNamingTheFileAndTheField) {
    const fs::path dir = fm::test::scratchDir("prep_bad");
    const auto json = [&](const std::string& preparation) {
        std::ofstream(dir / "t.json") << R"({"cameras": [{"calibration": "c.txt", "frames": "f",
            "preparation": )" << preparation << R"(}], "bones": [{"name": "b", "mesh": "b.stl"}]})";
        return errorOf([&] { fm::readTrial(dir / "t.json"); });
    };
    const std::pair<const char*, const char*> cases[] = {
        {R"({"values": "lg"})", "\"cameras[0].preparation.values\" must be \"log\", \"invert\" or \"as-stored\""},
        {R"({"i0": 100})", "\"cameras[0].preparation.values\" is missing"},
        {R"({"values": "invert", "i0": 100})", "\"cameras[0].preparation.i0\" applies to log values only"},
        {R"({"values": "log", "i0": -3})", "\"cameras[0].preparation.i0\" must be a positive intensity"},
        {R"({"values": "log", "erode": 2})", "\"cameras[0].preparation.erode\" applies with an exclusion only"},
        {R"({"values": "log", "exclude_below": 0, "erode": 2.5})", "\"cameras[0].preparation.erode\" must be whole"},
        {R"({"values": "log", "roi": [0, 0, 0, 10]})", "\"cameras[0].preparation.roi\" must be x,y >= 0 and w,h >= 1"},
        {R"({"values": "log", "roi": [0, 0.5, 10, 10]})", "\"cameras[0].preparation.roi\" must be whole pixels"},
        {R"({"values": "log", "exclude-below": 0})", "\"cameras[0].preparation.exclude-below\" is not a preparation field"},
        {R"("log")", "\"cameras[0].preparation\" must be an object"},
    };
    for (const auto& [text, expected] : cases) {
        const std::string e = json(text);
        EXPECT_NE(e.find("t.json"), std::string::npos) << text << ": " << e;
        EXPECT_NE(e.find(expected), std::string::npos) << text << ": " << e;
    }

    const std::string head = "Version 1.1\nmayaCam_csv a.txt\nmayaCam_csv b.txt\nCameraRootDir a\nCameraRootDir b\n"
                             "VolumeFile v.tif\nVoxelSize 1 1 1\n";
    const auto cfg = [&](const std::string& lines) {
        std::ofstream(dir / "t.cfg") << head << lines;
        return errorOf([&] { fm::readTrial(dir / "t.cfg"); });
    };
    const std::pair<std::string, const char*> cfgCases[] = {
        {"RadiographPreparation log\n", "one RadiographPreparation per camera or none (2 cameras, 1"},
        {"RadiographPreparation log\nRadiographPreparation lg\n", "line 9 (RadiographPreparation): RadiographPreparation must be"},
        {"RadiographPreparation log i0=0\nRadiographPreparation log\n", "line 8 (RadiographPreparation): RadiographPreparation i0 must be a positive"},
        {"RadiographPreparation invert i0=5\nRadiographPreparation log\n", "i0 applies to log values only"},
        {"RadiographPreparation log erode=3\nRadiographPreparation log\n", "erode applies with an exclusion only"},
        {"RadiographPreparation log roi=1,2,3\nRadiographPreparation log\n", "roi (x,y,w,h)"},
        {"RadiographPreparation log gain=2\nRadiographPreparation log\n", "gain is not a preparation field"},
        {"RadiographPreparation log i0=5 i0=6\nRadiographPreparation log\n", "i0 is given twice"},
        {"RadiographPreparation log i0\nRadiographPreparation log\n", "i0 needs a value"},
    };
    for (const auto& [text, expected] : cfgCases) {
        const std::string e = cfg(text);
        EXPECT_NE(e.find("t.cfg"), std::string::npos) << text << ": " << e;
        EXPECT_NE(e.find(expected), std::string::npos) << text << ": " << e;
    }
}

}  // namespace
