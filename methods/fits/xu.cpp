// Xu-2: Xu's 1-ring parameterization with a quadratic fit through the vertex (paper §4.2.1,
// §4.3.1; docs/algorithms.md §7).
//
//   neighbours p_1..p_n of the interior vertex p0, counter-clockwise about the outward normal
//   (taken from the face order); alpha_j = angle(p_j - p0, p_{j+1} - p0) by atan2(|a x b|, a.b);
//   A = sum alpha_j; theta_1 = 0, theta_j = (2 pi / A) sum_{i<j} alpha_i;
//   (u_j, v_j) = |p_j - p0| (cos theta_j, sin theta_j)
//   fit x - p0 ~ c10 u + c01 v + c20 u^2/2 + c11 uv + c02 v^2/2   (5 unknown 3-vectors, no
//   constant, unweighted), columns scaled by ||.||_inf, solved by the eigen-decomposition of
//   A^T A keeping eigenvalues >= 1e-8 (one decomposition for x, y, z); eqs. (1)-(8).
// Valence-3 and valence-4 vertices give fewer rows than unknowns: the eigen threshold returns the
// minimum-norm solution in the scaled variables. Such a vertex keeps status ok and degree 2 (no
// degree is dropped; Xu's solver has no degree safeguard), which is exactly the behaviour the
// paper blames for Xu-2's failures (§5.1-5.2). Their minimum-norm solution is not invariant
// under a rotation of (u, v) (the columns are scaled per axis), so it depends on which neighbour
// is p_1, i.e. on the mesh's numbering: a randomly renumbered copy of the level-3 unstructured
// torus changes H at 238 of its 21155 vertices (all of valence 4), by up to 31 where |H| ~ 2.
// Boundary vertices (and vertices whose incident faces do not form one closed fan) are not
// computed: status excluded, values NaN (paper §5.2 excludes them from Xu's errors).
// Degree 2 and ring 1 only.
#include <cmath>
#include <cstdio>
#include <memory>
#include <numbers>
#include <string>
#include <vector>

#include "core/errors.h"
#include "core/shape_operator.h"
#include "methods/estimator.h"
#include "methods/fits/polynomial_fit.h"
#include "methods/local_frame.h"
#include "methods/vertex_result.h"

namespace curvbench {

namespace {

struct XuWorkspace final : Workspace {
  XuWorkspace() {
    from.reserve(32);
    to.reserve(32);
    order.reserve(32);
  }
  std::vector<int> from, to, order;
  RowVector u, v, w;
  RhsMatrix f;
  FitScratch fit;
};

class XuEstimator final : public Estimator {
 public:
  explicit XuEstimator(EstimatorOptions options) : Estimator(options) {
    if (options_.degree != 2)
      throw UsageError("xu supports only degree 2 (got " + std::to_string(options_.degree) + ")");
    if (options_.rings != 0.0 && options_.rings != 1.0) {
      char ring[32];
      std::snprintf(ring, sizeof ring, "%g", options_.rings);
      throw UsageError(std::string("xu uses the 1-ring only (got ring ") + ring + ")");
    }
    if (options_.threads < 0) throw UsageError("threads must be >= 0");
    settings_.degree = 2;
    settings_.include_constant = false;
    settings_.solver = LsqSolver::normal_eigen;
    settings_.scaling = ColumnScaling::inf_norm;
    settings_.threshold = 1e-8;
  }

  std::string name() const override { return "xu"; }
  std::string display_name() const override { return "Xu"; }
  double default_ring() const override { return 1.0; }
  /// Paper §5.2: Xu's errors are taken over interior vertices (its boundary rows are excluded).
  bool scores_interior_only() const override { return true; }

  std::unique_ptr<Workspace> make_workspace(const Mesh&) const override {
    return std::make_unique<XuWorkspace>();
  }

