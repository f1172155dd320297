// The Gaussian bump's irregular mesh read as a mesher's output (docs/claims.md, reading
// "irregular-bump"): CGAL's 2-D Delaunay refinement of the unit square, lifted onto the bump. The
// paper (§5.2) shows its "irregular" bump mesh in a figure only; its well-shaped torus meshes come
// from an unstructured mesher (GAMBIT), and this family is that reading for the bump, beside the
// jittered grid of bump-irregular.
//
// Level L: N = 16*2^(L-1) as for the other bumps, h = 1/N. The square's boundary is split into N
// equal segments per side (the grid bumps' boundary points) and constrained; CGAL's
// Delaunay_mesher_2 refines the constrained Delaunay triangulation with
// Delaunay_mesh_size_criteria_2: smallest angle >= 30 degrees (shape bound sin^2 = 1/4, the angle
// bound of torus-unstructured's surface mesher) and edges at most 1.6 h, which gives within 3% of
// the grid bumps' (N+1)^2 vertices at every level. No randomness: vertices and faces carry creation
// stamps (cgal_timestamped.h), so the mesh is the same bytes on every run. Output vertices are
// sorted by (y, x); faces ccw in xy (normals +z), smallest index first, sorted.
// Output: exact_points == vertices, surface = bump, family "bump-unstructured".
#pragma once

#include "meshgen/bump_grid.h"
#include "meshgen/generated_mesh.h"

namespace curvbench {

/// The level-`level` Delaunay-refined bump mesh (1 <= level <= max_bump_level()).
GeneratedMesh bump_unstructured(int level);

}  // namespace curvbench
