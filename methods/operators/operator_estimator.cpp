// Common base of the degree-free discrete operators; see operator_estimator.h.
#include "methods/operators/operator_estimator.h"

#include <string>
#include <vector>

#include "core/errors.h"
#include "core/text.h"
#include "methods/operators/vertex_normals.h"
#include "methods/vertex_result.h"

namespace curvbench {

OperatorEstimator::OperatorEstimator(EstimatorOptions options, VertexNormals default_normals,
                                     bool ring_option, FittedNormals fitted)
    : Estimator(options), default_normals_(default_normals) {
  if (options_.degree != 0)
    throw UsageError("a discrete operator takes no degree (got " + std::to_string(options_.degree) +
                     ")");
  if (!ring_option && options_.rings != 0.0 && options_.rings != 1.0)
    throw UsageError("this method uses the 1-ring only (got ring " + format_g(options_.rings) +
                     ")");
  const std::string& fit = options_.vertex_normals.fit;
  if (fit.empty()) return;
  if (fitted == FittedNormals::refused)
    throw UsageError("vertex-normals " + fit +
                     ": a fit's normals apply to icc and normal-cycle only (this method takes "
                     "area, angle or max)");
  // The fit runs as the operator does (threads, kernel), and with its noisy input's ring.
  EstimatorOptions fit_options;
  fit_options.noisy = options_.noisy;
  fit_options.threads = options_.threads;
  fit_options.kernel = options_.kernel;
  normal_fit_ = make_estimator(fit, fit_options);
  if (!normal_fit_->takes_degree())
    throw UsageError("vertex-normals: '" + fit +
                     "' is not a fit (a fitted source is a fit's label such as lhf-3, jet-4)");
}

VertexNormals OperatorEstimator::normal_weighting() const {
  const VertexNormals w = options_.vertex_normals.weighting;
  return w == VertexNormals::method_default ? default_normals_ : w;
}

std::unique_ptr<Workspace> OperatorEstimator::make_workspace(const Mesh&) const {
  return std::make_unique<Workspace>();
}

void OperatorEstimator::fill_mesh_data(const Mesh& mesh, int threads,
                                       OperatorMeshData& data) const {
  if (normal_fit_ == nullptr) {
    // The area-weighted normals are MeshContext::approx_normals already.
    if (normal_weighting() != VertexNormals::area)
      data.normals = weighted_vertex_normals(mesh, normal_weighting(), threads);
    return;
  }
  // A fit's normals: turned to the side of the own normal, which stands in where there is none.
  data.normals = weighted_vertex_normals(mesh, normal_weighting(), threads);
  const std::vector<VertexEstimate> fitted = estimate_mesh(mesh, *normal_fit_);
  const int n = mesh.num_vertices();
  data.fallback.assign(static_cast<size_t>(n), 0);
  for (int v = 0; v < n; ++v) {
    const VertexEstimate& e = fitted[static_cast<size_t>(v)];
    const bool usable = e.status != VertexStatus::failed && e.status != VertexStatus::excluded &&
                        e.normal.allFinite() && e.normal.squaredNorm() > 0.0;
    if (!usable) {
      data.fallback[static_cast<size_t>(v)] = 1;
      continue;
    }
    const Vec3 own = data.normals.row(v).transpose();
    data.normals.row(v) = (own.dot(e.normal) < 0.0 ? Vec3(-e.normal) : e.normal).transpose();
  }
}

std::unique_ptr<MeshData> OperatorEstimator::prepare(const Mesh& mesh, const VertexMatrix&,
                                                     int threads) const {
  auto data = std::make_unique<OperatorMeshData>();
  fill_mesh_data(mesh, threads, *data);
  return data;
}

bool OperatorEstimator::interior_with_faces(const Mesh& mesh, int v, VertexEstimate& out) {
  if (mesh.vertex_faces(v).empty()) {
    set_failed(1.0, 0, out);
    return false;
  }
  if (mesh.is_boundary_vertex(v)) {
    set_excluded(1.0, 0, out);
    return false;
  }
  return true;
}

}  // namespace curvbench
