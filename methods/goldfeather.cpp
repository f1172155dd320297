// Goldfeather: the adjacent-normal cubic approximation of J. Goldfeather and V. Interrante, "A
// novel cubic-order algorithm for approximating principal direction vectors", ACM Transactions
// on Graphics 23(1) (2004), 45-63. Degree-free; label "Goldfeather".
//
// Per vertex p with unit normal n (see "Choices") and local frame (t1, t2, n) (§3.3):
//   every 1-ring neighbour q_j in local coordinates (x_j, y_j, z_j) = ((q_j - p) . t1,
//   (q_j - p) . t2, (q_j - p) . n), with its unit normal in local coordinates (a_j, b_j, c_j);
//   the cubic through p with tangent plane z = 0,
//     z = A/2 x^2 + B x y + C/2 y^2 + D x^3 + E x^2 y + F x y^2 + G y^3      (7 unknowns),
//   fitted by unweighted least squares to three equations per neighbour (eq. 9-11):
//     z(x_j, y_j) = z_j,  z_x(x_j, y_j) = -a_j / c_j,  z_y(x_j, y_j) = -b_j / c_j
//   (a neighbour whose normal is more than 60 degrees from n, c_j < 1/2, keeps its position
//   equation only: see kMinNormalCosine); the Weingarten matrix at p is [A B; B C] in (t1, t2):
//   eqs. (7)-(8) give k1 >= k2, d1, d2 (principal_from_symmetric); H = (A + C)/2,
//   K = AC - B^2; the normal is n.
// Sign convention (estimator.h): with the outward normal as the z axis a sphere of radius r gives
// z ~ -(x^2 + y^2)/(2r), A = C = -1/r: the convention B = n . x_uu directly.
// Choices: the paper's normals come with its data (accurate normals are an input of the method:
// a slope error e becomes a curvature error e/h); on a mesh we use Max's weights (exact for
// vertices on a sphere, the most accurate of the face-normal averages; with area weights the
// icosphere's O(h) normal errors stop the convergence), option EstimatorOptions::vertex_normals.
// The least squares are solved through the normal equations after scaling the coordinates by their
// RMS distance (same solution as the paper's SVD when the system has full rank), with the
// residuals in the paper's units: positions in length, normals as slopes (no relative weight).
// Rank-deficient cubic (by the safeguard of the project's QR, |R_ii| < 1e-3 max |R_jj|: see
// kCubicTolerance2; e.g. a vertex on a fold, a CAD corner or a thin handle, where few neighbour
// normals are usable and the position rows alone cannot fix 7 unknowns): the quadratic
// z = A/2 x^2 + B x y + C/2 y^2 with the same rows, i.e. the paper's cubic with D = E = F = G = 0
// (their quadratic model extended, like the cubic, by the slopes of the neighbours whose normals
// are usable; the upper-left 3x3 block of the same normal equations), status degree_reduced. We
// keep the normal rows rather than fit positions only because the method's premise is that
// adjacent normals carry the curvature information; where none are usable the two coincide.
// Failed: fewer than 3 neighbours, or the quadratic numerically singular too.
// Boundary vertices: the fit needs no closed 1-ring (at least 3 neighbours give 9 >= 7 equations):
// computed on the neighbours they have, status ok (degree_reduced as above).
// Cost: one 7x7 system per vertex over its 1-ring (and a 3x3 one where the 7x7 is ill-conditioned).
#include <Eigen/Cholesky>
#include <cmath>
#include <memory>
#include <string>
#include <vector>

#include "core/shape_operator.h"
#include "methods/local_frame.h"
#include "methods/operator_estimator.h"
#include "methods/vertex_result.h"

namespace curvbench {

namespace {

using Mat7 = Eigen::Matrix<double, 7, 7>;
using Vec7 = Eigen::Matrix<double, 7, 1>;

/// A neighbour's normal enters the fit (its two slope equations) only within 60 degrees of the
/// vertex normal: the slope -a/c grows without bound as c = n_j . n -> 0 (on a CAD crease of 90
/// degrees c is 0 up to rounding and one slope of 1e16 decides the fit), while on a smooth surface
/// resolved by the mesh adjacent normals differ by about k h << 1 radian.
constexpr double kMinNormalCosine = 0.5;

/// The cubic is trusted when |R_ii| >= 1e-3 max |R_jj| (the safeguard of the project's polynomial
/// fits, docs/algorithms.md §5.4), in squares for the LDLT pivots; the quadratic, the last model,
/// only needs to be numerically nonsingular (|R_ii| >= 1e-6 max |R_jj|).
constexpr double kCubicTolerance2 = 1e-6;
constexpr double kQuadraticTolerance2 = 1e-12;

struct GoldfeatherWorkspace final : Workspace {
  GoldfeatherWorkspace() { neighbours.reserve(32); }
  std::vector<int> neighbours;
};

class GoldfeatherEstimator final : public OperatorEstimator {
 public:
  explicit GoldfeatherEstimator(EstimatorOptions options)
      : OperatorEstimator(options, VertexNormals::max) {}

