#include "search/ParticleSwarm.h"

#include <algorithm>
#include <cmath>

#include "core/Error.h"

namespace fm {

void runParticleSwarm(SearchProblem& problem, const ParticleSwarmSettings& s) {
    if (s.particles < 2) throw Error("particle swarm: needs at least 2 particles");
    const int n = problem.dimension();
    const Point& radius = problem.radius();
    std::vector<Point> x(s.particles), v(s.particles, Point(n, 0.0));
    x[0] = problem.start();
    for (int i = 1; i < s.particles; ++i) x[i] = problem.sampleAround(problem.start(), radius);
    for (int i = 0; i < s.particles; ++i)
        for (int d = 0; d < n; ++d) v[i][d] = radius[d] * (problem.rng().uniform() - 0.5);
    std::vector<double> cost = problem.evaluate(x);
    std::vector<Point> personal = x;
    std::vector<double> personalCost = cost;
    while (!problem.done()) {
        const Point global = problem.result().best;
        // Converged when every particle sits within tolerance*radius of the global best.
        double spread = 0.0;
        for (const Point& p : x)
            for (int d = 0; d < n; ++d)
                spread = std::max(spread, std::abs(p[d] - global[d]) / radius[d]);
        if (spread < problem.tolerance()) break;
        for (int i = 0; i < s.particles; ++i)
            for (int d = 0; d < n; ++d) {
                const double r1 = problem.rng().uniform(), r2 = problem.rng().uniform();
                double vel = s.inertia * v[i][d] + s.cognitive * r1 * (personal[i][d] - x[i][d]) +
                             s.social * r2 * (global[d] - x[i][d]);
                vel = std::clamp(vel, -radius[d], radius[d]);
                v[i][d] = vel;
                x[i][d] += vel;
            }
        for (int i = 0; i < s.particles; ++i) {
            const Point clamped = problem.clamp(x[i]);
            // A particle leaving the box stops at the wall there (absorbing boundary).
            for (int d = 0; d < n; ++d)
                if (clamped[d] != x[i][d]) v[i][d] = 0.0;
            x[i] = clamped;
        }
        cost = problem.evaluate(x);
        for (int i = 0; i < s.particles; ++i)
            if (cost[i] < personalCost[i]) {
                personalCost[i] = cost[i];
                personal[i] = x[i];
            }
    }
}

}  // namespace fm
