// Gaussian bump of paper §5.2; see gaussian_bump.h.
#include "surfaces/gaussian_bump.h"

#include <cmath>
#include <memory>

namespace curvbench {

SurfacePtr make_gaussian_bump() {
  constexpr double a = kBumpExponent;
  auto g = [](double x, double y) {
    const double dx = x - 0.5;
    const double dy = y - 0.5;
    return std::exp(-a * (dx * dx + dy * dy));
  };
  HeightFunction fn;
  fn.f = g;
  fn.fx = [g](double x, double y) { return -2.0 * a * (x - 0.5) * g(x, y); };
  fn.fy = [g](double x, double y) { return -2.0 * a * (y - 0.5) * g(x, y); };
  fn.fxx = [g](double x, double y) {
    const double dx = x - 0.5;
    return (4.0 * a * a * dx * dx - 2.0 * a) * g(x, y);
  };
  fn.fxy = [g](double x, double y) { return 4.0 * a * a * (x - 0.5) * (y - 0.5) * g(x, y); };
  fn.fyy = [g](double x, double y) {
    const double dy = y - 0.5;
    return (4.0 * a * a * dy * dy - 2.0 * a) * g(x, y);
  };
  return std::make_shared<const HeightField>("bump", std::move(fn), 0.0, 1.0, 0.0, 1.0);
}

}  // namespace curvbench
