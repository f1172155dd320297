// Shared per-vertex driver of LHF, LOP and LSCM (docs/algorithms.md §5.5); see
// ring_fit_estimator.h.
#include "methods/fits/ring_fit_estimator.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>

#include "core/errors.h"
#include "core/shape_operator.h"
#include "core/text.h"
#include "mesh/rings.h"
#include "methods/fits/weights.h"
#include "methods/kernels/batched_curvature.h"
#include "methods/kernels/batched_fit.h"
#include "methods/vertex_result.h"

namespace curvbench {

namespace {

struct RingFitWorkspace final : Workspace {
  explicit RingFitWorkspace(const Mesh& mesh) : rings(mesh) { uv.reserve(256); }
  RingCollector rings;
  std::vector<Vec2> uv;
  RowVector u, v, gamma, w;
  RhsMatrix f;
  FitScratch fit;
  std::unique_ptr<ParamScratch> param;
  std::unique_ptr<BatchedSystems> batch;  // the batched kernel's buffers (when it is used)
  bool partial = false;  // the last assembled system dropped rows with a non-finite (u, v)
};

}  // namespace

RingFitEstimator::RingFitEstimator(EstimatorOptions options, FitRoute route)
    : Estimator(options), route_(route) {
  if (options_.degree == 0) options_.degree = 2;  // the default degree (estimator.h)
  const EstimatorOptions& o = options_;
  if (o.degree < 1 || o.degree > kMaxDegree)
    throw UsageError("degree " + std::to_string(o.degree) + " is not supported (valid: 1..6)");
  options_.rings = half_rings(o.rings, "fit");
  settings_.degree = o.degree;
  settings_.include_constant = o.include_centre;
  settings_.qr_tolerance = o.qr_tolerance;
  settings_.qr_condition = o.qr_condition;
}

void RingFitEstimator::set_solver(LsqSolver solver, ColumnScaling scaling, double threshold,
                                  bool relative_threshold) {
  settings_.solver = solver;
  settings_.scaling = scaling;
  settings_.threshold = threshold;
  settings_.relative_threshold = relative_threshold;
}

std::unique_ptr<Workspace> RingFitEstimator::make_workspace(const Mesh& mesh) const {
  auto ws = std::make_unique<RingFitWorkspace>(mesh);
  ws->param = make_param_scratch(mesh);
  if (uses_batched_kernel()) ws->batch = std::make_unique<BatchedSystems>();
  return ws;
}

std::unique_ptr<ParamScratch> RingFitEstimator::make_param_scratch(const Mesh&) const {
  return nullptr;
}

bool RingFitEstimator::parameterize(const RingView& ring, std::vector<Vec2>& uv,
                                    ParamScratch*) const {
  // LOP (paper §4.2.2, docs/algorithms.md §3): u = (p - p0) . t1, v = (p - p0) . t2.
  const Vec3 p0 = ring.mesh.position(ring.centre);
  uv.resize(1 + ring.neighbours.size());
  uv[0] = Vec2::Zero();
  for (size_t i = 0; i < ring.neighbours.size(); ++i) {
    const Vec3 d = ring.mesh.position(ring.neighbours[i]) - p0;
    uv[i + 1] = Vec2(d.dot(ring.frame.t1), d.dot(ring.frame.t2));
  }
  return true;
}

namespace {

// The rows of the fit at vertex v (docs/algorithms.md §5.5) for the neighbours nb of its ring:
// the centre (if include_centre, gamma = 1), then the neighbours in order with gamma > 0 and
// finite (u, v), at most kMaxRows. uv_of(i, d) gives the parameters of nb[i] (d = p_i - p0),
// taken relative to origin (the centre's). Calls put(row, u, v, gamma, d) (d = 0 for the centre)
// and returns the row count. partial: some neighbour had a non-finite (u, v). The one gather of
// both kernels (scalar and batched).
template <class UvOf, class Put>
int gather_rows(const MeshContext& ctx, int v, std::span<const int> nb, const Vec2& origin,
                UvOf&& uv_of, const Vec3& m0, bool include_centre, bool safeguard, bool& partial,
                Put&& put) {
  partial = false;
  const Vec3 p0 = ctx.mesh.position(v);
  int rows = 0, turned_away = 0;
  if (include_centre) put(rows++, 0.0, 0.0, 1.0, Vec3::Zero().eval());
  for (size_t i = 0; i < nb.size() && rows < kMaxRows; ++i) {
    const Vec3 d = ctx.mesh.position(nb[i]) - p0;
    const Vec2 uv = uv_of(i, d);
    if (!uv.allFinite()) {
      partial = true;
      continue;
    }
    const double g =
        safeguard ? normal_safeguard_gamma(ctx.approx_normals.row(nb[i]).transpose(), m0) : 1.0;
    if (!(g > 0.0)) {
      ++turned_away;
      continue;
    }
    const Vec2 q = uv - origin;
    put(rows++, q.x(), q.y(), g, d);
  }
  // The normal safeguard leaves at least the rows of a plane (include_centre: c00, c10, c01):
  // where every neighbour's normal turns away (the vertices of a tetrahedron, an octahedron),
  // the neighbours come back with gamma = 1, so that the safeguarded QR's degree reduction still
  // gives the normal (degree 1, degree_reduced) instead of a failed vertex.
  const int plane_rows = include_centre ? 3 : 2;
  if (rows < plane_rows && turned_away > 0)
    return gather_rows(ctx, v, nb, origin, uv_of, m0, include_centre, false, partial, put);
  return rows;
}

// The weighted system (ws.u, ws.v, ws.f, ws.w) of the ring currently held by ws.rings, from the
// parameterization in ws.uv. Returns false if the hook failed.
bool assemble_current_ring(const RingFitEstimator& est, bool hook_ok, const MeshContext& ctx, int v,
                           const LocalFrame& frame, bool safeguard, RingFitWorkspace& ws) {
  const std::span<const int> nb = ws.rings.neighbours();
  if (!hook_ok || ws.uv.size() != 1 + nb.size() || !ws.uv[0].allFinite()) return false;
  const EstimatorOptions& o = est.options();
  const int k = est.route() == FitRoute::height ? 1 : 3;
  double f[kMaxRhs][kMaxRows];
  ws.u.resize(kMaxRows);
  ws.v.resize(kMaxRows);
  ws.gamma.resize(kMaxRows);
  const int rows = gather_rows(
      ctx, v, nb, ws.uv[0], [&](size_t i, const Vec3&) { return ws.uv[i + 1]; }, frame.m,
      o.include_centre, safeguard, ws.partial,
      [&](int r, double u, double vv, double g, const Vec3& d) {
        ws.u(r) = u;
        ws.v(r) = vv;
        ws.gamma(r) = g;
        if (k == 1)
          f[0][r] = d.dot(frame.m);
        else
          for (int c = 0; c < 3; ++c) f[c][r] = d(c);
      });
  ws.u.conservativeResize(rows);
  ws.v.conservativeResize(rows);
  ws.gamma.conservativeResize(rows);
  ws.f.resize(rows, k);
  for (int c = 0; c < k; ++c)
    for (int r = 0; r < rows; ++r) ws.f(r, c) = f[c][r];
  compute_weights(ws.u, ws.v, ws.gamma, weight_exponent(o.degree, o.weight_power), ws.w);
  return true;
}

// One fit on the ring currently held by ws.rings. Returns false if the hook failed.
bool fit_current_ring(const RingFitEstimator& est, bool hook_ok, const MeshContext& ctx, int v,
                      const LocalFrame& frame, bool safeguard, RingFitWorkspace& ws,
                      FitResult& result) {
  if (!assemble_current_ring(est, hook_ok, ctx, v, frame, safeguard, ws)) return false;
  result = fit_polynomial(ws.u, ws.v, ws.f, ws.w, est.fit_settings(), ws.fit);
  return true;
}

// The quantities c of a fit of degree >= 1 with `rows` rows, and the status.
void set_fit_curvature(const Curvature& c, int degree, int rows, int requested, double ring,
                       bool partial, VertexEstimate& out) {
  if (!set_quantities(c, degree, requested, rows, ring, out))
    set_failed(ring, rows, out);
  else if (partial && out.status == VertexStatus::ok)
    out.status = VertexStatus::disk_cut;
}

constexpr double kMinMappedNormalCosine = 0.0;  // cos 90 degrees

// The curvature of a fit of degree >= 1 (core/shape_operator.h) on the route.
Curvature fit_curvature(FitRoute route, const LocalFrame& frame, const FitResult& fit) {
  const auto& t = fit.taylor;
  return route == FitRoute::height
             ? curvature_from_height(frame.t1, frame.t2, frame.m, t(kFu, 0), t(kFv, 0), t(kFuu, 0),
                                     t(kFuv, 0), t(kFvv, 0))
             : curvature_from_parametric(t.row(kFu).transpose(), t.row(kFv).transpose(),
                                         t.row(kFuu).transpose(), t.row(kFuv).transpose(),
                                         t.row(kFvv).transpose());
}

// The quantities of a fit of degree >= 1 and the status.
void set_fit_quantities(FitRoute route, const LocalFrame& frame, const FitResult& fit,
                        int requested, double ring, bool partial, VertexEstimate& out) {
  set_fit_curvature(fit_curvature(route, frame, fit), fit.degree, fit.rows, requested, ring,
                    partial, out);
}

}  // namespace

void RingFitEstimator::estimate(const MeshContext& ctx, int v, Workspace& base,
                                VertexEstimate& out) const {
  auto& ws = static_cast<RingFitWorkspace&>(base);
  const Vec3 m0 = ctx.approx_normals.row(v).transpose();
  const LocalFrame frame = make_local_frame(m0);
  const int d = options_.degree;
  const int min_nb = min_neighbours(d);
  bool safeguard = use_normal_safeguard();
  // The fit with the rank-failure rule, on the method's parameterization or (project) on the
  // orthogonal projection onto the frame plane (LOP's: the base class's parameterize()).
  const auto fit_with_growth = [&](bool project, FitResult& fit, bool& fit_partial,
                                   double& fit_ring) {
    const double r0 = collect_neighbourhood(ctx, ws.rings, v);
    const double max_ring = 2.0 * r0;
    double ring = ws.rings.ring();
    bool have_fit = false;
    fit_ring = ring;
    for (;;) {
      const RingView view{
          ctx.mesh, ctx.approx_normals, v, ws.rings.ring(), ws.rings.neighbours(), ws.rings.faces(),
          frame};
      const bool hook_ok = project ? RingFitEstimator::parameterize(view, ws.uv, nullptr)
                                   : parameterize(view, ws.uv, ws.param.get());
      FitResult attempt;
      if (fit_current_ring(*this, hook_ok, ctx, v, frame, safeguard, ws, attempt)) {
        fit = attempt;
        have_fit = true;
        fit_partial = ws.partial;
        fit_ring = ring;
      }
      // Rank-failure rule (docs/algorithms.md §1.2, [C2]): grow by half a ring up to 2 r0.
      const bool reduced = !have_fit || fit.degree < d;
      // A point neighbourhood (ring 0: k-NN or ball) does not grow.
      if (!options_.adaptive || !reduced || r0 == 0.0 || ring >= max_ring - 1e-9) break;
      const size_t before_v = ws.rings.neighbours().size();
      const size_t before_f = ws.rings.num_faces();
      ring = ws.rings.collect_at_least(v, ring + 0.5, min_nb, max_ring);
      if (ws.rings.neighbours().size() == before_v && ws.rings.num_faces() == before_f)
        break;  // the component is exhausted: nothing new to fit
    }
    if (!have_fit) fit.rows = 0;
    return have_fit && fit.degree >= 1;
  };
  FitResult fit;
  bool fit_partial = false;
  double fit_ring = 0.0;
  bool fitted = fit_with_growth(false, fit, fit_partial, fit_ring);
  if (!fitted && safeguard) {
    // The normal safeguard left no plane (e.g. the bottom vertex of an open octahedron, whose
    // neighbours' normals all turn away, the rest of the points on a line): the points without
    // it, as the safeguard's degree reduction intends (at least the normal, degree_reduced).
    safeguard = false;
    fitted = fit_with_growth(false, fit, fit_partial, fit_ring);
  }
  if (!fitted) {
    set_failed(fit_ring, fit.rows, out);
    return;
  }
  // A map that folds the ring (a ring wrapped around a hole, or a whole small closed surface such
  // as the 1.5-ring of a tetrahedron: the fitted x_u x x_v turns more than 90 degrees from the
  // mesh's vertex normal m0) gives no tangent plane: the same fit on the orthogonal projection of
  // the ring instead, status reprojected.
  if (rejects_turned_normal() &&
      !(fit_curvature(route_, frame, fit).normal.dot(m0) > kMinMappedNormalCosine)) {
    if (!fit_with_growth(true, fit, fit_partial, fit_ring)) {
      set_failed(fit_ring, fit.rows, out);
      return;
    }
    set_fit_quantities(route_, frame, fit, d, fit_ring, false, out);
    if (out.status != VertexStatus::failed) out.status = VertexStatus::reprojected;
    return;
  }
  set_fit_quantities(route_, frame, fit, d, fit_ring, fit_partial, out);
}

bool RingFitEstimator::uses_batched_kernel() const {
  return options_.kernel == Kernel::batched && batchable() &&
         settings_.solver == LsqSolver::safeguarded_qr && options_.degree <= kBatchMaxDegree &&
         batched_weight_power_supported(weight_exponent(options_.degree, options_.weight_power));
}

void RingFitEstimator::estimate_batch(const MeshContext& ctx, int first, int count, Workspace& base,
                                      VertexEstimate* out) const {
  auto& ws = static_cast<RingFitWorkspace&>(base);
  if (!ws.batch || !uses_batched_kernel()) {
    Estimator::estimate_batch(ctx, first, count, base, out);
    return;
  }
  BatchedSystems& s = *ws.batch;
  const int d = options_.degree;
  const int k = route_ == FitRoute::height ? 1 : 3;
  const int n = num_columns(d, options_.include_centre);
  const bool safeguard = use_normal_safeguard();
  s.degree = d;
  s.include_constant = options_.include_centre;
  s.rhs = k;
  s.tol = settings_.qr_tolerance;
  s.condition = settings_.qr_condition;
  s.power = weight_exponent(d, options_.weight_power);
  constexpr int L = kBatchLanes;
  LocalFrame frames[L];
  double rings[L];
  alignas(64) double normals[3 * L] = {};
  BatchedFrames batch_frames;
  BatchedCurvature batch_curvature;
  for (int b = 0; b < count; b += L) {
    const int lanes = std::min(L, count - b);
    // The frames of the batch lane-wise (the same bits as make_local_frame, which takes the
    // lanes the batched code leaves out).
    for (int l = 0; l < lanes; ++l)
      for (int c = 0; c < 3; ++c) normals[c * L + l] = ctx.approx_normals(first + b + l, c);
    batched_local_frames(normals, batch_frames);
    // Gather: lane l holds vertex first + b + l, or nothing (rows 0) if it goes the scalar way.
    s.max_rows = 0;
    for (int l = 0; l < L; ++l) {
      int rows = 0;
      if (l < lanes) {
        const int v = first + b + l;
        frames[l] = batch_frames.regular[static_cast<size_t>(l)]
                        ? batch_frames.frame(l)
                        : make_local_frame(ctx.approx_normals.row(v).transpose());
        collect_neighbourhood(ctx, ws.rings, v);
        rings[l] = ws.rings.ring();
        bool partial = false;
        const LocalFrame& fr = frames[l];
        // The projection hook of LHF/LOP (parameterize(), paper §4.2.2) inline: batchable()
        // methods keep the default hook.
        const auto project = [&](size_t, const Vec3& dp) {
          return Vec2(dp.dot(fr.t1), dp.dot(fr.t2));
        };
        rows = gather_rows(ctx, v, ws.rings.neighbours(), Vec2::Zero().eval(), project, fr.m,
                           options_.include_centre, safeguard, partial,
                           [&](int r, double u, double vv, double g, const Vec3& dp) {
                             const auto i = static_cast<size_t>(r * L + l);
                             s.u[i] = u;
                             s.v[i] = vv;
                             s.gamma[i] = g;
                             if (k == 1)
                               s.f[i] = dp.dot(fr.m);
                             else
                               for (int c = 0; c < 3; ++c)
                                 s.f[static_cast<size_t>(c * kMaxRows * L) + i] = dp(c);
                           });
        // Too few rows for the degree (pre-reduction) or a partial ring: the scalar path.
        if (rows < n || partial) rows = 0;
      }
      s.rows[static_cast<size_t>(l)] = rows;
      s.max_rows = std::max(s.max_rows, rows);
    }
    // Zero padding up to the longest lane (zero weight: no effect on the fit).
    for (int l = 0; l < L; ++l)
      for (int r = s.rows[static_cast<size_t>(l)]; r < s.max_rows; ++r) {
        const auto i = static_cast<size_t>(r * L + l);
        s.u[i] = s.v[i] = s.gamma[i] = 0.0;
        for (int c = 0; c < k; ++c) s.f[static_cast<size_t>((c * kMaxRows + r) * L + l)] = 0.0;
      }
    if (s.max_rows > 0) batched_fit(s);
    // The height route's formulas lane-wise (the same bits as curvature_from_height, which takes
    // the lanes the batched code leaves out).
    const bool lane_formulas = k == 1 && s.max_rows > 0;
    if (lane_formulas)
      batched_curvature_from_height(batch_frames, s.taylor.data(), kMaxRhs * L, batch_curvature);
    for (int l = 0; l < lanes; ++l) {
      VertexEstimate& o = out[b + l];
      if (s.max_rows == 0 || !s.solved[static_cast<size_t>(l)]) {
        // The safeguard fired (degree reduction, adaptive growth) or the lane was not batched.
        estimate(ctx, first + b + l, base, o);
        continue;
      }
      const auto i = static_cast<size_t>(l);
      if (lane_formulas && batch_frames.regular[i] && batch_curvature.regular[i]) {
        set_fit_curvature(batch_curvature.curvature(l), d, s.rows[i], d, rings[l], false, o);
        continue;
      }
      FitResult fit;
      fit.degree = d;
      fit.rank = n;
      fit.rows = s.rows[static_cast<size_t>(l)];
      for (int t = 0; t < 6; ++t)
        for (int c = 0; c < k; ++c)
          fit.taylor(t, c) = s.taylor[static_cast<size_t>((t * kMaxRhs + c) * L + l)];
      set_fit_quantities(route_, frames[l], fit, d, rings[l], false, o);
    }
  }
}

bool RingFitEstimator::first_system(const MeshContext& ctx, int v, Workspace& base,
                                    FitSystem& out) const {
  auto& ws = static_cast<RingFitWorkspace&>(base);
  const LocalFrame frame = make_local_frame(ctx.approx_normals.row(v).transpose());
  collect_neighbourhood(ctx, ws.rings, v);
  const RingView view{
      ctx.mesh, ctx.approx_normals, v, ws.rings.ring(), ws.rings.neighbours(), ws.rings.faces(),
      frame};
  const bool hook_ok = parameterize(view, ws.uv, ws.param.get());
  if (!assemble_current_ring(*this, hook_ok, ctx, v, frame, use_normal_safeguard(), ws))
    return false;
  out.u = ws.u;
  out.v = ws.v;
  out.f = ws.f;
  out.w = ws.w;
  return true;
}

}  // namespace curvbench
