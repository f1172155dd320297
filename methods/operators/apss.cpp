// APSS: algebraic point set surfaces (G. Guennebaud, M. Gross, "Algebraic point set surfaces",
// SIGGRAPH 2007; G. Guennebaud, M. Germann, M. Gross, "Dynamic sampling and rendering of
// algebraic point set surfaces", Eurographics 2008). Degree-free; label "APSS".
//
// Per vertex v, with x^ = (x - x_v) / h the coordinates scaled by the kernel support h:
//   neighbourhood  collect_neighbourhood (the rings of option `rings`, default 2; on a point set
//                  the k-NN table that serves collect_neighbourhood), the centre included
//   support, weights  h = the distance to the farthest point of the neighbourhood,
//                  w_i(x) = (1 - |x - x_i|^2 / h^2)^4 (G&G 2007's smooth compact kernel): h
//                  follows the sampling, and the kernel and its first three derivatives vanish
//                  where the neighbourhood ends, so the field's derivatives at the vertex do not
//                  miss points the neighbourhood lacks (for a k-NN ball exactly; for rings, all
//                  but the few inside h beyond the last ring). A support 1.5 h gave a cylinder's
//                  k1 = -0.047 instead of 0 (tests/methods/test_apss.cpp).
//   sphere         s_u(x^) = u0 + ul . x^ + u4 |x^|^2, u = (u0, ul, u4), the minimiser of
//                  sum_i w_i [ s_u(x^_i)^2 + beta |grad s_u(x^_i) - n_i|^2 ]     (G&G 2007 §3.3)
//                  with n_i the input normals (MeshContext::approx_normals, or the weighting of
//                  option vertex-normals) and beta = option apss-beta (dimensionless here: in
//                  unscaled coordinates the paper's beta is apss-beta h^2, the scale-invariant
//                  choice). The normals fix the scale and the orientation of u: no normalisation
//                  constraint. 5x5 normal equations, Jacobi-scaled LDLT.
//   normal, H      from the sphere at the vertex: n = grad s_u(0) / |.| = ul / |ul|, and
//                  H = -2 u4 / sqrt(|ul|^2 - 4 u0 u4) / h (the sphere's 1/radius with the sign of
//                  estimator.h: |grad s_u| on the sphere is sqrt(|ul|^2 - 4 u0 u4), and u4 > 0
//                  with outward normals is a sphere curving away from them: H = -1/r)
//   shape operator from the MLS field f(x) = s_{u(x)}(x), u(x) the fit with weights centred at x,
//                  evaluated at the vertex itself (no projection onto f = 0: on samples of the
//                  surface f(x_v) is already small, and the vertex is where the truth is
//                  scored). With A(x) u = b(x), A = sum w_i M_i, b = sum w_i c_i, the first and
//                  second derivatives of u follow from differentiating the weights (h fixed):
//                  A du_k = sum dw_i/dx_k (c_i - M_i u), and A d2u_kl likewise; then
//                  Hess f(0)_kl = d2u0_kl + dul_l/dx_k + dul_k/dx_l + 2 u4 delta_kl,
//                  grad f(0) = du0 + ul. The shape operator in the tangent plane (q1, q2) of n:
//                  W = -[q_a . Hess f q_b] / (|grad f| h) (B = n . x_uu = -dn for the level set),
//                  k1 >= k2, d1, d2 from eqs. (7)-(8), K = k1 k2.
//   output         normal and H from the sphere, k1, k2, d1, d2, K from the field: H is not
//                  (k1 + k2) / 2 exactly (both are exact on a sphere, where du = 0).
// Exact on spheres and planes sampled with exact normals (zero residuals: u does not depend on
// x). Fewer than 2 points with a usable normal, or a singular system: status failed. An
// imaginary sphere (|ul|^2 <= 4 u0 u4) leaves H NaN: status partial.
// Cost: two passes over the neighbourhood with 5x5 products, and 10 solves with one LDLT.
#include <Eigen/Cholesky>
#include <algorithm>
#include <array>
#include <cmath>
#include <memory>
#include <string>
#include <vector>

#include "core/errors.h"
#include "core/shape_operator.h"
#include "core/text.h"
#include "mesh/rings.h"
#include "methods/local_frame.h"
#include "methods/operators/operator_estimator.h"
#include "methods/vertex_result.h"

