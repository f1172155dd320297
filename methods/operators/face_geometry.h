// Per-corner quantities of the discrete curvature operators (Meyer et al. 2003, Taubin 1995,
// Rusinkiewicz 2004), for one triangle (x0, x1, x2) with angle theta_k at corner k:
//   twice_area       |a x b|, a = x1 - x0, b = x2 - x0 (c = x2 - x1)
//   cot[k]           cot theta_k = (dot product of the two edges leaving corner k) / |a x b|
//                    (infinite for a degenerate face)
//   mixed_area(k)    Meyer et al. 2003 §3.3, Fig. 4 ("A_mixed"): the Voronoi part of the face at
//                    corner k, (|x_k - x_{k+1}|^2 cot theta_{k+2} + |x_k - x_{k+2}|^2
//                    cot theta_{k+1}) / 8, when no angle of the face is obtuse; area/2 at the
//                    obtuse corner and area/4 at the other two otherwise. The three corners sum
//                    to the area.
// Computed where they are used, with no memory: the operators call these while they walk a
// vertex's faces (or all faces once) instead of reading per-face arrays filled beforehand (on a
// large mesh, writing and reading such arrays costs more than the arithmetic).
#pragma once

#include <algorithm>
#include <limits>

#include "core/types.h"
#include "mesh/mesh.h"

namespace curvbench {

/// The triangle (x0, x1, x2): edges a = x1 - x0, b = x2 - x0, c = x2 - x1.
struct CornerGeometry {
  Vec3 a, b, c;
  double twice_area = 0.0;  ///< |a x b|
  double dot[3] = {};       ///< dot product of the two edges leaving corner k
  double cot[3] = {};       ///< cot theta_k at corners 0, 1, 2 (infinite if twice_area == 0)
};

/// Edges, dot products and cotangents of the triangle (x0, x1, x2).
inline CornerGeometry corner_geometry(const Vec3& x0, const Vec3& x1, const Vec3& x2) {
  CornerGeometry g;
  g.a = x1 - x0;
  g.b = x2 - x0;
  g.c = x2 - x1;
  g.twice_area = g.a.cross(g.b).norm();
  // a . b at corner 0, (x2 - x1) . (x0 - x1) at corner 1, (x0 - x2) . (x1 - x2) at corner 2.
  g.dot[0] = g.a.dot(g.b);
  g.dot[1] = -g.a.dot(g.c);
  g.dot[2] = g.b.dot(g.c);
  for (int k = 0; k < 3; ++k)
    g.cot[k] =
        g.twice_area > 0.0 ? g.dot[k] / g.twice_area : std::numeric_limits<double>::infinity();
  return g;
}

/// The mixed area at corner k (0, 1 or 2) of the triangle of g.
inline double mixed_area(const CornerGeometry& g, int k) {
  // Meyer et al. 2003, Fig. 4: an angle is obtuse when its cosine is negative.
  if (g.dot[k] < 0.0) return 0.25 * g.twice_area;                                       // area / 2
  if (g.dot[0] < 0.0 || g.dot[1] < 0.0 || g.dot[2] < 0.0) return 0.125 * g.twice_area;  // / 4
  // The edge x0-x1 (a) is opposite corner 2, x0-x2 (b) opposite corner 1, x1-x2 (c) corner 0.
  switch (k) {
    case 0:
      return (g.a.squaredNorm() * g.cot[2] + g.b.squaredNorm() * g.cot[1]) / 8.0;
    case 1:
      return (g.c.squaredNorm() * g.cot[0] + g.a.squaredNorm() * g.cot[2]) / 8.0;
    default:
      return (g.b.squaredNorm() * g.cot[1] + g.c.squaredNorm() * g.cot[0]) / 8.0;
  }
}

/// The per-face passes that add a face's terms to its corners (Rusinkiewicz's tensors, weighted
/// vertex normals) without races and in a fixed order: the vertices are split into `threads`
/// ranges [lo, hi), one per OpenMP thread, and range(lo, hi) runs once per range. Inside it,
/// for_each_face_touching() walks every face with a corner in the range in increasing face order,
/// so each vertex sums its faces in the same order whatever the number of threads.
template <class Range>
void for_each_vertex_range(int num_vertices, int threads, Range range) {
  const int chunks = std::max(1, std::min(threads, num_vertices));
#pragma omp parallel for num_threads(chunks) schedule(static, 1)
  for (int chunk = 0; chunk < chunks; ++chunk)
    range(static_cast<int>(static_cast<long long>(num_vertices) * chunk / chunks),
          static_cast<int>(static_cast<long long>(num_vertices) * (chunk + 1) / chunks));
}

/// Calls face(f, vs) for every face f with a vertex in [lo, hi), in increasing f; vs[k] is the
/// vertex at corner k.
template <class Face>
void for_each_face_touching(const Mesh& mesh, int lo, int hi, Face face) {
  for (int f = 0, m = mesh.num_faces(); f < m; ++f) {
    const int vs[3] = {mesh.face_vertex(f, 0), mesh.face_vertex(f, 1), mesh.face_vertex(f, 2)};
    if ((vs[0] >= lo && vs[0] < hi) || (vs[1] >= lo && vs[1] < hi) || (vs[2] >= lo && vs[2] < hi))
      face(f, vs);
  }
}

/// Corner k of face f that holds vertex v (0, 1 or 2); -1 if v is not a vertex of f.
inline int corner_of(const Mesh& mesh, int f, int v) {
  for (int k = 0; k < 3; ++k)
    if (mesh.face_vertex(f, k) == v) return k;
  return -1;
}

}  // namespace curvbench
