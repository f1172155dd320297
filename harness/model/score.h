// Scoring per-vertex estimates made by any program against the exact quantities of a mesh
// written by `curvbench mesh`, with the error metrics of the harness (metrics.h, paper §5).
//
//   exact mesh   binary PLY of `curvbench mesh --output X.ply`: x y z, then the exact point
//                ex ey ez, exact normal nx ny nz, k1 k2 H K and (since this command scores
//                directions) d1x d1y d1z and umbilic per vertex
//   estimates    CSV with a header: a `vertex` column (0-based ids, each vertex exactly once)
//                and any subset of nx,ny,nz,k1,k2,H,K,d1x,d1y,d1z,d2x,d2y,d2z; other columns
//                (e.g. degree, points, status of `curvbench estimate`) are ignored. "nan" marks a
//                vertex the estimator could not do: it is counted as failed, not averaged.
//
// Quantities scored: normal (nx,ny,nz), H, K, k1, k2, d1 (d1x,d1y,d1z), each present one in
// L2 and Linf. d2 columns are accepted and not scored (the harness has no d2 metric; d2 follows
// from d1 and the normal).
#pragma once

#include <span>
#include <string>
#include <vector>

#include "harness/model/metrics.h"
#include "mesh/mesh.h"
#include "methods/estimator.h"
#include "surfaces/surface.h"

namespace curvbench {

/// A mesh with the exact quantities of its surface at each vertex.
struct ExactMesh {
  Mesh mesh;
  std::vector<SurfacePoint> exact;  ///< one per vertex (point left zero: not needed to score)
  bool has_directions = false;      ///< the file carries d1x d1y d1z (older files do not)
};

/// Reads a PLY written by `curvbench mesh`. Throws InputError naming the file when it cannot be
/// read as a mesh or lacks the exact quantities (e.g. a mesh from elsewhere).
ExactMesh read_exact_mesh(const std::string& path);

/// Per-vertex estimates read from a CSV; quantities absent from the file are NaN.
struct EstimateTable {
  std::vector<VertexEstimate> estimates;  ///< indexed by vertex id
  std::vector<Quantity> quantities;       ///< the quantities the file gives, in metric order
};

/// Reads an estimate CSV for a mesh of `num_vertices` vertices. Throws InputError (one line
/// "<path>:<line>: column '<name>': ...", or "<path>: ..." for file-level problems) on a missing
/// or unreadable file, no `vertex` column, no quantity column, an incomplete triple
/// (nx without ny, ...), a row count other than num_vertices, a duplicate or out-of-range vertex
/// id, or a cell that is not a number ("nan" and "inf" are numbers).
EstimateTable read_estimate_csv(const std::string& path, int num_vertices);

/// One quantity's errors over the vertex set.
struct QuantityScore {
  Quantity quantity = Quantity::normal;
  ErrorValue l2, linf;  ///< .excluded = vertices of the set whose estimate is NaN (failed)
};

struct ScoreResult {
  VertexSet vertex_set = VertexSet::all;
  int vertices_in_set = 0;
  std::vector<QuantityScore> scores;  ///< one per quantity, in `quantities` order
};

/// Errors of the estimates against the exact values over the vertex set (compute_error, the
/// harness's metric). d1 needs exact.has_directions; without it d1 is skipped.
ScoreResult score_estimates(const Mesh& mesh, std::span<const SurfacePoint> exact,
                            std::span<const VertexEstimate> estimates,
                            std::span<const Quantity> quantities, VertexSet set);

/// Reads both files and scores them: the whole of `curvbench score`.
ScoreResult score_files(const std::string& mesh_path, const std::string& estimates_path,
                        VertexSet set);

/// The result as a small JSON object (NaN as null).
std::string score_json(const ScoreResult& r, const std::string& mesh_path,
                       const std::string& estimates_path);

/// The result as a plain-text table, one line per quantity.
std::string score_text(const ScoreResult& r);

}  // namespace curvbench
