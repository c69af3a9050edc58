#pragma once
// Nelder-Mead simplex (1965) with the dimension-adaptive coefficients of Gao & Han 2012
// (reflection 1, expansion 1 + 2/n, contraction 0.75 - 1/(2n), shrink 1 - 1/n), which keep
// it working beyond 2-3 parameters. Used as the local polish after a global search. The
// first simplex is the start plus `initialStep` times the radius along each axis; it restarts
// once from its best point when it converges, which catches premature collapse.
#include "search/SearchProblem.h"

namespace fm {

struct NelderMeadSettings {
    double initialStep = 0.5;  // fraction of the search radius
    int restarts = 1;
};

void runNelderMead(SearchProblem& problem, const NelderMeadSettings& settings = {});

}  // namespace fm
