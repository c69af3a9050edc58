#pragma once
// Monte Carlo search with a shrinking range: each round draws `samplesPerRound` uniform points
// in a box around the best point so far; a round that finds nothing better shrinks the box.
// A plain global search whose coverage is easy to reason about (random search with range
// reduction). Shrinking only on failure keeps the box from collapsing before the best point
// has caught up with the optimum.
#include "search/SearchProblem.h"

namespace fm {

struct MonteCarloSettings {
    int samplesPerRound = 24;
    double shrink = 0.7;  // half-widths are multiplied by this after a round without progress
};

void runMonteCarlo(SearchProblem& problem, const MonteCarloSettings& settings = {});

}  // namespace fm
