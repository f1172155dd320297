// Area-uniform point samples of the analytic surfaces; see point_samples.h.
#include "meshgen/point_samples.h"

#include <cmath>
#include <numbers>
#include <string>

#include "core/errors.h"
#include "meshgen/random.h"

namespace curvbench {

VertexMatrix sample_torus_points(int n, double R, double r, std::uint64_t seed) {
  if (n < 1) throw UsageError("torus points: n = " + std::to_string(n) + " must be at least 1");
  if (!(R > r && r > 0.0 && std::isfinite(R)))
    throw UsageError("torus points: the radii must satisfy R > r > 0");
  Rng rng(seed);
  VertexMatrix points(n, 3);
  const double two_pi = 2.0 * std::numbers::pi;
  for (int i = 0; i < n; ++i) {
    const double u = two_pi * rng.uniform01();
    double v = 0.0;
    do {
      v = two_pi * rng.uniform01();
    } while (rng.uniform01() * (R + r) > R + r * std::cos(v));
    const double rho = R + r * std::cos(v);
    points.row(i) << rho * std::cos(u), rho * std::sin(u), r * std::sin(v);
  }
  return points;
}

}  // namespace curvbench
