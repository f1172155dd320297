// Analytic surfaces with exact differential quantities, used to score the estimators.
//
// Sign convention (paper eq. 2, docs/algorithms.md §0): B = n . x_uu with n the outward normal of a
// closed surface or the upward (+z) normal of a height field. A sphere of radius a therefore has
// k1 = k2 = H = -1/a and K = 1/a^2. k1 >= k2 algebraically; d1 is the direction of k1.
#pragma once

#include <memory>
#include <string>

#include "core/types.h"

namespace curvbench {

/// Exact first- and second-order quantities at one point of an analytic surface.
struct SurfacePoint {
  Vec3 point = Vec3::Zero();   ///< the point on the surface
  Vec3 normal = Vec3::Zero();  ///< unit normal, outward (closed) or upward (height field)
  double k1 = 0.0;             ///< larger principal curvature (algebraically)
  double k2 = 0.0;             ///< smaller principal curvature
  double H = 0.0;              ///< mean curvature (k1 + k2) / 2
  double K = 0.0;              ///< Gaussian curvature k1 * k2
  Vec3 d1 = Vec3::Zero();      ///< unit principal direction of k1 (sign arbitrary)
  Vec3 d2 = Vec3::Zero();      ///< unit principal direction of k2; (d1, d2, normal) right-handed
  bool umbilic = false;        ///< k1 == k2 (to 1e-8 relative): d1, d2 are then arbitrary
};

/// An analytic surface. Implementations are immutable and thread-safe.
class Surface {
 public:
  virtual ~Surface() = default;

  /// Short identifier, e.g. "torus", "bump", "sphere".
  virtual std::string name() const = 0;

  /// Closest point on the surface to an arbitrary point p (for a height field: the foot point of
  /// the minimum-distance normal line, found by Newton iteration; inside the domain if possible).
  virtual Vec3 project(const Vec3& p) const = 0;

  /// Exact quantities at a point on the surface. A point slightly off the surface is first
  /// projected with project().
  virtual SurfacePoint evaluate(const Vec3& p) const = 0;

  /// Position of the surface at parameters (u, v) of its natural parameterization (torus: angles;
  /// sphere: longitude/latitude; height field: x, y). Used by tests and mesh generators.
  virtual Vec3 position(double u, double v) const = 0;
};

using SurfacePtr = std::shared_ptr<const Surface>;

}  // namespace curvbench
