// How a trial's frames are prepared: the default follows the frames' depth (8-bit display signal:
// inverted; 16-bit raw intensities: log), a trial's log preparation gives -ln(I / I0) pixel for
// pixel (computed here from the stored values, not by the preparation code) with the mask
// `radiograph --exclude-below --erode` gives, and the command line's flags replace only their part.
#include <cmath>
#include <fstream>

#include <gtest/gtest.h>

#include "common/TestData.h"
#include "core/Error.h"
#include "io/AtomicFile.h"
#include "io/ImageFileWriter.h"
#include "radiograph/Radiograph.h"
#include "track/TrialScene.h"

namespace {

namespace fs = std::filesystem;
using fm::FramePreparation;

fs::path jtml() { return fm::test::sharedDataDir() / "jtml-kneel-tka-fluoro"; }

// A one-camera, one-frame trial of JTML frame 0160 (8-bit, or as 16-bit counts: value * 257),
// the femoral implant its bone, frames compared as they are (no reduction).
fs::path makeTrial(const fs::path& dir, int bits, const std::string& preparation) {
    fs::create_directories(dir / "frames");
    const fs::path frame = jtml() / "AT_K1_V1_0160.tif";
    if (bits == 8) {
        fs::copy_file(frame, dir / "frames/f0.tif", fs::copy_options::overwrite_existing);
    } else {
        fm::io::writeFileAtomically(dir / "frames/f0.tif", fm::encodeTiffGrey16(fm::readRadiograph(frame).image, 257.0));
    }
    std::ofstream(dir / "t.json") << R"({"cameras": [{"calibration": ")" << (jtml() / "calibration.txt").string()
                                   << R"(", "frames": "frames")" << (preparation.empty() ? "" : ", \"preparation\": " + preparation)
                                   << R"(}], "bones": [{"name": "femur", "mesh": ")" << (jtml() / "KR_right_7_fem.stl").string()
                                   << R"("}], "render_resolution": [16384, 16384]})";
    return dir / "t.json";
}

fm::TrialScene load(const fs::path& trial) { return fm::loadTrialScene(fm::readTrial(trial), {}, 2); }

TEST(TrialPreparation, TheDefaultFollowsTheFramesDepth) {
    FM_REQUIRE_SHARED_DATA("jtml-kneel-tka-fluoro");
    const fm::TrialScene display = load(makeTrial(fm::test::scratchDir("prep8"), 8, ""));
    ASSERT_EQ(display.preparations.size(), 1u);
    EXPECT_EQ(display.preparations[0].spec.values, FramePreparation::Values::Invert);
    EXPECT_EQ(display.preparations[0].spec.excludeBelow, 0.0);
    EXPECT_NE(display.preparations[0].source.find("default for 8-bit frames"), std::string::npos);
    const fm::TrialScene raw = load(makeTrial(fm::test::scratchDir("prep16"), 16, ""));
    EXPECT_EQ(raw.preparations[0].bitsPerSample, 16);
    EXPECT_EQ(raw.preparations[0].spec.values, FramePreparation::Values::Log);
    EXPECT_EQ(raw.preparations[0].spec.i0, 0.0);  // the full scale
    EXPECT_NE(raw.preparations[0].source.find("default for 16-bit frames: raw detector intensities"), std::string::npos);
    EXPECT_EQ(fm::describePreparation(raw.preparations[0].spec, 16),
              "log, -ln(I / I0), I0 = 65535 (the full scale); values <= 0 excluded, grown 3 px");
}

TEST(TrialPreparation, ALogTrialGivesMinusLnOfTheStoredValuesAndRadiographsMask) {
    FM_REQUIRE_SHARED_DATA("jtml-kneel-tka-fluoro");
    const fs::path dir = fm::test::scratchDir("preplog");
    const fm::TrialScene t =
        load(makeTrial(dir, 16, R"({"values": "log", "i0": 60000, "exclude_below": 0, "erode": 2})"));
    EXPECT_EQ(t.preparations[0].source, "the trial's");
    const auto views = fm::trialFrameViews(t)(0);
    ASSERT_EQ(views.size(), 1u);
    const fm::Image stored = fm::readRadiograph(dir / "frames/f0.tif").image;
    ASSERT_EQ(views[0].reference.pixels.size(), stored.pixels.size());
    std::size_t bright = 0;
    for (std::size_t i = 0; i < stored.pixels.size(); ++i) {
        const double v = std::clamp<double>(stored.pixels[i], 1.0, 60000.0);
        ASSERT_NEAR(views[0].reference.pixels[i], -std::log(v / 60000.0), 1e-5) << i;
        bright += stored.pixels[i] > 60000.0f;
    }
    EXPECT_GT(bright, 0u);  // the clamp at I0 was exercised
    // The mask `radiograph F --log --i0 60000 --exclude-below 0 --erode 2` compares.
    fm::RadiographPreparation p;
    p.logTransform = true;
    p.i0 = 60000.0;
    p.fullScale = 65535.0;
    p.excludeBelow = 0.0;
    p.erodePixels = 2;
    ASSERT_TRUE(views[0].valid);
    EXPECT_EQ(views[0].valid->inside, fm::prepareRadiograph(stored, p).valid.inside);
}

TEST(TrialPreparation, TheFlagsReplaceOnlyTheirPartAndRefuseWhatDoesNotApply) {
    FM_REQUIRE_SHARED_DATA("jtml-kneel-tka-fluoro");
    const fs::path trial = makeTrial(fm::test::scratchDir("prepflags"), 16,
                                     R"({"values": "log", "i0": 60000, "exclude_below": 0, "erode": 2})");
    fm::TrialScene t = load(trial);
    fm::PreparationOverride invert;
    invert.values = FramePreparation::Values::Invert;
    invert.flags = "--invert";
    fm::overridePreparations(t, invert);
    EXPECT_EQ(t.preparations[0].spec.values, FramePreparation::Values::Invert);
    EXPECT_EQ(t.preparations[0].spec.i0, 0.0);
    EXPECT_EQ(t.preparations[0].spec.excludeBelow, 0.0);  // kept from the trial
    EXPECT_EQ(t.preparations[0].spec.erodePixels, 2);
    EXPECT_EQ(t.preparations[0].source, "--invert over the trial's");
    const fm::Image stored = fm::readRadiograph(trial.parent_path() / "frames/f0.tif").image;
    EXPECT_FLOAT_EQ(fm::trialFrameViews(t)(0)[0].reference.pixels[1000], 65535.0f - stored.pixels[1000]);

    fm::TrialScene plain = load(makeTrial(fm::test::scratchDir("prepflags2"), 16, R"({"values": "as-stored"})"));
    fm::PreparationOverride erode;
    erode.erodePixels = 4;
    erode.flags = "--erode 4";
    const auto message = [&](fm::TrialScene& s, const fm::PreparationOverride& o) {
        try {
            fm::overridePreparations(s, o);
        } catch (const fm::Error& e) {
            return std::string(e.what());
        }
        return std::string();
    };
    EXPECT_NE(message(plain, erode).find("--erode: camera cam1 excludes no pixels"), std::string::npos);
    fm::PreparationOverride roi;
    roi.roi = fm::PixelRect{1000, 0, 100, 100};
    roi.flags = "--roi 1000,0,100,100";
    const std::string e = message(t, roi);
    EXPECT_NE(e.find("camera cam1 preparation roi 1000,0,100,100"), std::string::npos) << e;
    EXPECT_NE(e.find("must lie inside its 1024 x 1024 images"), std::string::npos) << e;
}

}  // namespace
