// Dispatcher over the test-mesh generators (docs/algorithms.md §10), used by `curvbench mesh` and
// the experiments, plus simple mesh-quality statistics.
//
// Families and levels:
//   torus-structured     levels 1..6  staggered well-shaped torus, n_u x n_v = 64x22 .. 512x176
//                                     at levels 1-4 (the paper's); 5-6 (to 2048x704 = 1.44M
//                                     vertices) for scaling benchmarks (torus_structured.h;
//                                     --jitter allowed)
//   torus-jittered       levels 1..6  the same with seeded tangential jitter of +-0.15 cells,
//                                     vertices on the torus: the stand-in for the paper's
//                                     unstructured GAMBIT meshes (breaks the stencil symmetry)
//   torus-iso            levels 1..5  marching-cubes torus, n = 16..256 grid points per axis,
//                                     vertices left where marching cubes put them (§5.3 noise)
//   torus-iso-projected  levels 1..5  the same, vertices projected onto the torus (§5.1)
//   bump-48              levels 1..5  4-8 mesh of the Gaussian bump, N = 16..256 (bump_grid.h)
//   bump-irregular       levels 1..5  seeded jittered Delaunay mesh of the bump (bump_irregular.h)
// noise_order k > 0 adds alpha h^k normal noise (noise.h) with the same seed.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "meshgen/generated_mesh.h"

namespace curvbench {

struct MeshSpec {
  std::string family;
  int level = 1;
  int noise_order = 0;  ///< 0: no noise; k >= 1: alpha h^k normal noise (§10.3)
  std::uint64_t seed = 1;
  bool jitter = false;  ///< torus-structured only
};

/// Builds the mesh. Throws UsageError (naming the valid values) for an unknown family, a level
/// out of range, a noise order outside 0..4, or --jitter with a family other than
/// torus-structured.
GeneratedMesh generate_mesh(const MeshSpec& spec);

/// The family names, in the order listed above.
std::vector<std::string> mesh_families();

/// Largest valid level of a family (levels start at 1). Throws UsageError for an unknown family.
int max_mesh_level(const std::string& family);

/// Triangle-shape and valence statistics. Valence = number of distinct edge neighbours.
struct MeshQuality {
  double min_angle_deg = 0.0;  ///< smallest triangle angle, degrees
  double max_angle_deg = 0.0;  ///< largest triangle angle, degrees
  int min_valence = 0;         ///< over interior (non-boundary) vertices
  int max_valence = 0;
  int min_boundary_valence = 0;  ///< over boundary vertices (0 if there are none)
  int max_boundary_valence = 0;
};
MeshQuality mesh_quality(const Mesh& mesh);

}  // namespace curvbench
