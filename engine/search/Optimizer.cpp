#include "search/Optimizer.h"

#include "core/Error.h"
#include "search/BeesAlgorithm.h"
#include "search/CmaEs.h"
#include "search/MonteCarlo.h"
#include "search/NelderMead.h"
#include "search/ParticleSwarm.h"

namespace fm {

const char* toString(SearchMethod method) {
    switch (method) {
        case SearchMethod::MonteCarlo:
            return "mc";
        case SearchMethod::ParticleSwarm:
            return "pso";
        case SearchMethod::Bees:
            return "bees";
        case SearchMethod::CmaEs:
            return "cmaes";
        case SearchMethod::NelderMead:
            return "nm";
    }
    return "?";
}

SearchMethod parseSearchMethod(const std::string& text) {
    if (text == "mc") return SearchMethod::MonteCarlo;
    if (text == "pso") return SearchMethod::ParticleSwarm;
    if (text == "bees") return SearchMethod::Bees;
    if (text == "cmaes") return SearchMethod::CmaEs;
    if (text == "nm") return SearchMethod::NelderMead;
    throw Error("unknown search method '" + text + "' (expected mc, pso, bees, cmaes or nm)");
}

std::vector<SearchMethod> globalSearchMethods() {
    return {SearchMethod::MonteCarlo, SearchMethod::ParticleSwarm, SearchMethod::Bees,
            SearchMethod::CmaEs};
}

OptimizerResult runOptimizer(SearchMethod method, SearchProblem& problem) {
    switch (method) {
        case SearchMethod::MonteCarlo:
            runMonteCarlo(problem);
            break;
        case SearchMethod::ParticleSwarm:
            runParticleSwarm(problem);
            break;
        case SearchMethod::Bees:
            runBeesAlgorithm(problem);
            break;
        case SearchMethod::CmaEs:
            runCmaEs(problem);
            break;
        case SearchMethod::NelderMead:
            runNelderMead(problem);
            break;
    }
    return problem.result();
}

OptimizerResult minimize(SearchMethod method, BatchCost cost, Point start, Point radius,
                         SearchBox box, OptimizerOptions options) {
    SearchProblem problem(std::move(cost), std::move(start), std::move(radius), std::move(box),
                          std::move(options));
    return runOptimizer(method, problem);
}

}  // namespace fm
