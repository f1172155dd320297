// "Poor-shaped" torus meshes: marching cubes on the signed distance function of the torus
// (paper §5.1, §5.3, Table 4; docs/algorithms.md §10.1(a); docs/claims.md A2-A4).
//
// MATLAB original:  [X,Y,Z] = meshgrid(linspace(-1.5,1.5,n));
//                   V = sqrt((sqrt(X.^2+Y.^2)-1).^2+Z.^2)-0.3;  isosurface(X,Y,Z,V,0)
// i.e. f(x) = sqrt((rho - R)^2 + z^2) - r, rho = sqrt(x^2 + y^2), R = 1, r = 0.3, sampled at
// x_i = -1.5 + 3i/(n-1), i = 0..n-1, on each axis ("#volume cells n^3" in Table 4 counts samples).
// meshgen/marching_cubes.h extracts {f = 0}: one vertex per sign-changing grid edge (linear
// interpolation), faces oriented towards increasing f (outward). For n = 16..256 no cube face is
// ambiguous, and the result is a closed genus-1 surface with V = 320, 1760, 7320, 31136, 122464
// (Table 4) and F = 2V. At n = 256 some vertices lie ~1e-11 apart; they are kept.
//
// Output GeneratedMesh (V x 3 vertices, F x 3 faces, exact_points V x 3, surface = Torus(1, 0.3)):
//   project = false ("torus-iso", §5.3): raw vertices; exact_points = closest torus points;
//   project = true  ("torus-iso-projected", §5.1): vertices projected onto the torus,
//                   exact_points = vertices; same faces.
#pragma once

#include <vector>

#include "meshgen/generated_mesh.h"

namespace curvbench {

/// Grid points per axis of isosurface level L (1-based): 16 * 2^(L-1) -> 16, 32, 64, 128, 256.
/// Throws UsageError unless 1 <= level <= 8.
int isosurface_grid_points(int level);

/// The sampled function f(x, y, z) = sqrt((sqrt(x^2 + y^2) - 1)^2 + z^2) - 0.3 (signed distance
/// to the torus R = 1, r = 0.3; negative inside), evaluated in MATLAB's operation order.
double torus_signed_distance(double x, double y, double z);

/// Marching cubes on the signed distance function of the torus R=1, r=0.3 sampled at n points per
/// axis on [-1.5,1.5]^3 (MATLAB linspace). project=false: raw vertices, exact_points = closest
/// torus points; project=true: vertices projected onto the torus (noise-free), exact_points =
/// vertices. family "torus-iso" or "torus-iso-projected", level = log2(n/16)+1 when n is such a
/// size, else 0. Throws UsageError unless 2 <= grid_points <= 2048.
GeneratedMesh torus_isosurface(int grid_points, bool project);

/// One row of Table 4. mean_edge_length is the true mean over unique edges (the paper's column
/// is half of it, docs/claims.md A4); errors are the RMS and max of |f| at the raw vertices.
struct Table4Row {
  int grid_points;
  int vertices;
  double mean_edge_length;
  double rms_error;
  double max_error;
};

/// Rows for n = 16, 32, ... up to max_grid_points (raw vertices; errors = distances to the torus).
/// Throws UsageError if max_grid_points < 16 or > 2048.
std::vector<Table4Row> table4(int max_grid_points = 256);

}  // namespace curvbench
