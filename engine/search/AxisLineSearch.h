#pragma once
// A line search along one parameter by parabola fits: each round evaluates `pointsPerRound`
// points spaced h apart around the current centre (one batch, so they render in parallel),
// fits a least-squares parabola and moves to its vertex (or to the best point when the fit
// opens downwards), then shrinks h. Used to refine the depth of a registration: the cost is
// smooth and nearly symmetric but very flat along depth, where simplex methods stall.
#include "search/SearchProblem.h"

namespace fm {

struct AxisLineSearchSettings {
    int axis = 0;
    int rounds = 3;
    int pointsPerRound = 5;  // odd, >= 3
    double shrink = 1.0 / 3.0;
};

// Starts at problem.start() with h = problem.radius()[axis] / 2.
void runAxisLineSearch(SearchProblem& problem, const AxisLineSearchSettings& settings);

}  // namespace fm
