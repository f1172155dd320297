// Batched weighted polynomial fits, one vertex per SIMD lane (docs/algorithms.md §5.5): eq. (15)
// weights, the weighted Vandermonde system of eq. (13), 2-norm column scaling (eq. 14), the
// Householder QR of the safeguarded solver (safeguarded_qr.h, steps 2, 3 and 5), back
// substitution and the Taylor derivatives of polynomial_fit.h, for kBatchLanes systems at once.
// Two rearrangements that change only rounding: the column scaling is folded into the
// safeguard's test and the back substitution instead of being applied to the matrix (a
// Householder reflector is the same for a scaled column), and the reflectors are applied to the
// columns right of each panel of four as one block reflector (each column is written once per
// four reflectors: the unblocked update was bound by its stores).
//
// Layout (structure of arrays): value of row i of lane l at [i * kBatchLanes + l]; right-hand
// side c of row i at f[(c * kMaxRows + i) * kBatchLanes + l]. Rows rows[l] .. max_rows - 1 of a
// lane must be zero (u = v = gamma = f = 0): their weight is 0, so they change neither the
// weights' mean nor the least-squares solution. A lane with rows[l] = 0 is unused.
//
// A lane is solved (solved[l] = true) only if its fit keeps the requested degree: every column
// passes the |R_jj| >= tol test. The caller checks the degree pre-reduction (rows >= columns)
// before and sends every unsolved lane through the scalar path (safeguarded_qr.h), which also
// handles degree reduction and the adaptive growth of the ring. Every operation is lane-wise,
// so a lane's result does not depend on the other lanes of its batch. Weights are bit-identical
// to compute_weights() (same operations, correctly rounded square roots and divisions); the QR
// sums in another order and uses fused multiply-adds, so the fit agrees with the scalar path to
// rounding (tests/methods/test_batched_fit.cpp).
//
// The kernel is compiled for every x86 instruction set Highway targets and picks the widest the
// CPU has at run time (AVX-512 where available); no -march flag is needed.
#pragma once

#include <array>

#include "methods/fits/vandermonde.h"

namespace curvbench {

inline constexpr int kBatchLanes = 8;
inline constexpr int kBatchMaxDegree = 4;
inline constexpr int kBatchCols = num_coefficients(kBatchMaxDegree);  // 15

/// Whether batched_fit() handles a weight exponent p of eq. (15): p = q/4 with q = 1..4 (the
/// defaults d/4 for d = 1..4).
bool batched_weight_power_supported(double power);

struct BatchedSystems {
  // ---- input ----
  int degree = 2;                ///< 1..kBatchMaxDegree
  bool include_constant = true;  ///< fit c00
  int rhs = 1;                   ///< 1 (height) or 3 (parametric)
  double tol = 1e-3;             ///< |R_jj| threshold
  bool condition = true;         ///< the ||R^-1||_F test too (safeguarded_qr.h step 3b)
  double power = 0.5;            ///< weight exponent p (batched_weight_power_supported)
  int max_rows = 0;              ///< max over the lanes of rows[l]
  std::array<int, kBatchLanes> rows{};
  std::array<double, kMaxRows * kBatchLanes> u{}, v{}, gamma{};
  std::array<double, kMaxRhs * kMaxRows * kBatchLanes> f{};
  // ---- output ----
  std::array<bool, kBatchLanes> solved{};
  /// Taylor derivative t (TaylorRow) of right-hand side c of lane l at [(t * kMaxRhs + c) *
  /// kBatchLanes + l]; as FitResult::taylor.
  std::array<double, 6 * kMaxRhs * kBatchLanes> taylor{};
  // ---- scratch: the weighted matrix [A B] (not column-scaled), column-major per lane ----
  std::array<double, (kBatchCols + kMaxRhs) * kMaxRows * kBatchLanes> work{};
};

/// Solves every lane of s (see the file comment).
void batched_fit(BatchedSystems& s);

}  // namespace curvbench