namespace curvbench {

namespace {

using Vec5 = Eigen::Matrix<double, 5, 1>;
using Mat5 = Eigen::Matrix<double, 5, 5>;

constexpr double kDefaultRing = 2.0;
// Kernel support relative to the farthest neighbour (see "support, weights" above).
constexpr double kSupport = 1.0;

// One point of the fit, in scaled coordinates: its row matrix M_i = a a^T + beta G^T G and right
// side c_i = beta G^T n_i, with a = (1, x, |x|^2) and G = [0 I 2x] (the gradient of s_u at x).
struct Row {
  Vec3 x;
  Vec3 n;
  void matrix(double beta, Mat5& M, Vec5& c) const {
    Vec5 a;
    a << 1.0, x, x.squaredNorm();
    M.noalias() = a * a.transpose();
    for (int l = 0; l < 3; ++l) {
      M(1 + l, 1 + l) += beta;
      M(1 + l, 4) += 2.0 * beta * x(l);
      M(4, 1 + l) += 2.0 * beta * x(l);
    }
    M(4, 4) += 4.0 * beta * x.squaredNorm();
    c << 0.0, beta * n, 2.0 * beta * x.dot(n);
  }
};

struct ApssWorkspace final : Workspace {
  explicit ApssWorkspace(const Mesh& mesh) : rings(mesh) { rows.reserve(128); }
  RingCollector rings;
  std::vector<Row> rows;  ///< the points of the current vertex
};

class ApssEstimator final : public OperatorEstimator {
 public:
  explicit ApssEstimator(EstimatorOptions options)
      : OperatorEstimator(options, VertexNormals::area, /*ring_option=*/true) {
    options_.rings = half_rings(options_.rings, "apss");
  }

  std::string name() const override { return "apss"; }
  std::string display_name() const override { return "APSS"; }
  double default_ring() const override { return kDefaultRing; }
  NeighbourhoodUse neighbourhood_use() const override { return NeighbourhoodUse::neighbours; }

  std::unique_ptr<Workspace> make_workspace(const Mesh& mesh) const override {
    return std::make_unique<ApssWorkspace>(mesh);
  }

  void estimate(const MeshContext& ctx, int v, Workspace& base,
                VertexEstimate& out) const override {
    auto& ws = static_cast<ApssWorkspace&>(base);
    const double ring = collect_neighbourhood(ctx, ws.rings, v);
    const OperatorMeshData& data = mesh_data(ctx);
    const Vec3 x0 = ctx.mesh.position(v);
    double far = 0.0;
    for (int w : ws.rings.neighbours()) far = std::max(far, (ctx.mesh.position(w) - x0).norm());
    const double h = kSupport * far;
    // The centre, then the neighbours; a point without a usable normal (no faces) is left out.
    const auto neighbours = ws.rings.neighbours();
    std::vector<Row>& rows = ws.rows;
    rows.clear();
    const auto add = [&](int w) {
      const Vec3 n = data.normal(ctx, w);
      if (n.allFinite() && n.squaredNorm() > 0.25)
        rows.push_back({(ctx.mesh.position(w) - x0) / h, n});
    };
    add(v);
    for (int w : neighbours) add(w);
    const int points = static_cast<int>(rows.size());
    if (points < 2 || !(h > 0.0) || !std::isfinite(h)) {
      set_failed(ring, points, out);
      return;
    }
    if (!fit(rows, h, points, ring, out)) set_failed(ring, points, out);
  }

 private:
  // The kernel and its derivatives at the vertex (x^ = 0) for a point at x^_i: w, grad w, Hess w.
  static void weight(const Vec3& xi, double& w, Vec3& dw, Mat3& ddw) {
    const double t = xi.squaredNorm(), s = 1.0 - t;
    w = s * s * s * s;
    // phi(t) = (1-t)^4 with t = |x - x_i|^2: grad = 2 phi' (x - x_i), Hess = 4 phi'' (x - x_i)
    // (x - x_i)^T + 2 phi' I, phi' = -4 (1-t)^3, phi'' = 12 (1-t)^2; at x = 0, x - x_i = -x_i.
    dw = 8.0 * s * s * s * xi;
    ddw = 48.0 * s * s * (xi * xi.transpose()) - 8.0 * s * s * s * Mat3::Identity();
  }