  std::string name() const override { return "goldfeather"; }
  std::string display_name() const override { return "Goldfeather"; }

  std::unique_ptr<Workspace> make_workspace(const Mesh&) const override {
    return std::make_unique<GoldfeatherWorkspace>();
  }

  /// Whether every LDLT pivot of the normal equations R^T R (the R_ii^2) exceeds tolerance2
  /// times the largest.
  template <class D>
  static bool full_rank(const D& pivots, double tolerance2) {
    const double big = pivots.cwiseAbs().maxCoeff();
    return big > 0.0 && std::isfinite(big) && pivots.minCoeff() > tolerance2 * big;
  }

  void estimate(const MeshContext& ctx, int v, Workspace& base,
                VertexEstimate& out) const override {
    auto& ws = static_cast<GoldfeatherWorkspace&>(base);
    const Mesh& mesh = ctx.mesh;
    const OperatorMeshData& data = mesh_data(ctx);
    // The 1-ring neighbours, each once, in the order the incident faces list them.
    ws.neighbours.clear();
    for (int f : mesh.vertex_faces(v))
      for (int k = 0; k < 3; ++k) {
        const int w = mesh.face_vertex(f, k);
        bool seen = w == v;
        for (int u : ws.neighbours) seen = seen || u == w;
        if (!seen) ws.neighbours.push_back(w);
      }
    const int points = static_cast<int>(ws.neighbours.size());
    if (points < 3) {
      set_failed(1.0, points, out);
      return;
    }
    const Vec3 n = data.normal(ctx, v);
    const LocalFrame frame = make_local_frame(n);
    const Vec3 p = mesh.position(v);
    double s2 = 0.0;
    for (int w : ws.neighbours) {
      const Vec3 d = mesh.position(w) - p;
      s2 += d.dot(frame.t1) * d.dot(frame.t1) + d.dot(frame.t2) * d.dot(frame.t2);
    }
    const double s = std::sqrt(s2 / points);
    if (!(s > 0.0) || !std::isfinite(s)) {
      set_failed(1.0, points, out);
      return;
    }
    // Scaled coordinates X = x/s, Z = z/s: unknowns (A s, B s, C s, D s^2, E s^2, F s^2, G s^2);
    // a position residual in length units is s times its scaled residual, a slope residual is
    // the same in both.
    Mat7 ata = Mat7::Zero();
    Vec7 atb = Vec7::Zero();
    const auto add = [&](const Vec7& row, double rhs) {
      ata.noalias() += row * row.transpose();
      atb.noalias() += rhs * row;
    };
    for (int w : ws.neighbours) {
      const Vec3 d = (mesh.position(w) - p) / s;
      const double x = d.dot(frame.t1), y = d.dot(frame.t2), z = d.dot(frame.m);
      Vec7 row;
      row << 0.5 * x * x, x * y, 0.5 * y * y, x * x * x, x * x * y, x * y * y, y * y * y;
      add(s * row, s * z);  // the position residual in length units, as in the paper
      const Vec3 nw = data.normal(ctx, w);
      const double a = nw.dot(frame.t1), b = nw.dot(frame.t2), c = nw.dot(frame.m);
      if (!(c >= kMinNormalCosine)) continue;  // across a crease or facing away: position only
      row << x, y, 0.0, 3.0 * x * x, 2.0 * x * y, y * y, 0.0;
      add(row, -a / c);
      row << 0.0, x, y, 0.0, x * x, 2.0 * x * y, 3.0 * y * y;
      add(row, -b / c);
    }
    Curvature c;
    VertexStatus status = VertexStatus::ok;
    if (const Eigen::LDLT<Mat7> ldlt(ata); full_rank(ldlt.vectorD(), kCubicTolerance2)) {
      const Vec7 coef = ldlt.solve(atb);
      c = curvature_from_tangent_tensor(frame.m, coef(0) / s, coef(1) / s, coef(2) / s, frame.t1,
                                        frame.t2);
    } else {
      // The quadratic fallback: the same rows restricted to (A, B, C), i.e. the upper-left 3x3
      // block of the normal equations (the cubic coefficients set to zero).
      const Eigen::LDLT<Eigen::Matrix3d> ldlt3(ata.topLeftCorner<3, 3>());
      if (!full_rank(ldlt3.vectorD(), kQuadraticTolerance2)) {
        set_failed(1.0, points, out);
        return;
      }
      const Eigen::Vector3d coef = ldlt3.solve(atb.head<3>());
      c = curvature_from_tangent_tensor(frame.m, coef(0) / s, coef(1) / s, coef(2) / s, frame.t1,
                                        frame.t2);
      status = VertexStatus::degree_reduced;
    }
    if (!set_operator_quantities(c, computes(), points, 1.0, out)) {
      set_failed(1.0, points, out);
      return;
    }
    out.status = status;
  }
};

}  // namespace

std::unique_ptr<Estimator> make_goldfeather_estimator(EstimatorOptions options) {
  return std::make_unique<GoldfeatherEstimator>(options);
}

}  // namespace curvbench
