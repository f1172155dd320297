#include "meshgen/noise.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <numeric>
#include <string>
#include <vector>

#include "core/errors.h"
#include "meshgen/random.h"

namespace curvbench {

namespace {

std::string g(double x) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%g", x);
  return buf;
}

// The word of a distribution in a noise label.
const char* label_word(NoiseDistribution d) {
  switch (d) {
    case NoiseDistribution::uniform:
      return "uniform01";
    case NoiseDistribution::uniform_centred:
      return "uniform";
    default:
      return "gauss";
  }
}

// An orthonormal tangent pair (t1, t2) with (t1, t2, n) right-handed, from the axis least
// aligned with n (deterministic).
void tangent_frame(const Vec3& n, Vec3& t1, Vec3& t2) {
  Eigen::Index axis;
  n.cwiseAbs().minCoeff(&axis);
  t1 = Vec3::Unit(axis).cross(n).normalized();
  t2 = n.cross(t1);
}

}  // namespace

const char* to_string(NoiseDistribution d) {
  switch (d) {
    case NoiseDistribution::uniform:
      return "uniform";
    case NoiseDistribution::uniform_centred:
      return "uniform-centred";
    default:
      return "gaussian";
  }
}

const char* to_string(NoiseDirection d) {
  switch (d) {
    case NoiseDirection::isotropic:
      return "isotropic";
    case NoiseDirection::tangential:
      return "tangential";
    default:
      return "normal";
  }
}

NoiseDistribution parse_noise_distribution(const std::string& text) {
  for (auto d : {NoiseDistribution::gaussian, NoiseDistribution::uniform,
                 NoiseDistribution::uniform_centred})
    if (text == to_string(d)) return d;
  throw UsageError("noise distribution '" + text +
                   "' is not one of gaussian, uniform, uniform-centred");
}

NoiseDirection parse_noise_direction(const std::string& text) {
  for (auto d : {NoiseDirection::normal, NoiseDirection::isotropic, NoiseDirection::tangential})
    if (text == to_string(d)) return d;
  throw UsageError("noise model '" + text + "' is not one of normal, isotropic, tangential");
}

void validate_noise_model(const NoiseModel& model) {
  if (!std::isfinite(model.scale) || model.scale < 0)
    throw UsageError("noise scale (sigma/h) " + g(model.scale) + " must be finite and >= 0");
  if (!(model.outlier_fraction >= 0.0 && model.outlier_fraction <= 1.0))
    throw UsageError("outlier fraction " + g(model.outlier_fraction) + " is outside [0, 1]");
}

std::string noise_label(int k, const NoiseModel& model) {
  char buf[96];
  if (model.is_outliers()) {
    std::snprintf(buf, sizeof buf, "outliers %g%%", 100.0 * model.outlier_fraction);
  } else if (model.direction == NoiseDirection::normal && k != 1) {
    std::snprintf(buf, sizeof buf, "h^%d", k);
  } else {
    std::snprintf(buf, sizeof buf, k == 1 ? "%s %s %gh" : "%s %s %gh^%d",
                  to_string(model.direction), label_word(model.distribution), model.scale, k);
  }
  return buf;
}

NoiseLevel noise_level(int k, const NoiseModel& model) {
  if (k == 0) return {"", 0.0};
  if (k != 1 || model.is_outliers()) return {};
  return {std::string(to_string(model.direction)) + " " + label_word(model.distribution),
          model.scale};
}

NoiseLevel parse_noise_label(const std::string& label) {
  if (label == "none") return {"", 0.0};
  // "<direction> <distribution> <scale>h": order 1 only (order k ends "h^k").
  const size_t space = label.rfind(' ');
  if (space == std::string::npos || label.back() != 'h') return {};
  const std::string model = label.substr(0, space);
  bool known = false;
  for (auto d : {NoiseDirection::normal, NoiseDirection::isotropic, NoiseDirection::tangential})
    for (auto w : {NoiseDistribution::gaussian, NoiseDistribution::uniform,
                   NoiseDistribution::uniform_centred})
      known = known || model == std::string(to_string(d)) + " " + label_word(w);
  const std::string value = label.substr(space + 1, label.size() - space - 2);
  char* end = nullptr;
  const double x = std::strtod(value.c_str(), &end);
  if (!known || value.empty() || *end != '\0' || !std::isfinite(x)) return {};
  return {model, x};
}

