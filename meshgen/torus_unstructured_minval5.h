// Well-shaped unstructured torus meshes without vertices of valence 3 or 4: a second reading of
// the paper's well-shaped GAMBIT meshes (paper §5.1; vertex counts of Table 5: 1338, 5246, 21156,
// 85208; docs/mesh_families.md).
//
// Why: about 1.5% of the vertices of torus-unstructured (CGAL's Delaunay refinement) have four
// neighbours. A degree-2 fit over such a 1-ring (Xu-2) has fewer equations than unknowns, and its
// error there dominates the Linf norm of the whole mesh. The paper describes its meshes only as
// the kind CAD software makes for finite-element analysis; such meshes may well have had no
// vertex of valence 4. This family lets the comparison be run on both readings.
//
// Method: start from torus_unstructured(level, seed) (same vertices, same numbering, same torus
// R = 1, r = 0.3 and the same exact points / exact curvatures code path), then repeat
//  1. for each vertex of valence < 5, in index order, flip the best edge of its link (the edge
//     opposite the vertex in one of its triangles): the flip joins the vertex to the far corner,
//     raising its valence by one. Allowed only if both ends of the flipped edge keep valence >= 5,
//     the far corner stays <= 9, the new edge is not an edge already and both new triangles face
//     outward; among the allowed ones, the flip whose two new triangles have the largest minimum
//     angle wins. If none is allowed (every link edge has an end of valence 5), first raise one
//     of those valence-5 neighbours the same way, by a flip that leaves the vertex's edges alone
//     (needed once, at level 4);
//  2. tangential relaxation of the vertices within one ring of the flipped edges (and of any
//     triangle under 25 degrees): move the vertex half-way towards the centroid of its neighbours
//     in the torus tangent plane, then onto its exact closest point on the torus (Torus::project),
//     and keep the move only if it raises the smallest angle of the vertex's triangles (five
//     Gauss-Seidel sweeps in index order);
// until no vertex has valence < 5 and no angle is under 25 degrees (one or two passes on levels
// 1-4; throws std::runtime_error if 20 do not do it). Faces are then reordered by their smallest
// vertex, as in the base family. Single-threaded and seeded by the base mesh: the same bytes on
// every run.
//
// Output: GeneratedMesh with mesh (V x 3, F x 3), exact_points == vertices (on the torus to
// roundoff), surface = torus, family "torus-unstructured-minval5", level, description (with the
// numbers of flips, relaxation moves and passes).
#pragma once

#include <cstdint>

#include "meshgen/generated_mesh.h"

namespace curvbench {

/// Highest level (4, as torus-unstructured).
int torus_unstructured_minval5_max_level();

/// Builds the level-`level` mesh (1 <= level <= 4; throws UsageError otherwise). Cached per
/// (level, seed) within a process, as torus_unstructured().
GeneratedMesh torus_unstructured_minval5(int level, std::uint64_t seed = 1);

}  // namespace curvbench
