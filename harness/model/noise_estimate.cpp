#include "harness/model/noise_estimate.h"

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "core/errors.h"
#include "mesh/rings.h"
#include "methods/fits/polynomial_fit.h"
#include "methods/local_frame.h"

namespace curvbench {

namespace {

// Median of the dihedral angles of the manifold interior edges (each once), degrees; 0 for none.
double median_dihedral_angle(const Mesh& mesh) {
  std::vector<double> angles;
  for (int f = 0; f < mesh.num_faces(); ++f)
    for (int k = 0; k < 3; ++k)
      if (mesh.face_neighbor(f, k) > f) {
        const double a = dihedral_angle_deg(mesh, f, k);
        if (!std::isnan(a)) angles.push_back(a);
      }
  if (angles.empty()) return 0.0;
  auto mid = angles.begin() + static_cast<std::ptrdiff_t>(angles.size() / 2);
  std::nth_element(angles.begin(), mid, angles.end());
  return *mid;
}

}  // namespace

NoiseEstimate estimate_noise(const Mesh& mesh, double crease_angle) {
  constexpr int kDegree = 4;
  NoiseEstimate e;
  e.h = mesh.mean_edge_length();
  (void)detect_creases(mesh, crease_angle);  // throws UsageError for an angle out of range
  e.crease_angle = std::fmax(crease_angle, kCreaseOverMedianAngle * median_dihedral_angle(mesh));
  const Creases creases = e.crease_angle < 180.0 ? detect_creases(mesh, e.crease_angle) : Creases{};
  e.sharp_edges = creases.num_edges();
  RingCollector rings(mesh);
  FitSettings settings;
  settings.degree = kDegree;
  settings.include_constant = true;
  FitScratch scratch;
  // |height| of each vertex above its fit: away from creases, and next to one (a crease vertex
  // in the fit neighbourhood); crease vertices themselves are not fitted.
  std::vector<double> away, near;
  auto is_crease = [&](int v) {
    return !creases.is_vertex.empty() && creases.is_vertex[static_cast<size_t>(v)] != 0;
  };
  for (int v = 0; v < mesh.num_vertices(); ++v) {
    if (mesh.is_boundary_vertex(v)) continue;
    if (is_crease(v)) {
      ++e.crease_vertices;
      continue;
    }
    rings.collect_at_least(v, 2.0, min_neighbours(kDegree), 4.0);
    const auto nb = rings.neighbours();
    if (static_cast<int>(nb.size()) < min_neighbours(kDegree) ||
        static_cast<int>(nb.size()) > kMaxRows)
      continue;
    const Vec3 n = mesh.area_weighted_normal(v);
    if (!(n.norm() > 0)) continue;
    const LocalFrame frame = make_local_frame(n.normalized());
    const Vec3 p0 = mesh.position(v);
    const int m = static_cast<int>(nb.size());
    RowVector u(m), w(m), none;
    RhsMatrix f(m, 1);
    for (int i = 0; i < m; ++i) {
      const Vec3 d = mesh.position(nb[static_cast<size_t>(i)]) - p0;
      u(i) = d.dot(frame.t1);
      w(i) = d.dot(frame.t2);
      f(i, 0) = d.dot(frame.m);
    }
    const FitResult fit = fit_polynomial(u, w, f, none, settings, scratch);
    if (fit.degree < 2) continue;
    const double height = std::fabs(fit.taylor(kF, 0));  // the vertex is at height 0
    (std::any_of(nb.begin(), nb.end(), is_crease) ? near : away).push_back(height);
  }
  e.near_crease_vertices = static_cast<int>(near.size());
  std::vector<double>& heights = away.empty() ? near : away;
  e.creases_left_out = !away.empty();
  if (heights.empty())
    throw InputError("cannot estimate the noise: no interior vertex off the creases has " +
                     std::to_string(min_neighbours(kDegree)) + " neighbours within 4 rings");
  e.vertices_used = static_cast<int>(heights.size());
  auto mid = heights.begin() + static_cast<std::ptrdiff_t>(heights.size() / 2);
  std::nth_element(heights.begin(), mid, heights.end());
  e.sigma_over_h = 1.4826 * *mid / kNoiseResidualGain / e.h;
  e.sigma_over_h2 = e.sigma_over_h / e.h;
  return e;
}

double estimate_sigma_over_h(const Mesh& mesh) {
  return estimate_noise(mesh).sigma_over_h;
}

}  // namespace curvbench
