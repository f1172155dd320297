// Consistent face orientation before estimating (docs/robustness.md): meshes from scanners and polygon
// soups often have faces that run their shared edges the same way, and every estimator takes its
// sign from the face orientation (sign convention: outward normals of a closed surface).
//
//   mesh  n x 3 vertices, m x 3 faces, any orientation
//
// Patches: faces joined across manifold edges (exactly two incident faces). Each patch is walked
// breadth-first from its lowest face, each face taking the orientation that runs the shared edge
// opposite to the face it was reached from. Then, per patch:
//   closed (no boundary or non-manifold edge) and orientable: oriented so that its signed volume
//     (divergence theorem) is positive, i.e. outward. A closed surface nested inside another
//     (a cavity) is also made outward of its own volume.
//   open and orientable: of the two consistent orientations, the one that keeps more of the
//     input faces (ties: the input orientation of the patch's lowest face).
//   non-orientable (the walk meets an edge already run the same way: a Möbius strip, a Klein
//     bottle): kept as the walk left it (consistent except along a seam, the locally consistent
//     patches either side of it), and every vertex of the patch marked sign_undetermined.
// Vertices on a non-manifold edge or shared by several patches (a non-manifold vertex) are
// marked sign_undetermined as well: their faces have no common orientation.
// Only the order of a face's corners changes: reversed where the face is flipped, and rotated so
// that the smallest vertex index comes first (so that a mesh and any reoriented copy of it give
// the same face rows, hence bit-identical estimates). Vertices and face order are kept: vertex
// and face numbering is the input's.
#pragma once

#include <string>
#include <vector>

#include "mesh/mesh.h"

namespace curvbench {

struct OrientationResult {
  Mesh mesh;               ///< the input with faces reoriented
  int faces_flipped = 0;   ///< faces whose corner order was reversed
  int patches = 0;         ///< manifold-connected face patches
  int closed_patches = 0;  ///< of which closed and orientable (oriented outward)
  int nonorientable_patches = 0;
  int vertices_undetermined = 0;  ///< vertices with sign_undetermined set
  /// Per vertex (n): 1 if the sign of its normal and curvatures is not determined.
  std::vector<unsigned char> sign_undetermined;
};

/// Orients every patch of `mesh` as described in the file comment. O(n + m). The mesh is moved
/// into the result and its faces reoriented in place (Mesh::reorient_faces): no copy, and none
/// of its arrays is touched when it is already consistently oriented, closed parts outward,
/// every face starting at its smallest vertex index.
OrientationResult orient_mesh(Mesh&& mesh);

/// The same on a copy of `mesh`.
OrientationResult orient_mesh(const Mesh& mesh);

/// One-line warnings for a user (empty when the input was consistently oriented outward and
/// orientable): faces flipped, and vertices whose sign is undetermined.
std::vector<std::string> orientation_warnings(const OrientationResult& result);

}  // namespace curvbench
