// The shared per-vertex driver of the ring-based fitting methods (docs/algorithms.md §5.5):
// LHF-d, LOP-d and (through the parameterization hook) LSCM-d.
//
// Per vertex v (approximate normal m0 = area-weighted normal, frame of §3):
//   r0 = options().rings, or default_ring() = (d+1)/2 (+0.5 when noisy)
//   adaptive:     ring = collect_at_least(v, r0, min_neighbours(d), 2 r0)   (point-count rule)
//   non-adaptive: ring = collect(v, r0)
//   loop:
//     uv  = parameterize(ring)                       hook; default: projection onto (t1, t2)
//     rows: the centre (if options().include_centre, gamma = 1) then the ring neighbours in
//           discovery order; gamma_i = max(0, m_i . m0) if use_normal_safeguard() else 1;
//           rows with gamma_i <= 0 or non-finite (u, v) are dropped; at most kMaxRows rows
//     data: height route     f_i = (p_i - p0) . m0                        (1 RHS, LHF)
//           parametric route x_i - p0                                     (3 RHS, LOP, LSCM)
//     weights eq. (15), safeguarded QR (polynomial_fit.h)  ->  d_used
//     adaptive and d_used < d and ring < 2 r0 and the ring can grow: ring += 0.5, repeat
//   quantities (core/shape_operator.h): height route curvature_from_height(t1, t2, m0, f_u, ...),
//   parametric route curvature_from_parametric(x_u, x_v, x_uu, x_uv, x_vv).
// Status: ok (d_used = d), disk_cut (d_used = d, but the hook left some ring vertices without a
// finite (u, v): e.g. the LSCM disk cut of a ring that is not a disk), degree_reduced (1 <= d_used
// < d, with or without a cut), failed (d_used = 0, the hook failed, or non-finite quantities):
// values NaN (vertex_result.h).
// Exceptions are caught by estimate_mesh (the vertex is failed).
//
// ---- Extension point (LSCM and any other ring parameterization) -------------------------------
// Derive from RingFitEstimator, pass FitRoute::parametric to the constructor, and override
//
//   bool parameterize(const RingView& ring, std::vector<Vec2>& uv,
//                     ParamScratch* scratch) const override;
//
//   in:  ring.mesh, ring.approx_normals   the mesh and its area-weighted normals
//        ring.centre                      the vertex v being estimated
//        ring.neighbours                  RingCollector::neighbours(): V_r \ {v}, discovery order
//        ring.faces                       RingCollector::faces(): the ring faces F_r
//        ring.ring                        the ring r actually collected (after adaptive growth)
//        ring.frame                       the §3 frame (t1, t2, m0) of the approximate normal
//        scratch                          the object this estimator's make_param_scratch()
//                                         returned for the calling thread (nullptr by default)
//   out: uv resized to N = 1 + ring.neighbours.size(); uv[0] = centre, uv[i] = neighbours[i-1].
//        The driver translates uv[0] to (0, 0). The map must preserve orientation: (u, v)
//        counter-clockwise seen from the outward/upward side (flip v -> -v if the mapped patch
//        has negative signed area), so that x_u x x_v points outward. A non-finite uv[i] drops
//        that row, and the vertex's status then says disk_cut (the map covers only part of the
//        ring's vertices, e.g. the LSCM disk cut).
//   return false if no parameterization exists (e.g. no disk around the centre): the vertex is
//        then reported as failed (or, in the adaptive rank-failure loop, the previous fit is
//        kept if there was one).
//   It is called once per fit attempt (several times when the ring grows), from several threads
//   at once (const; keep all mutable state in the scratch object). If it throws, the vertex is
//   reported as failed (estimate_mesh).
//
// Optional overrides:
//   std::unique_ptr<ParamScratch> make_param_scratch(const Mesh&) const
//       per-thread state for parameterize() (e.g. an LscmMap); called once per thread before
//       the parallel loop, may allocate and throw.
//   bool use_normal_safeguard() const
//       whether gamma_i = max(0, m_i . m0) of eq. (15) multiplies the weights; the default is
//       options().normal_safeguard (LHF/LOP); docs/algorithms.md §4 recommends gamma = 1 for LSCM.
// Everything else (rings, rows, weights, solver, rank-failure rule, formulas, status) is shared.
#pragma once

#include <memory>
#include <span>
#include <vector>

#include "core/types.h"
#include "methods/estimator.h"
#include "methods/fits/polynomial_fit.h"
#include "methods/local_frame.h"

