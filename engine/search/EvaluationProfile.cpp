#include "search/EvaluationProfile.h"

#include <cstdio>

#include "core/Parallel.h"

namespace fm {

EvaluationProfile& EvaluationProfile::operator+=(const EvaluationProfile& o) {
    evaluations += o.evaluations;
    wallSeconds += o.wallSeconds;
    setupSeconds += o.setupSeconds;
    renderSeconds += o.renderSeconds;
    footprintSeconds += o.footprintSeconds;
    similaritySeconds += o.similaritySeconds;
    return *this;
}

std::string describeEvaluations(const EvaluationProfile& p, int threads) {
    const int cores = threads > 0 ? threads : defaultThreadCount();
    char buf[320];
    if (p.evaluations == 0 || !(p.wallSeconds > 0.0)) {
        std::snprintf(buf, sizeof buf, "%d evaluations", p.evaluations);
        return buf;
    }
    const double perSecond = p.evaluations / p.wallSeconds;
    const double ms = 1e3 / p.evaluations;
    std::snprintf(buf, sizeof buf,
                  "%d evaluations in %.3f s on %d thread%s: %.0f per second, %.0f per core-second; each %.3f ms of "
                  "thread time: render %.3f, footprint %.3f, similarity %.3f, set-up %.3f",
                  p.evaluations, p.wallSeconds, cores, cores == 1 ? "" : "s", perSecond, perSecond / cores,
                  p.threadSeconds() * ms, p.renderSeconds * ms, p.footprintSeconds * ms, p.similaritySeconds * ms,
                  p.setupSeconds * ms);
    return buf;
}

}  // namespace fm
