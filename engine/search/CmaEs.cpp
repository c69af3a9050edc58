#include "search/CmaEs.h"

#include <algorithm>
#include <cmath>
#include <numeric>

#include "core/Error.h"

namespace fm {

void symmetricEigen(int n, const std::vector<double>& matrix, std::vector<double>& values,
                    std::vector<double>& vectors) {
    std::vector<double> a = matrix;
    vectors.assign(static_cast<std::size_t>(n) * n, 0.0);
    for (int i = 0; i < n; ++i) vectors[i * n + i] = 1.0;
    auto at = [n](std::vector<double>& m, int r, int c) -> double& { return m[r * n + c]; };
    for (int sweep = 0; sweep < 100; ++sweep) {
        double off = 0.0;
        for (int p = 0; p < n; ++p)
            for (int q = p + 1; q < n; ++q) off += at(a, p, q) * at(a, p, q);
        if (off < 1e-30) break;
        for (int p = 0; p < n; ++p)
            for (int q = p + 1; q < n; ++q) {
                const double apq = at(a, p, q);
                if (std::abs(apq) < 1e-300) continue;
                const double theta = (at(a, q, q) - at(a, p, p)) / (2.0 * apq);
                const double t =
                    (theta >= 0 ? 1.0 : -1.0) / (std::abs(theta) + std::sqrt(theta * theta + 1.0));
                const double c = 1.0 / std::sqrt(t * t + 1.0), s = t * c;
                for (int k = 0; k < n; ++k) {  // A <- A J
                    const double akp = at(a, k, p), akq = at(a, k, q);
                    at(a, k, p) = c * akp - s * akq;
                    at(a, k, q) = s * akp + c * akq;
                }
                for (int k = 0; k < n; ++k) {  // A <- J^T A
                    const double apk = at(a, p, k), aqk = at(a, q, k);
                    at(a, p, k) = c * apk - s * aqk;
                    at(a, q, k) = s * apk + c * aqk;
                }
                for (int k = 0; k < n; ++k) {  // V <- V J
                    const double vkp = at(vectors, k, p), vkq = at(vectors, k, q);
                    at(vectors, k, p) = c * vkp - s * vkq;
                    at(vectors, k, q) = s * vkp + c * vkq;
                }
            }
    }
    values.resize(n);
    for (int i = 0; i < n; ++i) values[i] = at(a, i, i);
}

void runCmaEs(SearchProblem& problem, const CmaEsSettings& settings) {
    const int n = problem.dimension();
    const int lambda = settings.populationSize > 0
                           ? settings.populationSize
                           : 4 + static_cast<int>(std::floor(3.0 * std::log(double(n))));
    if (lambda < 2) throw Error("CMA-ES: population size must be at least 2");
    if (!(settings.initialSigma > 0.0)) throw Error("CMA-ES: initial sigma must be positive");
    const int mu = lambda / 2;
    std::vector<double> w(mu);
    for (int i = 0; i < mu; ++i) w[i] = std::log((lambda + 1) / 2.0) - std::log(i + 1.0);
    const double wsum = std::accumulate(w.begin(), w.end(), 0.0);
    for (double& wi : w) wi /= wsum;
    double w2 = 0.0;
    for (double wi : w) w2 += wi * wi;
    const double mueff = 1.0 / w2;
    const double cc = (4.0 + mueff / n) / (n + 4.0 + 2.0 * mueff / n);
    const double cs = (mueff + 2.0) / (n + mueff + 5.0);
    const double c1 = 2.0 / ((n + 1.3) * (n + 1.3) + mueff);
    const double cmu =
        std::min(1.0 - c1, 2.0 * (mueff - 2.0 + 1.0 / mueff) / ((n + 2.0) * (n + 2.0) + mueff));
    const double damps = 1.0 + 2.0 * std::max(0.0, std::sqrt((mueff - 1.0) / (n + 1.0)) - 1.0) + cs;
    const double chiN = std::sqrt(double(n)) * (1.0 - 1.0 / (4.0 * n) + 1.0 / (21.0 * n * n));

    const Point& start = problem.start();
    const Point& radius = problem.radius();
    auto toPoint = [&](const std::vector<double>& y) {
        Point x(n);
        for (int d = 0; d < n; ++d) x[d] = start[d] + radius[d] * y[d];
        return x;
    };
    std::vector<double> mean(n, 0.0), pc(n, 0.0), ps(n, 0.0);
    std::vector<double> C(n * n, 0.0), B(n * n, 0.0), D(n, 1.0), invSqrtC(n * n, 0.0);
    for (int i = 0; i < n; ++i) C[i * n + i] = B[i * n + i] = invSqrtC[i * n + i] = 1.0;
    double sigma = settings.initialSigma;
    int generation = 0;
    bool first = true;

    while (!problem.done()) {
        // Sample lambda offspring y = mean + sigma * B D z.
        std::vector<std::vector<double>> y(lambda, std::vector<double>(n));
        std::vector<Point> xs(lambda);
        for (int k = 0; k < lambda; ++k) {
            std::vector<double> z(n);
            for (double& zi : z) zi = problem.rng().normal();
            for (int i = 0; i < n; ++i) {
                double bdz = 0.0;
                for (int j = 0; j < n; ++j) bdz += B[i * n + j] * D[j] * z[j];
                y[k][i] = mean[i] + sigma * bdz;
            }
            xs[k] = toPoint(y[k]);
        }
        // The first generation also evaluates the start, so the result is never worse than it.
        if (first) {
            xs[0] = start;
            std::fill(y[0].begin(), y[0].end(), 0.0);
            first = false;
        }
        const std::vector<double> cost = problem.evaluate(xs);
        ++generation;
        std::vector<int> order(lambda);
        std::iota(order.begin(), order.end(), 0);
        std::stable_sort(order.begin(), order.end(),
                         [&](int a, int b) { return cost[a] < cost[b]; });

        const std::vector<double> oldMean = mean;
        std::fill(mean.begin(), mean.end(), 0.0);
        for (int k = 0; k < mu; ++k)
            for (int i = 0; i < n; ++i) mean[i] += w[k] * y[order[k]][i];
        std::vector<double> step(n);
        for (int i = 0; i < n; ++i) step[i] = (mean[i] - oldMean[i]) / sigma;

        // Step-size path in the isotropic frame: ps = (1-cs) ps + sqrt(cs(2-cs)mueff) C^-1/2 step.
        const double csNorm = std::sqrt(cs * (2.0 - cs) * mueff);
        for (int i = 0; i < n; ++i) {
            double v = 0.0;
            for (int j = 0; j < n; ++j) v += invSqrtC[i * n + j] * step[j];
            ps[i] = (1.0 - cs) * ps[i] + csNorm * v;
        }
        double psNorm = 0.0;
        for (double v : ps) psNorm += v * v;
        psNorm = std::sqrt(psNorm);
        const bool hsig = psNorm / std::sqrt(1.0 - std::pow(1.0 - cs, 2.0 * generation)) / chiN <
                          1.4 + 2.0 / (n + 1.0);
        const double ccNorm = std::sqrt(cc * (2.0 - cc) * mueff);
        for (int i = 0; i < n; ++i) pc[i] = (1.0 - cc) * pc[i] + (hsig ? ccNorm * step[i] : 0.0);

        // Covariance: rank-one (pc) and rank-mu (selected steps) updates.
        const double dh = hsig ? 0.0 : c1 * cc * (2.0 - cc);
        for (int i = 0; i < n; ++i)
            for (int j = 0; j <= i; ++j) {
                double rankMu = 0.0;
                for (int k = 0; k < mu; ++k) {
                    const auto& yk = y[order[k]];
                    rankMu += w[k] * (yk[i] - oldMean[i]) * (yk[j] - oldMean[j]);
                }
                rankMu /= sigma * sigma;
                const double v =
                    (1.0 - c1 - cmu + dh) * C[i * n + j] + c1 * pc[i] * pc[j] + cmu * rankMu;
                C[i * n + j] = C[j * n + i] = v;
            }
        sigma *= std::exp((cs / damps) * (psNorm / chiN - 1.0));

        // Decompose C = B D^2 B^T (6x6: cheap enough to do every generation).
        std::vector<double> eig;
        symmetricEigen(n, C, eig, B);
        for (int i = 0; i < n; ++i) D[i] = std::sqrt(std::max(eig[i], 1e-20));
        for (int i = 0; i < n; ++i)
            for (int j = 0; j < n; ++j) {
                double v = 0.0;
                for (int k = 0; k < n; ++k) v += B[i * n + k] * B[j * n + k] / D[k];
                invSqrtC[i * n + j] = v;
            }
        const double maxD = *std::max_element(D.begin(), D.end());
        if (sigma * maxD < problem.tolerance()) break;
        if (!std::isfinite(sigma) || sigma * maxD > 1e6) break;  // diverged: keep the best found
    }
}

}  // namespace fm
