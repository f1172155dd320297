// Eq. (15) weights; see weights.h.
#include "methods/weights.h"

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

double inverse_power(double x, double p) {
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

}  // namespace curvbench
