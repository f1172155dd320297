// Where the safeguarded QR's condition test fires (docs/claims.md, "The safeguard on
// near-degenerate stencils"; the reading `safeguard`): per mesh level and method, the vertices
// whose first stencil (RingFitEstimator::first_system) the test ||R_k^-1||_F <= 1/tol cuts while
// every |R_jj| passes, with the condition number of the columns the |R_jj| test keeps and what
// the estimator then does with and without the test (degree, ring, points). `curvbench
// safeguard-fires` writes them to results/diag-safeguard-fires.csv in `make experiments` (about
// 20 s of CPU: two estimations per mesh and method, levels 1-4 of both bumps).
#pragma once

#include <string>
#include <vector>

#include "harness/model/safeguard_fire.h"

namespace curvbench {

/// Every vertex where the condition test cuts the first stencil, in case, level, method and
/// vertex order. A level where it fires nowhere has one row with vertex = -1 (the level was
/// looked at).
std::vector<SafeguardFire> safeguard_fires(const std::vector<SafeguardFireCase>& cases);

}  // namespace curvbench
