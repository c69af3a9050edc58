#include "search/BeesAlgorithm.h"

#include <algorithm>
#include <numeric>

#include "core/Error.h"

namespace fm {

namespace {

struct Site {
    Point center;
    double cost;
    double patch;  // fraction of the search radius
    int stagnation = 0;
};

}  // namespace

void runBeesAlgorithm(SearchProblem& problem, const BeesSettings& s) {
    if (s.scouts < 1 || s.selectedSites < 1 || s.selectedSites > s.scouts || s.eliteSites < 0 ||
        s.eliteSites > s.selectedSites || s.eliteRecruits < 1 || s.selectedRecruits < 1 ||
        !(s.initialPatch > 0.0) || !(s.patchShrink > 0.0 && s.patchShrink < 1.0))
        throw Error("bees algorithm: inconsistent settings");
    const Point& radius = problem.radius();
    auto scoutBatch = [&](int count, bool includeStart) {
        std::vector<Point> pts;
        if (includeStart) pts.push_back(problem.start());
        while (static_cast<int>(pts.size()) < count)
            pts.push_back(problem.sampleAround(problem.start(), radius));
        return pts;
    };
    std::vector<Site> sites;
    {
        const std::vector<Point> pts = scoutBatch(s.scouts, true);
        const std::vector<double> c = problem.evaluate(pts);
        for (std::size_t i = 0; i < pts.size(); ++i)
            sites.push_back({pts[i], c[i], s.initialPatch});
    }
    while (!problem.done()) {
        // Stable sort: equal costs keep their order, so the run stays deterministic.
        std::stable_sort(sites.begin(), sites.end(),
                         [](const Site& a, const Site& b) { return a.cost < b.cost; });
        // Converged when the best site's neighbourhood has shrunk to the tolerance.
        if (sites[0].patch < problem.tolerance()) break;
        // Recruits for every selected site, then fresh scouts, all in one batch.
        std::vector<Point> batch;
        std::vector<int> owner;
        for (int i = 0; i < s.selectedSites; ++i) {
            const int recruits = i < s.eliteSites ? s.eliteRecruits : s.selectedRecruits;
            Point half(radius.size());
            for (std::size_t d = 0; d < half.size(); ++d) half[d] = radius[d] * sites[i].patch;
            for (int k = 0; k < recruits; ++k) {
                batch.push_back(problem.sampleAround(sites[i].center, half));
                owner.push_back(i);
            }
        }
        const int freshScouts = s.scouts - s.selectedSites;
        const std::vector<Point> fresh = scoutBatch(freshScouts, false);
        batch.insert(batch.end(), fresh.begin(), fresh.end());
        const std::vector<double> c = problem.evaluate(batch);
        std::vector<bool> improved(s.selectedSites, false);
        for (std::size_t k = 0; k < owner.size(); ++k) {
            Site& site = sites[owner[k]];
            if (c[k] < site.cost) {
                site.cost = c[k];
                site.center = batch[k];
                improved[owner[k]] = true;
            }
        }
        for (int i = 0; i < s.selectedSites; ++i) {
            if (improved[i]) {
                sites[i].stagnation = 0;
                continue;
            }
            sites[i].patch *= s.patchShrink;  // neighbourhood shrinking
            // The best site is never abandoned: it holds the best point and keeps refining it.
            if (i > 0 && ++sites[i].stagnation >= s.stagnationLimit) {
                // Abandon the site (its best is kept by the problem) and scout afresh.
                sites[i] = {problem.sampleAround(problem.start(), radius),
                            std::numeric_limits<double>::infinity(), s.initialPatch};
            }
        }
        for (int k = 0; k < freshScouts; ++k) {
            Site& slot = sites[s.selectedSites + k];
            slot = {fresh[k], c[owner.size() + k], s.initialPatch};
        }
    }
}

}  // namespace fm
