// "Well-shaped" torus meshes: the staggered structured substitute for the paper's GAMBIT meshes
// (docs/algorithms.md §10.1(b); paper §5.1, Table 5: V = 1338, 5246, 21156, 85208, F = 2V).
//
// Torus R = 1, r = 0.3, x(u,v) = ((R + r cos v) cos u, (R + r cos v) sin u, r sin v).
// Level L: n_v = 22*2^(L-1) rows around the tube, n_u = 64*2^(L-1) points per row,
//   V = n_u*n_v = 1408, 5632, 22528, 90112;  F = 2V;  closed, genus 1 (V - E + F = 0).
// Vertex (i, j) has index j*n_u + i and sits at u = 2pi(i + (j mod 2)/2)/n_u, v = 2pi j/n_v.
// Triangles between rows j and j+1 (indices mod n_u, n_v):
//   j even: (i,j)(i+1,j)(i,j+1) and (i+1,j)(i+1,j+1)(i,j+1);
//   j odd:  (i,j)(i+1,j+1)(i,j+1) and (i,j)(i+1,j)(i+1,j+1);
// all counter-clockwise in (u,v), hence outward (x_u x x_v is the outward normal).
// Optional jitter: each vertex moves by independent U(-0.15, 0.15) cells in u and in v (cell =
// 2pi/n_u resp. 2pi/n_v), drawn from Rng(derive_seed(seed, level)); the vertex is then placed
// exactly on the torus at the jittered angles. Connectivity is the same with or without jitter.
//
// Output: GeneratedMesh with mesh (V x 3, F x 3), exact_points == vertices, surface = torus,
// family "torus-structured", level, description.
#pragma once

#include <cstdint>

#include "meshgen/generated_mesh.h"

namespace curvbench {

/// Rows around the tube and points per row at `level` (>= 1).
int torus_structured_rows(int level);     // n_v = 22 * 2^(level-1)
int torus_structured_columns(int level);  // n_u = 64 * 2^(level-1)

/// The staggered triangles above for n_u points per row and n_v rows (n_v even, both >= 3):
/// 2 n_u n_v faces, ccw in (u, v). Shared with torus-anisotropic (anisotropic.h).
FaceMatrix staggered_torus_faces(int nu, int nv);

/// The same triangles between `bands` + 1 rows that do not close up (an open tube: the
/// lantern, lantern.h): 2 n_u bands faces, row j + 1 of every odd band shifted by half a point.
FaceMatrix staggered_tube_faces(int nu, int bands);

/// Builds the level-`level` mesh (level >= 1; throws UsageError otherwise).
GeneratedMesh torus_structured(int level, bool jitter = false, std::uint64_t seed = 1);

}  // namespace curvbench
