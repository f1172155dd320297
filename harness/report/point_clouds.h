// The point-cloud study's section (experiments with `report points`, docs/point_sets.md), from
// their errors CSVs:
//   - per experiment and measure (H L2, normals' RMS angle, H rectified), the rate table: one
//     row per estimator, one column per point-set series (sampling, surface, noise), each cell
//     the finest level's error and the average rate against the nominal spacing h;
//   - meshes and point sets side by side: the torus, the ellipsoid and the bump as Delaunay meshes
//     (the estimators' rings) and as uniform points (k nearest points), per estimator, the finest
//     level's error and rate of each, in normals and H.
#pragma once

#include <string>
#include <vector>

#include "harness/model/experiment.h"
#include "harness/report/model.h"

namespace curvbench {

/// The meshes and point sets the side-by-side table compares, each pair the same surface.
struct MeshAndPoints {
  const char* mesh;
  const char* points;
};
inline constexpr MeshAndPoints kSideBySide[] = {
    {"torus-unstructured", "points-torus-uniform"},
    {"ellipsoid", "points-ellipsoid-uniform"},
    {"bump-unstructured", "points-bump-uniform"},
};

/// Whether `family` is a point-cloud family of the family table (false for an unknown name).
bool is_point_set_family(const std::string& family);

/// The studies' section "point-cloud-study" (report/point-cloud-study.md; the experiments' own
/// pages are report/point-clouds.md and report/point-clouds-noise.md); a line saying so when no
/// experiment of the study has results in `results_dir`.
report::Section point_cloud_section(const std::vector<Experiment>& experiments,
                                    const std::string& results_dir);

/// REPORT.md's short form: the torus's rows of the side-by-side table and the H L2 rate table of
/// the study's first experiment, with a link to report/point-cloud-study.md; empty without
/// results.
report::Section point_cloud_summary(const std::vector<Experiment>& experiments,
                                    const std::string& results_dir);

}  // namespace curvbench
