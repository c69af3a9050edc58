// The 2011 six-parameter scene: pose text, the default AP view, distances, the poles, the
// azimuth seam, film rotation and the CT offset, checked against hand-worked geometry from
// the convention in docs/geometry.md (LPS world: +x left, +y posterior, +z superior).
#include <algorithm>
#include <cmath>
#include <string>

#include <gtest/gtest.h>

#include "core/Error.h"
#include "geometry/Pose.h"
#include "geometry/ProjectionGeometry.h"
#include "phantom/Phantoms.h"

namespace {

// Positions are sums of products of numbers <= ~1e3 with sines/cosines: a few ulps of 1e3.
constexpr double kPositionTolMm = 1e-9;
// Unit vectors from a handful of sin/cos products.
constexpr double kUnitTol = 1e-12;
// Pixel coordinates (<= 256) from projections of <= 1e3 mm coordinates.
constexpr double kPixelTol = 1e-8;
// Continuity: an angle step of 1e-6 deg is 1.75e-8 rad; unit vectors built from sin/cos move
// by at most a few times that.
constexpr double kAngleStepDeg = 1e-6;
constexpr double kContinuityTol = 1e-7;

const glm::dvec3 kCenter{12.5, -40.0, 230.0};  // an off-origin volume centre

void expectNear(const glm::dvec3& a, const glm::dvec3& b, double tol, const std::string& what) {
    for (int i = 0; i < 3; ++i) EXPECT_NEAR(a[i], b[i], tol) << what << " [" << i << "]";
}

fm::Pose pose(double x, double y, double z, double az, double el, double rot) {
    return fm::Pose::fromArray({x, y, z, az, el, rot});
}

std::string parseError(const std::string& text) {
    try {
        fm::parsePose(text);
    } catch (const fm::Error& e) {
        return e.what();
    }
    return "";
}

// ---- pose text ----------------------------------------------------------------------------

TEST(Pose, ParsesSixNumbers) {
    const fm::Pose p = fm::parsePose("1.5,-2,3e1, 45 ,-30,+10");
    EXPECT_EQ(p.offset, glm::dvec3(1.5, -2.0, 30.0));
    EXPECT_EQ(p.azimuthDeg, 45.0);
    EXPECT_EQ(p.elevationDeg, -30.0);
    EXPECT_EQ(p.rotationDeg, 10.0);
}

TEST(Pose, AcceptsTheRangeLimits) {
    EXPECT_NO_THROW(fm::parsePose("0,0,0,180,90,90"));
    EXPECT_NO_THROW(fm::parsePose("0,0,0,-180,-90,-90"));
}

TEST(Pose, RejectsBadTextNamingTheParameter) {
    const struct {
        const char* text;
        const char* expected;
    } cases[] = {
        // clang-format off
        {"1,2,3,4,5", "6 comma-separated"},
        {"1,2,3,4,5,6,7", "6 comma-separated"},
        {"", "6 comma-separated"},
        {"1,2,,4,5,6", "z offset"},
        {"1,abc,3,4,5,6", "y offset"},
        {"1,2,3,4deg,5,6", "azimuth"},
        {"nan,0,0,0,0,0", "x offset"},
        {"0,0,0,inf,0,0", "azimuth"},
        {"0,0,0,0,1e999,0", "elevation"},
        {"0,0,0,180.001,0,0", "azimuth"},
        {"0,0,0,-181,0,0", "azimuth"},
        {"0,0,0,0,90.5,0", "elevation"},
        {"0,0,0,0,-91,0", "elevation"},
        {"0,0,0,0,0,91", "rotation"},
        {"0,0,0,0,0,-90.0001", "rotation"},
        {"0;0;0;0;0;0", "6 comma-separated"},
        // clang-format on
    };
    for (const auto& c : cases) {
        const std::string message = parseError(c.text);
        EXPECT_NE(message.find(c.expected), std::string::npos)
            << "\"" << c.text << "\" gave \"" << message << "\"";
    }
}

TEST(Pose, FormatReadsBackExactly) {
    const fm::Pose p = pose(0.1, -1.0 / 3.0, 1e-9, 179.99999999999997, -89.5, 2.0 / 3.0);
    const fm::Pose back = fm::parsePose(fm::formatPose(p));
    // Text round trip is not a computation: every bit must come back.
    EXPECT_EQ(back.toArray(), p.toArray());
    EXPECT_EQ(fm::formatPose(pose(1, 2, 3, 4, 5, 6)), "1,2,3,4,5,6");
}

TEST(Pose, ValidateRejectsNonFinite) {
    EXPECT_THROW(fm::validatePose(pose(std::nan(""), 0, 0, 0, 0, 0)), fm::Error);
    EXPECT_THROW(fm::validatePose(pose(0, 0, 0, 0, 0, INFINITY)), fm::Error);
    EXPECT_NO_THROW(fm::validatePose(pose(-1e4, 0, 1e4, -180, 90, 0)));
}

// ---- the default scene --------------------------------------------------------------------

TEST(Scene, DefaultSetupHasEqualDistancesAnd256Pixels) {
    const fm::SceneSetup s = fm::defaultSceneSetup();
    EXPECT_GT(s.sourceToIsocenterMm, 0.0);
    EXPECT_EQ(s.sourceToIsocenterMm, s.isocenterToFilmMm);
    EXPECT_EQ(s.filmPixels, glm::ivec2(256, 256));
    EXPECT_GT(s.filmSizeMm.x, 0.0);
    EXPECT_NO_THROW(fm::validateSceneSetup(s));
}

TEST(Scene, DefaultSetupFramesTheKneePhantom) {
    // The default scene must show the whole default phantom in the cardinal views: every
    // corner of the box around its tissue (above -500 HU: fat, muscle, bone) lands on the
    // film, at least kMarginPixels inside.
    constexpr double kMarginPixels = 2.0;
    constexpr float kTissueHU = -500.0f;
    const fm::Volume knee = fm::makePhantom("knee");
    glm::ivec3 lo(knee.dims), hi(-1);
    for (int k = 0; k < knee.dims.z; ++k)
        for (int j = 0; j < knee.dims.y; ++j)
            for (int i = 0; i < knee.dims.x; ++i)
                if (knee.at(i, j, k) > kTissueHU) {
                    lo = glm::min(lo, glm::ivec3(i, j, k));
                    hi = glm::max(hi, glm::ivec3(i, j, k));
                }
    ASSERT_GE(hi.x, lo.x) << "no tissue in the phantom";
    // The phantom's tissue runs the whole field along the leg (z): a real framing test.
    EXPECT_EQ(lo.z, 0);
    EXPECT_EQ(hi.z, knee.dims.z - 1);
    const fm::SceneSetup s = fm::defaultSceneSetup();
    for (auto [az, el] : {std::pair{0.0, 0.0},
                          {90.0, 0.0},
                          {180.0, 0.0},
                          {-90.0, 0.0},
                          {0.0, 90.0},
                          {0.0, -90.0}}) {
        const auto g = fm::sceneGeometry(pose(0, 0, 0, az, el, 0), s, knee.center());
        for (int corner = 0; corner < 8; ++corner) {
            // Voxel boxes extend half a voxel beyond the centres.
            const glm::dvec3 ijk((corner & 1) ? hi.x + 0.5 : lo.x - 0.5,
                                 (corner & 2) ? hi.y + 0.5 : lo.y - 0.5,
                                 (corner & 4) ? hi.z + 0.5 : lo.z - 0.5);
            const auto p = g.projectToPixel(knee.indexToWorld(ijk));
            ASSERT_TRUE(p);
            SCOPED_TRACE("az " + std::to_string(az) + " el " + std::to_string(el));
            EXPECT_GE(p->x, kMarginPixels);
            EXPECT_GE(p->y, kMarginPixels);
            EXPECT_LE(p->x, s.filmPixels.x - 1 - kMarginPixels);
            EXPECT_LE(p->y, s.filmPixels.y - 1 - kMarginPixels);
        }
    }
}

TEST(Scene, DefaultPoseIsAnApView) {
    const fm::SceneSetup s = fm::defaultSceneSetup();
    const double sad = s.sourceToIsocenterMm, sid = s.isocenterToFilmMm;
    const fm::ProjectionGeometry g = fm::sceneGeometry(fm::Pose{}, s, kCenter);
    // Source anterior (-y) of the volume centre, film posterior (+y).
    expectNear(g.source, kCenter + glm::dvec3(0, -sad, 0), kPositionTolMm, "source");
    expectNear(g.detector.center(), kCenter + glm::dvec3(0, sid, 0), kPositionTolMm, "film");
    // Columns run towards patient left (+x): patient right on the image's left, as an AP
    // film is read. Rows run towards inferior (-z): superior at the top.
    expectNear(g.detector.u, {1, 0, 0}, kUnitTol, "u");
    expectNear(g.detector.v, {0, 0, -1}, kUnitTol, "v");
    // u x v points along the beam (from the source towards the film): beam's-eye view.
    expectNear(g.detector.normal(), {0, 1, 0}, kUnitTol, "normal");
    EXPECT_NEAR(g.detector.spacing.x, s.filmSizeMm.x / 256.0, kUnitTol);
    EXPECT_NEAR(g.detector.spacing.y, s.filmSizeMm.y / 256.0, kUnitTol);
    EXPECT_NO_THROW(g.validate("default scene"));
}

TEST(Scene, CardinalViewsPutTheSourceWhereTheConventionSays) {
    const fm::SceneSetup s = fm::defaultSceneSetup();
    const double sad = s.sourceToIsocenterMm;
    const struct {
        double az, el;
        glm::dvec3 direction;  // isocenter -> source, LPS
        const char* name;
    } views[] = {
        {90, 0, {1, 0, 0}, "left lateral"},
        {-90, 0, {-1, 0, 0}, "right lateral"},
        {180, 0, {0, 1, 0}, "PA"},
        {-180, 0, {0, 1, 0}, "PA (-180)"},
        {0, 90, {0, 0, 1}, "from superior"},
        {0, -90, {0, 0, -1}, "from inferior"},
        {45, 0, {std::sqrt(0.5), -std::sqrt(0.5), 0}, "anterior-left oblique"},
    };
    for (const auto& view : views) {
        const fm::ProjectionGeometry g =
            fm::sceneGeometry(pose(0, 0, 0, view.az, view.el, 0), s, kCenter);
        expectNear(g.source, kCenter + sad * view.direction, kPositionTolMm, view.name);
    }
    // Left lateral: seen from the patient's left, posterior is to the image's right.
    const fm::ProjectionGeometry lateral = fm::sceneGeometry(pose(0, 0, 0, 90, 0, 0), s, kCenter);
    expectNear(lateral.detector.u, {0, 1, 0}, kUnitTol, "lateral u");
    expectNear(lateral.detector.v, {0, 0, -1}, kUnitTol, "lateral v");
}

TEST(Scene, DistancesAndOrthonormalFilmForAllAngles) {
    const fm::SceneSetup s = fm::defaultSceneSetup();
    const double sad = s.sourceToIsocenterMm, sid = s.isocenterToFilmMm;
    for (double az = -180; az <= 180; az += 22.5)
        for (double el = -90; el <= 90; el += 15)
            for (double rot : {-90.0, -33.0, 0.0, 61.0, 90.0}) {
                const glm::dvec3 offset{3, -7, 11};
                const fm::ProjectionGeometry g =
                    fm::sceneGeometry(pose(offset.x, offset.y, offset.z, az, el, rot), s, kCenter);
                const glm::dvec3 iso = kCenter - offset;
                const auto& d = g.detector;
                SCOPED_TRACE("az " + std::to_string(az) + " el " + std::to_string(el) + " rot " +
                             std::to_string(rot));
                EXPECT_NEAR(glm::length(g.source - iso), sad, kPositionTolMm);
                EXPECT_NEAR(glm::length(d.center() - iso), sid, kPositionTolMm);
                // Film centre, isocenter and source on one line (the central ray).
                EXPECT_NEAR(glm::length(glm::cross(g.source - iso, d.center() - iso)), 0.0,
                            1e-9 * sad * sid);
                EXPECT_NEAR(glm::length(d.u), 1.0, kUnitTol);
                EXPECT_NEAR(glm::length(d.v), 1.0, kUnitTol);
                EXPECT_NEAR(glm::dot(d.u, d.v), 0.0, kUnitTol);
                // Film faces the source: its normal lies along the central ray, pointing away.
                expectNear(d.normal(), glm::normalize(iso - g.source), kUnitTol, "normal");
                EXPECT_NEAR(glm::dot(g.source - d.origin, -d.normal()), sad + sid, kPositionTolMm);
                EXPECT_NO_THROW(g.validate("scene"));
            }
}

// ---- continuity: poles and the azimuth seam -------------------------------------------------

double frameDistance(const fm::SceneFrame& a, const fm::SceneFrame& b) {
    return std::max({glm::length(a.sourceDirection - b.sourceDirection),
                     glm::length(a.filmU - b.filmU), glm::length(a.filmV - b.filmV)});
}

TEST(Scene, PolesAreFiniteOrthonormalAndContinuous) {
    for (double el : {90.0, -90.0})
        for (double az : {-180.0, -120.0, 0.0, 37.0, 180.0})
            for (double rot : {-90.0, 0.0, 45.0}) {
                SCOPED_TRACE("el " + std::to_string(el) + " az " + std::to_string(az));
                const fm::SceneFrame f = fm::sceneFrame(az, el, rot);
                for (const glm::dvec3& w : {f.sourceDirection, f.filmU, f.filmV})
                    for (int i = 0; i < 3; ++i) EXPECT_TRUE(std::isfinite(w[i]));
                EXPECT_NEAR(glm::length(f.filmU), 1.0, kUnitTol);
                EXPECT_NEAR(glm::length(f.filmV), 1.0, kUnitTol);
                EXPECT_NEAR(glm::dot(f.filmU, f.filmV), 0.0, kUnitTol);
                EXPECT_NEAR(glm::dot(f.filmU, f.sourceDirection), 0.0, kUnitTol);
                EXPECT_NEAR(glm::dot(f.filmV, f.sourceDirection), 0.0, kUnitTol);
                expectNear(f.sourceDirection, {0, 0, el > 0 ? 1.0 : -1.0}, kUnitTol, "pole");
                // Approaching the pole gives the frame at the pole.
                const double inside = el > 0 ? el - kAngleStepDeg : el + kAngleStepDeg;
                EXPECT_LT(frameDistance(fm::sceneFrame(az, inside, rot), f), kContinuityTol);
            }
    // Approaching the pole along a diagonal (azimuth and elevation both changing): no flip.
    const fm::SceneFrame top = fm::sceneFrame(10.0, 90.0, 0.0);
    EXPECT_LT(frameDistance(fm::sceneFrame(10.0 + kAngleStepDeg, 90.0 - kAngleStepDeg, 0.0), top),
              kContinuityTol);
}

TEST(Scene, AzimuthSeamIsContinuous) {
    for (double el : {-60.0, 0.0, 45.0, 89.0})
        for (double rot : {-80.0, 0.0, 30.0}) {
            SCOPED_TRACE("el " + std::to_string(el) + " rot " + std::to_string(rot));
            const fm::SceneFrame plus = fm::sceneFrame(180.0, el, rot);
            const fm::SceneFrame minus = fm::sceneFrame(-180.0, el, rot);
            EXPECT_LT(frameDistance(plus, minus), kUnitTol);
            EXPECT_LT(frameDistance(fm::sceneFrame(180.0 - kAngleStepDeg, el, rot),
                                    fm::sceneFrame(-180.0 + kAngleStepDeg, el, rot)),
                      kContinuityTol);
        }
}

TEST(Scene, SmallAngleStepsGiveSmallGeometryChanges) {
    const fm::SceneSetup s = fm::defaultSceneSetup();
    // A step of 1e-6 deg moves points 1e3 mm away by ~2e-5 mm at most: the geometry (not just
    // the unit frame) is continuous.
    const double kMoveTolMm = 1e-4;
    for (double az : {-179.0, -45.0, 0.0, 123.0})
        for (double el : {-89.9, -10.0, 0.0, 70.0})
            for (double rot : {-89.0, 0.0, 89.0})
                for (int parameter = 0; parameter < 3; ++parameter) {
                    fm::Pose a = pose(0, 0, 0, az, el, rot), b = a;
                    (parameter == 0   ? b.azimuthDeg
                     : parameter == 1 ? b.elevationDeg
                                      : b.rotationDeg) += kAngleStepDeg;
                    const auto ga = fm::sceneGeometry(a, s, kCenter);
                    const auto gb = fm::sceneGeometry(b, s, kCenter);
                    EXPECT_LT(glm::length(ga.source - gb.source), kMoveTolMm);
                    EXPECT_LT(glm::length(ga.detector.origin - gb.detector.origin), kMoveTolMm);
                }
}

// ---- rotation and offset --------------------------------------------------------------------

TEST(Scene, RotationTurnsTheFilmInItsPlane) {
    const fm::SceneSetup s = fm::defaultSceneSetup();
    for (double az : {0.0, 70.0, -150.0})
        for (double el : {0.0, -40.0, 90.0})
            for (double rot : {-90.0, -30.0, 25.0, 90.0}) {
                const auto g0 = fm::sceneGeometry(pose(0, 0, 0, az, el, 0), s, kCenter);
                const auto g = fm::sceneGeometry(pose(0, 0, 0, az, el, rot), s, kCenter);
                // Same source and film centre; axes turned by exactly `rot`, towards the rows.
                expectNear(g.source, g0.source, kPositionTolMm, "source");
                expectNear(g.detector.center(), g0.detector.center(), kPositionTolMm, "centre");
                const double turned = std::atan2(glm::dot(g.detector.u, g0.detector.v),
                                                 glm::dot(g.detector.u, g0.detector.u));
                EXPECT_NEAR(turned, glm::radians(rot), kUnitTol);
                expectNear(g.detector.normal(), g0.detector.normal(), kUnitTol, "normal");
            }
    // What it does to the picture (AP view, 30 deg): a point right of the centre on the
    // unrotated image moves up-right, i.e. the anatomy turns counterclockwise as displayed.
    const auto g0 = fm::sceneGeometry(fm::Pose{}, s, kCenter);
    const auto g30 = fm::sceneGeometry(pose(0, 0, 0, 0, 0, 30), s, kCenter);
    const glm::dvec3 point = kCenter + glm::dvec3(40.0, 0.0, 0.0);  // 40 mm to patient left
    const auto p0 = g0.projectToPixel(point), p30 = g30.projectToPixel(point);
    ASSERT_TRUE(p0 && p30);
    const double centre = 127.5, r = glm::radians(30.0);
    const double dc = p0->x - centre, dr = p0->y - centre;
    EXPECT_NEAR(dr, 0.0, kPixelTol);
    EXPECT_NEAR(p30->x - centre, dc * std::cos(r) + dr * std::sin(r), kPixelTol);
    EXPECT_NEAR(p30->y - centre, -dc * std::sin(r) + dr * std::cos(r), kPixelTol);
    EXPECT_LT(p30->y, centre);  // moved up on the screen
}

TEST(Scene, OffsetMovesTheCtRelativeToTheBeam) {
    const fm::SceneSetup s = fm::defaultSceneSetup();
    const double sad = s.sourceToIsocenterMm, sid = s.isocenterToFilmMm;
    const double du = s.filmSizeMm.x / 256.0, dv = s.filmSizeMm.y / 256.0;
    const double centre = 127.5;

    // No offset: the volume centre is the isocenter and lands on the middle of the film.
    const auto g0 = fm::sceneGeometry(fm::Pose{}, s, kCenter);
    const auto c0 = g0.projectToPixel(kCenter);
    ASSERT_TRUE(c0);
    EXPECT_NEAR(c0->x, centre, kPixelTol);
    EXPECT_NEAR(c0->y, centre, kPixelTol);

    // AP view with an offset: by hand, a world point p sits at q = p - isocenter with
    // isocenter = centre - offset; the source is at depth 0, the isocenter at depth sad, the
    // film at sad + sid along +y. Magnification (sad + sid) / (sad + q.y); columns along +x,
    // rows along -z.
    const glm::dvec3 offset{14.0, -25.0, -9.0};
    const auto g = fm::sceneGeometry(pose(offset.x, offset.y, offset.z, 0, 0, 0), s, kCenter);
    for (const glm::dvec3& rel :
         {glm::dvec3(0, 0, 0), glm::dvec3(30, 40, -50), glm::dvec3(-60, -80, 100)}) {
        const glm::dvec3 p = kCenter + rel;
        const glm::dvec3 q = p - (kCenter - offset);
        const double m = (sad + sid) / (sad + q.y);
        const auto pixel = g.projectToPixel(p);
        ASSERT_TRUE(pixel);
        EXPECT_NEAR(pixel->x, centre + m * q.x / du, kPixelTol);
        EXPECT_NEAR(pixel->y, centre - m * q.z / dv, kPixelTol);
    }
    // The whole geometry moved by -offset relative to the volume.
    expectNear(g.source, g0.source - offset, kPositionTolMm, "source");
    expectNear(g.detector.origin, g0.detector.origin - offset, kPositionTolMm, "origin");
}

TEST(Scene, RejectsNonFinitePosesAndBadSetups) {
    const fm::SceneSetup good = fm::defaultSceneSetup();
    EXPECT_THROW(fm::sceneGeometry(pose(NAN, 0, 0, 0, 0, 0), good, kCenter), fm::Error);
    EXPECT_THROW(fm::sceneGeometry(pose(0, 0, 0, 0, INFINITY, 0), good, kCenter), fm::Error);
    EXPECT_THROW(fm::sceneGeometry(fm::Pose{}, good, glm::dvec3(NAN)), fm::Error);
    auto broken = [&](auto change) {
        fm::SceneSetup s = good;
        change(s);
        return s;
    };
    const fm::SceneSetup bad[] = {
        broken([](fm::SceneSetup& s) { s.sourceToIsocenterMm = 0; }),
        broken([](fm::SceneSetup& s) { s.isocenterToFilmMm = -1; }),
        broken([](fm::SceneSetup& s) { s.filmPixels.x = 0; }),
        broken([](fm::SceneSetup& s) { s.filmPixels.y = 20000; }),
        broken([](fm::SceneSetup& s) { s.filmSizeMm.y = NAN; }),
        broken([](fm::SceneSetup& s) { s.filmSizeMm.x = 0; }),
    };
    for (const auto& s : bad) EXPECT_THROW(fm::sceneGeometry(fm::Pose{}, s, kCenter), fm::Error);
}

TEST(Scene, BothModesMeetInOneGeometry) {
    // The JSON written for a pose reads back to the same geometry the pose gives directly.
    const auto g =
        fm::sceneGeometry(fm::parsePose("5,-3,12,-135,62,-17"), fm::defaultSceneSetup(), kCenter);
    const auto back = fm::geometryFromJson(fm::geometryToJson(g));
    EXPECT_EQ(back.source, g.source);
    EXPECT_EQ(back.detector.origin, g.detector.origin);
    EXPECT_EQ(back.detector.u, g.detector.u);
    EXPECT_EQ(back.detector.v, g.detector.v);
    EXPECT_EQ(back.detector.spacing, g.detector.spacing);
}

}  // namespace

