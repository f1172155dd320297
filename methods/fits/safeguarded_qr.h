// Householder QR with the degree safeguard of Jiao and Zha (paper §4.3.2; docs/algorithms.md
// §5.2-5.4, following [C1] FronTier `safeqr`).
//
//   1. pre-reduce:  while d > 1 and m < ncols(d): d--            (m rows after dropping)
//   2. scale:       s_j = ||A(:, j)||_2 over the ncols(d) leading columns (eq. 14)
//   3. factor:      Householder QR left to right (= increasing degree), applying each reflector
//                   to the right-hand sides B in the same loop; stop at the first column j with
//                   |R_jj| < tol (or j >= m): rank = j
//   3b. condition:  rank = the largest k <= rank with ||R(0:k, 0:k)^-1||_F <= 1 / tol
//                   (unless switched off: EstimatorOptions::qr_condition, the |R_jj| test alone)
//   4. drop blocks: while rank < ncols(d): d--  (whole degree blocks, highest degree first);
//                   d == 0 is a failure
//   5. solve:       R(0:n, 0:n) y = (Q^T B)(0:n, :) with n = ncols(d); c_j = y_j / s_j
// The QR of the leading columns is the leading part of the full QR, so dropping blocks needs no
// refactorisation. |R_jj| < tol certifies cond_2(A(:, 0:j+1)) >= 1/tol (unit-norm columns), but
// |R_jj| >= tol does not bound it: columns can be nearly dependent together while each is far
// from the span of those before it (a degree-4 stencil on four grid lines). Step 3b bounds the
// condition number of the kept columns, as §4.3.2 asks: ||R_k^-1||_F >= 1 / sigma_min(A_k), so
// sigma_min(A_k) >= tol and cond_2(A_k) <= sqrt(k) / tol; it costs O(k^3 / 6) flops.
#pragma once

#include "methods/fits/vandermonde.h"

namespace curvbench {

struct QrSolveResult {
  int degree = 0;       ///< degree used, 0 = failure (no degree >= 1 fit is well-conditioned)
  int rank = 0;         ///< leading columns accepted by the safeguard (before dropping blocks)
  int column_rank = 0;  ///< leading columns accepted by the |R_jj| test alone (step 3)
  /// sqrt(k) ||R_k^-1||_F of the k = column_rank columns accepted by step 3: their Frobenius
  /// condition number ||A_k||_F ||A_k^+||_F (unit-norm columns); computed only where the
  /// condition test runs and cuts (rank < column_rank), else 0.
  double condition = 0.0;
};

/// Solves min ||A c - B|| for the monomial coefficients of a degree <= `degree` fit.
///   A  m x (>= num_columns(degree, include_constant)): row-weighted Vandermonde matrix in the
///      column order of vandermonde.h; overwritten (scaled columns, reflectors, R).
///   B  m x k row-weighted right-hand sides, k <= kMaxRhs; overwritten with Q^T B.
///   X  out: num_columns(d_used, include_constant) x k monomial coefficients (unscaled);
///      0 x k on failure.
///   scale  out: column scaling factors (scratch).
/// tol is the |R_jj| and 1 / ||R_k^-1||_F threshold (EstimatorOptions::qr_tolerance, default 1e-3).
/// condition_test = false skips step 3b (EstimatorOptions::qr_condition): the |R_jj| test alone,
/// the safeguard of the paper's time.
QrSolveResult safeguarded_qr_solve(FitMatrix& A, RhsMatrix& B, int degree, bool include_constant,
                                   double tol, CoeffMatrix& X, ColVector& scale,
                                   bool condition_test = true);

}  // namespace curvbench
