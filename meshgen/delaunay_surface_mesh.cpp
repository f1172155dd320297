#include "meshgen/delaunay_surface_mesh.h"

#include <CGAL/Complex_2_in_triangulation_3.h>
#include <CGAL/Delaunay_triangulation_3.h>
#include <CGAL/Delaunay_triangulation_cell_base_with_circumcenter_3.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Implicit_surface_3.h>
#include <CGAL/Random.h>
#include <CGAL/Robust_circumcenter_traits_3.h>
#include <CGAL/Surface_mesh_cell_base_3.h>
#include <CGAL/Surface_mesh_vertex_base_3.h>
#include <CGAL/make_surface_mesh.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <map>
#include <numbers>
#include <numeric>
#include <string>
#include <vector>

#include "meshgen/cgal_timestamped.h"

namespace curvbench {
namespace {

// CGAL's default surface-mesher triangulation, with time-stamped vertices and cells
// (cgal_timestamped.h): the mesh does not depend on the state of the heap.
using Kernel =
    CGAL::Robust_circumcenter_traits_3<CGAL::Exact_predicates_inexact_constructions_kernel>;
using Vb = Timestamped<CGAL::Surface_mesh_vertex_base_3<Kernel>>;
using Cb = Timestamped<CGAL::Delaunay_triangulation_cell_base_with_circumcenter_3<
    Kernel, CGAL::Surface_mesh_cell_base_3<Kernel>>>;
using Tr = CGAL::Delaunay_triangulation_3<Kernel, CGAL::Triangulation_data_structure_3<Vb, Cb>>;
using C2t3 = CGAL::Complex_2_in_triangulation_3<Tr>;
using GT = Tr::Geom_traits;
using Point3 = GT::Point_3;

struct Function {
  double (*f)(double, double, double);
  GT::FT operator()(const Point3& p) const { return f(p.x(), p.y(), p.z()); }
};
using ImplicitSurface = CGAL::Implicit_surface_3<GT, Function>;

// Z-order (Morton) key of two angles in [-pi, pi]: 21 bits each, bits interleaved.
std::uint64_t morton_key(double a, double b) {
  const auto quantize = [](double x) {
    const double t = (x + std::numbers::pi) / (2.0 * std::numbers::pi);
    return static_cast<std::uint64_t>(std::clamp(t, 0.0, 1.0) * double((1u << 21) - 1));
  };
  const std::uint64_t qa = quantize(a), qb = quantize(b);
  std::uint64_t key = 0;
  for (int bit = 0; bit < 21; ++bit)
    key |= ((qa >> bit) & 1u) << (2 * bit + 1) | ((qb >> bit) & 1u) << (2 * bit);
  return key;
}

}  // namespace

GeneratedMesh delaunay_surface_mesh(const ImplicitMeshing& spec) {
  const double rho = spec.radius_bound;
  CGAL::get_default_random() = CGAL::Random(static_cast<unsigned int>(spec.seed));
  Tr tr;
  C2t3 c2t3(tr);
  const double R = spec.bounding_radius;
  const ImplicitSurface implicit(Function{spec.implicit}, GT::Sphere_3(CGAL::ORIGIN, R * R), 1e-10);
  const CGAL::Surface_mesh_default_criteria_3<Tr> criteria(30.0, rho, 0.1 * rho);
  CGAL::make_surface_mesh(c2t3, implicit, criteria, CGAL::Manifold_tag());

  const Surface& surface = *spec.surface;
  std::map<Tr::Vertex_handle, int> index;
  std::vector<Vec3> points;
  for (auto v = tr.finite_vertices_begin(); v != tr.finite_vertices_end(); ++v) {
    if (c2t3.face_status(v) == C2t3::NOT_IN_COMPLEX) continue;
    index.emplace(v, static_cast<int>(points.size()));
    const Point3& p = v->point();
    points.push_back(surface.project(Vec3(p.x(), p.y(), p.z())));
  }
  std::vector<std::array<int, 3>> faces;
  for (auto f = c2t3.facets_begin(); f != c2t3.facets_end(); ++f) {
    const auto cell = f->first;
    const int i = f->second;
    std::array<int, 3> t;
    for (int k = 0, n = 0; k < 4; ++k)
      if (k != i) t[n++] = index.at(cell->vertex(k));
    // Outward: the face normal agrees with the surface normal at the centroid.
    const Vec3 a = points[t[0]], b = points[t[1]], c = points[t[2]];
    const Vec3 centroid = (a + b + c) / 3.0;
    if ((b - a).cross(c - a).dot(surface.evaluate(centroid).normal) < 0) std::swap(t[1], t[2]);
    faces.push_back(t);
  }
  // The mesher numbers vertices in refinement order, which scatters neighbours across memory
  // (at the torus's level 4 every ring gather misses the cache). Renumber along a Z-order curve
  // of the two angles, then sort the faces by their smallest vertex: neighbours get nearby
  // numbers, as on a structured mesh. Deterministic.
  const size_t nv = points.size();
  std::vector<std::uint64_t> key(nv);
  for (size_t i = 0; i < nv; ++i) {
    const std::array<double, 2> ang = spec.angles(points[i]);
    key[i] = morton_key(ang[0], ang[1]);
  }
  std::vector<int> order(nv);
  std::iota(order.begin(), order.end(), 0);
  std::stable_sort(order.begin(), order.end(), [&](int a, int b) { return key[a] < key[b]; });
  std::vector<int> new_index(nv);
  for (size_t i = 0; i < nv; ++i) new_index[static_cast<size_t>(order[i])] = static_cast<int>(i);
  for (auto& t : faces)
    for (int& k : t) k = new_index[static_cast<size_t>(k)];
  std::stable_sort(faces.begin(), faces.end(), [](const auto& a, const auto& b) {
    return std::min({a[0], a[1], a[2]}) < std::min({b[0], b[1], b[2]});
  });
  VertexMatrix V(nv, 3);
  for (size_t i = 0; i < nv; ++i) V.row(i) = points[static_cast<size_t>(order[i])].transpose();
  FaceMatrix F(faces.size(), 3);
  for (size_t i = 0; i < faces.size(); ++i) F.row(i) << faces[i][0], faces[i][1], faces[i][2];

  GeneratedMesh out;
  out.exact_points = V;
  out.mesh = Mesh(std::move(V), std::move(F), spec.name);
  out.surface = spec.surface;
  out.family = spec.name;
  out.level = spec.level;
  char mesher[128];
  std::snprintf(mesher, sizeof mesher, "CGAL surface mesher (angle 30 deg, radius %g, distance %g)",
                spec.radius_bound, 0.1 * spec.radius_bound);
  out.description = spec.name + " level " + std::to_string(spec.level) + ": " + spec.surface_words +
                    ", " + mesher + ", vertices projected to " + spec.projected_to +
                    ", seed=" + std::to_string(spec.seed);
  return out;
}

}  // namespace curvbench
