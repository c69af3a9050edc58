#pragma once
// CMA-ES (Hansen & Ostermeier 2001; Hansen, "The CMA Evolution Strategy: A Tutorial", 2016):
// (mu/mu_w, lambda) with full covariance, cumulative step-size adaptation, rank-one and
// rank-mu updates, default strategy parameters from the tutorial. It runs in coordinates
// scaled by the search radius, so sigma is a fraction of it. Bounds are handled by
// evaluating the nearest point inside (the sampled point still drives the update).
#include "search/SearchProblem.h"

namespace fm {

struct CmaEsSettings {
    int populationSize = 0;     // lambda; 0 = 4 + floor(3 ln n), the tutorial default
    double initialSigma = 0.5;  // in units of the search radius
};

void runCmaEs(SearchProblem& problem, const CmaEsSettings& settings = {});

// Eigen-decomposition of a symmetric n x n matrix (row-major) by cyclic Jacobi rotations:
// fills eigenvalues and eigenvectors (column k of `vectors`, row-major, is eigenvector k).
void symmetricEigen(int n, const std::vector<double>& matrix, std::vector<double>& values,
                    std::vector<double>& vectors);

}  // namespace fm
