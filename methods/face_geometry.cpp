// Per-face cotangents, angles, areas and Meyer's mixed areas; see face_geometry.h.
#include "methods/face_geometry.h"

#include <cmath>
#include <limits>

namespace curvbench {

FaceGeometry face_geometry(const Mesh& mesh, int threads) {
  const int m = mesh.num_faces();
  FaceGeometry g;
  g.area.resize(m);
  g.angle.resize(m, 3);
  g.cot.resize(m, 3);
  g.mixed_area.resize(m, 3);
#pragma omp parallel for num_threads(threads > 0 ? threads : 1) schedule(static)
  for (int f = 0; f < m; ++f) {
    Vec3 x[3];
    for (int k = 0; k < 3; ++k) x[k] = mesh.position(mesh.face_vertex(f, k));
    const double twice_area = (x[1] - x[0]).cross(x[2] - x[0]).norm();
    g.area(f) = 0.5 * twice_area;
    double len2[3];  // len2[k] = |edge opposite corner k|^2
    for (int k = 0; k < 3; ++k) {
      const Vec3 a = x[(k + 1) % 3] - x[k];
      const Vec3 b = x[(k + 2) % 3] - x[k];
      const double dot = a.dot(b);
      const double cross = a.cross(b).norm();
      g.angle(f, k) = std::atan2(cross, dot);
      g.cot(f, k) = cross > 0.0 ? dot / cross : std::numeric_limits<double>::infinity();
      len2[k] = (x[(k + 2) % 3] - x[(k + 1) % 3]).squaredNorm();
    }
    // Meyer et al. 2003, Fig. 4: an angle is obtuse when its cosine is negative.
    int obtuse = -1;
    for (int k = 0; k < 3; ++k)
      if ((x[(k + 1) % 3] - x[k]).dot(x[(k + 2) % 3] - x[k]) < 0.0) obtuse = k;
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
