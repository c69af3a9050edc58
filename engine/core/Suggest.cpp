#include "core/Suggest.h"

#include <algorithm>
#include <cctype>

namespace fm {

namespace {
std::string lower(std::string s) {
    for (char& c : s) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
    return s;
}
}  // namespace

std::size_t editDistance(const std::string& a, const std::string& b) {
    const std::size_t n = a.size(), m = b.size();
    std::vector<std::vector<std::size_t>> d(n + 1, std::vector<std::size_t>(m + 1));
    for (std::size_t i = 0; i <= n; ++i) d[i][0] = i;
    for (std::size_t j = 0; j <= m; ++j) d[0][j] = j;
    for (std::size_t i = 1; i <= n; ++i)
        for (std::size_t j = 1; j <= m; ++j) {
            const std::size_t cost = a[i - 1] == b[j - 1] ? 0 : 1;
            d[i][j] = std::min({d[i - 1][j] + 1, d[i][j - 1] + 1, d[i - 1][j - 1] + cost});
            if (i > 1 && j > 1 && a[i - 1] == b[j - 2] && a[i - 2] == b[j - 1])
                d[i][j] = std::min(d[i][j], d[i - 2][j - 2] + 1);
        }
    return d[n][m];
}

std::optional<std::string> closestMatch(const std::string& word,
                                        const std::vector<std::string>& candidates) {
    const std::string w = lower(word);
    if (w.empty()) return std::nullopt;
    const std::size_t allowed = std::max<std::size_t>(1, std::min<std::size_t>(3, w.size() / 3));
    std::optional<std::string> best;
    std::size_t bestDistance = allowed + 1;
    std::vector<std::string> prefixed;
    for (const std::string& c : candidates) {
        const std::string lc = lower(c);
        if (lc.rfind(w, 0) == 0 && lc != w) prefixed.push_back(c);
        const std::size_t d = editDistance(w, lc);
        if (d < bestDistance) {
            bestDistance = d;
            best = c;
        }
    }
    if (best) return best;
    if (prefixed.size() == 1) return prefixed.front();
    return std::nullopt;
}

}  // namespace fm
