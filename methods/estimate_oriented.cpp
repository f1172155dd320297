#include "methods/estimate_oriented.h"

#include <algorithm>
#include <chrono>
#include <stdexcept>
#include <utility>

#include "methods/vertex_result.h"

namespace curvbench {

OrientedEstimate estimate_oriented(Mesh mesh, const Estimator& estimator) {
  OrientedEstimate r{orient_mesh(std::move(mesh)), {}};
  r.estimates = estimate_mesh(r.orientation.mesh, estimator);
  mark_sign_undetermined(r.orientation.sign_undetermined, r.estimates);
  return r;
}

OrientedRun estimate_oriented(Mesh mesh, const Estimator& estimator, int block,
                              const EstimateSink& sink) {
  if (block < 1) throw std::invalid_argument("estimate_oriented: block must be at least 1");
  using Clock = std::chrono::steady_clock;
  const auto seconds = [](Clock::time_point a, Clock::time_point b) {
    return std::chrono::duration<double>(b - a).count();
  };
  OrientedRun r{orient_mesh(std::move(mesh)), {}, 0.0, 0.0};
  const Mesh& oriented = r.orientation.mesh;
  const std::span<const unsigned char> undetermined = r.orientation.sign_undetermined;
  const auto t0 = Clock::now();
  MeshEstimation run(oriented, estimator);
  const int n = oriented.num_vertices();
  std::vector<VertexEstimate> estimates(static_cast<size_t>(std::min(block, n)));
  r.estimate_seconds += seconds(t0, Clock::now());  // the estimation's set-up and its buffer
  for (int first = 0; first < n; first += block) {
    const std::span<VertexEstimate> out =
        std::span(estimates).first(static_cast<size_t>(std::min(block, n - first)));
    const auto t1 = Clock::now();
    run.run(first, out);
    mark_sign_undetermined(undetermined.subspan(static_cast<size_t>(first), out.size()), out);
    for (const VertexEstimate& e : out) ++r.status_counts[static_cast<size_t>(e.status)];
    const auto t2 = Clock::now();
    sink(oriented, first, out);
    r.sink_seconds += seconds(t2, Clock::now());
    r.estimate_seconds += seconds(t1, t2);
  }
  return r;
}

}  // namespace curvbench
