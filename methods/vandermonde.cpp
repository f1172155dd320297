// Monomial matrices of eq. (10); see vandermonde.h.
#include "methods/vandermonde.h"

namespace curvbench {

void fill_vandermonde(const RowVector& u, const RowVector& v, int degree, bool include_constant,
                      FitMatrix& V) {
  const Eigen::Index m = u.size();
  V.resize(m, num_columns(degree, include_constant));
  for (Eigen::Index i = 0; i < m; ++i) {
    // Row i: for each degree p the block u^p, u^{p-1} v, ..., v^p, built from the previous
    // block by multiplying with u (all but the last entry) and v (the last entry).
    double block[kMaxDegree + 1];
    double next[kMaxDegree + 1];
    block[0] = 1.0;
    int col = 0;
    if (include_constant) V(i, col++) = 1.0;
    for (int p = 1; p <= degree; ++p) {
      for (int k = 0; k < p; ++k) next[k] = block[k] * u(i);
      next[p] = block[p - 1] * v(i);
      for (int k = 0; k <= p; ++k) {
        block[k] = next[k];
        V(i, col++) = block[k];
      }
    }
  }
}

}  // namespace curvbench
