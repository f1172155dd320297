// The noise estimate (harness/model/noise_estimate.h) checked against known noise
// (docs/robustness.md, "The noise estimate"): every generated family at some levels, without
// noise and with normal Gaussian noise sigma = s h along the exact normal (meshgen/noise.h,
// order 1), the estimated sigma/h against the true s. `curvbench noise-check` writes the table.
//
// Tolerance. Noise and the floor add in quadrature: the estimate expected is
// hypot(s, floor), floor the estimate of the same mesh without noise (the discretisation floor:
// a degree-4 fit of a smooth surface leaves residuals that shrink like h^4, while the vertices of
// an isosurface, torus-iso, sit O(h^2) off the surface, sigma/h = 0.18 at level 1, 0.008 at
// level 2). A row is within when |estimate - expected| <= rel x expected + kNoiseEstimateAbsTol,
// rel = kNoiseEstimateRelTol from level 2 on (500 to 5600 vertices) and kNoiseEstimateCoarseRelTol
// at level 1 (144 to 1408 vertices: the median of few residuals, and a gain measured at level 2).
#pragma once

#include <cstdint>
#include <string>
#include <vector>

namespace curvbench {

inline constexpr double kNoiseEstimateRelTol = 0.15;
inline constexpr double kNoiseEstimateCoarseRelTol = 0.5;
inline constexpr double kNoiseEstimateAbsTol = 0.0005;

struct NoiseCheckSpec {
  std::vector<std::string>
      families;  ///< empty: every mesh family of mesh_family_table() (no point sets)
  std::vector<int> levels = {1, 2};  ///< levels above a family's largest are skipped
  std::vector<double> sigmas = {0.0, 0.001, 0.003, 0.01, 0.03, 0.1};  ///< true sigma/h; 0 first
  std::uint64_t seed = 1;
};

struct NoiseCheckRow {
  std::string family;
  int level = 0;
  int vertices = 0;
  double h = 0.0;           ///< mean edge length of the mesh without noise
  double true_sigma = 0.0;  ///< sigma/h added
  double estimated = 0.0;   ///< estimate_noise(...).sigma_over_h (NaN when it threw)
  double floor = 0.0;       ///< the estimate of the same mesh without noise
  int vertices_used = 0;
  int crease_vertices = 0;  ///< vertices left out on a sharp edge
  double expected = 0.0;    ///< hypot(true_sigma, floor)
  bool within = false;      ///< within the tolerance of the file comment
};

/// The table, in family (table order), level and sigma order. Deterministic: the noise is
/// seeded per mesh (add_noise with `seed`).
std::vector<NoiseCheckRow> noise_check(const NoiseCheckSpec& spec);

/// family,level,vertices,h,true_sigma_over_h,estimated_sigma_over_h,ratio,floor,expected,
/// vertices_used,crease_vertices,within (shortest round-trip numbers; ratio, estimated over true,
/// empty at sigma 0; within "yes" or "out").
std::string noise_check_csv(const std::vector<NoiseCheckRow>& rows);

/// One Markdown row per family and level: the estimates at each sigma of the table, then the
/// worst deviation from the expected estimate (percent) and whether every row is within the
/// tolerance.
std::string noise_check_markdown(const std::vector<NoiseCheckRow>& rows);

}  // namespace curvbench
