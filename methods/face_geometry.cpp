// Per-face cotangents, angles, areas and Meyer's mixed areas; see face_geometry.h.
#include "methods/face_geometry.h"

#include <cmath>
#include <limits>

namespace curvbench {

FaceGeometry face_geometry(const Mesh& mesh, int threads, bool angles) {
  const int m = mesh.num_faces();
  FaceGeometry g;
  g.area.resize(m);
  if (angles) g.angle.resize(m, 3);
  g.cot.resize(m, 3);
  g.mixed_area.resize(m, 3);
#pragma omp parallel for num_threads(threads > 0 ? threads : 1) schedule(static)
  for (int f = 0; f < m; ++f) {
    Vec3 x[3];
    for (int k = 0; k < 3; ++k) x[k] = mesh.position(mesh.face_vertex(f, k));
    // |a x b| is twice the area at every corner: one cross product per face.
    const double twice_area = (x[1] - x[0]).cross(x[2] - x[0]).norm();
    g.area(f) = 0.5 * twice_area;
    double dot[3], len2[3];  // len2[k] = |edge opposite corner k|^2
    for (int k = 0; k < 3; ++k) {
      dot[k] = (x[(k + 1) % 3] - x[k]).dot(x[(k + 2) % 3] - x[k]);
      if (angles) g.angle(f, k) = std::atan2(twice_area, dot[k]);
      g.cot(f, k) =
          twice_area > 0.0 ? dot[k] / twice_area : std::numeric_limits<double>::infinity();
      len2[k] = (x[(k + 2) % 3] - x[(k + 1) % 3]).squaredNorm();
    }
    // Meyer et al. 2003, Fig. 4: an angle is obtuse when its cosine is negative.
    int obtuse = -1;
    for (int k = 0; k < 3; ++k)
      if (dot[k] < 0.0) obtuse = k;
    for (int k = 0; k < 3; ++k) {
      if (obtuse < 0) {
        // Voronoi region of corner k: the edges k-(k+1) (opposite corner k+2) and k-(k+2)
        // (opposite corner k+1).
        g.mixed_area(f, k) = (len2[(k + 2) % 3] * g.cot(f, (k + 2) % 3) +
                              len2[(k + 1) % 3] * g.cot(f, (k + 1) % 3)) /
                             8.0;
      } else {
        g.mixed_area(f, k) = g.area(f) * (k == obtuse ? 0.5 : 0.25);
      }
    }
  }
  return g;
}

}  // namespace curvbench
