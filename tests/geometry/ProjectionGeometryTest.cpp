// The JSON projection geometry contract: parsing, strict validation, exact round trip,
// pixel placement, projection of world points and detector downsampling.
#include <cmath>
#include <fstream>
#include <functional>
#include <string>
#include <vector>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "common/TestData.h"
#include "core/Error.h"
#include "geometry/ProjectionGeometry.h"

namespace {

using Json = nlohmann::json;

// Sums and products of a few numbers of size <= 1e3: a few ulps of 1e3.
constexpr double kGeometryPositionTolMm = 1e-9;
// Continuous pixel coordinates from a handful of double operations on numbers <= 1e3.
constexpr double kGeometryPixelTol = 1e-9;

// A hand-made geometry: source 1000 mm above the z = 0 plane, a 256 x 200 detector with
// 1 x 1.5 mm pixels centred under the source (the centre of pixel (127.5, 99.5) is the foot).
const char* const kHandGeometry = R"({
  "source": [0, 0, 1000],
  "detector": {
    "size": [256, 200],
    "spacing": [1.0, 1.5],
    "origin": [-127.5, -149.25, 0],
    "u": [1, 0, 0],
    "v": [0, 1, 0]
  }
})";

std::string messageOf(const std::string& text) {
    try {
        fm::geometryFromJson(text, "test.json");
    } catch (const fm::Error& e) {
        return e.what();
    }
    return "";
}

TEST(ProjectionGeometry, ParsesTheContractFields) {
    const fm::ProjectionGeometry g = fm::geometryFromJson(kHandGeometry);
    EXPECT_EQ(g.source, glm::dvec3(0, 0, 1000));
    EXPECT_EQ(g.detector.size, glm::ivec2(256, 200));
    EXPECT_EQ(g.detector.spacing, glm::dvec2(1.0, 1.5));
    EXPECT_EQ(g.detector.origin, glm::dvec3(-127.5, -149.25, 0));
    EXPECT_EQ(g.detector.u, glm::dvec3(1, 0, 0));
    EXPECT_EQ(g.detector.v, glm::dvec3(0, 1, 0));
}

TEST(ProjectionGeometry, PixelCentresFollowTheContract) {
    const fm::ProjectionGeometry g = fm::geometryFromJson(kHandGeometry);
    // origin + c*du*u + r*dv*v, worked out by hand for pixel (10, 20).
    const glm::dvec3 p = g.detector.pixelCenter(10, 20);
    EXPECT_NEAR(p.x, -127.5 + 10.0, kGeometryPositionTolMm);
    EXPECT_NEAR(p.y, -149.25 + 30.0, kGeometryPositionTolMm);
    EXPECT_NEAR(p.z, 0.0, kGeometryPositionTolMm);
    // The centre of the middle of the grid is right under the source.
    const glm::dvec3 c = g.detector.center();
    EXPECT_NEAR(c.x, 0.0, kGeometryPositionTolMm);
    EXPECT_NEAR(c.y, 0.0, kGeometryPositionTolMm);
}

TEST(ProjectionGeometry, JsonRoundTripIsExact) {
    // Awkward binary fractions and magnitudes: the writer must keep every bit.
    fm::ProjectionGeometry g;
    g.source = {1.0 / 3.0, -123.456789012345678, 987.6543210000001};
    g.detector.size = {17, 3};
    g.detector.spacing = {0.1, 2.0 / 7.0};
    g.detector.origin = {-1e5 / 3.0, 0.30000000000000004, -0.0};
    const double c = std::cos(0.3), s = std::sin(0.3);
    g.detector.u = {c, s, 0.0};
    g.detector.v = {-s, c, 0.0};
    const fm::ProjectionGeometry back = fm::geometryFromJson(fm::geometryToJson(g));
    // Serialization is not a computation: the contract is bit-exact reproduction.
    for (int i = 0; i < 3; ++i) {
        EXPECT_EQ(back.source[i], g.source[i]);
        EXPECT_EQ(back.detector.origin[i], g.detector.origin[i]);
        EXPECT_EQ(back.detector.u[i], g.detector.u[i]);
        EXPECT_EQ(back.detector.v[i], g.detector.v[i]);
    }
    EXPECT_EQ(back.detector.size, g.detector.size);
    EXPECT_EQ(back.detector.spacing[0], g.detector.spacing[0]);
    EXPECT_EQ(back.detector.spacing[1], g.detector.spacing[1]);
}

