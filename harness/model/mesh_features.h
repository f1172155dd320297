// What a mesh looks like to an estimator, measured on the mesh alone (docs/advice.md): the
// features `curvbench recommend` compares a user's mesh with the swept meshes by
// (harness/report/advice.h), and whose range it checks the mesh against.
//
//   small_angle_share        share of the triangle angles below 20 degrees (slivers, caps)
//   obtuse_angle_share       share above 100 degrees (caps, the lanterns' flat triangles)
//   irregular_valence_share  share of the interior vertices whose valence is not 6
//   anisotropy               the median over the interior vertices of sqrt(lambda1 / lambda2) of
//                            the edge tensor sum P e e^T P over the edges of its triangles (P:
//                            the projection onto the tangent plane of the area-weighted normal):
//                            the ratio of the principal edge directions' lengths; 1 for an
//                            equilateral grid, A for one stretched A times along a direction
//   density_ratio            the 90th over the 10th percentile of the vertices' mean edge length:
//                            how much the sampling density varies over the mesh
//   boundary_share           share of the vertices on the boundary
//   size_over_h              sqrt(area / 4 pi) / h: the mesh's size in edge lengths (a sphere's
//                            radius over h), the factor between sigma/h and the relative
//                            curvature error sigma / (h^2 |H|) for |H| ~ 1 / size (not a feature
//                            of the distance: it sets the noise level the curvature advice reads)
#pragma once

#include <string>
#include <vector>

#include "mesh/mesh.h"

namespace curvbench {

struct MeshFeatures {
  double small_angle_share = 0.0;
  double obtuse_angle_share = 0.0;
  double irregular_valence_share = 0.0;
  double anisotropy = 1.0;
  double density_ratio = 1.0;
  double boundary_share = 0.0;
  double size_over_h = 0.0;
};

inline constexpr double kSmallAngleDeg = 20.0;
inline constexpr double kObtuseAngleDeg = 100.0;

/// The features of `mesh` (file comment). Throws InputError for a mesh without faces.
MeshFeatures measure_mesh_features(const Mesh& mesh);

/// One feature of the distance between meshes: its name (a CSV column), how it reads in words,
/// the member, and whether the distance compares its logarithm (ratios >= 1) or its value
/// (shares).
struct FeatureInfo {
  const char* name;
  const char* words;
  double MeshFeatures::*field;
  bool logarithmic;
};
/// The features the advice compares meshes by, in CSV order (size_over_h is not one of them).
const std::vector<FeatureInfo>& advice_features();

/// A feature's coordinate in the distance: log(value) for a logarithmic one, the value else.
double feature_coordinate(const FeatureInfo& f, const MeshFeatures& m);

}  // namespace curvbench
