// Local orthonormal frame at a vertex (docs/algorithms.md §3 [C1, C2, C3]; paper §2.2).
//
//   e  = (|m.x| > |m.y| && |m.x| > |m.z|) ? (0,1,0) : (1,0,0)
//   t1 = normalize(e - (e.m) m),   t2 = m x t1,   U = [t1 t2 m]  (right-handed)
//
// A point p is mapped to (u, v, w) = U^T (p - p0): (u, v) is the orthogonal projection onto the
// plane through p0 normal to m (LOP, paper §4.2.2) and w the local height (LHF, §2.2).
#pragma once

#include "core/types.h"

namespace curvbench {

struct LocalFrame {
  Vec3 t1 = Vec3::UnitX();  ///< u axis
  Vec3 t2 = Vec3::UnitY();  ///< v axis
  Vec3 m = Vec3::UnitZ();   ///< w axis (the approximate normal)
};

/// Frame of docs/algorithms.md §3 for a unit normal m. A zero or non-finite m (an isolated vertex)
/// gives the global frame (x, y, z).
LocalFrame make_local_frame(const Vec3& m);

}  // namespace curvbench