namespace curvbench {

/// Which formulas of paper Table 1 turn the fitted derivatives into quantities.
enum class FitRoute {
  height,      ///< fit the height f = (p - p0) . m0 (1 RHS); Table 1 height column (§6.1)
  parametric,  ///< fit x - p0 (3 RHS); eqs. (1)-(8) (§6.2)
};

/// The ring handed to the parameterization hook (see the file comment).
struct RingView {
  const Mesh& mesh;
  const VertexMatrix& approx_normals;
  int centre;
  double ring;
  std::span<const int> neighbours;
  std::span<const int> faces;
  const LocalFrame& frame;
};

/// Per-thread state of a parameterization hook; derive from it.
class ParamScratch {
 public:
  virtual ~ParamScratch() = default;
};

class RingFitEstimator : public Estimator {
 public:
  bool ring_fit() const final { return true; }
  std::unique_ptr<Workspace> make_workspace(const Mesh& mesh) const final;
  void estimate(const MeshContext& ctx, int v, Workspace& ws, VertexEstimate& out) const final;
  /// The batched kernel (methods/kernels/batched_fit.h) when uses_batched_kernel(), else estimate()
  /// per vertex. Per vertex: the same neighbourhood, rows, weights and formulas as estimate(); a
  /// vertex the batch cannot finish at the requested degree (too few rows, a column failing the
  /// safeguard, so degree reduction or adaptive growth) goes through estimate().
  void estimate_batch(const MeshContext& ctx, int first, int count, Workspace& ws,
                      VertexEstimate* out) const final;
  /// options().kernel is batched, the method is batchable(), the solver is the safeguarded QR,
  /// degree <= kBatchMaxDegree and the weight exponent is one the batch computes (d/4).
  bool uses_batched_kernel() const;
  /// Neighbours and faces: a parameterization hook may read the ring faces. A method whose hook
  /// does not (LHF, LOP) overrides this with NeighbourhoodUse::neighbours.
  NeighbourhoodUse neighbourhood_use() const override {
    return NeighbourhoodUse::neighbours_and_faces;
  }

  FitRoute route() const { return route_; }
  /// Least-squares settings used for every fit (degree, centre row, solver, QR tolerance).
  const FitSettings& fit_settings() const { return settings_; }
  /// The weighted least-squares system the driver fits first at vertex v (starting
  /// neighbourhood, before any rank-failure growth): rows (u, v), right-hand sides f and
  /// weights w of eq. (15). For benchmarks that time the solve alone. Returns false if there is
  /// none (the parameterization hook failed). `ws` comes from make_workspace().
  struct FitSystem {
    RowVector u, v, w;
    RhsMatrix f;
  };
  bool first_system(const MeshContext& ctx, int v, Workspace& ws, FitSystem& out) const;

  /// Replaces the solver settings (comparison runs: SVD instead of the safeguarded QR). The
  /// degree and include_centre always come from options().
  void set_solver(LsqSolver solver, ColumnScaling scaling = ColumnScaling::two_norm,
                  double threshold = 1e-8, bool relative_threshold = false);

 protected:
  /// Degree 0 means the default, 2. Throws UsageError for a degree outside 1..kMaxDegree, a ring
  /// that is neither 0 nor one of 1, 1.5, 2, ..., a negative QR tolerance, a non-finite weight
  /// power or negative threads.
  RingFitEstimator(EstimatorOptions options, FitRoute route);

  /// The parameterization hook; default: orthogonal projection onto the frame plane (LOP,
  /// paper §4.2.2): uv_i = ((p_i - p0) . t1, (p_i - p0) . t2).
  virtual bool parameterize(const RingView& ring, std::vector<Vec2>& uv,
                            ParamScratch* scratch) const;
  virtual std::unique_ptr<ParamScratch> make_param_scratch(const Mesh& mesh) const;
  virtual bool use_normal_safeguard() const { return options().normal_safeguard; }
  /// True if a fitted normal more than 60 degrees from the mesh's vertex normal is no answer (a
  /// map of the ring that can fold a whole small closed surface onto the plane: LSCM).
  virtual bool rejects_turned_normal() const { return false; }
  /// Whether the batched kernel may fit this method. It computes the default projection of
  /// parameterize() inline, so only a method that keeps that hook may return true (LHF, LOP); a
  /// method that overrides parameterize() keeps the default false.
  virtual bool batchable() const { return false; }

 private:
  FitRoute route_;
  FitSettings settings_;
};

}  // namespace curvbench
