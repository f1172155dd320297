// Monomial matrices of eq. (10); see vandermonde.h.
#include "methods/fits/vandermonde.h"

namespace curvbench {

void fill_vandermonde(const RowVector& u, const RowVector& v, int degree, bool include_constant,
                      FitMatrix& V, const RowVector& w) {
  const Eigen::Index m = u.size();
  const bool weighted = w.size() == m;
  V.resize(m, num_columns(degree, include_constant));
  // Column by column (contiguous in the column-major V): the block of degree p, columns
  // u^p, u^{p-1} v, ..., v^p, is the previous block times u (all but the last column) and its
  // last column times v. Degree 0 is the column of ones (of weights, for a weighted matrix),
  // kept only with the constant; the weighted blocks follow by the same recurrence.
  const double* uu = u.data();
  const double* vv = v.data();
  const auto weight = [&](Eigen::Index i) { return weighted ? w(i) : 1.0; };
  double* next = V.data();
  if (include_constant)
    for (Eigen::Index i = 0; i < m; ++i, ++next) *next = weight(i);
  if (degree < 1) return;
  double* prev = next;  // degree 1: w u, w v
  for (Eigen::Index i = 0; i < m; ++i) next[i] = weight(i) * uu[i], next[m + i] = weight(i) * vv[i];
  next += 2 * m;
  for (int p = 2; p <= degree; ++p) {
    double* const block = next;
    for (int k = 0; k < p; ++k, next += m)
      for (Eigen::Index i = 0; i < m; ++i) next[i] = prev[k * m + i] * uu[i];
    for (Eigen::Index i = 0; i < m; ++i) next[i] = prev[(p - 1) * m + i] * vv[i];
    next += m;
    prev = block;
  }
}

}  // namespace curvbench
