// The `ellipsoid` family (docs/mesh_families.md): the ellipsoid with semi-axes 1, 0.8, 0.6,
// meshed by CGAL's Delaunay refinement as the well-shaped torus is (delaunay_surface_mesh.h:
// angle bound 30 degrees, radius bound rho_L, distance bound 0.1 rho_L, seeded, same bytes on
// every run), every vertex then moved to its exact closest point on the ellipsoid, triangles
// oriented outward. rho_L halves per level (kRadius in the .cpp), so V roughly quadruples.
// Exact points: the vertices. Surface: make_ellipsoid(1, 0.8, 0.6).
#pragma once

#include <cstdint>

#include "meshgen/generate.h"
#include "meshgen/generated_mesh.h"

namespace curvbench {

/// Semi-axes of the family's ellipsoid.
inline constexpr double kEllipsoidAxes[3] = {1.0, 0.8, 0.6};

/// Meshes level 1..4 (throws UsageError otherwise) anew.
GeneratedMesh ellipsoid_mesh(int level, std::uint64_t seed = 1);

/// The family generator of CURVBENCH_MESH_FAMILIES (generate.cpp). Each (level, seed) is meshed
/// once per process (generation_cache.h).
GeneratedMesh generate_ellipsoid(const MeshSpec& spec);

}  // namespace curvbench
