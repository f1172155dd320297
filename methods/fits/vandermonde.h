// Bivariate monomial (generalized Vandermonde) matrices for local polynomial fitting
// (paper eqs. 10-11; docs/algorithms.md §0).
//
// Column order: by total degree, then by decreasing power of u:
//   1 | u v | u^2 uv v^2 | u^3 u^2v uv^2 v^3 | ...      n(d) = (d+1)(d+2)/2 columns
// Plain monomials u^j v^k, without the 1/(j! k!) of eq. (10); column scaling (eq. 14) makes the
// constant factors irrelevant. The Taylor derivative is c_jk = j! k! (monomial coefficient).
// Without the constant column (a fit through the centre) every index shifts down by one.
//
// Fixed-capacity types: at most kMaxRows points (docs/algorithms.md §1.2 caps a stencil at 128),
// kMaxCols = n(6) = 28 columns, kMaxRhs = 3 right-hand sides. Resizing within the capacity
// never allocates, so a per-thread scratch of these types makes the per-vertex loop
// allocation-free.
#pragma once

#include <Eigen/Core>

#include "core/types.h"
#include "mesh/rings.h"

namespace curvbench {

inline constexpr int kMaxDegree = 6;
inline constexpr int kMaxCols = num_coefficients(kMaxDegree);  // 28
inline constexpr int kMaxRows = 128;
inline constexpr int kMaxRhs = 3;

/// rows x cols design matrix, rows <= kMaxRows, cols <= kMaxCols (column-major, no heap).
using FitMatrix =
    Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, Eigen::ColMajor, kMaxRows, kMaxCols>;
/// rows x k right-hand sides, k <= kMaxRhs.
using RhsMatrix =
    Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, Eigen::ColMajor, kMaxRows, kMaxRhs>;
/// cols x k coefficients.
using CoeffMatrix =
    Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, Eigen::ColMajor, kMaxCols, kMaxRhs>;
/// One value per row (u, v, weights, ...).
using RowVector = Eigen::Matrix<double, Eigen::Dynamic, 1, Eigen::ColMajor, kMaxRows, 1>;
/// One value per column (scaling factors, ...).
using ColVector = Eigen::Matrix<double, Eigen::Dynamic, 1, Eigen::ColMajor, kMaxCols, 1>;

/// Number of columns of a degree-d fit: n(d), or n(d) - 1 without the constant.
constexpr int num_columns(int degree, bool include_constant) {
  return degree < 0 ? 0 : num_coefficients(degree) - (include_constant ? 0 : 1);
}

/// Column of the monomial u^j v^k (j + k >= 1 when include_constant is false).
constexpr int monomial_index(int j, int k, bool include_constant = true) {
  return num_coefficients(j + k - 1) + k - (include_constant ? 0 : 1);
}

/// j! k!: converts a monomial coefficient into the Taylor derivative d^{j+k} f / du^j dv^k.
constexpr double taylor_factor(int j, int k) {
  double f = 1.0;
  for (int i = 2; i <= j; ++i) f *= i;
  for (int i = 2; i <= k; ++i) f *= i;
  return f;
}

/// Fills V (u.size() x num_columns(degree, include_constant)) with the monomials of degree
/// <= degree evaluated at the rows (u_i, v_i). degree in 0..kMaxDegree, u.size() <= kMaxRows.
/// With row weights w (same size as u) it fills Omega V of eq. (13) instead, row i times w_i.
void fill_vandermonde(const RowVector& u, const RowVector& v, int degree, bool include_constant,
                      FitMatrix& V, const RowVector& w = RowVector());

}  // namespace curvbench
