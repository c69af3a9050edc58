#include "find/FindStage.h"

#include <cstdio>

namespace fm {

double findSeconds(const std::vector<FindStage>& stages) {
    double t = 0.0;
    for (const FindStage& s : stages) t += s.seconds;
    return t;
}

std::vector<std::string> describeFindStages(const std::vector<FindStage>& stages) {
    std::vector<std::string> lines;
    for (const FindStage& s : stages) {
        char buf[200];
        const char* what = s.name == "templates" ? "renders -> templates"
                           : s.name == "scan"    ? "placements -> hypotheses"
                           : s.name == "glance"  ? "evaluations -> hypotheses"
                           : s.name == "refine"  ? "evaluations -> finalists"
                                                 : "evaluations -> distinct answers";
        std::snprintf(buf, sizeof buf, "%-9s %6.2f s %10lld %s %d", s.name.c_str(), s.seconds, s.evaluations, what, s.kept);
        lines.push_back(buf);
    }
    return lines;
}

}  // namespace fm
