#include "meshgen/bump_irregular.h"

#include <CGAL/Delaunay_triangulation_2.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Triangulation_vertex_base_with_info_2.h>

#include <algorithm>
#include <array>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include "core/errors.h"
#include "meshgen/random.h"

namespace curvbench {

namespace {

using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
using VertexBase = CGAL::Triangulation_vertex_base_with_info_2<int, Kernel>;
using Tds = CGAL::Triangulation_data_structure_2<VertexBase>;
using Delaunay = CGAL::Delaunay_triangulation_2<Kernel, Tds>;

constexpr double kJitter = 0.25;  // in units of h (docs/algorithms.md §10.2 [CH])

}  // namespace

PlanarPoints bump_irregular_points(int level, std::uint64_t seed) {
  check_bump_level("bump-irregular", level);
  const int N = bump_grid_size(level);
  const double h = 1.0 / N;
  Rng rng(derive_seed(seed, static_cast<std::uint64_t>(level)));
  auto jitter = [&rng, h]() { return rng.uniform(-kJitter * h, kJitter * h); };
  PlanarPoints xy((N + 1) * (N + 1), 2);
  for (int j = 0; j <= N; ++j) {
    for (int i = 0; i <= N; ++i) {
      // Exact 0 and 1 on the boundary: i*h is exact for N a power of two, but say so explicitly.
      double x = (i == N) ? 1.0 : i * h;
      double y = (j == N) ? 1.0 : j * h;
      const bool bx = (i == 0 || i == N), by = (j == 0 || j == N);
      if (!bx && !by) {
        x += jitter();
        y += jitter();
      } else if (!bx) {  // bottom or top edge: move along x only
        x += jitter();
      } else if (!by) {  // left or right edge: move along y only
        y += jitter();
      }
      xy.row(j * (N + 1) + i) << x, y;
    }
  }
  return xy;
}

FaceMatrix delaunay_triangulation(const PlanarPoints& xy) {
  const int n = static_cast<int>(xy.rows());
  std::vector<std::pair<Kernel::Point_2, int>> points;
  points.reserve(n);
  for (int i = 0; i < n; ++i) points.emplace_back(Kernel::Point_2(xy(i, 0), xy(i, 1)), i);
  Delaunay dt;
  dt.insert(points.begin(), points.end());
  if (static_cast<int>(dt.number_of_vertices()) != n)
    throw InputError("delaunay_triangulation: " + std::to_string(n - dt.number_of_vertices()) +
                     " duplicate point(s)");

  std::vector<std::array<int, 3>> faces;  // CGAL's finite faces are ccw
  faces.reserve(dt.number_of_faces());
  for (auto f = dt.finite_faces_begin(); f != dt.finite_faces_end(); ++f)
    faces.push_back({f->vertex(0)->info(), f->vertex(1)->info(), f->vertex(2)->info()});
  return canonical_faces(std::move(faces));
}

GeneratedMesh bump_irregular(int level, std::uint64_t seed) {
  const PlanarPoints xy = bump_irregular_points(level, seed);
  const int N = bump_grid_size(level);
  FaceMatrix F = delaunay_triangulation(xy);
  // Hull = the square with its 4N boundary points: a triangulation has 2V - 4N - 2 = 2N^2 faces.
  if (F.rows() != 2 * static_cast<Eigen::Index>(N) * N)
    throw std::logic_error("bump_irregular: Delaunay triangulation has " +
                           std::to_string(F.rows()) +
                           " faces, expected 2N^2 = " + std::to_string(2 * N * N));
  return lift_onto_bump(
      xy, std::move(F), "bump-irregular", level,
      "bump-irregular level " + std::to_string(level) +
          ": Gaussian bump a=81/16 on [0,1]^2, N=" + std::to_string(N) +
          " grid, interior points jittered U(-h/4,h/4) in x and y, boundary points along their "
          "edge, corners fixed, CGAL Delaunay (docs/algorithms.md 10.2), seed=" +
          std::to_string(seed));
}

}  // namespace curvbench
