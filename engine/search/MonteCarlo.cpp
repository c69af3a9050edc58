#include "search/MonteCarlo.h"

#include "core/Error.h"

namespace fm {

void runMonteCarlo(SearchProblem& problem, const MonteCarloSettings& settings) {
    if (settings.samplesPerRound < 1 || !(settings.shrink > 0.0 && settings.shrink < 1.0))
        throw Error("Monte Carlo: samples per round must be >= 1 and shrink in (0, 1)");
    Point center = problem.start();
    Point half = problem.radius();
    double scale = 1.0;
    // Round 0 includes the start itself, so the result is never worse than the start.
    std::vector<Point> batch{center};
    while (!problem.done() && scale > problem.tolerance()) {
        while (static_cast<int>(batch.size()) < settings.samplesPerRound)
            batch.push_back(problem.sampleAround(center, half));
        const double before = problem.result().bestCost;
        problem.evaluate(batch);
        batch.clear();
        center = problem.result().best;
        if (problem.result().bestCost < before) continue;
        for (double& h : half) h *= settings.shrink;
        scale *= settings.shrink;
    }
}

}  // namespace fm
