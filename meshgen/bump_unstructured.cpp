#include "meshgen/bump_unstructured.h"

#include <CGAL/Constrained_Delaunay_triangulation_2.h>
#include <CGAL/Delaunay_mesh_face_base_2.h>
#include <CGAL/Delaunay_mesh_size_criteria_2.h>
#include <CGAL/Delaunay_mesh_vertex_base_2.h>
#include <CGAL/Delaunay_mesher_2.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>

#include <algorithm>
#include <array>
#include <map>
#include <string>
#include <vector>

#include "meshgen/cgal_timestamped.h"

namespace curvbench {

namespace {

using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
using Vb = Timestamped<CGAL::Delaunay_mesh_vertex_base_2<Kernel>>;
using Fb = Timestamped<CGAL::Delaunay_mesh_face_base_2<Kernel>>;
using Cdt =
    CGAL::Constrained_Delaunay_triangulation_2<Kernel,
                                               CGAL::Triangulation_data_structure_2<Vb, Fb>>;
using Criteria = CGAL::Delaunay_mesh_size_criteria_2<Cdt>;

constexpr double kShapeBound = 0.25;     // sin^2 of the smallest angle: 30 degrees
constexpr double kEdgeBoundOverH = 1.6;  // (N+1)^2 vertices within 3% at levels 1-5

// The boundary point k of 4N, counter-clockwise from the origin, exactly on the square.
Kernel::Point_2 boundary_point(int k, int N) {
  const int side = k / N, i = k % N;
  const double t = (i == 0) ? 0.0 : static_cast<double>(i) / N;
  switch (side) {
    case 0:
      return {t, 0.0};
    case 1:
      return {1.0, t};
    case 2:
      return {1.0 - t, 1.0};
    default:
      return {0.0, 1.0 - t};
  }
}

}  // namespace

GeneratedMesh bump_unstructured(int level) {
  check_bump_level("bump-unstructured", level);
  const int N = bump_grid_size(level);
  Cdt cdt;
  std::vector<Cdt::Vertex_handle> boundary;
  boundary.reserve(4 * static_cast<size_t>(N));
  for (int k = 0; k < 4 * N; ++k) boundary.push_back(cdt.insert(boundary_point(k, N)));
  for (int k = 0; k < 4 * N; ++k) cdt.insert_constraint(boundary[k], boundary[(k + 1) % (4 * N)]);
  CGAL::refine_Delaunay_mesh_2(cdt, Criteria(kShapeBound, kEdgeBoundOverH / N));

  // Vertices sorted by (y, x); the square is convex, so every finite face is in the domain.
  std::vector<Cdt::Vertex_handle> vertices;
  vertices.reserve(cdt.number_of_vertices());
  for (auto v = cdt.finite_vertices_begin(); v != cdt.finite_vertices_end(); ++v)
    vertices.push_back(v);
  std::sort(vertices.begin(), vertices.end(), [](const auto& a, const auto& b) {
    const auto &p = a->point(), &q = b->point();
    return p.y() != q.y() ? p.y() < q.y() : p.x() < q.x();
  });
  std::map<Cdt::Vertex_handle, int> index;
  PlanarPoints xy(static_cast<Eigen::Index>(vertices.size()), 2);
  for (size_t i = 0; i < vertices.size(); ++i) {
    index[vertices[i]] = static_cast<int>(i);
    xy.row(static_cast<Eigen::Index>(i)) << vertices[i]->point().x(), vertices[i]->point().y();
  }
  std::vector<std::array<int, 3>> faces;  // CGAL's finite faces are ccw
  faces.reserve(cdt.number_of_faces());
  for (auto f = cdt.finite_faces_begin(); f != cdt.finite_faces_end(); ++f)
    faces.push_back({index.at(f->vertex(0)), index.at(f->vertex(1)), index.at(f->vertex(2))});
  return lift_onto_bump(
      xy, canonical_faces(std::move(faces)), "bump-unstructured", level,
      "bump-unstructured level " + std::to_string(level) +
          ": Gaussian bump a=81/16 on [0,1]^2, boundary in N=" + std::to_string(N) +
          " segments per side, CGAL Delaunay refinement (angle 30 deg, edges "
          "<= 1.6/N)");
}

}  // namespace curvbench
