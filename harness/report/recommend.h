// "Choosing an estimator and a radius": recommendations from the radius sweeps,
// and the classification of a user's mesh that `curvbench recommend` matches against them.
//
// Table: per (mesh quality, noise sigma/h), from the radius sweeps' errors CSVs and their timings
// CSVs (results_table.h), ranked by the relative L2 error in the mean curvature H (the quantity
// the radius matters most for; the normals' best radius is usually the smallest):
//   - the most accurate method and radius: the smallest error of best_radii() (report/sweeps.h);
//     a tie goes to the faster, then to the first in the rows' order;
//   - the cheapest within 2x: of every case (method and radius) of the same mesh and noise with
//     error <= 2 x the best and a timing, the one of least seconds (a tie goes to the smaller
//     error, then to the first); a case without a timing is never the cheapest.
// Times join the errors by (experiment, family, level, method label): the timings CSV keeps one
// per case label and mesh level, the first noise level's (estimation time hardly depends on the
// noise). A (quality, noise) pair no sweep has rows for is "not swept". `curvbench recommend`
// reads this class table only when it finds no advice cases (the advice from mesh features and
// per quantity, harness/report/advice.h).
#pragma once

#include <string>
#include <vector>

#include "harness/model/noise_estimate.h"
#include "harness/model/results_table.h"
#include "harness/report/model.h"
#include "harness/report/sweeps.h"
#include "mesh/mesh.h"

namespace curvbench {

/// The quantity and norm the recommendations rank by.
inline constexpr const char* kRecommendQuantity = "H";
inline constexpr const char* kRecommendNorm = "L2";

/// The mesh quality classes, in table order: "well-shaped", "isosurface", "irregular".
const std::vector<std::string>& quality_classes();
/// The quality class a mesh family stands for ("" for a family that stands for none):
/// torus-unstructured well-shaped, torus-iso-projected isosurface, bump-irregular irregular.
std::string quality_of_family(const std::string& family);
/// The noise levels of the table (sigma/h along the normal): 0, 0.01, 0.03, 0.1.
const std::vector<double>& recommendation_noise_levels();
/// The level of recommendation_noise_levels() nearest to sigma_over_h (linear distance).
double nearest_noise_level(double sigma_over_h);

struct Recommendation {
  std::string quality;
  double sigma_over_h = 0.0;
  bool swept = false;  ///< false: no radius sweep has this mesh quality at this noise
  BestRadius best;     ///< the most accurate method at its best radius (label: the case)
  double best_seconds = std::numeric_limits<double>::quiet_NaN();
  bool has_cheapest = false;  ///< false when no case within 2x has a timing
  BestRadius cheapest;        ///< method, parameter, radius, label, error of the cheapest
  double cheapest_seconds = std::numeric_limits<double>::quiet_NaN();
  int cases = 0;  ///< cases (method and radius) compared
};

/// The table (quality_classes() x recommendation_noise_levels(), in that order) from the rows of
/// the radius sweeps and their timings. Rows of other families, noise models than normal
/// Gaussian, quantities or norms are ignored; when several (experiment, level) have rows for one
/// cell, the first in the rows' order is used.
std::vector<Recommendation> recommendations(const std::vector<ErrorRow>& rows,
                                            const std::vector<TimingRow>& timings);

/// Writes results/recommendations.csv (provenance comment, header, rows) atomically:
/// quality,sigma_over_h,status,experiment,family,level,vertices,h,noise,quantity,norm,cases,
/// best_method,best_parameter,best_radius,best_label,best_error,best_seconds,cheapest_method,
/// cheapest_parameter,cheapest_radius,cheapest_label,cheapest_error,cheapest_seconds
/// (status "swept" or "not swept"; the fields of a missing pick empty).
void write_recommendations_csv(const std::string& path, const std::vector<Recommendation>& recs);

/// The report's section "Choosing an estimator and a radius" (id "choosing"): its words and the
/// table of the picks, each cell with its number (error, seconds).
report::Section recommendations_section(const std::vector<Recommendation>& recs);

/// The quality class of a user's mesh from its triangle angles and valences (mesh_quality(),
/// meshgen/generate.h), with the reason in words. Throws InputError when the mesh cannot be
/// classified: fewer than kMinRecommendVertices vertices, or non-manifold edges or vertices.
struct MeshClass {
  std::string quality;
  std::string reason;
};
inline constexpr int kMinRecommendVertices = 50;
/// Thresholds (docs/cli.md, "curvbench recommend"; chosen between what the three families
/// measure): isosurface when at least this fraction of the triangle angles is below 10 degrees;
/// else well-shaped when the smallest angle is at least kWellShapedMinAngle degrees; else
/// irregular. The valences are reported in the reason, not used.
inline constexpr double kIsosurfaceSmallAngleFraction = 0.01;
inline constexpr double kWellShapedMinAngle = 20.0;
MeshClass classify_mesh(const Mesh& mesh);

}  // namespace curvbench
