// Orientation letters: axis directions by hand, and the edges of the 2011 scene's AP and
// lateral views of the knee.
#include <gtest/gtest.h>

#include "geometry/PatientDirection.h"
#include "geometry/Pose.h"

namespace {

TEST(PatientDirection, LettersOfAxesAndObliques) {
    EXPECT_EQ(fm::patientDirectionLetters({1, 0, 0}), "L");
    EXPECT_EQ(fm::patientDirectionLetters({-1, 0, 0}), "R");
    EXPECT_EQ(fm::patientDirectionLetters({0, 1, 0}), "P");
    EXPECT_EQ(fm::patientDirectionLetters({0, -1, 0}), "A");
    EXPECT_EQ(fm::patientDirectionLetters({0, 0, 2}), "S");
    EXPECT_EQ(fm::patientDirectionLetters({0, 0, -1}), "I");
    EXPECT_EQ(fm::patientDirectionLetters({-0.8, -0.6, 0.1}), "RA") << "45-ish deg oblique";
    EXPECT_EQ(fm::patientDirectionLetters({0.9, 0.2, 0}), "L") << "a small part is left out";
    EXPECT_EQ(fm::patientDirectionLetters({0, 0, 0}), "");
}

TEST(PatientDirection, EdgesOfTheSceneViews) {
    const fm::SceneSetup setup = fm::defaultSceneSetup();
    // AP (source anterior): superior at the top, the patient's left and right at the sides.
    const auto ap = fm::imageEdgeLetters(fm::sceneGeometry(fm::Pose{}, setup, {0, 0, 0}));
    EXPECT_EQ(ap.top, "S");
    EXPECT_EQ(ap.bottom, "I");
    EXPECT_TRUE((ap.left == "R" && ap.right == "L") || (ap.left == "L" && ap.right == "R"));
    // Lateral (source at the patient's left): anterior and posterior at the sides.
    const auto lat = fm::imageEdgeLetters(
        fm::sceneGeometry(fm::Pose::fromArray({0, 0, 0, 90, 0, 0}), setup, {0, 0, 0}));
    EXPECT_EQ(lat.top, "S");
    EXPECT_TRUE((lat.left == "A" && lat.right == "P") || (lat.left == "P" && lat.right == "A"));
    // Seen from the front (AP) and from behind (PA) the sides swap.
    const auto pa = fm::imageEdgeLetters(
        fm::sceneGeometry(fm::Pose::fromArray({0, 0, 0, 180, 0, 0}), setup, {0, 0, 0}));
    EXPECT_EQ(pa.left, ap.right);
    EXPECT_EQ(pa.right, ap.left);
}

TEST(PatientDirection, EdgesOfAnImageFromItsAxes) {
    // Columns towards the patient's left, rows towards the feet: a coronal image from the front.
    const auto e = fm::imageEdgeLetters(glm::dvec3{1, 0, 0}, glm::dvec3{0, 0, -1});
    EXPECT_EQ(e.left, "R");
    EXPECT_EQ(e.right, "L");
    EXPECT_EQ(e.top, "S");
    EXPECT_EQ(e.bottom, "I");
    // An axial image with rows running posterior: anterior at the top.
    const auto a = fm::imageEdgeLetters(glm::dvec3{-1, 0, 0}, glm::dvec3{0, 1, 0});
    EXPECT_EQ(a.top, "A");
    EXPECT_EQ(a.bottom, "P");
    EXPECT_EQ(a.left, "L");
}

}  // namespace
