#include "mesh/creases.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <string>

#include "core/errors.h"
#include "core/text.h"
#include "mesh/mesh_checks.h"

namespace curvbench {

namespace {

Vec3 face_cross(const Mesh& mesh, int f) {
  const Vec3 a = mesh.position(mesh.face_vertex(f, 0));
  return (mesh.position(mesh.face_vertex(f, 1)) - a)
      .cross(mesh.position(mesh.face_vertex(f, 2)) - a);
}

}  // namespace

double dihedral_angle_deg(const Mesh& mesh, int f, int k) {
  constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
  const int g = mesh.face_neighbor(f, k);
  if (g < 0 || is_zero_area_face(mesh, f) || is_zero_area_face(mesh, g)) return kNaN;
  const int a = mesh.face_vertex(f, k);
  const int b = mesh.face_vertex(f, (k + 1) % 3);
  // Consistent orientation: g runs the edge b -> a. If it runs a -> b, its normal is reversed.
  bool same_direction = false;
  for (int j = 0; j < 3; ++j)
    same_direction =
        same_direction || (mesh.face_vertex(g, j) == a && mesh.face_vertex(g, (j + 1) % 3) == b);
  const Vec3 n1 = face_cross(mesh, f).normalized();
  Vec3 n2 = face_cross(mesh, g).normalized();
  if (same_direction) n2 = -n2;
  return std::atan2(n1.cross(n2).norm(), n1.dot(n2)) * 180.0 / std::numbers::pi;
}

Creases detect_creases(const Mesh& mesh, double threshold_deg) {
  if (!(threshold_deg > 0.0 && threshold_deg < 180.0))
    throw UsageError("crease angle " + format_g(threshold_deg) +
                     " degrees out of range: must be in (0, 180)");
  Creases c;
  c.threshold_deg = threshold_deg;
  c.is_vertex.assign(static_cast<size_t>(mesh.num_vertices()), 0);
  for (int f = 0; f < mesh.num_faces(); ++f)
    for (int k = 0; k < 3; ++k) {
      if (mesh.face_neighbor(f, k) < f) continue;  // each interior edge once, from its lower face
      if (!(dihedral_angle_deg(mesh, f, k) > threshold_deg)) continue;  // NaN: never sharp
      const int a = mesh.face_vertex(f, k);
      const int b = mesh.face_vertex(f, (k + 1) % 3);
      c.edges.push_back({std::min(a, b), std::max(a, b)});
      c.is_vertex[static_cast<size_t>(a)] = 1;
      c.is_vertex[static_cast<size_t>(b)] = 1;
    }
  std::sort(c.edges.begin(), c.edges.end());
  for (int v = 0; v < mesh.num_vertices(); ++v)
    if (c.is_vertex[static_cast<size_t>(v)]) c.vertices.push_back(v);
  return c;
}

}  // namespace curvbench
