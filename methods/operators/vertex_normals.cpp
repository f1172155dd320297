// Weighted vertex normals; see vertex_normals.h.
#include "methods/operators/vertex_normals.h"

#include <algorithm>
#include <cmath>

#include "core/errors.h"
#include "core/huge_pages.h"
#include "methods/operators/face_geometry.h"

namespace curvbench {

VertexMatrix weighted_vertex_normals(const Mesh& mesh, VertexNormals weighting, int threads) {
  if (weighting == VertexNormals::method_default)
    throw UsageError("weighted_vertex_normals: no weighting given");
  const int n = mesh.num_vertices();
  VertexMatrix N(n, 3);
  advise_huge_pages(N.data(), sizeof(double) * static_cast<size_t>(N.size()));
  N.setZero();
  // One pass over the faces, each adding its corners' weighted normals (in a fixed order for
  // any thread count: for_each_vertex_range, methods/operators/face_geometry.h).
  for_each_vertex_range(n, threads, [&](int lo, int hi) {
    for_each_face_touching(mesh, lo, hi, [&](int, const int(&vs)[3]) {
      const Vec3 x[3] = {mesh.position(vs[0]), mesh.position(vs[1]), mesh.position(vs[2])};
      if (weighting == VertexNormals::area) {
        // Weight area(f) = |cross|/2 on the unit normal: the cross product itself (the 1/2 goes
        // in the normalisation), once per face and computed as Mesh::area_weighted_normal does,
        // so that the normals have its bits.
        const Vec3 cross = (x[1] - x[0]).cross(x[2] - x[0]);
        for (int k = 0; k < 3; ++k)
          if (vs[k] >= lo && vs[k] < hi) N.row(vs[k]) += cross.transpose();
        return;
      }
      for (int k = 0; k < 3; ++k) {
        if (vs[k] < lo || vs[k] >= hi) continue;
        const Vec3 a = x[(k + 1) % 3] - x[k];
        const Vec3 b = x[(k + 2) % 3] - x[k];
        const Vec3 cross = a.cross(b);  // 2 area(f) times the unit face normal
        if (!(cross.squaredNorm() > 0.0)) continue;
        // w / |cross| times cross; max needs no square root.
        double w_over_len = 0.0;
        switch (weighting) {
          case VertexNormals::angle: {
            const double len = cross.norm();
            w_over_len = std::atan2(len, a.dot(b)) / len;
            break;
          }
          case VertexNormals::max:
            w_over_len = 1.0 / (a.squaredNorm() * b.squaredNorm());
            break;
          case VertexNormals::area:  // above
          case VertexNormals::method_default:
            break;
        }
        N.row(vs[k]) += (w_over_len * cross).transpose();
      }
    });
    for (int v = lo; v < hi; ++v) {
      const Vec3 sum = N.row(v).transpose();
      const double len = sum.norm();
      N.row(v) = (len > 0.0 && std::isfinite(len) ? Vec3(sum / len) : Vec3::Zero()).transpose();
    }
  });
  return N;
}

}  // namespace curvbench
