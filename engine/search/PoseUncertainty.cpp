#include "search/PoseUncertainty.h"

#include <cmath>
#include <cstdio>
#include <algorithm>
#include <limits>
#include <vector>

#include "core/Error.h"
#include "search/CmaEs.h"

namespace fm {

namespace {

constexpr int kN = 6;
// Relative eigenvalue (of the step-scaled Hessian) below which a direction counts as flat.
constexpr double kFlatFraction = 1e-6;
// An unfixed direction leaves a coordinate unfixed when it moves it by at least this share.
constexpr double kUnfixedShare = 0.1;

}  // namespace

SearchPoint spreadAlong(const PoseUncertainty& u, const glm::dmat3& axes) {
    SearchPoint out{};
    for (int block = 0; block < 2; ++block) {
        const int o = 3 * block;
        for (int a = 0; a < 3; ++a) {
            const glm::dvec3 d = axes[a];
            double v = 0.0;
            bool unfixed = false;
            for (int i = 0; i < 3; ++i) {
                if (std::abs(d[i]) > 1e-9 && !std::isfinite(u.sd[o + i])) unfixed = true;
                for (int j = 0; j < 3; ++j) v += d[i] * u.covariance[o + i][o + j] * d[j];
            }
            out[o + a] = unfixed ? std::numeric_limits<double>::infinity() : std::sqrt(std::max(0.0, v));
        }
    }
    return out;
}

const char* searchCoordinateName(int i) {
    static const char* names[kN] = {"u", "v", "depth", "about u", "about v", "about view"};
    return i >= 0 && i < kN ? names[i] : "?";
}

std::vector<int> PoseUncertainty::weak() const {
    std::vector<int> out;
    for (int i = 0; i < kN; ++i) {
        const double bound = i < 2 ? kWeakTranslationMm : i == 2 ? kWeakDepthMm : kWeakRotationDeg;
        if (!(sd[i] <= bound)) out.push_back(i);
    }
    return out;
}

PoseUncertainty poseUncertainty(const std::function<double(const SearchPoint&)>& cost,
                                const SearchPoint& step, double costResolution) {
    for (double h : step)
        if (!(h > 0.0) || !std::isfinite(h)) throw Error("pose uncertainty: steps must be positive");
    PoseUncertainty out;
    out.step = step;
    // 1. The cost at the answer and at +-h along each axis and each diagonal pair.
    auto at = [&](int i, int si, int j, int sj) {
        SearchPoint x{};
        if (i >= 0) x[i] += si * step[i];
        if (j >= 0) x[j] += sj * step[j];
        ++out.evaluations;
        return cost(x);
    };
    const double c0 = at(-1, 0, -1, 0);
    std::array<double, kN> plus{}, minus{};
    for (int i = 0; i < kN; ++i) {
        plus[i] = at(i, 1, -1, 0);
        minus[i] = at(i, -1, -1, 0);
    }
    // 2. The Hessian in step units (dimensionless: conditioned for the eigen-decomposition).
    std::vector<double> scaled(kN * kN, 0.0);
    for (int i = 0; i < kN; ++i) {
        scaled[i * kN + i] = plus[i] - 2.0 * c0 + minus[i];
        for (int j = i + 1; j < kN; ++j) {
            const double hij = (at(i, 1, j, 1) - at(i, 1, j, -1) - at(i, -1, j, 1) + at(i, -1, j, -1)) / 4.0;
            scaled[i * kN + j] = scaled[j * kN + i] = hij;
        }
    }
    for (int i = 0; i < kN; ++i)
        for (int j = 0; j < kN; ++j) out.hessian[i][j] = scaled[i * kN + j] / (step[i] * step[j]);
    // 3. Spread per coordinate with the others free: sd_i^2 = 2k (H^-1)_ii, summed over the
    //    eigen-directions; a flat or falling direction makes every coordinate it moves unfixed.
    std::vector<double> values, vectors;
    symmetricEigen(kN, scaled, values, vectors);
    double largest = 0.0;
    for (double v : values) largest = std::max(largest, std::abs(v));
    SearchPoint variance{};
    out.bounded = largest > 0.0;
    for (int k = 0; k < kN; ++k) {
        const bool flat = !(values[k] > kFlatFraction * largest);
        if (flat) out.bounded = false;
        for (int i = 0; i < kN; ++i) {
            const double e = vectors[i * kN + k];
            if (flat) {
                if (std::abs(e) >= kUnfixedShare) variance[i] = std::numeric_limits<double>::infinity();
            } else {
                variance[i] += 2.0 * costResolution * e * e / values[k];
                for (int j = 0; j < kN; ++j)
                    out.covariance[i][j] += 2.0 * costResolution * e * vectors[j * kN + k] / values[k] * step[i] * step[j];
            }
        }
    }
    for (int i = 0; i < kN; ++i) out.sd[i] = std::sqrt(variance[i]) * step[i];
    return out;
}

PoseUncertainty poseUncertainty(const Registration& registration, const SceneParams& answer,
                                const SearchPoint& step, double costResolution) {
    const int finest = registration.levelCount() - 1;
    const SceneParameterization& p = registration.parameterization();
    return poseUncertainty(
        [&](const SearchPoint& x) { return registration.cost(p.fromSearchPoint(answer, x), finest); }, step,
        costResolution);
}

std::string describeUncertainty(const PoseUncertainty& u, const std::array<const char*, 6>* names) {
    const auto name = [&](int i) { return names ? (*names)[static_cast<std::size_t>(i)] : searchCoordinateName(i); };
    std::string text;
    char part[64];
    for (int i = 0; i < kN; ++i) {
        if (std::isfinite(u.sd[i]))
            std::snprintf(part, sizeof part, "%s%s %.3g %s", i ? ", " : "", name(i), u.sd[i],
                          i < 3 ? "mm" : "deg");
        else
            std::snprintf(part, sizeof part, "%s%s not fixed", i ? ", " : "", name(i));
        text += part;
    }
    const std::vector<int> weak = u.weak();
    if (!weak.empty()) {
        text += "; weakly fixed:";
        for (std::size_t k = 0; k < weak.size(); ++k) {
            text += k ? ", " : " ";
            text += name(weak[k]);
        }
    }
    return text;
}

}  // namespace fm
