#include "search/SearchOptions.h"

#include "core/Error.h"

namespace fm {

RegistrationSettings applySearchOptions(const SearchOptions& o, RegistrationSettings s) {
    const std::string& p = o.prefix;
    s.method = parseSearchMethod(o.method);
    if (s.method == SearchMethod::NelderMead)
        throw Error(p + "method: nm is the local polish, not a global search (use mc, pso, bees or cmaes)");
    s.similarity = parseSimilarityMeasure(o.similarity);
    s.polishMethod = parseSearchMethod(o.polish);
    s.seed = o.seed;
    if (o.budget < 0) throw Error(p + "budget must be positive");
    if (o.budget > 0) s.globalEvaluations = o.budget;
    if (o.polishBudget >= 0) s.polishEvaluations = s.finestPolishEvaluations = o.polishBudget;
    if (o.threads < 0) throw Error(p + "threads must be 0 (all cores) or more");
    s.threads = o.threads;
    if (!o.levels.empty()) {
        for (int f : o.levels)
            if (f < 1 || f > 64) throw Error(p + "levels: factors must be whole numbers 1..64");
        s.levelFactors = o.levels;
    }
    if (!o.radius.empty()) {
        if (o.radius.size() != 1 && o.radius.size() != 6)
            throw Error(p + "radius: give one number or six (u,v,depth,az,el,rot)");
        for (int i = 0; i < 6; ++i) {
            s.searchRadius[i] = o.radius.size() == 1 ? o.radius[0] : o.radius[i];
            if (!(s.searchRadius[i] > 0.0)) throw Error(p + "radius: values must be positive");
        }
    }
    return s;
}

}  // namespace fm
