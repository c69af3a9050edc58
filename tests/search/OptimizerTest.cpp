// Optimizers on analytic functions with known minima, budgets, stop flags and determinism.
#include <atomic>
#include <cmath>
#include <numeric>

#include <gtest/gtest.h>

#include "core/Error.h"
#include "search/CmaEs.h"
#include "search/Optimizer.h"
#include "core/Random.h"

namespace fm {
namespace {

const Point kOptimum{1.0, -2.0, 0.5, 3.0, -1.0, 2.0};

double sphere(const Point& x) {
    double s = 0.0;
    for (std::size_t i = 0; i < x.size(); ++i) s += (x[i] - kOptimum[i]) * (x[i] - kOptimum[i]);
    return s;
}

// Ill-conditioned (weights 1..100, condition number 100) and shifted: like the pose cost, where
// depth is far weaker than in-plane translation.
double weightedQuadratic(const Point& x) {
    double s = 0.0;
    for (std::size_t i = 0; i < x.size(); ++i) {
        const double w = std::pow(100.0, double(i) / double(x.size() - 1));
        s += w * (x[i] - kOptimum[i]) * (x[i] - kOptimum[i]);
    }
    return s;
}

double rosenbrock(const Point& x) {
    return 100.0 * std::pow(x[1] - x[0] * x[0], 2) + std::pow(1.0 - x[0], 2);
}

double distance(const Point& a, const Point& b) {
    double s = 0.0;
    for (std::size_t i = 0; i < a.size(); ++i) s += (a[i] - b[i]) * (a[i] - b[i]);
    return std::sqrt(s);
}

OptimizerResult run(SearchMethod method, double (*f)(const Point&), int dim, int budget,
                    std::uint64_t seed = 1, double radius = 5.0) {
    OptimizerOptions options;
    options.maxEvaluations = budget;
    options.seed = seed;
    options.tolerance = 1e-6;
    return minimize(method, sequentialCost(f), Point(dim, 0.0), Point(dim, radius),
                    {Point(dim, -10.0), Point(dim, 10.0)}, options);
}

// Distance to the optimum each method must reach on the 6-D problems (start 5.9 units away,
// search radius 5): local and covariance methods converge to solver precision; the sampling
// methods (Monte Carlo, Bees) refine only by shrinking their sampling boxes, so they are held to
// 1% of the radius. Budgets are those of one registration stage (a few thousand evaluations).
double sixDimensionalTolerance(SearchMethod m) {
    switch (m) {
        case SearchMethod::CmaEs:
        case SearchMethod::NelderMead:
            return 1e-3;
        case SearchMethod::ParticleSwarm:
            return 1e-2;
        default:
            return 5e-2;
    }
}

const SearchMethod kAllMethods[] = {SearchMethod::MonteCarlo, SearchMethod::ParticleSwarm,
                                    SearchMethod::Bees, SearchMethod::CmaEs,
                                    SearchMethod::NelderMead};

TEST(Optimizers, ReachTheSphereMinimumIn6D) {
    for (SearchMethod m : kAllMethods) {
        const OptimizerResult r = run(m, sphere, 6, 4000);
        EXPECT_LT(distance(r.best, kOptimum), sixDimensionalTolerance(m)) << toString(m);
        EXPECT_LE(r.evaluations, 4000) << toString(m);
    }
}

TEST(Optimizers, ReachTheShiftedIllConditionedQuadraticMinimumIn6D) {
    for (SearchMethod m : kAllMethods) {
        const OptimizerResult r = run(m, weightedQuadratic, 6, 6000);
        EXPECT_LT(distance(r.best, kOptimum), sixDimensionalTolerance(m) * 2.0) << toString(m);
    }
}

TEST(Optimizers, ReachTheRosenbrockMinimumIn2D) {
    // The banana valley: the minimum (1, 1) lies at the end of a curved flat valley.
    // Sampling methods get within 0.1 of it (the valley floor rises by only ~1e-2 there).
    for (SearchMethod m : kAllMethods) {
        const OptimizerResult r = run(m, rosenbrock, 2, 4000, 3, 2.0);
        const double tol = (m == SearchMethod::CmaEs || m == SearchMethod::NelderMead) ? 1e-3 : 0.1;
        EXPECT_LT(distance(r.best, {1.0, 1.0}), tol) << toString(m);
    }
}

TEST(Optimizers, SameSeedSameRunOtherSeedOtherRun) {
    for (SearchMethod m : globalSearchMethods()) {
        const OptimizerResult a = run(m, sphere, 6, 300, 11);
        const OptimizerResult b = run(m, sphere, 6, 300, 11);
        const OptimizerResult c = run(m, sphere, 6, 300, 12);
        EXPECT_EQ(a.best, b.best) << toString(m);
        EXPECT_EQ(a.bestCostHistory, b.bestCostHistory) << toString(m);
        EXPECT_NE(a.best, c.best) << toString(m);
    }
}

TEST(Optimizers, NeverExceedTheBudgetAndNeverGetWorseThanTheStart) {
    for (SearchMethod m : kAllMethods)
        for (int budget : {1, 7, 50}) {
            const OptimizerResult r = run(m, sphere, 6, budget);
            EXPECT_LE(r.evaluations, budget) << toString(m);
            EXPECT_GE(r.evaluations, 1) << toString(m);
            EXPECT_LE(r.bestCost, sphere(Point(6, 0.0))) << toString(m);
            // The history is monotone non-increasing.
            for (std::size_t i = 1; i < r.bestCostHistory.size(); ++i)
                EXPECT_LE(r.bestCostHistory[i], r.bestCostHistory[i - 1]);
        }
}

TEST(Optimizers, StopFlagEndsTheRunAfterTheCurrentBatch) {
    for (SearchMethod m : kAllMethods) {
        std::atomic<bool> stop{false};
        OptimizerOptions options;
        options.maxEvaluations = 100000;
        options.stop = &stop;
        int batches = 0;
        options.progress = [&](const OptimizerProgress& p) {
            EXPECT_EQ(p.best.size(), 6u);
            if (++batches == 3) stop = true;
        };
        const OptimizerResult r = minimize(m, sequentialCost(sphere), Point(6, 0.0), Point(6, 5.0),
                                           {Point(6, -10.0), Point(6, 10.0)}, options);
        EXPECT_TRUE(r.stopped) << toString(m);
        EXPECT_EQ(batches, 3) << toString(m);
        EXPECT_LT(r.evaluations, 200) << toString(m);
    }
}

TEST(Optimizers, RespectBounds) {
    // Optimum outside the box: the best point must be on the box wall, never beyond it.
    for (SearchMethod m : kAllMethods) {
        OptimizerOptions options;
        options.maxEvaluations = 2000;
        const OptimizerResult r =
            minimize(m, sequentialCost([](const Point& x) {
                         return (x[0] - 5.0) * (x[0] - 5.0) + x[1] * x[1];
                     }),
                     {0.0, 0.5}, {1.0, 1.0}, {{-2.0, -2.0}, {2.0, 2.0}}, options);
        EXPECT_LE(r.best[0], 2.0) << toString(m);
        EXPECT_NEAR(r.best[0], 2.0, 0.05) << toString(m);
    }
}

TEST(Optimizers, BadProblemsThrow) {
    OptimizerOptions options;
    auto f = sequentialCost(sphere);
    EXPECT_THROW(minimize(SearchMethod::CmaEs, f, {0.0}, {0.0}, {{-1.0}, {1.0}}, options), Error);
    EXPECT_THROW(minimize(SearchMethod::CmaEs, f, {3.0}, {1.0}, {{-1.0}, {1.0}}, options), Error);
    EXPECT_THROW(minimize(SearchMethod::CmaEs, f, {0.0, 0.0}, {1.0}, {{-1.0}, {1.0}}, options),
                 Error);
    options.maxEvaluations = 0;
    EXPECT_THROW(minimize(SearchMethod::CmaEs, f, {0.0}, {1.0}, {{-1.0}, {1.0}}, options), Error);
    EXPECT_THROW(parseSearchMethod("ga"), Error);
    for (SearchMethod m : kAllMethods) EXPECT_EQ(parseSearchMethod(toString(m)), m);
}

TEST(Random, UniformAndNormalHaveTheRightMoments) {
    // n = 200000 draws: the sample mean has standard deviation sigma/sqrt(n) (uniform: 0.289,
    // normal: 1), the sample variance about sigma^2*sqrt(2/n) (normal); 5 standard deviations.
    constexpr int n = 200000;
    Rng rng(42);
    double su = 0.0, suu = 0.0, sn = 0.0, snn = 0.0;
    for (int i = 0; i < n; ++i) {
        const double u = rng.uniform();
        ASSERT_GE(u, 0.0);
        ASSERT_LT(u, 1.0);
        su += u, suu += u * u;
        const double z = rng.normal();
        sn += z, snn += z * z;
    }
    EXPECT_NEAR(su / n, 0.5, 5 * 0.2887 / std::sqrt(double(n)));
    EXPECT_NEAR(suu / n - (su / n) * (su / n), 1.0 / 12.0, 5 * 0.0745 / std::sqrt(double(n)));
    EXPECT_NEAR(sn / n, 0.0, 5.0 / std::sqrt(double(n)));
    EXPECT_NEAR(snn / n, 1.0, 5.0 * std::sqrt(2.0 / n));
    Rng a(9), b(9);
    for (int i = 0; i < 100; ++i) EXPECT_EQ(a.normal(), b.normal());
    for (int i = 0; i < 1000; ++i) EXPECT_LT(a.below(7), 7u);
}

TEST(SymmetricEigen, RecoversAKnownDecomposition) {
    // [[2,1,0],[1,2,0],[0,0,5]] has eigenvalues 1, 3, 5 (exact).
    const std::vector<double> m{2, 1, 0, 1, 2, 0, 0, 0, 5};
    std::vector<double> values, vectors;
    symmetricEigen(3, m, values, vectors);
    std::vector<double> sorted = values;
    std::sort(sorted.begin(), sorted.end());
    EXPECT_NEAR(sorted[0], 1.0, 1e-12);
    EXPECT_NEAR(sorted[1], 3.0, 1e-12);
    EXPECT_NEAR(sorted[2], 5.0, 1e-12);
    // M v = lambda v for every column.
    for (int k = 0; k < 3; ++k)
        for (int i = 0; i < 3; ++i) {
            double mv = 0.0;
            for (int j = 0; j < 3; ++j) mv += m[i * 3 + j] * vectors[j * 3 + k];
            EXPECT_NEAR(mv, values[k] * vectors[i * 3 + k], 1e-12);
        }
}

}  // namespace
}  // namespace fm
