// "Irregular" Gaussian-bump meshes: a seeded jittered point set on [0,1]^2, triangulated by
// CGAL's 2-D Delaunay triangulation and lifted onto the bump (docs/algorithms.md §10.2 [CH]; paper
// §5.2 gives only a figure: "well-shaped" with varying valences).
//
// Level L: N = 16*2^(L-1), h = 1/N. Point (i, j), 0 <= i, j <= N, index j*(N+1) + i, starts at
// (i h, j h) and is jittered with Rng(derive_seed(seed, level)), drawn in index order:
//   interior point (0 < i, j < N):  x += U(-h/4, h/4), then y += U(-h/4, h/4);
//   boundary non-corner point:      moved along its edge only by U(-h/4, h/4), the other
//                                   coordinate stays exactly 0 or 1;
//   corners:                        fixed.
// The convex hull is therefore exactly the unit square, with the 4N boundary points on it.
// Triangulation: CGAL::Delaunay_triangulation_2 with Exact_predicates_inexact_constructions_kernel
// (exact predicates: the collinear boundary points give hull edges, never zero-area faces).
// Faces are ccw in xy (normals +z) and canonicalised (smallest index first, then sorted), so the
// output depends only on the points. V = (N+1)^2, F = 2N^2 (= 2V - b - 2 with b = 4N hull points),
// V - E + F = 1. Output: exact_points == vertices, surface = bump, family "bump-irregular".
#pragma once

#include <cstdint>

#include "meshgen/bump_grid.h"
#include "meshgen/generated_mesh.h"

namespace curvbench {

/// The jittered planar point set of bump_irregular (n x 2, n = (N+1)^2).
PlanarPoints bump_irregular_points(int level, std::uint64_t seed);

/// Delaunay triangulation of planar points (n x 2): m x 3 faces, ccw, canonical order.
/// Throws InputError if two points coincide.
FaceMatrix delaunay_triangulation(const PlanarPoints& xy);

/// The level-`level` irregular mesh (1 <= level <= max_bump_level()).
GeneratedMesh bump_irregular(int level, std::uint64_t seed = 1);

}  // namespace curvbench
