#include "surfaces/surface_point.h"

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

SurfacePoint nan_surface_point() {
  return to_surface_point(Vec3::Constant(Curvature::kNaN), Curvature{});
}

}  // namespace curvbench
