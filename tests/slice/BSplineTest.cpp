#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "core/Random.h"
#include "slice/BSplinePrefilter.h"
#include "slice/SliceTestUtil.h"

using namespace fm;
using fm::test::analyticVolume;

TEST(BSpline, PrefilteredCoefficientsReproduceTheSamplesByTheCubicKernel) {
    // The cubic B-spline at integer k is (c[k-1] + 4 c[k] + c[k+1]) / 6, mirrored at the ends.
    Rng rng(3);
    for (int n : {2, 3, 5, 17, 64}) {
        std::vector<double> s(n), c(n);
        for (int k = 0; k < n; ++k) c[k] = s[k] = rng.uniform(-10, 10);
        cubicBSplinePrefilterLine(c.data(), n);
        for (int k = 0; k < n; ++k) {
            const double left = c[k == 0 ? 1 : k - 1], right = c[k == n - 1 ? n - 2 : k + 1];
            EXPECT_NEAR((left + 4 * c[k] + right) / 6.0, s[k], 1e-9) << n << " " << k;
        }
    }
}

TEST(BSpline, WeightsSumToOneAndInterpolateAtIntegers) {
    for (double t = 0.0; t < 1.0; t += 0.125) {
        const auto w = cubicBSplineWeights(t);
        EXPECT_NEAR(w[0] + w[1] + w[2] + w[3], 1.0, 1e-15);
        // First moment: the spline of c[k] = k is x itself.
        EXPECT_NEAR(-1 * w[0] + 0 * w[1] + 1 * w[2] + 2 * w[3], t, 1e-15);
    }
    const auto w0 = cubicBSplineWeights(0.0);
    EXPECT_NEAR(w0[0], 1.0 / 6, 1e-15);
    EXPECT_NEAR(w0[1], 4.0 / 6, 1e-15);
}

TEST(BSpline, InterpolatesVoxelsAndReproducesACubicAwayFromTheBoundary) {
    auto f = [](const glm::dvec3& p) {
        return 0.002 * p.x * p.x * p.x - 0.05 * p.y * p.y + 0.3 * p.x * p.z + p.z + 7.0;
    };
    auto volume = analyticVolume({40, 40, 40}, {1, 1, 1}, {-20, -20, -20}, glm::dmat3(1.0), f);
    const std::vector<float> c = cubicBSplineCoefficients(*volume, 2);
    EXPECT_EQ(c, cubicBSplineCoefficients(*volume, 1));  // any thread count, same result
    for (int i : {0, 7, 39})
        EXPECT_NEAR(evaluateCubicBSpline(c, volume->dims, {i, 13, 39 - i}), volume->at(i, 13, 39 - i),
                    2e-4 * (1 + std::abs(volume->at(i, 13, 39 - i))));
    // Off the grid, 14+ voxels from every face (the mirror boundary's effect decays as 0.268^d).
    Rng rng(5);
    for (int n = 0; n < 100; ++n) {
        const glm::dvec3 ijk{rng.uniform(14, 25), rng.uniform(14, 25), rng.uniform(14, 25)};
        const double expected = f(volume->indexToWorld(ijk));
        EXPECT_NEAR(evaluateCubicBSpline(c, volume->dims, ijk), expected,
                    1e-4 * (1 + std::abs(expected)));
    }
}
