// Eq. (15) weights; see weights.h.
#include "methods/fits/weights.h"

#include <cmath>

namespace curvbench {

void compute_weights(const RowVector& u, const RowVector& v, const RowVector& gamma, double power,
                     RowVector& w) {
  const Eigen::Index n = u.size();
  w.resize(n);
  double mean = 0.0;
  for (Eigen::Index i = 0; i < n; ++i) mean += u(i) * u(i) + v(i) * v(i);
  mean = n > 0 ? mean / static_cast<double>(n) : 0.0;
  if (!(mean > 0.0) || power == 0.0) {
    for (Eigen::Index i = 0; i < n; ++i) w(i) = gamma(i);
    return;
  }
  const double eps = 0.01 * mean;
  for (Eigen::Index i = 0; i < n; ++i)
    w(i) = gamma(i) * inverse_power(u(i) * u(i) + v(i) * v(i) + eps, power);
}

}  // namespace curvbench
