#include "search/NelderMead.h"

#include <algorithm>
#include <cmath>
#include <numeric>

#include "core/Error.h"

namespace fm {

namespace {

// One Nelder-Mead run from `start`; returns when converged or the problem is done.
void simplexRun(SearchProblem& problem, const Point& start, double step) {
    const int n = problem.dimension();
    const Point& radius = problem.radius();
    const double alpha = 1.0, beta = 1.0 + 2.0 / n, gamma = 0.75 - 0.5 / n, delta = 1.0 - 1.0 / n;
    std::vector<Point> simplex(n + 1, start);
    for (int i = 0; i < n; ++i) {
        simplex[i + 1][i] += step * radius[i];
        // Step inwards if the outward vertex would sit on the bound (degenerate simplex).
        if (simplex[i + 1][i] > problem.box().upper[i])
            simplex[i + 1][i] = start[i] - step * radius[i];
        simplex[i + 1] = problem.clamp(simplex[i + 1]);
    }
    std::vector<double> f = problem.evaluate(simplex);
    auto eval = [&](const Point& p) -> std::pair<Point, double> {
        Point q = problem.clamp(p);
        const double c = problem.evaluate(q);
        return {q, c};
    };
    std::vector<int> order(n + 1);
    while (!problem.done()) {
        std::iota(order.begin(), order.end(), 0);
        std::stable_sort(order.begin(), order.end(), [&](int a, int b) { return f[a] < f[b]; });
        const int best = order[0], worst = order[n], second = order[n - 1];
        // Converged when every vertex lies within tolerance*radius of the best one.
        double size = 0.0;
        for (int k = 0; k <= n; ++k)
            for (int d = 0; d < n; ++d)
                size = std::max(size, std::abs(simplex[k][d] - simplex[best][d]) / radius[d]);
        if (size < problem.tolerance()) return;
        Point centroid(n, 0.0);
        for (int k = 0; k <= n; ++k)
            if (k != worst)
                for (int d = 0; d < n; ++d) centroid[d] += simplex[k][d] / n;
        auto along = [&](double t) {
            Point p(n);
            for (int d = 0; d < n; ++d) p[d] = centroid[d] + t * (centroid[d] - simplex[worst][d]);
            return p;
        };
        auto [xr, fr] = eval(along(alpha));
        if (fr < f[best]) {
            auto [xe, fe] = eval(along(alpha * beta));
            if (fe < fr) {
                simplex[worst] = xe, f[worst] = fe;
            } else {
                simplex[worst] = xr, f[worst] = fr;
            }
            continue;
        }
        if (fr < f[second]) {
            simplex[worst] = xr, f[worst] = fr;
            continue;
        }
        // Contraction: outside if the reflection helped a little, inside otherwise.
        const bool outside = fr < f[worst];
        auto [xc, fc] = eval(along(outside ? alpha * gamma : -gamma));
        if (fc < (outside ? fr : f[worst])) {
            simplex[worst] = xc, f[worst] = fc;
            continue;
        }
        std::vector<Point> shrunk;
        std::vector<int> index;
        for (int k = 0; k <= n; ++k) {
            if (k == best) continue;
            Point p(n);
            for (int d = 0; d < n; ++d)
                p[d] = simplex[best][d] + delta * (simplex[k][d] - simplex[best][d]);
            shrunk.push_back(problem.clamp(p));
            index.push_back(k);
        }
        const std::vector<double> fs = problem.evaluate(shrunk);
        for (std::size_t i = 0; i < index.size(); ++i)
            simplex[index[i]] = shrunk[i], f[index[i]] = fs[i];
    }
}

}  // namespace

void runNelderMead(SearchProblem& problem, const NelderMeadSettings& settings) {
    if (!(settings.initialStep > 0.0) || settings.restarts < 0)
        throw Error("Nelder-Mead: initial step must be positive and restarts >= 0");
    simplexRun(problem, problem.start(), settings.initialStep);
    double step = settings.initialStep;
    for (int r = 0; r < settings.restarts && !problem.done(); ++r) {
        step *= 0.5;
        simplexRun(problem, problem.result().best, step);
    }
}

}  // namespace fm
