// Weighted vertex normals; see vertex_normals.h.
#include "methods/vertex_normals.h"

#include <cmath>

#include "core/errors.h"

namespace curvbench {

VertexMatrix weighted_vertex_normals(const Mesh& mesh, VertexNormals weighting, int threads) {
  if (weighting == VertexNormals::method_default)
    throw UsageError("weighted_vertex_normals: no weighting given");
  const int n = mesh.num_vertices();
  VertexMatrix N(n, 3);
#pragma omp parallel for num_threads(threads > 0 ? threads : 1) schedule(static)
  for (int v = 0; v < n; ++v) {
    Vec3 sum = Vec3::Zero();
    for (int f : mesh.vertex_faces(v)) {
      int k = 0;
      while (mesh.face_vertex(f, k) != v) ++k;
      const Vec3 x0 = mesh.position(v);
      const Vec3 a = mesh.position(mesh.face_vertex(f, (k + 1) % 3)) - x0;
      const Vec3 b = mesh.position(mesh.face_vertex(f, (k + 2) % 3)) - x0;
      const Vec3 cross = a.cross(b);  // 2 area(f) times the unit face normal
      if (!(cross.squaredNorm() > 0.0)) continue;
      // w / |cross| times cross; area and max need no square root.
      double w_over_len = 0.0;
      switch (weighting) {
        case VertexNormals::area:
          w_over_len = 0.5;
          break;
        case VertexNormals::angle: {
          const double len = cross.norm();
          w_over_len = std::atan2(len, a.dot(b)) / len;
          break;
        }
        case VertexNormals::max:
          w_over_len = 1.0 / (a.squaredNorm() * b.squaredNorm());
          break;
        case VertexNormals::method_default:
          break;
      }
      sum += w_over_len * cross;
    }
    const double len = sum.norm();
    N.row(v) = (len > 0.0 && std::isfinite(len) ? Vec3(sum / len) : Vec3::Zero()).transpose();
  }
  return N;
}

}  // namespace curvbench