  bool fit(const std::vector<Row>& rows, double h, int points, double ring,
           VertexEstimate& out) const {
    const double beta = options_.apss_beta;
    Mat5 A = Mat5::Zero(), M;
    Vec5 b = Vec5::Zero(), c;
    double w;
    Vec3 dw;
    Mat3 ddw;
    for (const Row& r : rows) {
      weight(r.x, w, dw, ddw);
      r.matrix(beta, M, c);
      A += w * M;
      b += w * c;
    }
    // Jacobi scaling D A D, then LDLT; every pivot clearly positive or the system is singular.
    const Vec5 d = A.diagonal().cwiseMax(0.0).cwiseSqrt().cwiseInverse();
    if (!d.allFinite()) return false;
    const Eigen::LDLT<Mat5> ldlt(d.asDiagonal() * A * d.asDiagonal());
    const Vec5 piv = ldlt.vectorD();
    if (ldlt.info() != Eigen::Success || !(piv.minCoeff() > 1e-12 * piv.cwiseAbs().maxCoeff()))
      return false;
    const auto solve = [&](const Vec5& rhs) -> Vec5 {
      return d.asDiagonal() * ldlt.solve(d.asDiagonal() * rhs);
    };
    const Vec5 u = solve(b);
    // First derivatives: A du_k = sum dw_k (c_i - M_i u); then the second (only u0's is needed):
    // A d2u_kl = sum [ddw_kl (c_i - M_i u) - dw_k M_i du_l - dw_l M_i du_k].
    Eigen::Matrix<double, 5, 3> R = Eigen::Matrix<double, 5, 3>::Zero();
    for (const Row& r : rows) {
      weight(r.x, w, dw, ddw);
      r.matrix(beta, M, c);
      R += (c - M * u) * dw.transpose();
    }
    Eigen::Matrix<double, 5, 3> du;
    for (int k = 0; k < 3; ++k) du.col(k) = solve(R.col(k));
    std::array<Vec5, 6> S;
    for (Vec5& s : S) s.setZero();
    for (const Row& r : rows) {
      weight(r.x, w, dw, ddw);
      r.matrix(beta, M, c);
      const Vec5 e = c - M * u;
      const Eigen::Matrix<double, 5, 3> Mdu = M * du;
      int q = 0;
      for (int k = 0; k < 3; ++k)
        for (int l = k; l < 3; ++l, ++q)
          S[static_cast<size_t>(q)] += ddw(k, l) * e - dw(k) * Mdu.col(l) - dw(l) * Mdu.col(k);
    }
    Mat3 hess;
    int q = 0;
    for (int k = 0; k < 3; ++k)
      for (int l = k; l < 3; ++l, ++q) {
        const double d2u0 = solve(S[static_cast<size_t>(q)])(0);
        hess(k, l) = hess(l, k) = d2u0 + du(1 + l, k) + du(1 + k, l) + (k == l ? 2.0 * u(4) : 0.0);
      }
    const Vec3 ul = u.segment<3>(1);
    const Vec3 grad = du.row(0).transpose() + ul;
    Curvature cv;
    cv.normal = ul.normalized();
    const double pratt = ul.squaredNorm() - 4.0 * u(0) * u(4);
    if (pratt > 0.0) cv.H = -2.0 * u(4) / (std::sqrt(pratt) * h);
    const LocalFrame f = make_local_frame(cv.normal);
    const double g = grad.norm() * h;
    principal_from_symmetric(-f.t1.dot(hess * f.t1) / g, -f.t1.dot(hess * f.t2) / g,
                             -f.t2.dot(hess * f.t2) / g, f.t1, f.t2, cv.k1, cv.k2, cv.d1, cv.d2);
    cv.K = cv.k1 * cv.k2;
    return set_operator_quantities(cv, computes(), points, ring, out);
  }
};

}  // namespace

std::unique_ptr<Estimator> make_apss_estimator(EstimatorOptions options) {
  return std::make_unique<ApssEstimator>(options);
}

}  // namespace curvbench
