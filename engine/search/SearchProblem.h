#pragma once
// What every optimizer works on: a cost over n parameters, a start, an initial search radius
// per parameter, hard bounds, an evaluation budget, a stop flag and a progress callback.
// Optimizers hand over whole batches (a swarm, a CMA-ES generation) so the cost function may
// evaluate them in parallel; results never depend on how it does so.
#include <atomic>
#include <cstdint>
#include <functional>
#include <limits>
#include <vector>

#include "core/Random.h"

namespace fm {

using Point = std::vector<double>;

// Fills costs[i] (already sized) with the cost of points[i]; lower is better.
using BatchCost = std::function<void(const std::vector<Point>& points, std::vector<double>& costs)>;

// Wraps a cost of one point as a batch cost (sequential).
BatchCost sequentialCost(std::function<double(const Point&)> cost);

struct SearchBox {
    Point lower;
    Point upper;
};

struct OptimizerProgress {
    int iteration = 0;    // batches (generations, sweeps) so far
    int evaluations = 0;  // cost evaluations so far
    double bestCost = std::numeric_limits<double>::infinity();
    Point best;       // best point so far
    Point candidate;  // the last point evaluated
};

struct OptimizerOptions {
    int maxEvaluations = 1000;  // hard budget: never exceeded
    std::uint64_t seed = 1;
    // Converged when the search has shrunk below this fraction of the initial radius.
    double tolerance = 1e-3;
    const std::atomic<bool>* stop = nullptr;  // set from another thread to stop early
    std::function<void(const OptimizerProgress&)> progress;  // after each batch, same thread
};

struct OptimizerResult {
    Point best;
    double bestCost = std::numeric_limits<double>::infinity();
    int evaluations = 0;
    int iterations = 0;
    bool stopped = false;                 // the stop flag ended it
    std::vector<double> bestCostHistory;  // best cost after each batch
};

class SearchProblem {
  public:
    // Throws fm::Error if sizes disagree, a radius is not positive, bounds are inverted, the
    // start lies outside the bounds or the budget is not positive.
    SearchProblem(BatchCost cost, Point start, Point radius, SearchBox box,
                  OptimizerOptions options);

    int dimension() const { return static_cast<int>(start_.size()); }
    const Point& start() const { return start_; }
    const Point& radius() const { return radius_; }
    const SearchBox& box() const { return box_; }
    Rng& rng() { return rng_; }
    double tolerance() const { return options_.tolerance; }

    // The nearest point inside the bounds.
    Point clamp(Point p) const;
    // Uniform in [center - halfWidth, center + halfWidth] per parameter, clamped to the box.
    Point sampleAround(const Point& center, const Point& halfWidth);

    // Evaluates the points (clamped to the bounds) while budget and stop flag allow; the rest
    // get +infinity. Counts one iteration and reports progress.
    std::vector<double> evaluate(const std::vector<Point>& points);
    double evaluate(const Point& point) { return evaluate(std::vector<Point>{point})[0]; }

    // True once the budget is spent or stop was requested: optimizers must then return.
    bool done() const;
    int remainingEvaluations() const { return options_.maxEvaluations - evaluations_; }

    OptimizerResult result() const;

  private:
    BatchCost cost_;
    Point start_, radius_;
    SearchBox box_;
    OptimizerOptions options_;
    Rng rng_;
    int evaluations_ = 0;
    int iterations_ = 0;
    bool stopped_ = false;
    Point best_;
    double bestCost_ = std::numeric_limits<double>::infinity();
    std::vector<double> history_;
};

}  // namespace fm
