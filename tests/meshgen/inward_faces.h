// The faces of a closed mesh whose normal points against the surface's outward direction at the
// face centroid (0 for a consistently outward mesh; a folded face counts too).
#pragma once

#include "mesh/mesh.h"

namespace curvbench::testing {

template <class Outward>
int inward_faces(const Mesh& m, Outward outward) {
  int inward = 0;
  for (int f = 0; f < m.num_faces(); ++f) {
    const Vec3 a = m.position(m.face_vertex(f, 0)), b = m.position(m.face_vertex(f, 1)),
               c = m.position(m.face_vertex(f, 2));
    inward += (b - a).cross(c - a).dot(outward((a + b + c) / 3.0)) <= 0;
  }
  return inward;
}

}  // namespace curvbench::testing
