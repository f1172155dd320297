// Local frame of docs/algorithms.md §3; see local_frame.h.
#include "methods/local_frame.h"

#include <cmath>

namespace curvbench {

LocalFrame make_local_frame(const Vec3& m) {
  LocalFrame f;
  const double len = m.norm();
  if (!(len > 0.0) || !std::isfinite(len)) return f;
  f.m = m / len;
  const Vec3 e = (std::abs(f.m.x()) > std::abs(f.m.y()) && std::abs(f.m.x()) > std::abs(f.m.z()))
                     ? Vec3::UnitY()
                     : Vec3::UnitX();
  f.t1 = (e - e.dot(f.m) * f.m).normalized();
  f.t2 = f.m.cross(f.t1);
  return f;
}

}  // namespace curvbench
