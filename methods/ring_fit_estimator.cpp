// Shared per-vertex driver of LHF, LOP and LSCM (docs/algorithms.md §5.5); see
// ring_fit_estimator.h.
#include "methods/ring_fit_estimator.h"

#include <cmath>
#include <cstdio>
#include <string>

#include "core/errors.h"
#include "core/shape_operator.h"
#include "core/text.h"
#include "mesh/rings.h"
#include "methods/vertex_result.h"
#include "methods/weights.h"

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
  bool partial = false;  // the last assembled system dropped rows with a non-finite (u, v)
};

}  // namespace

RingFitEstimator::RingFitEstimator(EstimatorOptions options, FitRoute route)
    : Estimator(options), route_(route) {
  if (options_.degree == 0) options_.degree = 2;  // the default degree (estimator.h)
  const EstimatorOptions& o = options_;
  if (o.degree < 1 || o.degree > kMaxDegree)
    throw UsageError("degree " + std::to_string(o.degree) + " is not supported (valid: 1..6)");
  const bool half_ring = std::isfinite(o.ring) && o.ring >= 1.0 &&
                         std::abs(2.0 * o.ring - std::round(2.0 * o.ring)) < 1e-12;
  if (!(o.ring == 0.0 || half_ring))
    throw UsageError("ring " + format_g(o.ring) +
                     " is not supported (valid: 0 = default, or 1, 1.5, 2, 2.5, ...)");
  if (!(o.qr_tolerance >= 0.0) || !std::isfinite(o.qr_tolerance))
    throw UsageError("QR tolerance must be finite and >= 0");
  if (!std::isfinite(o.weight_power)) throw UsageError("weight power must be finite");
  if (o.threads < 0) throw UsageError("threads must be >= 0");
  if (o.ring != 0.0) options_.ring = 0.5 * std::round(2.0 * o.ring);
  settings_.degree = o.degree;
  settings_.include_constant = o.include_centre;
  settings_.qr_tolerance = o.qr_tolerance;
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

// The weighted system (ws.u, ws.v, ws.f, ws.w) of the ring currently held by ws.rings, from the
// parameterization in ws.uv. Returns false if the hook failed.
bool assemble_current_ring(const RingFitEstimator& est, bool hook_ok, const MeshContext& ctx, int v,
                           const LocalFrame& frame, bool safeguard, RingFitWorkspace& ws) {
  if (!hook_ok || ws.uv.size() != 1 + ws.rings.neighbours().size()) return false;
  const EstimatorOptions& o = est.options();
  const std::span<const int> nb = ws.rings.neighbours();
  const Vec2 origin = ws.uv[0];
  if (!origin.allFinite()) return false;

  // Rows: the centre (gamma = 1), then the neighbours with gamma > 0 and finite (u, v).
  int sel[kMaxRows];
  double gam[kMaxRows];
  int rows = 0;
  ws.partial = false;
  if (o.include_centre) {
    sel[rows] = 0;
    gam[rows++] = 1.0;
  }
  for (size_t i = 0; i < nb.size() && rows < kMaxRows; ++i) {
    if (!ws.uv[i + 1].allFinite()) {
      ws.partial = true;
      continue;
    }
    const double g =
        safeguard ? normal_safeguard_gamma(ctx.approx_normals.row(nb[i]).transpose(), frame.m)
                  : 1.0;
    if (!(g > 0.0)) continue;
    sel[rows] = static_cast<int>(i + 1);
    gam[rows++] = g;
  }

  const int k = est.route() == FitRoute::height ? 1 : 3;
  const Vec3 p0 = ctx.mesh.position(v);
  ws.u.resize(rows);
  ws.v.resize(rows);
  ws.gamma.resize(rows);
  ws.f.resize(rows, k);
  for (int r = 0; r < rows; ++r) {
    const int s = sel[r];
    const Vec2 uv = ws.uv[static_cast<size_t>(s)] - origin;
    ws.u(r) = s == 0 ? 0.0 : uv.x();
    ws.v(r) = s == 0 ? 0.0 : uv.y();
    ws.gamma(r) = gam[r];
    const Vec3 d = s == 0 ? Vec3::Zero() : Vec3(ctx.mesh.position(nb[s - 1]) - p0);
    if (k == 1) {
      ws.f(r, 0) = d.dot(frame.m);
    } else {
      for (int c = 0; c < 3; ++c) ws.f(r, c) = d(c);
    }
  }
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

}  // namespace

void RingFitEstimator::estimate(const MeshContext& ctx, int v, Workspace& base,
                                VertexEstimate& out) const {
  auto& ws = static_cast<RingFitWorkspace&>(base);
  const Vec3 m0 = ctx.approx_normals.row(v).transpose();
  const LocalFrame frame = make_local_frame(m0);
  const int d = options_.degree;
  const int min_nb = min_neighbours(d);
  const bool safeguard = use_normal_safeguard();
  const double r0 = collect_neighbourhood(ws.rings, v);
  const double max_ring = 2.0 * r0;
  double ring = ws.rings.ring();
  FitResult fit;
  bool have_fit = false;
  bool fit_partial = false;
  double fit_ring = ring;
  for (;;) {
    const RingView view{
        ctx.mesh, ctx.approx_normals, v, ws.rings.ring(), ws.rings.neighbours(), ws.rings.faces(),
        frame};
    const bool hook_ok = parameterize(view, ws.uv, ws.param.get());
    FitResult attempt;
    if (fit_current_ring(*this, hook_ok, ctx, v, frame, safeguard, ws, attempt)) {
      fit = attempt;
      have_fit = true;
      fit_partial = ws.partial;
      fit_ring = ring;
    }
    // Rank-failure rule (docs/algorithms.md §1.2, [C2]): grow by half a ring up to 2 r0.
    const bool reduced = !have_fit || fit.degree < d;
    if (!options_.adaptive || !reduced || ring >= max_ring - 1e-9) break;
    const size_t before_v = ws.rings.neighbours().size();
    const size_t before_f = ws.rings.faces().size();
    ring = ws.rings.collect_at_least(v, ring + 0.5, min_nb, max_ring);
    if (ws.rings.neighbours().size() == before_v && ws.rings.faces().size() == before_f)
      break;  // the component is exhausted: nothing new to fit
  }
  if (!have_fit || fit.degree < 1) {
    set_failed(fit_ring, have_fit ? fit.rows : 0, out);
    return;
  }
  const auto& t = fit.taylor;
  const Curvature c =
      route_ == FitRoute::height
          ? curvature_from_height(frame.t1, frame.t2, frame.m, t(kFu, 0), t(kFv, 0), t(kFuu, 0),
                                  t(kFuv, 0), t(kFvv, 0))
          : curvature_from_parametric(t.row(kFu).transpose(), t.row(kFv).transpose(),
                                      t.row(kFuu).transpose(), t.row(kFuv).transpose(),
                                      t.row(kFvv).transpose());
  if (!set_quantities(c, fit.degree, d, fit.rows, fit_ring, out))
    set_failed(fit_ring, fit.rows, out);
  else if (fit_partial && out.status == VertexStatus::ok)
    out.status = VertexStatus::disk_cut;
}

bool RingFitEstimator::first_system(const MeshContext& ctx, int v, Workspace& base,
                                    FitSystem& out) const {
  auto& ws = static_cast<RingFitWorkspace&>(base);
  const LocalFrame frame = make_local_frame(ctx.approx_normals.row(v).transpose());
  collect_neighbourhood(ws.rings, v);
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
