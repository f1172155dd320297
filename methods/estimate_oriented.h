// The estimation path every front end uses on a user's mesh (command line, C++ API, Python):
// orient the faces consistently, closed parts outward (mesh/orientation.h), estimate every vertex
// (estimate_mesh), then mark the vertices whose sign cannot be determined (sign_undetermined).
// The experiment runner does not use it: generated meshes are oriented by construction.
#pragma once

#include <vector>

#include "mesh/mesh.h"
#include "mesh/orientation.h"
#include "methods/estimator.h"

namespace curvbench {

struct OrientedEstimate {
  OrientationResult orientation;          ///< the reoriented mesh and what was changed
  std::vector<VertexEstimate> estimates;  ///< one per vertex, in the input's numbering
};

/// Orients `mesh`, estimates with `estimator`, marks sign_undetermined vertices.
OrientedEstimate estimate_oriented(const Mesh& mesh, const Estimator& estimator);

}  // namespace curvbench
