#include "meshgen/torus_isosurface.h"

#include <algorithm>
#include <cmath>
#include <memory>
#include <string>

#include "core/errors.h"
#include "meshgen/marching_cubes.h"
#include "surfaces/torus.h"

namespace curvbench {

namespace {

constexpr double kMajor = 1.0;    // R
constexpr double kMinor = 0.3;    // r
constexpr double kHalfBox = 1.5;  // grid [-1.5, 1.5]^3

// Level of n = 16 * 2^(L-1), or 0.
int level_of(int n) {
  int level = 1;
  for (int m = 16; m <= n; m *= 2, ++level)
    if (m == n) return level;
  return 0;
}

}  // namespace

int isosurface_grid_points(int level) {
  if (level < 1 || level > 8)
    throw UsageError("torus-iso: level must be in 1..8, got " + std::to_string(level));
  return 16 << (level - 1);
}

double torus_signed_distance(double x, double y, double z) {
  const double rho = std::sqrt(x * x + y * y);
  return std::sqrt((rho - kMajor) * (rho - kMajor) + z * z) - kMinor;
}

GeneratedMesh torus_isosurface(int grid_points, bool project) {
  if (grid_points < 2 || grid_points > 2048)
    throw UsageError("torus-iso: grid points per axis must be in 2..2048, got " +
                     std::to_string(grid_points));
  const std::vector<double> axis = matlab_linspace(-kHalfBox, kHalfBox, grid_points);
  IsosurfaceMesh iso = marching_cubes(axis, axis, axis, torus_signed_distance);

  const auto torus = std::make_shared<const Torus>(kMajor, kMinor);
  VertexMatrix closest(iso.vertices.rows(), 3);
  for (Eigen::Index i = 0; i < iso.vertices.rows(); ++i)
    closest.row(i) = torus->project(iso.vertices.row(i).transpose()).transpose();

  GeneratedMesh out;
  out.family = project ? "torus-iso-projected" : "torus-iso";
  out.level = level_of(grid_points);
  out.description = "marching cubes (asymptotic decider) on the torus SDF R=1 r=0.3, n=" +
                    std::to_string(grid_points) + " samples per axis on [-1.5,1.5]^3, " +
                    (project ? "vertices projected onto the torus" : "raw vertices");
  out.surface = torus;
  const std::string source = out.family + " n=" + std::to_string(grid_points);
  if (project) {
    out.mesh = Mesh(closest, std::move(iso.faces), source);
    out.exact_points = std::move(closest);
  } else {
    out.mesh = Mesh(std::move(iso.vertices), std::move(iso.faces), source);
    out.exact_points = std::move(closest);
  }
  return out;
}

std::vector<Table4Row> table4(int max_grid_points) {
  if (max_grid_points < 16 || max_grid_points > 2048)
    throw UsageError("table4: max grid points must be in 16..2048, got " +
                     std::to_string(max_grid_points));
  std::vector<Table4Row> rows;
  for (int n = 16; n <= max_grid_points; n *= 2) {
    const GeneratedMesh g = torus_isosurface(n, false);
    const VertexMatrix& V = g.mesh.vertices();
    double sum_sq = 0.0, max_err = 0.0;
    for (Eigen::Index i = 0; i < V.rows(); ++i) {
      const double d = std::abs(torus_signed_distance(V(i, 0), V(i, 1), V(i, 2)));
      sum_sq += d * d;
      max_err = std::max(max_err, d);
    }
    const int nv = g.mesh.num_vertices();
    rows.push_back(
        {n, nv, g.mesh.mean_edge_length(), nv > 0 ? std::sqrt(sum_sq / nv) : 0.0, max_err});
  }
  return rows;
}

}  // namespace curvbench
