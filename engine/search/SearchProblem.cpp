#include "search/SearchProblem.h"

#include <algorithm>
#include <cmath>
#include <string>

#include "core/Error.h"

namespace fm {

BatchCost sequentialCost(std::function<double(const Point&)> cost) {
    return [cost = std::move(cost)](const std::vector<Point>& points, std::vector<double>& costs) {
        for (std::size_t i = 0; i < points.size(); ++i) costs[i] = cost(points[i]);
    };
}

SearchProblem::SearchProblem(BatchCost cost, Point start, Point radius, SearchBox box,
                             OptimizerOptions options)
    : cost_(std::move(cost)),
      start_(std::move(start)),
      radius_(std::move(radius)),
      box_(std::move(box)),
      options_(std::move(options)),
      rng_(options_.seed) {
    const std::size_t n = start_.size();
    if (n == 0) throw Error("search: no parameters to optimise");
    if (radius_.size() != n || box_.lower.size() != n || box_.upper.size() != n)
        throw Error("search: start, radius and bounds must have " + std::to_string(n) +
                    " values each");
    for (std::size_t i = 0; i < n; ++i) {
        if (!(radius_[i] > 0.0) || !std::isfinite(radius_[i]))
            throw Error("search: radius of parameter " + std::to_string(i) + " must be positive");
        if (!(box_.lower[i] <= box_.upper[i]))
            throw Error("search: lower bound above upper bound for parameter " + std::to_string(i));
        if (!(start_[i] >= box_.lower[i] && start_[i] <= box_.upper[i]))
            throw Error("search: start of parameter " + std::to_string(i) +
                        " is outside the bounds");
    }
    if (options_.maxEvaluations < 1)
        throw Error("search: the evaluation budget must be at least 1, got " +
                    std::to_string(options_.maxEvaluations));
    if (!cost_) throw Error("search: no cost function");
}

Point SearchProblem::clamp(Point p) const {
    for (std::size_t i = 0; i < p.size(); ++i)
        p[i] = std::clamp(p[i], box_.lower[i], box_.upper[i]);
    return p;
}

Point SearchProblem::sampleAround(const Point& center, const Point& halfWidth) {
    Point p(center.size());
    for (std::size_t i = 0; i < p.size(); ++i)
        p[i] = center[i] + halfWidth[i] * (2.0 * rng_.uniform() - 1.0);
    return clamp(std::move(p));
}

bool SearchProblem::done() const {
    return evaluations_ >= options_.maxEvaluations || stopped_ ||
           (options_.stop && options_.stop->load(std::memory_order_relaxed));
}

std::vector<double> SearchProblem::evaluate(const std::vector<Point>& points) {
    std::vector<double> costs(points.size(), std::numeric_limits<double>::infinity());
    if (options_.stop && options_.stop->load(std::memory_order_relaxed)) stopped_ = true;
    if (stopped_) return costs;
    const std::size_t allowed =
        std::min(points.size(), static_cast<std::size_t>(std::max(0, remainingEvaluations())));
    if (allowed == 0) return costs;
    std::vector<Point> batch(points.begin(), points.begin() + static_cast<std::ptrdiff_t>(allowed));
    for (auto& p : batch) {
        if (p.size() != start_.size()) throw Error("search: a point has the wrong dimension");
        p = clamp(std::move(p));
    }
    std::vector<double> batchCosts(allowed, std::numeric_limits<double>::infinity());
    cost_(batch, batchCosts);
    for (std::size_t i = 0; i < allowed; ++i) {
        // NaN would poison every comparison: treat it as the worst possible cost.
        costs[i] =
            std::isnan(batchCosts[i]) ? std::numeric_limits<double>::infinity() : batchCosts[i];
        if (costs[i] < bestCost_) {
            bestCost_ = costs[i];
            best_ = batch[i];
        }
    }
    evaluations_ += static_cast<int>(allowed);
    ++iterations_;
    history_.push_back(bestCost_);
    if (options_.progress) {
        OptimizerProgress progress;
        progress.iteration = iterations_;
        progress.evaluations = evaluations_;
        progress.bestCost = bestCost_;
        progress.best = best_.empty() ? start_ : best_;
        progress.candidate = batch.back();
        options_.progress(progress);
    }
    return costs;
}

OptimizerResult SearchProblem::result() const {
    OptimizerResult r;
    r.best = best_.empty() ? start_ : best_;
    r.bestCost = bestCost_;
    r.evaluations = evaluations_;
    r.iterations = iterations_;
    r.stopped = stopped_ || (options_.stop && options_.stop->load(std::memory_order_relaxed));
    r.bestCostHistory = history_;
    return r;
}

}  // namespace fm
