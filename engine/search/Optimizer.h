#pragma once
// The optimizers by name, behind one call.
#include <string>
#include <vector>

#include "search/SearchProblem.h"

namespace fm {

enum class SearchMethod {
    MonteCarlo,     // "mc": random search with a shrinking range
    ParticleSwarm,  // "pso"
    Bees,           // "bees": the Bees Algorithm
    CmaEs,          // "cmaes"
    NelderMead,     // "nm": local simplex polish
};

const char* toString(SearchMethod method);
// Parses "mc", "pso", "bees", "cmaes" or "nm"; throws fm::Error naming the choices otherwise.
SearchMethod parseSearchMethod(const std::string& text);
// The global methods the registration offers (all but the local polish).
std::vector<SearchMethod> globalSearchMethods();

// Runs `method` on the problem (default settings) and returns problem.result().
OptimizerResult runOptimizer(SearchMethod method, SearchProblem& problem);

// Convenience: builds the problem and runs the method.
OptimizerResult minimize(SearchMethod method, BatchCost cost, Point start, Point radius,
                         SearchBox box, OptimizerOptions options);

}  // namespace fm
