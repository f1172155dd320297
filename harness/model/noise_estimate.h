// The noise of a mesh estimated from the mesh alone (`curvbench recommend`, `curvbench info`,
// harness/report/recommend_table.h; docs/robustness.md, "The noise estimate"): the spread of the
// vertices about a local polynomial fit to their neighbours, in units of the mean edge length h.
//
// Per interior vertex, the height of the vertex above the degree-4 polynomial fitted (unweighted
// least squares with a constant term, the fitting routine of LHF-4) to its neighbours' heights,
// ring 2 grown to at least 23 neighbours, in the frame of its area-weighted normal; sigma =
// 1.4826 x median |height| / kNoiseResidualGain (a robust deviation; the gain, the ratio of that
// deviation to the true sigma measured on the well-shaped torus, level 2, at sigma/h = 0.01, 0.03
// and 0.1, accounts for the noise of the fitted surface itself).
//
// Creases (mesh/creases.h) are not noise: a fit across a sharp edge leaves residuals of the order
// of the edge's turn times h (without this rule CGAL's meshed cube reads sigma/h = 0.02, fandisk
// 0.006). Left out are the crease vertices and every vertex whose fit neighbourhood holds one,
// so that only fits over a smooth patch count; when no vertex is left, the vertices next to
// creases are used after all. An edge counts as a crease here when its dihedral angle exceeds
// both the crease angle and kCreaseOverMedianAngle times the median dihedral angle of the mesh:
// noise turns face normals too, and a crease is an edge that stands out of the mesh's own angles.
// Noise-free CAD meshes have a median near 0 (the crease angle decides); at sigma = 0.1 h the
// generated creased meshes (tests/mesh/crease_test_meshes.h) have a median of about 16 degrees
// and their 90-degree creases stand 5.7 times above it, while a noisy smooth mesh's largest
// angles reach 4 to 10 times its median: some of its edges count as creases, which leaves out up
// to 70% of its vertices (torus-iso, level 2, sigma = 0.1 h) but moved no estimate of the table
// of docs/robustness.md by more than 6%.
#pragma once

#include "mesh/creases.h"
#include "mesh/mesh.h"

namespace curvbench {

inline constexpr double kNoiseResidualGain = 1.22;
/// See the file comment: below the 5.7 of the creased test meshes at sigma = 0.1 h.
inline constexpr double kCreaseOverMedianAngle = 5.0;

struct NoiseEstimate {
  double sigma_over_h = 0.0;
  /// sigma / h^2 (units 1/length, like a curvature): the scale of the curvature error the noise
  /// causes (a fit's second derivatives amplify heights by 1/h^2), where sigma/h is that of the
  /// normals' error.
  double sigma_over_h2 = 0.0;
  double h = 0.0;                ///< the mean edge length
  int vertices_used = 0;         ///< vertices whose fit residual counted
  int crease_vertices = 0;       ///< left out: on a sharp edge
  int near_crease_vertices = 0;  ///< left out: a crease vertex in the fit neighbourhood
  bool creases_left_out = true;  ///< false: no vertex was off the creases, the near ones counted
  int sharp_edges = 0;           ///< at crease_angle
  /// The angle the creases were taken at: max(the crease angle given, kCreaseOverMedianAngle x
  /// the median dihedral angle), degrees; at 180 or more no edge is a crease.
  double crease_angle = kDefaultCreaseAngle;
};

/// The estimate (file comment), leaving out the creases found at `crease_angle` degrees. Throws
/// InputError when no vertex has enough neighbours away from the creases, UsageError for a
/// crease angle outside (0, 180).
NoiseEstimate estimate_noise(const Mesh& mesh, double crease_angle = kDefaultCreaseAngle);

/// estimate_noise(mesh).sigma_over_h.
double estimate_sigma_over_h(const Mesh& mesh);

}  // namespace curvbench
