// Advice measured on the mesh itself (docs/advice.md, "Measured on the mesh"): which of a set of
// candidate estimators (the radius sweep's cases) has the least error on this mesh, judged without
// an exact answer, by splitting each candidate's error into the part the noise causes and the
// part its neighbourhood's smoothing causes (bias), both measured on the mesh.
//
// Per quantity q (the normals, absolute; the mean curvature H, relative to the reference's RMS,
// absolute where that is 0):
//   - the noise part: the mesh is perturbed `perturbations` times by normal Gaussian noise of the
//     mesh's own sigma (given or estimated; at least kMeasuredNoiseFloor h) along the normals of
//     the first rung of the reference ladder; V_c = the mean over perturbations of the mean
//     square change of candidate c's output. For an estimator that responds linearly to small
//     moves, that is the variance the mesh's own noise causes.
//   - the bias part: a reference r stands in for the exact answer. ||x_c - x_r||^2 estimates
//     ||b_c - b_r||^2 plus the variance of c - r, which the same perturbations measure (V_cr);
//     B_c(r) = max(0, ||x_c - x_r||^2 - V_cr).
//   - the reference: a rung of the ladder kMeasuredReferences (degree-4 fits on 2, 3 and 4
//     rings: the least bias among the sweep's cases on noise-free meshes, less noise as the ring
//     grows), the one of least B_r(first rung) + V_r: the smallest ring on a clean mesh, a wider
//     one where the noise dominates.
//   - the prediction: sqrt(B_c(r) + V_c); the choice, the least prediction (a tie: the first).
// It reads the mesh only: no exact answer and no swept mesh, so it needs no cross-validation to
// be fair to a mesh it never saw; the report scores it on the swept meshes against their exact
// answers all the same. Cost: every candidate runs 1 + `perturbations` times on the mesh.
#pragma once

#include <cstdint>
#include <limits>
#include <string>
#include <vector>

#include "harness/model/estimator_choice.h"
#include "mesh/mesh.h"

namespace curvbench {

/// The reference ladder, least biased first, and the least perturbation (sigma/h: a noise-free
/// mesh is perturbed this little, to measure each case's response without swamping its bias).
inline constexpr const char* kMeasuredReferences[] = {"LHF-4 rings=2", "LHF-4 rings=3",
                                                      "LHF-4 rings=4"};
inline constexpr double kMeasuredNoiseFloor = 1e-5;
inline constexpr int kMeasuredPerturbations = 2;

/// The quantities measured, in order: "normal", "H".
const std::vector<std::string>& measured_quantities();

struct MeasuredAdviceOptions {
  double sigma_over_h = 0.0;  ///< the mesh's noise along the normal (estimated or given), >= 0
  int perturbations = kMeasuredPerturbations;  ///< >= 1
  std::uint64_t seed = 1;                      ///< of the perturbations
  int threads = 0;                             ///< of each estimate (0: all cores)
  /// Vertices whose errors are not counted (crease vertices: no smooth-surface curvature
  /// there); they are still estimated and perturbed.
  std::vector<int> left_out;
};

struct MeasuredCase {
  std::string label;
  static constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
  double noise_part = kNaN;  ///< sqrt(V_c)
  double bias_part = kNaN;   ///< sqrt(B_c); 0 for the reference itself
  double predicted = kNaN;   ///< sqrt(B_c + V_c); +inf where the candidate gave no finite value
};

struct MeasuredQuantity {
  std::string quantity;
  /// The rung the bias parts are measured against ("": no rung finite, every prediction +inf).
  std::string reference;
  std::vector<MeasuredCase> cases;  ///< in the candidates' order
  int chosen = -1;                  ///< index of the least prediction (-1: none finite)
};

struct MeasuredAdvice {
  double h = 0.0;                            ///< the mesh's mean edge length
  double sigma_over_h = 0.0;                 ///< as given
  double perturbation_over_h = 0.0;          ///< max(sigma_over_h, kMeasuredNoiseFloor)
  int perturbations = 0;                     ///< as given
  std::vector<MeasuredQuantity> quantities;  ///< measured_quantities() order
};

/// Measures the candidates on `mesh`, whose faces must be oriented consistently (closed parts
/// outward): the runner's generated meshes are, a user's mesh after orient_mesh(). The
/// ladder's rungs run whether or not they are candidates. Deterministic for any thread count.
/// Throws UsageError for a negative or non-finite sigma, perturbations < 1, no candidate or a
/// vertex to leave out that the mesh lacks; InputError for a mesh without edges.
MeasuredAdvice measure_advice(const Mesh& mesh, const std::vector<EstimatorChoice>& candidates,
                              const MeasuredAdviceOptions& options);

}  // namespace curvbench
