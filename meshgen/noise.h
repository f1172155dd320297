// Controlled noise (docs/algorithms.md §10.3; paper §5.3). The paper's normal noise:
//   x_i <- x_i + alpha_i h^k n(x*_i),   alpha_i = scale * xi_i,
//   xi_i ~ N(0, 1) (NoiseDistribution::gaussian, the default), U[0, 1) (uniform: one-signed) or
//   U[-sqrt 3, sqrt 3) (uniform_centred: zero mean, unit variance, like N(0, 1)),
// with h = mesh_size(input) (the mean edge length, a point set's nominal spacing), k the noise
// order (2 or 3 in the paper; 1 for an amplitude sigma = scale * h), n the exact unit normal at the
// vertex's exact point x*_i (GeneratedMesh::exact_points), and xi_i drawn by Box-Muller
// (meshgen/random.h) from Rng(derive_seed(seed, 1000*level + k)), one value per vertex in index
// order. Every vertex is moved, boundary included. Other directions (NoiseModel::direction), with
// (t1, t2, n) an orthonormal frame at x*_i:
//   isotropic   x_i += a h^k (xi_n n + xi_1 t1 + xi_2 t2): three draws per vertex (n, t1, t2),
//               so the normal component has the law of the normal model;
//   tangential  y = project(x*_i + a h^k (xi_1 t1 + xi_2 t2)) (Surface::project), then
//               x_i += y - x*_i and the exact point becomes y: positions stay on the surface
//               (bad sampling without geometric noise), displacement tangent to first order.
// Outliers (NoiseModel::outlier_fraction p > 0; order, scale, distribution and direction unused):
//   round(p n) vertices, chosen by a partial Fisher-Yates shuffle from the same stream, each
//   moved by +-3h along n(x*_i) (sign drawn per outlier); the others stay.
// The paper's "alpha random between 0 and 0.1 with Gaussian distribution" is ambiguous; the
// model alpha = 0.1 * N(0,1) is the docs/algorithms.md default [CH] and curvbench's adopted
// reading; the others are NoiseModel values (docs/claims.md, "The noise model").
//
// Input/output: GeneratedMesh; the output has the same faces, exact_points (the unperturbed
// points, where exact quantities are evaluated; the moved ones for tangential noise), surface,
// family and level; the vertices (n x 3) are perturbed and the description records the model.
#pragma once

#include <cstdint>
#include <limits>
#include <string>

#include "meshgen/generated_mesh.h"

namespace curvbench {

enum class NoiseDistribution { gaussian, uniform, uniform_centred };
enum class NoiseDirection { normal, isotropic, tangential };

/// "gaussian", "uniform", "uniform-centred".
const char* to_string(NoiseDistribution d);
/// "normal", "isotropic", "tangential".
const char* to_string(NoiseDirection d);
/// Parses a to_string(NoiseDistribution) name; throws UsageError naming the valid ones.
NoiseDistribution parse_noise_distribution(const std::string& text);
/// Parses a to_string(NoiseDirection) name; throws UsageError naming the valid ones.
NoiseDirection parse_noise_direction(const std::string& text);

/// The noise model: the distribution of alpha (scale * xi), its direction, or outliers.
struct NoiseModel {
  NoiseDistribution distribution = NoiseDistribution::gaussian;
  double scale = 0.1;
  NoiseDirection direction = NoiseDirection::normal;
  double outlier_fraction = 0.0;  ///< p > 0: round(p n) vertices moved by 3h (the rest ignored)

  bool is_outliers() const { return outlier_fraction > 0.0; }
  bool is_default() const {
    return distribution == NoiseDistribution::gaussian && scale == 0.1 &&
           direction == NoiseDirection::normal && outlier_fraction == 0.0;
  }
  bool operator<(const NoiseModel& o) const {
    if (distribution != o.distribution) return distribution < o.distribution;
    if (scale != o.scale) return scale < o.scale;
    if (direction != o.direction) return direction < o.direction;
    return outlier_fraction < o.outlier_fraction;
  }
};

/// The one rule for noise orders: the order k of alpha h^k is 1..kMaxNoiseOrder (2 and 3 the
/// paper's, §5.3; 1 the sweeps' sigma h), 0 is no noise. Experiment files (`noise order=K`, a mesh
/// line's `noise-order=K`), `curvbench mesh --noise-order` and add_noise check it here.
inline constexpr int kMaxNoiseOrder = 4;
/// Throws UsageError "noise order K out of range (valid: 0 = none, 1..4)" unless
/// 0 <= k <= kMaxNoiseOrder.
void check_noise_order(int k);

/// Throws UsageError naming the option and value: a scale (sigma/h) that is negative or not
/// finite, an outlier fraction outside [0, 1].
void validate_noise_model(const NoiseModel& model);

/// The results' `noise` column for controlled noise of order k (k >= 1): "h^k" for the normal
/// direction at any order but 1 (the paper's labels); for order 1 "<direction> <gauss|uniform|
/// uniform01> <scale>h" (e.g. "normal gauss 0.03h", "tangential uniform 0.1h"; uniform01 is the
/// one-signed U[0,1)); other directions at order k "<direction> <dist> <scale>h^k"; outliers
/// "outliers <100 p>%" (e.g. "outliers 0.1%").
std::string noise_label(int k, const NoiseModel& model);

/// The noise of a results row as numbers: for order-1 noise (the sweeps' sigma h) its model
/// ("<direction> <distribution>", e.g. "normal gauss") and sigma/h; no noise is sigma/h 0 with
/// no model; any other noise (h^k, outliers, an isosurface's own) has no model and sigma/h NaN.
struct NoiseLevel {
  std::string model;
  double sigma_over_h = std::numeric_limits<double>::quiet_NaN();
  bool operator==(const NoiseLevel& o) const {
    return model == o.model && (sigma_over_h == o.sigma_over_h ||
                                (sigma_over_h != sigma_over_h && o.sigma_over_h != o.sigma_over_h));
  }
};
/// The level of noise of order k (0: none) under a model, as the runner knows it.
NoiseLevel noise_level(int k, const NoiseModel& model);
/// The level a `noise` column says (noise_label's text, or a family's own label: "none",
/// "isosurface"): parse_noise_label(noise_label(k, m)) == noise_level(k, m). Results read from a
/// CSV are typed by it, once, where they are read.
NoiseLevel parse_noise_label(const std::string& label);

/// Throws UsageError if k is not an order of noise (check_noise_order; 0 adds none) or the model
/// is invalid (validate_noise_model).
GeneratedMesh add_noise(const GeneratedMesh& input, int k, std::uint64_t seed,
                        const NoiseModel& model = {});

}  // namespace curvbench
