// Autoscoper .tra files: the xyzypr Euler order against matrices built here, matrix and xyzypr
// round trips with untracked frames, the layout Autoscoper reads, and refusal of broken rows.
#include <gtest/gtest.h>

#include <cmath>
#include <sstream>

#include "common/TestData.h"
#include "core/Error.h"
#include "RotationMatrices.h"
#include "pose/AutoscoperTra.h"

namespace {

using fm::test::mul;
using fm::test::rot;
using Mat = fm::test::Mat3;

std::string errorOf(const std::string& text, fm::TraForm form = fm::TraForm::Auto) {
    try {
        fm::parseTra(text, "bone.tra", form);
    } catch (const fm::Error& e) {
        return e.what();
    }
    return "";
}

std::string matrixRow(const fm::RigidTransform& t) {
    std::ostringstream s;
    s.precision(17);
    const auto m = t.toRowMajor4x4();
    for (int i = 0; i < 16; ++i) s << (i ? "," : "") << m[i];
    return s.str();
}

TEST(AutoscoperTra, XyzyprIsRzRyRx) {
    const double v[6] = {12.5, -3.0, 250.0, 40.0, -25.0, 70.0};
    const fm::RigidTransform t = fm::transformFromXyzypr(v);
    const Mat expected = mul(mul(rot(2, 40.0), rot(1, -25.0)), rot(0, 70.0));
    for (int r = 0; r < 3; ++r)
        for (int c = 0; c < 3; ++c) EXPECT_NEAR(t.rotation[c][r], expected[r][c], 1e-14);
    EXPECT_EQ(t.translation, glm::dvec3(12.5, -3.0, 250.0));
    double back[6];
    fm::xyzyprFromTransform(t, back);
    for (int i = 0; i < 6; ++i) EXPECT_NEAR(back[i], v[i], 1e-10);
}

TEST(AutoscoperTra, MatrixAndXyzyprRoundTripWithUntrackedFrames) {
    const double a[6] = {1.5, 2.5, -300.25, 10, 20, 30}, b[6] = {-45, 0.001, 12, -170, 80, -5};
    fm::TraFile tra;
    tra.objects = 2;
    tra.frames = {{fm::transformFromXyzypr(a), std::nullopt},
                  {std::nullopt, std::nullopt},
                  {fm::transformFromXyzypr(b), fm::transformFromXyzypr(a)}};
    for (fm::TraForm form : {fm::TraForm::Matrix, fm::TraForm::Xyzypr}) {
        tra.form = form;
        const auto path = fm::test::scratchDir("tra") / "bone.tra";
        fm::writeTra(path, tra);
        const fm::TraFile back = fm::readTra(path, form);
        ASSERT_EQ(back.frames.size(), 3u);
        EXPECT_EQ(back.objects, 2);
        EXPECT_FALSE(back.frames[0][1]);
        EXPECT_FALSE(back.frames[1][0]);
        ASSERT_TRUE(back.frames[2][1]);
        const auto m1 = back.frames[2][1]->toRowMajor4x4(), m0 = tra.frames[2][1]->toRowMajor4x4();
        for (int i = 0; i < 16; ++i) EXPECT_NEAR(m1[i], m0[i], 1e-12);
    }
    // Autoscoper's layout: 16 comma-separated fixed-point numbers per object, NaN when untracked.
    tra.form = fm::TraForm::Matrix;
    std::istringstream in(fm::traText(tra));
    std::string line;
    std::getline(in, line);
    EXPECT_EQ(std::count(line.begin(), line.end(), ','), 31);
    EXPECT_NE(line.find("-300.2500000000000000"), std::string::npos) << line;
    EXPECT_NE(line.find(",0.0000000000000000,0.0000000000000000,0.0000000000000000,1.0000000000000000,NaN"),
              std::string::npos)
        << line;
    std::getline(in, line);
    EXPECT_EQ(line.rfind("NaN,NaN", 0), 0u);
}

TEST(AutoscoperTra, ReadsSpaceSeparatedAndDeducesTheForm) {
    const double v[6] = {1, 2, 3, 4, 5, 6};
    std::string row = matrixRow(fm::transformFromXyzypr(v));
    for (char& c : row)
        if (c == ',') c = ' ';
    const fm::TraFile m = fm::parseTra(row + "\n" + row + "\n\n", "x.tra");
    EXPECT_EQ(m.form, fm::TraForm::Matrix);
    EXPECT_EQ(m.frames.size(), 2u);
    const fm::TraFile x = fm::parseTra("1 2 3 4 5 6\nnan nan nan nan nan nan\n", "x.tra");
    EXPECT_EQ(x.form, fm::TraForm::Xyzypr);
    EXPECT_FALSE(x.frames[1][0]);
    EXPECT_NEAR(x.frames[0][0]->rotation[0][1], fm::transformFromXyzypr(v).rotation[0][1], 1e-15);
}

TEST(AutoscoperTra, BrokenRowsAreRefusedWithFileLineAndField) {
    const std::string id = "1,0,0,5,0,1,0,6,0,0,1,7,0,0,0,1";
    EXPECT_EQ(errorOf(id + "\n"), "");
    const std::string count = errorOf(id + "\n1,0,0\n");
    EXPECT_NE(count.find("bone.tra: line 2"), std::string::npos) << count;
    const std::string word = errorOf(id + "\n1,0,0,5,0,1,0,6,0,x,1,7,0,0,0,1\n");
    EXPECT_NE(word.find("line 2, object 1, value 10"), std::string::npos) << word;
    EXPECT_NE(errorOf("NaN,0,0,5,0,1,0,6,0,0,1,7,0,0,0,1\n").find("NaN"), std::string::npos);
    EXPECT_NE(errorOf("2,0,0,5,0,1,0,6,0,0,1,7,0,0,0,1\n").find("line 1"), std::string::npos);
    // Column order (translation in the last row) is not a rigid row-major matrix.
    EXPECT_NE(errorOf("1,0,0,0,0,1,0,0,0,0,1,0,5,6,7,1\n"), "");
    EXPECT_NE(errorOf("1,2,3,4,5\n").find("not 16"), std::string::npos);
    const std::string row48 = id + "," + id + "," + id;
    const std::string ambiguous = errorOf(row48 + "\n");
    EXPECT_NE(ambiguous.find("3 matrices (16 numbers each) or 8 x, y, z, yaw, pitch, roll rows"),
              std::string::npos) << ambiguous;
    EXPECT_EQ(errorOf(row48 + "\n", fm::TraForm::Matrix), "");
    EXPECT_NE(errorOf("").find("empty"), std::string::npos);
    EXPECT_NE(errorOf(id + "\n\n" + id + "\n").find("line 2"), std::string::npos);
}

// The expected object count (a trial's bones, the models of one --start .tra) decides a line
// that both forms divide, and only then.
TEST(AutoscoperTra, TheExpectedObjectCountDecidesBetweenMatricesAndRows) {
    const std::string id = "1,0,0,5,0,1,0,6,0,0,1,7,0,0,0,1";
    const std::string row48 = id + "," + id + "," + id + "\n";
    const fm::TraFile three = fm::parseTra(row48, "wrist.tra", fm::TraForm::Auto, 3);
    EXPECT_EQ(three.form, fm::TraForm::Matrix);
    ASSERT_EQ(three.objects, 3);
    EXPECT_EQ(three.frames[0][2]->translation, glm::dvec3(5, 6, 7));
    const std::string rows8 = "1,2,3,10,20,30,1,2,3,10,20,30,1,2,3,10,20,30,1,2,3,10,20,30,"
                              "1,2,3,10,20,30,1,2,3,10,20,30,1,2,3,10,20,30,1,2,3,10,20,30\n";
    const fm::TraFile eight = fm::parseTra(rows8, "eight.tra", fm::TraForm::Auto, 8);
    EXPECT_EQ(eight.form, fm::TraForm::Xyzypr);
    EXPECT_EQ(eight.objects, 8);
    // A count that fits neither expectation stays a refusal that says so.
    std::string e;
    try {
        fm::parseTra(row48, "two.tra", fm::TraForm::Auto, 2);
    } catch (const fm::Error& error) {
        e = error.what();
    }
    EXPECT_NE(e.find("neither is the 2 objects expected"), std::string::npos) << e;
    // One object is never ambiguous, whatever is expected.
    EXPECT_EQ(fm::parseTra(id + "\n", "one.tra", fm::TraForm::Auto, 3).objects, 1);
}

}  // namespace