TEST(ProjectionGeometry, WrittenJsonHasExactlyTheContractKeys) {
    const Json j = Json::parse(fm::geometryToJson(fm::geometryFromJson(kHandGeometry)));
    ASSERT_TRUE(j.is_object());
    EXPECT_EQ(j.size(), 2u);
    EXPECT_TRUE(j.contains("source"));
    ASSERT_TRUE(j.contains("detector"));
    EXPECT_EQ(j["detector"].size(), 5u);
    for (const char* key : {"size", "spacing", "origin", "u", "v"})
        EXPECT_TRUE(j["detector"].contains(key)) << key;
    EXPECT_TRUE(j["detector"]["size"][0].is_number_integer());
}

TEST(ProjectionGeometry, AcceptsIntegralFloatSizes) {
    Json j = Json::parse(kHandGeometry);
    j["detector"]["size"] = {256.0, 200.0};
    EXPECT_EQ(fm::geometryFromJson(j.dump()).detector.size, glm::ivec2(256, 200));
}

struct InvalidCase {
    const char* name;
    std::function<void(Json&)> mutate;
    const char* expectedInMessage;  // the field the message must name
};

TEST(ProjectionGeometry, RejectsEachInvalidFieldNamingIt) {
    // One case per line reads best.
    // clang-format off
    const std::vector<InvalidCase> cases = {
        {"missing source", [](Json& j) { j.erase("source"); }, "\"source\" is missing"},
        {"missing detector", [](Json& j) { j.erase("detector"); }, "\"detector\" is missing"},
        {"missing size", [](Json& j) { j["detector"].erase("size"); }, "detector.size"},
        {"missing spacing", [](Json& j) { j["detector"].erase("spacing"); }, "detector.spacing"},
        {"missing origin", [](Json& j) { j["detector"].erase("origin"); }, "detector.origin"},
        {"missing u", [](Json& j) { j["detector"].erase("u"); }, "detector.u"},
        {"missing v", [](Json& j) { j["detector"].erase("v"); }, "detector.v"},
        {"source too short", [](Json& j) { j["source"] = {1, 2}; }, "\"source\""},
        {"source as text", [](Json& j) { j["source"] = "0 0 1000"; }, "\"source\""},
        {"origin element text", [](Json& j) { j["detector"]["origin"][1] = "x"; },
         "detector.origin[1]"},
        {"u element null", [](Json& j) { j["detector"]["u"][2] = nullptr; }, "detector.u[2]"},
        {"spacing element bool", [](Json& j) { j["detector"]["spacing"][0] = true; },
         "detector.spacing[0]"},
        {"detector not object", [](Json& j) { j["detector"] = Json::array({1, 2}); },
         "\"detector\""},
        {"size zero", [](Json& j) { j["detector"]["size"][0] = 0; }, "detector.size[0]"},
        {"size negative", [](Json& j) { j["detector"]["size"][1] = -5; }, "detector.size[1]"},
        {"size absurd", [](Json& j) { j["detector"]["size"][0] = 16385; }, "detector.size[0]"},
        {"size fractional", [](Json& j) { j["detector"]["size"][1] = 255.5; },
         "detector.size[1]"},
        {"spacing zero", [](Json& j) { j["detector"]["spacing"][0] = 0.0; },
         "detector.spacing[0]"},
        {"spacing negative", [](Json& j) { j["detector"]["spacing"][1] = -1.0; },
         "detector.spacing[1]"},
        {"u not unit", [](Json& j) { j["detector"]["u"] = {1.01, 0, 0}; }, "detector.u"},
        {"v not unit", [](Json& j) { j["detector"]["v"] = {0, 2, 0}; }, "detector.v"},
        {"u and v not orthogonal",
         [](Json& j) { j["detector"]["v"] = {std::sin(0.01), std::cos(0.01), 0}; }, "orthogonal"},
        {"source in the detector plane", [](Json& j) { j["source"] = {5, 5, 0}; },
         "\"source\" lies in the detector plane"},
        {"unknown top-level key", [](Json& j) { j["sid"] = 1000; }, "\"sid\""},
        {"unknown detector key", [](Json& j) { j["detector"]["pixels"] = 3; },
         "detector.pixels"},
        {"top level not object", [](Json& j) { j = Json::array({1, 2, 3}); }, "JSON object"},
    };
    // clang-format on
    for (const auto& c : cases) {
        Json j = Json::parse(kHandGeometry);
        c.mutate(j);
        const std::string message = messageOf(j.dump());
        EXPECT_NE(message.find(c.expectedInMessage), std::string::npos)
            << c.name << ": message was \"" << message << "\"";
        EXPECT_NE(message.find("test.json"), std::string::npos) << c.name;
    }
}

