// Generic height field z = f(x, y) over a rectangle, with f and its derivatives up to second
// order given analytically (paper §2.2; docs/algorithms.md §6.1).
//
//   position(x, y) = (x, y, f(x, y)), normal upward (+z), parameters (u, v) = (x, y).
//   evaluate(): project(), then curvature_from_height with the global frame t1 = (1, 0, 0),
//   t2 = (0, 1, 0), m = (0, 0, 1) (Table 1 height-function column; H, K from Table 1, the
//   principal pair from eqs. 7-8). umbilic = |k1 - k2| <= 1e-8 max(|k1|, |k2|) (exact k1 = k2
//   included).
#pragma once

#include <functional>
#include <string>

#include "surfaces/surface.h"

namespace curvbench {

/// f and its partial derivatives f_x, f_y, f_xx, f_xy, f_yy, each a function of (x, y).
struct HeightFunction {
  std::function<double(double, double)> f, fx, fy, fxx, fxy, fyy;
};

class HeightField : public Surface {
 public:
  /// Limits of project()'s damped Newton iteration.
  static constexpr int kMaxIterations = 100;       ///< Newton steps
  static constexpr int kMaxHalvings = 60;          ///< step halvings per line search
  static constexpr double kStepTolerance = 1e-14;  ///< stop when |dx| <= tol (1 + |x|_inf)

  /// Throws UsageError if a function is missing or the domain is empty or not finite.
  HeightField(std::string name, HeightFunction fn, double xmin, double xmax, double ymin,
              double ymax);

  std::string name() const override { return name_; }

  /// Closest point to p with (x, y) in the domain: minimises
  /// D(x, y) = ((x - px)^2 + (y - py)^2 + (f(x, y) - pz)^2) / 2 starting from (px, py) clamped
  /// to the domain. Each step solves the Newton system (I + grad f grad f^T + (f - pz) Hess f)
  /// dx = -grad D, falling back to Gauss-Newton (I + grad f grad f^T, always positive definite)
  /// where that matrix is not positive definite; coordinates at a bound with grad D pointing out
  /// of the domain are held fixed; the new iterate is clamped to the domain and the step is
  /// halved (at most kMaxHalvings times) until D or the projected |grad D|_inf decreases (D
  /// alone cannot resolve steps below sqrt(eps D)). Stops when the projected gradient is zero,
  /// when the step is at most kStepTolerance (1 + |x|_inf), when no step makes progress, or
  /// after kMaxIterations. A point on the surface is returned unchanged. Converges to the local
  /// minimum reached from the vertical foot point, which is the global one for points near the
  /// surface (closer than the focal distance).
  Vec3 project(const Vec3& p) const override;

  SurfacePoint evaluate(const Vec3& p) const override;

  Vec3 position(double x, double y) const override;

  const HeightFunction& function() const { return fn_; }
  double xmin() const { return xmin_; }
  double xmax() const { return xmax_; }
  double ymin() const { return ymin_; }
  double ymax() const { return ymax_; }

 private:
  std::string name_;
  HeightFunction fn_;
  double xmin_, xmax_, ymin_, ymax_;
};

}  // namespace curvbench
