// Graded Gaussian-bump meshes, family bump-density (docs/mesh_families.md): the sampling density
// varies across the domain so that the local edge length grows linearly by the factor D (option
// density=D >= 1, default kDefaultDensity = 8) from the side x = 0 to the side x = 1:
//   h(x) = h0 (1 + (D - 1) x),  h0 = ln D / ((D - 1) n)   (h = 1/n when D = 1).
// Columns: x_i = (D^(i/n) - 1) / (D - 1), i = 0..n (x_i = i/n when D = 1), so that
// x_{i+1} - x_i ~ h(x_i); column i holds m_i + 1 points y = k / m_i, m_i = max(1, round(1/h(x_i))),
// k = 0..m_i. Level L: n = n_1 2^(L-1), n_1 the integer nearest the root of
// c n^2 + 2n + 1 = 289 (the vertex count of the other bumps' level 1), c = (D-1)^2 / (D ln^2 D)
// (1 when D = 1): V ~ c n^2 + 2n + 1, level 4 below 20000 vertices.
// Jitter, from Rng(derive_seed(derive_seed(seed, kBumpDensityStream), level)) in point order
// (column by column, k upwards): an interior point moves by U(-1/4, 1/4) times the gap to the
// previous column in x, then by U(-1/4, 1/4) / m_i in y; a point of the sides x = 0, 1 only in y,
// one of the bottom or top side only in x; corners are fixed. The triangles are the CGAL 2-D
// Delaunay triangulation of the points (bump_irregular.h), lifted onto the bump (bump_grid.h);
// F = 2V - b - 2 with the b = m_0 + m_n + 2n points of the square's perimeter.
#pragma once

#include <cstdint>

#include "meshgen/bump_grid.h"
#include "meshgen/generate.h"
#include "meshgen/generated_mesh.h"

namespace curvbench {

/// Stream of derive_seed (random.h) that keeps bump-density's jitter apart from other families'.
inline constexpr std::uint64_t kBumpDensityStream = 0xde45;

/// The jittered planar points of bump-density at `level` (>= 1) with contrast `density` (>= 1).
PlanarPoints bump_density_points(int level, double density, std::uint64_t seed);

/// The bump-density mesh of spec.level (1..4) with contrast spec.shape.density.
GeneratedMesh generate_bump_density(const MeshSpec& spec);

}  // namespace curvbench