TEST(ProjectionGeometry, RejectsNonFiniteAndMalformedText) {
    // JSON has no NaN/inf literals; a number beyond the double range is refused too.
    std::string overflow = kHandGeometry;
    overflow.replace(overflow.find("1000"), 4, "1e999");
    EXPECT_NE(messageOf(overflow).find("test.json"), std::string::npos);
    EXPECT_NE(messageOf("[1, 2").find("not valid JSON"), std::string::npos);
    EXPECT_NE(messageOf("{\"source\": [0, 0,").find("not valid JSON"), std::string::npos);
    EXPECT_NE(messageOf("").find("not valid JSON"), std::string::npos);
    // Strict, as documented: a repeated key is ambiguous (nlohmann keeps the last silently).
    std::string twice = kHandGeometry;
    twice.replace(twice.find("\"source\""), 8, "\"source\": [1, 2, 3], \"source\"");
    const std::string duplicate = messageOf(twice);
    EXPECT_NE(duplicate.find("duplicate key"), std::string::npos) << duplicate;
    EXPECT_NE(duplicate.find("test.json"), std::string::npos) << duplicate;
    // Validation of geometries built in code catches NaN too.
    fm::ProjectionGeometry g = fm::geometryFromJson(kHandGeometry);
    g.detector.origin.y = std::nan("");
    EXPECT_THROW(g.validate("code"), fm::Error);
    // ... and the writer refuses to write what the reader would refuse.
    EXPECT_THROW(fm::geometryToJson(g), fm::Error);
}

TEST(ProjectionGeometry, ReadsFilesAndNamesMissingOnes) {
    const auto dir = fm::test::scratchDir("geometry_file");
    const auto path = dir / "view.json";
    std::ofstream(path) << kHandGeometry;
    EXPECT_EQ(fm::readGeometryFile(path).detector.size, glm::ivec2(256, 200));
    const auto missing = dir / "nope.json";
    try {
        fm::readGeometryFile(missing);
        FAIL() << "no error for a missing file";
    } catch (const fm::Error& e) {
        EXPECT_NE(std::string(e.what()).find("nope.json"), std::string::npos) << e.what();
    }
}

TEST(ProjectionGeometry, ProjectsWorldPointsBySimilarTriangles) {
    const fm::ProjectionGeometry g = fm::geometryFromJson(kHandGeometry);
    // Point halfway between source and detector plane: offsets double on the film.
    // (10, 20, 500) -> (20, 40, 0) -> col = (20 + 127.5) / 1, row = (40 + 149.25) / 1.5.
    const auto p = g.projectToPixel({10.0, 20.0, 500.0});
    ASSERT_TRUE(p.has_value());
    EXPECT_NEAR(p->x, 147.5, kGeometryPixelTol);
    EXPECT_NEAR(p->y, 189.25 / 1.5, kGeometryPixelTol);
    // A point beyond the plane projects too (magnification < 1 there).
    const auto q = g.projectToPixel({-30.0, 0.0, -1000.0});
    ASSERT_TRUE(q.has_value());
    EXPECT_NEAR(q->x, 127.5 - 15.0, kGeometryPixelTol);
    // Behind the source, or level with it: no projection.
    EXPECT_FALSE(g.projectToPixel({0.0, 0.0, 1500.0}).has_value());
    EXPECT_FALSE(g.projectToPixel({50.0, 0.0, 1000.0}).has_value());
}

