// Row weights of the weighted least-squares fit: paper eq. (15), docs/algorithms.md §4.
//
//   w_i = gamma_i / (sqrt(|u_i|^2 + eps))^(d/2) = gamma_i (|u_i|^2 + eps)^(-p),  p = d/4,
//   eps = 0.01 * mean_i |u_i|^2   over the rows being fitted (the centre's 0 included when the
//                                 centre is a row), so the weights are scale-invariant,
//   gamma_i = max(0, m_i . m_0)   normal-angle safeguard (90-degree cut-off), centre gamma = 1.
// Rows with gamma_i = 0 are dropped by the caller before the weights are computed (and before
// the points are counted).
#pragma once

#include <algorithm>
#include <cmath>

#include "core/types.h"
#include "methods/fits/vandermonde.h"

namespace curvbench {

/// Exponent p of eq. (15): d/4 by default (weight_power < 0), else weight_power.
inline double weight_exponent(int degree, double weight_power) {
  return weight_power < 0.0 ? 0.25 * degree : weight_power;
}

/// gamma_i = max(0, m_i . m_0) of eq. (15). 0 for NaN input.
inline double normal_safeguard_gamma(const Vec3& mi, const Vec3& m0) {
  const double c = mi.dot(m0);
  return c > 0.0 ? c : 0.0;
}

/// x^(-p) for x > 0. For the default exponents p = d/4, d = 1..6, it is computed with square
/// roots and one division (correctly rounded steps, within a few ulp of std::pow and about 10x
/// faster); other p use std::pow.
inline double inverse_power(double x, double p) {
  // p = q/4: x^(-q/4) from x, s = x^(1/2) and r = x^(1/4); otherwise std::pow.
  const double q = 4.0 * p;
  if (q == 2.0) return 1.0 / std::sqrt(x);  // degree 2, the common case
  if (q == 4.0) return 1.0 / x;
  if (q == 1.0) return 1.0 / std::sqrt(std::sqrt(x));
  if (q == 3.0) {
    const double s = std::sqrt(x);
    return 1.0 / (s * std::sqrt(s));
  }
  if (q == 5.0) return 1.0 / (x * std::sqrt(std::sqrt(x)));
  if (q == 6.0) return 1.0 / (x * std::sqrt(x));
  return std::pow(x, -p);
}

/// Eq. (15) for rows (u_i, v_i) with safeguard factors gamma_i (all n = u.size()).
/// Writes w (n). If every |u_i| is 0 the distance factor is 1 (eps would be 0).
void compute_weights(const RowVector& u, const RowVector& v, const RowVector& gamma, double power,
                     RowVector& w);

}  // namespace curvbench
