// Batch DRRs as an indexed job list: views files, the azimuth sweep, numbered names, and jobs
// whose geometry is the one a single `drr` would use.
#include <gtest/gtest.h>

#include <fstream>

#include "common/TestData.h"
#include "core/Error.h"
#include "drr/DrrBatch.h"

namespace {

namespace fs = std::filesystem;

TEST(DrrBatch, ViewsFileHoldsPosesAndGeometryFiles) {
    const auto views = fm::parseDrrViews(
        "# a comment\n"
        "0 0 0 0 0 0\n"
        "\n"
        "1.5, -2, 3, 90, 10, -5   # lateral\n"
        "cams/view3.json\n"
        "/abs/g.json\n",
        "views.txt", "/data/trial");
    ASSERT_EQ(views.size(), 4u);
    ASSERT_TRUE(views[0].pose.has_value());
    EXPECT_EQ(views[0].origin, "views.txt:2");
    ASSERT_TRUE(views[1].pose.has_value());
    EXPECT_EQ(views[1].pose->toArray(), (std::array<double, 6>{1.5, -2, 3, 90, 10, -5}));
    EXPECT_EQ(views[1].origin, "views.txt:4");
    EXPECT_FALSE(views[2].pose.has_value());
    EXPECT_EQ(views[2].geometryFile, fs::path("/data/trial/cams/view3.json")) << "relative to the file";
    EXPECT_EQ(views[3].geometryFile, fs::path("/abs/g.json"));
}

TEST(DrrBatch, BadViewsAreErrorsNamingTheLine) {
    auto message = [](const std::string& text) {
        try {
            fm::parseDrrViews(text, "v.txt", ".");
        } catch (const fm::Error& e) {
            return std::string(e.what());
        }
        return std::string("no error");
    };
    EXPECT_NE(message("0 0 0 0 0 0\n1 2 3\n").find("v.txt:2"), std::string::npos);
    EXPECT_NE(message("0 0 0 0 200 0\n").find("v.txt:1"), std::string::npos) << "elevation 200";
    EXPECT_NE(message("0 0 0 0 x 0\n").find("v.txt:1"), std::string::npos);
    EXPECT_NE(message("# nothing\n\n").find("no view"), std::string::npos);
    EXPECT_THROW(fm::readDrrViews(fm::test::scratchDir("drr-batch-missing") / "missing.txt"), fm::Error);
}

TEST(DrrBatch, SweepStepsTheAzimuthAndWraps) {
    const fm::Pose start = fm::Pose::fromArray({1, 2, 3, 170, 5, -4});
    const auto views = fm::azimuthSweep(start, 4, 10.0);
    ASSERT_EQ(views.size(), 4u);
    const double expected[] = {170, -180, -170, -160};
    for (int i = 0; i < 4; ++i) {
        EXPECT_DOUBLE_EQ(views[i].pose->azimuthDeg, expected[i]) << i;
        EXPECT_EQ(views[i].pose->elevationDeg, 5.0);
        EXPECT_EQ(views[i].pose->offset, start.offset);
    }
    EXPECT_EQ(views[1].origin, "sweep 2 of 4");
    EXPECT_THROW(fm::azimuthSweep(start, 0, 10.0), fm::Error);
    EXPECT_THROW(fm::azimuthSweep(start, 3, std::nan("")), fm::Error);
}

TEST(DrrBatch, NumberedOutputsAreAFunctionOfTheIndex) {
    EXPECT_EQ(fm::numberedOutput("out/drr.png", 7, 36), fs::path("out/drr_007.png"));
    EXPECT_EQ(fm::numberedOutput("drr.png", 0, 1), fs::path("drr_000.png"));
    EXPECT_EQ(fm::numberedOutput("x.nii.gz", 12, 20), fs::path("x_012.nii.gz"));
    EXPECT_EQ(fm::numberedOutput("big.tif", 42, 12000), fs::path("big_00042.tif"));
    EXPECT_EQ(fm::numberedOutput("noext", 3, 5), fs::path("noext_003"));
    EXPECT_EQ(fm::numberedOutput("", 3, 5), fs::path());
}

TEST(DrrBatch, JobsCarryTheSingleViewGeometry) {
    const fm::SceneSetup setup = fm::defaultSceneSetup();
    const glm::dvec3 center(10, -20, 30);
    const fs::path dir = fm::test::scratchDir("drr-batch");
    const fm::Pose lateral = fm::Pose::fromArray({1, 2, 3, 90, 0, 0});
    {
        std::ofstream g(dir / "g.json");
        g << fm::geometryToJson(fm::sceneGeometry(lateral, setup, center));
    }
    {
        std::ofstream f(dir / "views.txt");
        f << "0 0 0 0 0 0\ng.json\n";
    }
    const auto jobs = fm::makeDrrJobs(fm::readDrrViews(dir / "views.txt"), setup, center, 2,
                                      dir / "d.png", "");
    ASSERT_EQ(jobs.size(), 2u);
    const fm::ProjectionGeometry ap = fm::sceneGeometry(fm::Pose{}, setup, center).downsampled(2);
    const fm::ProjectionGeometry lat =
        fm::sceneGeometry(lateral, setup, center).downsampled(2);
    for (int k = 0; k < 2; ++k) {
        const fm::ProjectionGeometry& want = k == 0 ? ap : lat;
        EXPECT_EQ(jobs[k].index, std::size_t(k));
        EXPECT_EQ(jobs[k].geometry.detector.size, want.detector.size);
        for (int a = 0; a < 3; ++a) {
            EXPECT_NEAR(jobs[k].geometry.source[a], want.source[a], 1e-9) << k;
            EXPECT_NEAR(jobs[k].geometry.detector.center()[a], want.detector.center()[a], 1e-9)
                << k;
        }
        EXPECT_EQ(jobs[k].output, fm::numberedOutput(dir / "d.png", k, 2));
        EXPECT_TRUE(jobs[k].rawOutput.empty());
    }
    // A geometry file that does not exist names its line.
    {
        std::ofstream f(dir / "bad.txt");
        f << "0 0 0 0 0 0\nnothere.json\n";
    }
    try {
        fm::makeDrrJobs(fm::readDrrViews(dir / "bad.txt"), setup, center, 1, "d.png", "");
        FAIL() << "a missing geometry file was accepted";
    } catch (const fm::Error& e) {
        EXPECT_NE(std::string(e.what()).find("bad.txt:2"), std::string::npos) << e.what();
    }
}

}  // namespace