// poseOfSceneCamera inverts sceneGeometry: every pose of the 2011 ranges (poles aside, where
// azimuth means nothing) comes back from its camera, also a camera with another set-up and
// volume centre; at a pole the camera comes back even though the azimuth does not.
TEST(Pose, SceneCameraGivesItsPoseBack) {
    fm::SceneSetup setup = fm::defaultSceneSetup();
    setup.sourceToIsocenterMm = 620.0;
    setup.isocenterToFilmMm = 410.0;
    const glm::dvec3 centre{12.0, -30.0, 140.0};
    const fm::Pose poses[] = {fm::Pose{}, fm::parsePose("33,31.5,-14,33.1,-22.1,-20.4"),
                              fm::parsePose("-40,12,7,-179.5,60,89"), fm::parsePose("5,-3,4,180,-89,-90"),
                              fm::parsePose("0,0,0,-90,0,45")};
    for (const fm::Pose& p : poses) {
        const fm::Pose back = fm::poseOfSceneCamera(fm::sceneGeometry(p, setup, centre), setup, centre);
        const std::string what = fm::formatPose(p);
        for (int i = 0; i < 3; ++i) EXPECT_NEAR(back.offset[i], p.offset[i], kPositionTolMm) << what;
        EXPECT_NEAR(std::remainder(back.azimuthDeg - p.azimuthDeg, 360.0), 0.0, 1e-9) << what;
        EXPECT_NEAR(back.elevationDeg, p.elevationDeg, 1e-9) << what;
        EXPECT_NEAR(back.rotationDeg, p.rotationDeg, 1e-9) << what;
    }
    const fm::Pose pole = fm::parsePose("3,4,5,70,90,10");
    const fm::ProjectionGeometry g = fm::sceneGeometry(pole, setup, centre);
    const fm::ProjectionGeometry back = fm::sceneGeometry(fm::poseOfSceneCamera(g, setup, centre), setup, centre);
    EXPECT_LT(glm::length(back.source - g.source), kPositionTolMm);
    EXPECT_LT(glm::length(back.detector.u - g.detector.u), kUnitTol * 10);
    EXPECT_LT(glm::length(back.detector.origin - g.detector.origin), kPositionTolMm);
}
