// "Well-shaped" unstructured torus meshes, the stand-in for the paper's GAMBIT meshes (paper
// §5.1 and Table 5: V = 1338, 5246, 21156, 85208; docs/mesh_families.md).
//
// Torus R = 1, r = 0.3, implicit function f(p) = (sqrt(x^2 + y^2) - R)^2 + z^2 - r^2.
// Generator: CGAL's Delaunay-refinement surface mesher through delaunay_surface_mesh.h (angle
// bound 30 degrees, surface Delaunay ball radius bound rho_L, centre-to-surface distance bound
// 0.1 rho_L, manifold output; seeded and creation-stamped, so the same bytes on every run; every
// vertex then moved to its exact closest point on the torus, Torus::project). rho_L is fixed per
// level (kRadius in the .cpp, calibrated once so that V is within 3% of the paper's counts).
// Triangles are oriented outward (the normal of each face agrees with the torus normal at its
// centroid). Valences are mixed (typically 4-9), the minimum angle is >= 25 degrees (tested).
//
// Output: GeneratedMesh with mesh (V x 3, F x 3), exact_points == vertices, surface = torus,
// family "torus-unstructured", level, description.
#pragma once

#include <cstdint>

#include "meshgen/generated_mesh.h"

namespace curvbench {

/// Highest level (4: the paper's finest well-shaped mesh).
int torus_unstructured_max_level();

/// Builds the level-`level` mesh (1 <= level <= 4; throws UsageError otherwise). Meshes are
/// cached per (level, seed) within a process, so a run generates each level once.
GeneratedMesh torus_unstructured(int level, std::uint64_t seed = 1);

}  // namespace curvbench
