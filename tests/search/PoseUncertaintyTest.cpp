// search/PoseUncertainty against arithmetic: on a quadratic cost the finite differences are
// exact, so the Hessian is the one the test builds and each spread is sqrt(2 k (H^-1)_ii),
// with H^-1 computed here by Gauss-Jordan elimination; a flat direction leaves exactly the
// coordinates it moves unfixed.
#include <cmath>

#include <gtest/gtest.h>

#include "core/Error.h"
#include "search/PoseUncertainty.h"

namespace fm {
namespace {

using Matrix = std::array<std::array<double, 6>, 6>;

double quadratic(const Matrix& h, const SearchPoint& x) {
    double c = 0.0;
    for (int i = 0; i < 6; ++i)
        for (int j = 0; j < 6; ++j) c += 0.5 * x[i] * h[i][j] * x[j];
    return -0.9 + c;  // the optimum's cost does not matter
}

Matrix inverse(Matrix a) {
    Matrix inv{};
    for (int i = 0; i < 6; ++i) inv[i][i] = 1.0;
    for (int c = 0; c < 6; ++c) {
        int pivot = c;
        for (int r = c + 1; r < 6; ++r)
            if (std::abs(a[r][c]) > std::abs(a[pivot][c])) pivot = r;
        std::swap(a[c], a[pivot]);
        std::swap(inv[c], inv[pivot]);
        const double d = a[c][c];
        for (int k = 0; k < 6; ++k) a[c][k] /= d, inv[c][k] /= d;
        for (int r = 0; r < 6; ++r) {
            if (r == c) continue;
            const double f = a[r][c];
            for (int k = 0; k < 6; ++k) a[r][k] -= f * a[c][k], inv[r][k] -= f * inv[c][k];
        }
    }
    return inv;
}

// A single-view-like cost: in-plane stiff, depth soft and coupled with the tilt about u.
Matrix singleViewHessian() {
    Matrix h{};
    const double diag[6] = {4.0, 5.0, 0.002, 0.03, 0.04, 2.0};
    for (int i = 0; i < 6; ++i) h[i][i] = diag[i];
    h[2][3] = h[3][2] = 0.006;  // depth and the tilt about u trade against each other
    h[0][5] = h[5][0] = 0.5;
    return h;
}

TEST(PoseUncertainty, QuadraticCostGivesTheMarginalSpreads) {
    const Matrix h = singleViewHessian();
    const SearchPoint step{0.3, 0.3, 2.0, 0.5, 0.5, 0.5};
    const double k = 2e-3;
    const PoseUncertainty u = poseUncertainty([&](const SearchPoint& x) { return quadratic(h, x); }, step, k);
    EXPECT_EQ(u.evaluations, 73);
    EXPECT_TRUE(u.bounded);
    const Matrix inv = inverse(h);
    for (int i = 0; i < 6; ++i) {
        for (int j = 0; j < 6; ++j) EXPECT_NEAR(u.hessian[i][j], h[i][j], 1e-9 * (1.0 + std::abs(h[i][j])));
        EXPECT_NEAR(u.sd[i], std::sqrt(2.0 * k * inv[i][i]), 1e-9) << searchCoordinateName(i);
    }
    // The coupling widens depth beyond what its own curvature says (sqrt(2k/H_22) = 1.41 mm).
    EXPECT_GT(u.sd[2], 1.05 * std::sqrt(2.0 * k / h[2][2]));
    // Depth (sd ~1.6 mm) is within the single-view bound; the tilts (~0.3 deg) too; nothing weak.
    EXPECT_TRUE(u.weak().empty()) << describeUncertainty(u);
}

TEST(PoseUncertainty, SpreadAlongOtherAxesRotatesTheCovariance) {
    const Matrix h = singleViewHessian();
    const double k = 2e-3;
    const PoseUncertainty u = poseUncertainty([&](const SearchPoint& x) { return quadratic(h, x); }, kUncertaintySteps, k);
    const Matrix c = inverse(h);  // the covariance is 2k H^-1
    for (int i = 0; i < 6; ++i)
        for (int j = 0; j < 6; ++j) EXPECT_NEAR(u.covariance[i][j], 2.0 * k * c[i][j], 1e-9) << i << j;
    // The camera's own axes give the marginal spreads back.
    const SearchPoint same = spreadAlong(u, glm::dmat3(1.0));
    for (int i = 0; i < 6; ++i) EXPECT_NEAR(same[i], u.sd[i], 1e-12);
    // Axes turned 90 deg about the view: u and v swap, view stays; a diagonal axis mixes u and v
    // with their covariance: d' C d by hand.
    const glm::dmat3 turned(glm::dvec3(0, 1, 0), glm::dvec3(-1, 0, 0), glm::dvec3(0, 0, 1));
    const SearchPoint swapped = spreadAlong(u, turned);
    EXPECT_NEAR(swapped[0], u.sd[1], 1e-12);
    EXPECT_NEAR(swapped[1], u.sd[0], 1e-12);
    EXPECT_NEAR(swapped[5], u.sd[5], 1e-12);
    const double r = std::sqrt(0.5);
    const glm::dmat3 diagonal(glm::dvec3(r, r, 0), glm::dvec3(-r, r, 0), glm::dvec3(0, 0, 1));
    const SearchPoint mixed = spreadAlong(u, diagonal);
    const double byHand = 0.5 * 2.0 * k * (c[3][3] + 2.0 * c[3][4] + c[4][4]);
    EXPECT_NEAR(mixed[3], std::sqrt(byHand), 1e-12);
}

TEST(PoseUncertainty, FlatDirectionLeavesTheCoordinatesItMovesUnfixed) {
    Matrix h = singleViewHessian();
    h[2][2] = 0.0;  // depth free and uncoupled
    h[2][3] = h[3][2] = 0.0;
    const PoseUncertainty u =
        poseUncertainty([&](const SearchPoint& x) { return quadratic(h, x); }, kUncertaintySteps);
    EXPECT_FALSE(u.bounded);
    EXPECT_TRUE(std::isinf(u.sd[2]));
    for (int i : {0, 1, 3, 4, 5}) EXPECT_TRUE(std::isfinite(u.sd[i])) << searchCoordinateName(i);
    ASSERT_EQ(u.weak(), std::vector<int>{2});
    // Along other axes: unfixed wherever depth enters, fixed where it does not.
    const double r = std::sqrt(0.5);
    const SearchPoint along = spreadAlong(u, glm::dmat3(glm::dvec3(r, 0, r), glm::dvec3(0, 1, 0), glm::dvec3(-r, 0, r)));
    EXPECT_TRUE(std::isinf(along[0]));
    EXPECT_TRUE(std::isfinite(along[1]));
    EXPECT_TRUE(std::isinf(along[2]));
    EXPECT_NE(describeUncertainty(u).find("depth not fixed"), std::string::npos) << describeUncertainty(u);
    EXPECT_NE(describeUncertainty(u).find("weakly fixed: depth"), std::string::npos);
}

TEST(PoseUncertainty, SpreadScalesWithTheSquareRootOfTheCostResolution) {
    const Matrix h = singleViewHessian();
    const auto cost = [&](const SearchPoint& x) { return quadratic(h, x); };
    const PoseUncertainty a = poseUncertainty(cost, kUncertaintySteps, 1e-3);
    const PoseUncertainty b = poseUncertainty(cost, kUncertaintySteps, 4e-3);
    for (int i = 0; i < 6; ++i) EXPECT_NEAR(b.sd[i], 2.0 * a.sd[i], 1e-12);
}

TEST(PoseUncertainty, RefusesBadSteps) {
    const auto cost = [](const SearchPoint&) { return 0.0; };
    EXPECT_THROW(poseUncertainty(cost, {0.3, 0.3, 0.0, 0.5, 0.5, 0.5}), Error);
    EXPECT_THROW(poseUncertainty(cost, {0.3, NAN, 1.0, 0.5, 0.5, 0.5}), Error);
}

}  // namespace
}  // namespace fm