// Outer corner of the film: the edge of pixel (0,0), half a pixel before its centre.
glm::dvec3 filmCorner(const fm::DetectorGeometry& d, double c, double r) {
    return d.pixelCenter(c == 0 ? -0.5 : d.size.x - 0.5, r == 0 ? -0.5 : d.size.y - 0.5);
}

void expectSameCorners(const fm::DetectorGeometry& a, const fm::DetectorGeometry& b) {
    for (int c : {0, 1})
        for (int r : {0, 1}) {
            const glm::dvec3 pa = filmCorner(a, c, r), pb = filmCorner(b, c, r);
            for (int i = 0; i < 3; ++i) EXPECT_NEAR(pa[i], pb[i], kGeometryPositionTolMm) << c << r << i;
        }
}

TEST(ProjectionGeometry, DownsamplingKeepsTheFilm) {
    fm::ProjectionGeometry g = fm::geometryFromJson(kHandGeometry);
    // Tilt the film so that the corners test all three axes.
    const double c = std::cos(0.4), s = std::sin(0.4);
    g.detector.u = {c, 0.0, s};
    g.detector.v = {0.0, 1.0, 0.0};
    g.detector.origin = {-100.0, -150.0, -30.0};

    const fm::ProjectionGeometry half = g.downsampled(2);
    EXPECT_EQ(half.detector.size, glm::ivec2(128, 100));
    EXPECT_NEAR(half.detector.spacing.x, 2.0, kGeometryPositionTolMm);
    EXPECT_NEAR(half.detector.spacing.y, 3.0, kGeometryPositionTolMm);
    EXPECT_EQ(half.source, g.source);
    expectSameCorners(g.detector, half.detector);
    // Each coarse pixel centre is the mean of the 2 x 2 fine centres it covers.
    for (auto [col, row] : {std::pair{0, 0}, {5, 7}, {127, 99}}) {
        const glm::dvec3 mean = 0.25 * (g.detector.pixelCenter(2 * col, 2 * row) +
                                        g.detector.pixelCenter(2 * col + 1, 2 * row) +
                                        g.detector.pixelCenter(2 * col, 2 * row + 1) +
                                        g.detector.pixelCenter(2 * col + 1, 2 * row + 1));
        const glm::dvec3 coarse = half.detector.pixelCenter(col, row);
        for (int i = 0; i < 3; ++i) EXPECT_NEAR(coarse[i], mean[i], kGeometryPositionTolMm);
    }

    // 256 x 200 by 3: 86 x 67 pixels, stretched a little so the film stays the same.
    const fm::ProjectionGeometry third = g.downsampled(3);
    EXPECT_EQ(third.detector.size, glm::ivec2(86, 67));
    EXPECT_NEAR(third.detector.spacing.x * 86, 256.0, kGeometryPositionTolMm);
    EXPECT_NEAR(third.detector.spacing.y * 67, 300.0, kGeometryPositionTolMm);
    expectSameCorners(g.detector, third.detector);

    // Factor larger than the detector: one pixel covering the whole film.
    const fm::ProjectionGeometry one = g.downsampled(1000);
    EXPECT_EQ(one.detector.size, glm::ivec2(1, 1));
    expectSameCorners(g.detector, one.detector);
    EXPECT_NO_THROW(one.validate("one pixel"));

    const fm::ProjectionGeometry same = g.downsampled(1);
    EXPECT_EQ(same.detector.size, g.detector.size);
    EXPECT_EQ(same.detector.origin, g.detector.origin);

    EXPECT_THROW(g.downsampled(0), fm::Error);
    EXPECT_THROW(g.downsampled(-2), fm::Error);
}

}  // namespace
