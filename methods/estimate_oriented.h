// The estimation path every front end uses on a user's mesh (command line, C++ API, Python):
// orient the faces consistently, closed parts outward (mesh/orientation.h), estimate every vertex
// (MeshEstimation), then mark the vertices whose sign cannot be determined (sign_undetermined).
// The experiment runner does not use it: generated meshes are oriented by construction.
//
// Two forms: the whole vector of estimates (C++ API, Python), or blocks of `block` vertices handed
// to a sink in vertex order (the command line streams them to its output file), so that only one
// block of 144-byte records is held at a time. Both give the same estimates bit for bit for any
// block size and thread count.
#pragma once

#include <array>
#include <functional>
#include <span>
#include <vector>

#include "mesh/mesh.h"
#include "mesh/orientation.h"
#include "methods/estimator.h"

namespace curvbench {

struct OrientedEstimate {
  OrientationResult orientation;          ///< the reoriented mesh and what was changed
  std::vector<VertexEstimate> estimates;  ///< one per vertex, in the input's numbering
};

/// Orients `mesh` (moved in, reoriented in place: pass std::move(mesh) to avoid a copy),
/// estimates with `estimator`, marks sign_undetermined vertices.
OrientedEstimate estimate_oriented(Mesh mesh, const Estimator& estimator);

/// Receives the estimates of vertices [first, first + estimates.size()) of the oriented `mesh`, in
/// increasing `first`.
using EstimateSink =
    std::function<void(const Mesh& mesh, int first, std::span<const VertexEstimate> estimates)>;

/// What the block form returns besides the blocks.
struct OrientedRun {
  OrientationResult orientation;
  std::array<int, kVertexStatusCount> status_counts{};  ///< vertices per VertexStatus code
  double estimate_seconds = 0.0;       ///< wall time of the estimation (normals, neighbourhoods,
                                       ///< fits), without orientation and without the sink
  double sink_seconds = 0.0;           ///< wall time spent in `sink`
};

/// Default block: 64Ki vertices (9 MiB of estimates).
constexpr int kEstimateBlock = 1 << 16;

/// Orients `mesh` as above, then estimates `block` vertices at a time (block >= 1) and hands each
/// block, sign_undetermined marked, to `sink`.
OrientedRun estimate_oriented(Mesh mesh, const Estimator& estimator, int block,
                              const EstimateSink& sink);

}  // namespace curvbench