void check_noise_order(int k) {
  if (k < 0 || k > kMaxNoiseOrder)
    throw UsageError("noise order " + std::to_string(k) + " out of range (valid: 0 = none, 1.." +
                     std::to_string(kMaxNoiseOrder) + ")");
}

GeneratedMesh add_noise(const GeneratedMesh& input, int k, std::uint64_t seed,
                        const NoiseModel& model) {
  check_noise_order(k);
  if (k == 0) throw UsageError("add_noise: noise order 0 adds no noise");
  validate_noise_model(model);
  if (!input.surface || input.exact_points.rows() != input.mesh.num_vertices())
    throw UsageError("add_noise: mesh without surface or exact points");

  const double h = mesh_size(input);
  Rng rng(derive_seed(
      seed, 1000 * static_cast<std::uint64_t>(input.level) + static_cast<std::uint64_t>(k)));
  VertexMatrix V = input.mesh.vertices();
  VertexMatrix exact = input.exact_points;
  const auto normal_at = [&](Eigen::Index i) {
    return input.surface->evaluate(input.exact_points.row(i).transpose()).normal;
  };
  char buf[200];
  if (model.is_outliers()) {
    const auto n = static_cast<size_t>(V.rows());
    const auto count = static_cast<size_t>(std::llround(model.outlier_fraction * n));
    std::vector<size_t> order(n);
    std::iota(order.begin(), order.end(), size_t{0});
    for (size_t j = 0; j < count; ++j) {
      // Partial Fisher-Yates: order[j] is drawn uniformly from the indices not yet chosen.
      const size_t pick = j + std::min(n - j - 1, static_cast<size_t>(rng.uniform01() * (n - j)));
      std::swap(order[j], order[pick]);
      const double sign = rng.uniform01() < 0.5 ? -1.0 : 1.0;
      const auto i = static_cast<Eigen::Index>(order[j]);
      V.row(i) += (sign * 3.0 * h) * normal_at(i).transpose();
    }
    std::snprintf(buf, sizeof buf,
                  "; outliers: %zu of %zu vertices (p=%g) moved by 3h, h=%.6g, "
                  "seed=%llu",
                  count, n, model.outlier_fraction, h, static_cast<unsigned long long>(seed));
  } else {
    const double amplitude = model.scale * std::pow(h, k);  // eq. of §10.3: alpha_i h^k
    const auto draw = [&] {
      switch (model.distribution) {
        case NoiseDistribution::uniform:
          return rng.uniform01();
        case NoiseDistribution::uniform_centred:
          return std::sqrt(3.0) * (2.0 * rng.uniform01() - 1.0);
        default:
          return rng.normal();
      }
    };
    for (Eigen::Index i = 0; i < V.rows(); ++i) {
      const Vec3 n = normal_at(i);
      if (model.direction == NoiseDirection::normal) {
        V.row(i) += (amplitude * draw()) * n.transpose();
        continue;
      }
      Vec3 t1, t2;
      tangent_frame(n, t1, t2);
      if (model.direction == NoiseDirection::isotropic) {
        const double xn = draw(), x1 = draw(), x2 = draw();
        V.row(i) += amplitude * (xn * n + x1 * t1 + x2 * t2).transpose();
      } else {  // tangential: stay on the surface; the exact point moves with the vertex
        const double x1 = draw(), x2 = draw();
        if (amplitude == 0.0) continue;  // sigma = 0: no noise (project() would round)
        const Vec3 from = input.exact_points.row(i).transpose();
        const Vec3 to = input.surface->project(from + amplitude * (x1 * t1 + x2 * t2));
        V.row(i) += (to - from).transpose();
        exact.row(i) = to.transpose();
      }
    }
    std::snprintf(buf, sizeof buf, "; %s noise alpha*h^%d with alpha=%g*%s, h=%.6g, seed=%llu",
                  to_string(model.direction), k, model.scale,
                  model.distribution == NoiseDistribution::uniform ? "U[0,1)"
                  : model.distribution == NoiseDistribution::uniform_centred
                      ? "U[-sqrt3,sqrt3)"
                      : "N(0,1) (Box-Muller)",
                  h, static_cast<unsigned long long>(seed));
  }

  GeneratedMesh out;
  out.mesh = Mesh(std::move(V), input.mesh.faces(), input.family + " (noisy)");
  out.exact_points = std::move(exact);
  out.surface = input.surface;
  out.family = input.family;
  out.level = input.level;
  out.description = input.description + buf;
  out.spacing = input.spacing;  // a point set keeps its nominal spacing
  return out;
}

}  // namespace curvbench
