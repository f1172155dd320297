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

double estimate_sigma_over_h(const Mesh& mesh) {
  constexpr int kDegree = 4;
  RingCollector rings(mesh);
  FitSettings settings;
  settings.degree = kDegree;
  settings.include_constant = true;
  FitScratch scratch;
  std::vector<double> heights;
  for (int v = 0; v < mesh.num_vertices(); ++v) {
    if (mesh.is_boundary_vertex(v)) continue;
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
    heights.push_back(std::fabs(fit.taylor(kF, 0)));  // the vertex is at height 0
  }
  if (heights.empty())
    throw InputError("recommend: cannot estimate the noise: no interior vertex has " +
                     std::to_string(min_neighbours(kDegree)) + " neighbours within 4 rings");
  auto mid = heights.begin() + static_cast<std::ptrdiff_t>(heights.size() / 2);
  std::nth_element(heights.begin(), mid, heights.end());
  return 1.4826 * *mid / kNoiseResidualGain / mesh.mean_edge_length();
}

}  // namespace curvbench
