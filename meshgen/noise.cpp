#include "meshgen/noise.h"

#include <cmath>
#include <cstdio>
#include <string>

#include "core/errors.h"
#include "meshgen/random.h"

namespace curvbench {

const char* to_string(NoiseDistribution d) {
  return d == NoiseDistribution::uniform ? "uniform" : "gaussian";
}

NoiseDistribution parse_noise_distribution(const std::string& text) {
  if (text == "gaussian") return NoiseDistribution::gaussian;
  if (text == "uniform") return NoiseDistribution::uniform;
  throw UsageError("noise distribution '" + text + "' is not one of gaussian, uniform");
}

GeneratedMesh add_normal_noise(const GeneratedMesh& input, int k, std::uint64_t seed,
                               const NoiseModel& model) {
  const double alpha_scale = model.scale;
  const bool uniform = model.distribution == NoiseDistribution::uniform;
  if (k < 1) throw UsageError("noise order " + std::to_string(k) + " must be >= 1");
  if (!std::isfinite(alpha_scale) || alpha_scale < 0)
    throw UsageError("noise alpha scale must be finite and >= 0");
  if (!input.surface || input.exact_points.rows() != input.mesh.num_vertices())
    throw UsageError("add_normal_noise: mesh without surface or exact points");

  const double h = input.mesh.mean_edge_length();
  const double amplitude = alpha_scale * std::pow(h, k);  // eq. of §10.3: alpha_i h^k
  Rng rng(derive_seed(
      seed, 1000 * static_cast<std::uint64_t>(input.level) + static_cast<std::uint64_t>(k)));
  VertexMatrix V = input.mesh.vertices();
  for (Eigen::Index i = 0; i < V.rows(); ++i) {
    const Vec3 n = input.surface->evaluate(input.exact_points.row(i).transpose()).normal;
    const double xi = uniform ? rng.uniform01() : rng.normal();
    V.row(i) += (amplitude * xi) * n.transpose();
  }

  GeneratedMesh out;
  out.mesh = Mesh(std::move(V), input.mesh.faces(), input.family + " (noisy)");
  out.exact_points = input.exact_points;
  out.surface = input.surface;
  out.family = input.family;
  out.level = input.level;
  char buf[200];
  std::snprintf(buf, sizeof buf, "; normal noise alpha*h^%d with alpha=%g*%s, h=%.6g, seed=%llu", k,
                alpha_scale, uniform ? "U[0,1)" : "N(0,1) (Box-Muller)", h,
                static_cast<unsigned long long>(seed));
  out.description = input.description + buf;
  return out;
}

}  // namespace curvbench
