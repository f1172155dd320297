// Common base of the degree-free discrete operators; see operator_estimator.h.
#include "methods/operators/operator_estimator.h"

#include <string>

#include "core/errors.h"
#include "core/text.h"
#include "methods/operators/vertex_normals.h"
#include "methods/vertex_result.h"

namespace curvbench {

OperatorEstimator::OperatorEstimator(EstimatorOptions options, VertexNormals default_normals,
                                     bool ring_option)
    : Estimator(options), default_normals_(default_normals) {
  if (options_.degree != 0)
    throw UsageError("a discrete operator takes no degree (got " + std::to_string(options_.degree) +
                     ")");
  if (!ring_option && options_.rings != 0.0 && options_.rings != 1.0)
    throw UsageError("this method uses the 1-ring only (got ring " + format_g(options_.rings) +
                     ")");
}

VertexNormals OperatorEstimator::normal_weighting() const {
  return options_.vertex_normals == VertexNormals::method_default ? default_normals_
                                                                  : options_.vertex_normals;
}

std::unique_ptr<Workspace> OperatorEstimator::make_workspace(const Mesh&) const {
  return std::make_unique<Workspace>();
}

void OperatorEstimator::fill_mesh_data(const Mesh& mesh, int threads,
                                       OperatorMeshData& data) const {
  // The area-weighted normals are MeshContext::approx_normals already.
  if (normal_weighting() != VertexNormals::area)
    data.normals = weighted_vertex_normals(mesh, normal_weighting(), threads);
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