  void estimate(const MeshContext& ctx, int v, Workspace& base,
                VertexEstimate& out) const override {
    auto& ws = static_cast<XuWorkspace&>(base);
    const Mesh& mesh = ctx.mesh;
    if (mesh.is_boundary_vertex(v) || !ordered_ring(mesh, v, ws)) {
      set_excluded(1.0, 0, out);
      return;
    }
    const int n = static_cast<int>(ws.order.size());
    const Vec3 p0 = mesh.position(v);
    // Angles at p0 between consecutive edges (atan2: robust for near-zero edges).
    double alpha_sum = 0.0;
    ws.w.resize(n);  // alpha_j, reused as scratch (the fit itself is unweighted)
    for (int j = 0; j < n; ++j) {
      const Vec3 a = mesh.position(ws.order[static_cast<size_t>(j)]) - p0;
      const Vec3 b = mesh.position(ws.order[static_cast<size_t>((j + 1) % n)]) - p0;
      ws.w(j) = std::atan2(a.cross(b).norm(), a.dot(b));
      alpha_sum += ws.w(j);
    }
    if (!(alpha_sum > 0.0) || !std::isfinite(alpha_sum)) {
      set_failed(1.0, n, out);
      return;
    }
    const double scale = 2.0 * std::numbers::pi / alpha_sum;
    ws.u.resize(n);
    ws.v.resize(n);
    ws.f.resize(n, 3);
    double theta = 0.0;
    for (int j = 0; j < n; ++j) {
      const Vec3 d = mesh.position(ws.order[static_cast<size_t>(j)]) - p0;
      const double r = d.norm();
      ws.u(j) = r * std::cos(theta);
      ws.v(j) = r * std::sin(theta);
      for (int c = 0; c < 3; ++c) ws.f(j, c) = d(c);
      theta += scale * ws.w(j);
    }
    ws.w.resize(0);  // unweighted
    const FitResult fit = fit_polynomial(ws.u, ws.v, ws.f, ws.w, settings_, ws.fit);
    const auto& t = fit.taylor;
    const Curvature c =
        fit.degree < 1 ? Curvature{}
                       : curvature_from_parametric(t.row(kFu).transpose(), t.row(kFv).transpose(),
                                                   t.row(kFuu).transpose(), t.row(kFuv).transpose(),
                                                   t.row(kFvv).transpose());
    if (!set_quantities(c, fit.degree, 2, n, 1.0, out)) set_failed(1.0, n, out);
  }

 private:
  // Neighbours of v counter-clockwise about the outward normal: face (v, a, b) in the mesh's
  // counter-clockwise order means b follows a. False unless the faces form one closed fan.
  static bool ordered_ring(const Mesh& mesh, int v, XuWorkspace& ws) {
    ws.from.clear();
    ws.to.clear();
    ws.order.clear();
    for (int f : mesh.vertex_faces(v)) {
      int k = 0;
      while (k < 3 && mesh.face_vertex(f, k) != v) ++k;
      if (k == 3) return false;
      ws.from.push_back(mesh.face_vertex(f, (k + 1) % 3));
      ws.to.push_back(mesh.face_vertex(f, (k + 2) % 3));
    }
    const size_t n = ws.from.size();
    if (n < 3) return false;
    int cur = ws.from[0];
    for (size_t step = 0; step < n; ++step) {
      size_t i = 0;
      while (i < n && ws.from[i] != cur) ++i;
      if (i == n) return false;
      ws.order.push_back(cur);
      cur = ws.to[i];
      if (cur == ws.from[0]) break;
    }
    if (cur != ws.from[0] || ws.order.size() != n) return false;
    // Each neighbour must appear once (a closed fan without repeated vertices).
    for (size_t i = 0; i < n; ++i)
      for (size_t j = i + 1; j < n; ++j)
        if (ws.order[i] == ws.order[j]) return false;
    return true;
  }

  FitSettings settings_;
};

}  // namespace

std::unique_ptr<Estimator> make_xu_estimator(EstimatorOptions options) {
  return std::make_unique<XuEstimator>(options);
}

}  // namespace curvbench
