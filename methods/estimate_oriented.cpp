#include "methods/estimate_oriented.h"

#include "methods/vertex_result.h"

namespace curvbench {

OrientedEstimate estimate_oriented(const Mesh& mesh, const Estimator& estimator) {
  OrientedEstimate r{orient_mesh(mesh), {}};
  r.estimates = estimate_mesh(r.orientation.mesh, estimator);
  mark_sign_undetermined(r.orientation.sign_undetermined, r.estimates);
  return r;
}

}  // namespace curvbench
