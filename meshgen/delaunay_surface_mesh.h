// CGAL's Delaunay-refinement surface mesher on an implicit surface, shared by the well-shaped
// families (torus-unstructured, ellipsoid; docs/mesh_families.md).
//
// Surface_mesher's make_surface_mesh with Surface_mesh_default_criteria_3 (angle bound 30
// degrees, surface Delaunay ball radius bound rho, centre-to-surface distance bound 0.1 rho,
// manifold output) on the implicit function inside a ball about the origin. The mesher's
// initial points come from CGAL's default random generator, reseeded with `seed` right before
// meshing, and the triangulation's vertices and cells carry creation stamps so that CGAL orders
// them by creation instead of by address: the mesh is the same bytes on every run, whatever the
// process did before. Every vertex is then moved to its exact closest point
// (surface->project), each triangle is oriented so that its normal agrees with the surface
// normal at its centroid, and the vertices are renumbered along a Z-order curve of two angles
// of the point (neighbours get nearby numbers), the faces sorted by their smallest vertex.
#pragma once

#include <array>
#include <cstdint>
#include <string>

#include "meshgen/generated_mesh.h"

namespace curvbench {

struct ImplicitMeshing {
  double (*implicit)(double x, double y, double z) = nullptr;  ///< < 0 inside, 0 on the surface
  double bounding_radius = 2.0;  ///< a ball about the origin that contains the surface
  double radius_bound = 0.1;     ///< rho of the criteria
  SurfacePtr surface;            ///< projects the vertices and orients the faces
  /// Two angles in [-pi, pi] of a surface point, for the Z-order numbering.
  std::array<double, 2> (*angles)(const Vec3& p) = nullptr;
  std::uint64_t seed = 1;
  std::string name;  ///< the mesh's name and family ("torus-unstructured")
  int level = 1;
  /// For the description: the surface ("torus R=1 r=0.3") and what the vertices are projected
  /// to ("the torus").
  std::string surface_words, projected_to;
};

/// The mesh, with exact_points == vertices, surface, family (spec.name), level and the
/// description "<name> level L: <surface_words>, CGAL surface mesher (angle 30 deg, radius rho,
/// distance 0.1 rho), vertices projected to <projected_to>, seed=S".
GeneratedMesh delaunay_surface_mesh(const ImplicitMeshing& spec);

}  // namespace curvbench
