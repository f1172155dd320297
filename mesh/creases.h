// Sharp edges (creases) of a triangle mesh, by the dihedral angle across each edge
// (docs/robustness.md, "Creases"). CAD meshes (fandisk, a meshed cube) are piecewise smooth:
// along a crease the surface has no tangent plane, and a fit across it reads the corner as
// noise or as huge curvature.
//
//   creases = detect_creases(mesh, threshold_deg)
//
// Inputs:
//   mesh           n vertices, m triangles
//   threshold_deg  an edge is sharp when the angle between the unit normals of its two faces
//                  exceeds this, in degrees, in (0, 180); default kDefaultCreaseAngle
// Outputs (Creases):
//   edges          the sharp edges as vertex pairs {a, b}, a < b, sorted
//   vertices       the crease vertices (an endpoint of a sharp edge), sorted
//   is_vertex      n flags: 1 for a crease vertex
//
// The angle is atan2(|n1 x n2|, n1 . n2) of the faces' unit normals (0 for a flat pair, 90 for a
// cube's edge), with the second normal reversed when the two faces run the edge the same way
// (an inconsistently oriented pair), so the answer does not depend on the orientation. Only
// manifold interior edges (exactly two faces) are examined: boundary and non-manifold edges are
// never sharp, nor is an edge of a zero-area face (no normal; mesh/mesh_checks.h). O(m).
#pragma once

#include <array>
#include <vector>

#include "mesh/mesh.h"

namespace curvbench {

/// The default threshold, 60 degrees between face normals. A smooth surface sampled at edge
/// length h turns its face normals by about kappa h across an edge: the generated smooth families
/// stay below it at their coarsest levels but for two faceted by construction (the anisotropic
/// bump's level 1 with its stretched triangles and the squeezed lantern, 64 degrees between
/// slices), while a cube's edges (90 degrees) and most of fandisk's creases (70 to 100) are far
/// above it. Shallower features (fandisk has a family at 20 to 25 degrees) need a smaller
/// threshold: `curvbench info --crease-angle`.
inline constexpr double kDefaultCreaseAngle = 60.0;

struct Creases {
  double threshold_deg = kDefaultCreaseAngle;
  std::vector<std::array<int, 2>> edges;  ///< sharp edges {a, b}, a < b, sorted
  std::vector<int> vertices;              ///< crease vertices, sorted
  std::vector<unsigned char> is_vertex;   ///< n flags: 1 on a sharp edge
  int num_edges() const { return static_cast<int>(edges.size()); }
  int num_vertices() const { return static_cast<int>(vertices.size()); }
};

/// The sharp edges and crease vertices of `mesh` (see the file comment). Throws UsageError when
/// threshold_deg is not in (0, 180).
Creases detect_creases(const Mesh& mesh, double threshold_deg = kDefaultCreaseAngle);

/// The angle in degrees between the unit normals of the two faces of edge k of face f (see the
/// file comment); NaN for an edge that is not manifold interior or touches a zero-area face.
double dihedral_angle_deg(const Mesh& mesh, int f, int k);

}  // namespace curvbench
