#pragma once
// The Bees Algorithm (Pham et al. 2005/2006): scouts sample the search region at random; the
// best `selectedSites` are searched locally by recruited bees, more of them on the `eliteSites`
// best; a site's neighbourhood shrinks when its local search finds nothing better and the site
// is abandoned after `stagnationLimit` such rounds (site abandonment, Pham & Castellani 2009),
// except the best site, which keeps shrinking around the best point found.
#include "search/SearchProblem.h"

namespace fm {

struct BeesSettings {
    int scouts = 10;            // n: sites kept per round (selected + fresh scouts)
    int selectedSites = 4;      // m
    int eliteSites = 1;         // e (<= m)
    int eliteRecruits = 7;      // nep
    int selectedRecruits = 3;   // nsp
    double initialPatch = 0.5;  // neighbourhood half-width, as a fraction of the search radius
    double patchShrink = 0.9;
    int stagnationLimit = 10;  // consecutive rounds without improvement
};

void runBeesAlgorithm(SearchProblem& problem, const BeesSettings& settings = {});

}  // namespace fm
