#include "surfaces/surface_point.h"

#include <cmath>

namespace curvbench {

SurfacePoint to_surface_point(const Vec3& point, const Curvature& c) {
  SurfacePoint s;
  s.point = point;
  s.normal = c.normal;
  s.k1 = c.k1;
  s.k2 = c.k2;
  s.H = c.H;
  s.K = c.K;
  s.d1 = c.d1;
  s.d2 = c.d2;
  s.umbilic = is_umbilic(c.k1, c.k2);
  return s;
}

void orthonormal_tangents(const Vec3& n, Vec3& t1, Vec3& t2) {
  const double sign = std::copysign(1.0, n.z());
  const double a = -1.0 / (sign + n.z());
  const double b = n.x() * n.y() * a;
  t1 = Vec3(1.0 + sign * n.x() * n.x() * a, sign * b, -sign * n.x()).normalized();
  t2 = n.cross(t1).normalized();
}

SurfacePoint nan_surface_point() {
  return to_surface_point(Vec3::Constant(Curvature::kNaN), Curvature{});
}

}  // namespace curvbench
