// The point-cloud families (docs/point_sets.md, "Point-cloud families"): the analytic surfaces
// sampled without connectivity, with the exact point of every sample (it lies on the surface).
//
// A family is points-<surface>-<sampling>:
//   surfaces  torus (R = 1, r = 0.3, the mesh families' torus), sphere (radius 1), ellipsoid
//             (semi-axes 1, 0.8, 0.6), bump (the Gaussian bump of paper §5.2 on [0, 1]^2)
//   sampling  uniform     independent points, uniform by area: (u, v) uniform on the parameter
//                         domain, kept with probability J(u, v) / J_max, J = |x_u x x_v|
//             blue        Poisson disk by dart throwing: uniform candidates, each kept unless a
//                         kept point lies closer than 0.7 h
//             anisotropic Poisson disk in the metric that stretches x four times, (4 dx, dy, dz):
//                         along x the points are 4x denser than across it
//             stripes     scan lines: uniform candidates kept within 2h/50 of the planes
//                         x = c + 2h j, so points are dense along each line (about h/2 apart) and
//                         the lines 2h apart
// with h = sqrt(A / n) the nominal spacing, A the surface's area. Level L has n = 1000 * 4^(L-1)
// points, so each level halves h as the mesh levels halve the edge length. The sample is a
// function of (family, level, seed) only.
#pragma once

#include <string>
#include <vector>

#include "meshgen/generate.h"
#include "meshgen/generated_mesh.h"

namespace curvbench {

/// Largest level of a point-cloud family (level 5: 256,000 points).
inline constexpr int kMaxPointLevel = 5;

/// Number of points at a level: 1000 * 4^(level-1).
int point_family_size(int level);

/// The point set of a points-<surface>-<sampling> family (spec.family, spec.level, spec.seed;
/// noise is added by generate_mesh). GeneratedMesh::spacing is the nominal h = sqrt(A / n).
/// Throws UsageError for a family name it does not know.
GeneratedMesh generate_point_family(const MeshSpec& spec);

/// The area of the surface of a point family (quadrature of the area element; exact for the
/// torus and the sphere to rounding).
double point_family_area(const std::string& family);

}  // namespace curvbench
