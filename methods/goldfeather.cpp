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
// Their entries are sums over the neighbours of monomials x^a y^b (times z or a slope on the
// right-hand side), accumulated once per monomial; LDL^T with Eigen::LDLT's diagonal pivoting.
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
// Cost: per neighbour 47 monomial sums; per vertex one 7x7 system (and a 3x3 one where the 7x7 is
// ill-conditioned).
#include <algorithm>
#include <array>
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

/// A neighbour's normal enters the fit (its two slope equations) only within 60 degrees of the
/// vertex normal: the slope -a/c grows without bound as c = n_j . n -> 0 (on a CAD crease of 90
/// degrees c is 0 up to rounding and one slope of 1e16 decides the fit), while on a smooth surface
/// resolved by the mesh adjacent normals differ by about k h << 1 radian.
constexpr double kMinNormalCosine = 0.5;

/// The cubic is trusted when |R_ii| >= 1e-3 max |R_jj| (the safeguard of the project's polynomial
/// fits, docs/algorithms.md §5.4), in squares for the LDL^T pivots (see Ldlt); the quadratic, the
/// last model, only needs to be numerically nonsingular (|R_ii| >= 1e-6 max |R_jj|).
constexpr double kCubicTolerance2 = 1e-6;
constexpr double kQuadraticTolerance2 = 1e-12;

/// The monomials x^a y^b of degree a + b <= 6, indexed by degree, then by b: x^a y^b is at
/// (a + b)(a + b + 1)/2 + b.
constexpr int kMonomials = 28;
constexpr int monomial(int a, int b) {
  return (a + b) * (a + b + 1) / 2 + b;
}

/// The position row of eq. (9), r_i = kCoef[i] x^kPowX[i] y^kPowY[i] for the unknowns
/// (A, B, C, D, E, F, G); the slope rows of eqs. (10)-(11) are its derivatives d/dx and d/dy.
constexpr double kCoef[7] = {0.5, 1.0, 0.5, 1.0, 1.0, 1.0, 1.0};
constexpr int kPowX[7] = {2, 1, 0, 3, 2, 1, 0};
constexpr int kPowY[7] = {0, 1, 2, 0, 1, 2, 3};

/// An entry of the normal equations as a combination of monomial sums,
///   pos_coef s^2 pos[pos] + x_coef slope[x] + y_coef slope[y]
/// (matrix) or pos_coef s^2 pos_z[pos] + x_coef slope_x[x] + y_coef slope_y[y] (right-hand side),
/// with the sums of GoldfeatherEstimator::estimate; an absent term has coefficient 0.
struct Entry {
  int pos = 0;
  double pos_coef = 0.0;
  int x = 0;
  double x_coef = 0.0;
  int y = 0;
  double y_coef = 0.0;
};

/// The 28 entries (i, j), j >= i, of the upper triangle, row by row: r_i r_j, plus the products
/// of the slope rows, (d r_i/dx)(d r_j/dx) + (d r_i/dy)(d r_j/dy).
constexpr std::array<Entry, 28> kMatrixEntries = [] {
  std::array<Entry, 28> e{};
  for (int i = 0, k = 0; i < 7; ++i)
    for (int j = i; j < 7; ++j, ++k) {
      const int a = kPowX[i] + kPowX[j], b = kPowY[i] + kPowY[j];
      const double c = kCoef[i] * kCoef[j];
      e[k].pos = monomial(a, b);
      e[k].pos_coef = c;
      if (kPowX[i] > 0 && kPowX[j] > 0) {
        e[k].x = monomial(a - 2, b);
        e[k].x_coef = c * kPowX[i] * kPowX[j];
      }
      if (kPowY[i] > 0 && kPowY[j] > 0) {
        e[k].y = monomial(a, b - 2);
        e[k].y_coef = c * kPowY[i] * kPowY[j];
      }
    }
  return e;
}();

/// The right-hand side: r_i z, plus the slope rows times the slopes, (d r_i/dx) z_x +
/// (d r_i/dy) z_y.
constexpr std::array<Entry, 7> kRhsEntries = [] {
  std::array<Entry, 7> e{};
  for (int i = 0; i < 7; ++i) {
    const int a = kPowX[i], b = kPowY[i];
    e[i].pos = monomial(a, b);
    e[i].pos_coef = kCoef[i];
    if (a > 0) {
      e[i].x = monomial(a - 1, b);
      e[i].x_coef = kCoef[i] * a;
    }
    if (b > 0) {
      e[i].y = monomial(a, b - 1);
      e[i].y_coef = kCoef[i] * b;
    }
  }
  return e;
}();

struct GoldfeatherWorkspace final : Workspace {
  GoldfeatherWorkspace() {
    neighbours.reserve(32);
    local.reserve(32);
  }
  std::vector<int> neighbours;
  std::vector<Vec3> local;  ///< q_j - p in the frame (t1, t2, n), unscaled
};

/// LDL^T = P G P^T of the leading N x N block of the symmetric matrix G with Eigen::LDLT's
/// symmetric pivoting: the pivot order is that of G's diagonal, largest magnitude first (the
/// first of equal ones in Eigen's swapping order), so the pivots D_kk are the R_kk^2 of the QR of
/// the least squares with their columns in that order.
template <int N>
struct Ldlt {
  explicit Ldlt(const double (&g)[7][7]) {
    double diag[N];
    for (int k = 0; k < N; ++k) {
      perm[k] = k;
      diag[k] = std::abs(g[k][k]);
    }
    for (int k = 0; k < N; ++k) {
      int big = k;
#pragma GCC unroll 7
      for (int i = k + 1; i < N; ++i)
        if (diag[i] > diag[big]) big = i;
      std::swap(perm[k], perm[big]);
      std::swap(diag[k], diag[big]);
    }
    // The unpivoted factorisation of P G P^T in the upper triangle: D_kk on the diagonal,
    // L_ik (i > k) in a[k][i].
    for (int k = 0; k < N; ++k)
#pragma GCC unroll 7
      for (int i = k; i < N; ++i) a[k][i] = g[perm[k]][perm[i]];
#pragma GCC unroll 7
    for (int k = 0; k < N; ++k) {
      inverse[k] = 1.0 / a[k][k];
#pragma GCC unroll 7
      for (int i = k + 1; i < N; ++i) {
        const double l = a[k][i] * inverse[k];
#pragma GCC unroll 7
        for (int j = i; j < N; ++j) a[i][j] -= l * a[k][j];
        a[k][i] = l;
      }
    }
  }

  /// Whether every pivot (an R_kk^2) exceeds tolerance2 times the largest.
  bool full_rank(double tolerance2) const {
    double big = 0.0;
    for (int k = 0; k < N; ++k) big = std::max(big, std::abs(a[k][k]));
    if (!(big > 0.0) || !std::isfinite(big)) return false;
    for (int k = 0; k < N; ++k)
      if (!(a[k][k] > tolerance2 * big)) return false;
    return true;
  }

  /// The solution x of G x = b (first N entries).
  void solve(const double (&b)[7], double (&x)[7]) const {
    double y[N];
#pragma GCC unroll 7
    for (int i = 0; i < N; ++i) {
      y[i] = b[perm[i]];
#pragma GCC unroll 7
      for (int k = 0; k < i; ++k) y[i] -= a[k][i] * y[k];
    }
#pragma GCC unroll 7
    for (int i = N - 1; i >= 0; --i) {
      y[i] *= inverse[i];
#pragma GCC unroll 7
      for (int j = i + 1; j < N; ++j) y[i] -= a[i][j] * y[j];
      x[perm[i]] = y[i];
    }
  }

  int perm[N];
  double a[N][N];
  double inverse[N];  ///< 1 / D_kk
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
        if (w != v &&
            std::find(ws.neighbours.begin(), ws.neighbours.end(), w) == ws.neighbours.end())
          ws.neighbours.push_back(w);
      }
    const int points = static_cast<int>(ws.neighbours.size());
    if (points < 3) {
      set_failed(1.0, points, out);
      return;
    }
    const Vec3 n = data.normal(ctx, v);
    const LocalFrame frame = make_local_frame(n);
    const Vec3 p = mesh.position(v);
    ws.local.clear();
    double s2 = 0.0;
    for (int w : ws.neighbours) {
      const Vec3 d = mesh.position(w) - p;
      const Vec3 q(d.dot(frame.t1), d.dot(frame.t2), d.dot(frame.m));
      ws.local.push_back(q);
      s2 += q.x() * q.x() + q.y() * q.y();
    }
    const double s = std::sqrt(s2 / points);
    if (!(s > 0.0) || !std::isfinite(s)) {
      set_failed(1.0, points, out);
      return;
    }
    // Scaled coordinates X = x/s, Z = z/s: unknowns (A s, B s, C s, D s^2, E s^2, F s^2, G s^2);
    // a position residual in length units is s times its scaled residual, a slope residual is
    // the same in both. Every entry of the normal equations is a sum over the neighbours of a
    // monomial X^a Y^b (times Z or a slope on the right-hand side), so the sums are accumulated
    // once per monomial: pos over all neighbours (eq. 9), pos_z its right-hand sides, slope over
    // the neighbours whose normals are used (eqs. 10-11), slope_x and slope_y their right-hand
    // sides with the slopes -a/c and -b/c.
    const double inv_s = 1.0 / s;
    double pos[kMonomials] = {}, pos_z[kMonomials] = {}, slope[kMonomials] = {},
           slope_x[kMonomials] = {}, slope_y[kMonomials] = {};
    for (int j = 0; j < points; ++j) {
      const Vec3 q = ws.local[static_cast<size_t>(j)] * inv_s;
      const double x = q.x(), y = q.y(), z = q.z();
      // X^a Y^b at monomial(a, b), degrees 1 to 6: degree d is X times degree d - 1, and Y^d.
      double m[kMonomials];
      m[1] = x;
      m[2] = y;
#pragma GCC unroll 7
      for (int d = 2, i = 3; d <= 6; ++d, ++i) {
        for (int b = 0; b < d; ++b, ++i) m[i] = x * m[i - d];
        m[i] = y * m[i - d - 1];
      }
      for (int i = monomial(4, 0); i < kMonomials; ++i) pos[i] += m[i];
      for (int i = monomial(2, 0); i < monomial(4, 0); ++i) pos_z[i] += z * m[i];
      const Vec3 nw = data.normal(ctx, ws.neighbours[static_cast<size_t>(j)]);
      const double a = nw.dot(frame.t1), b = nw.dot(frame.t2), c = nw.dot(frame.m);
      if (!(c >= kMinNormalCosine)) continue;  // across a crease or facing away: position only
      const double inv_c = -1.0 / c, zx = a * inv_c, zy = b * inv_c;
      for (int i = monomial(2, 0); i < monomial(5, 0); ++i) slope[i] += m[i];
      for (int i = monomial(1, 0); i < monomial(3, 0); ++i) {
        slope_x[i] += zx * m[i];
        slope_y[i] += zy * m[i];
      }
    }
    double ata[7][7], atb[7];
    const double ss = s * s;
#pragma GCC unroll 7
    for (int i = 0, k = 0; i < 7; ++i) {
#pragma GCC unroll 7
      for (int j = i; j < 7; ++j, ++k) {
        const Entry& e = kMatrixEntries[static_cast<size_t>(k)];
        ata[i][j] = ata[j][i] =
            e.pos_coef * ss * pos[e.pos] + e.x_coef * slope[e.x] + e.y_coef * slope[e.y];
      }
      const Entry& e = kRhsEntries[static_cast<size_t>(i)];
      atb[i] = e.pos_coef * ss * pos_z[e.pos] + e.x_coef * slope_x[e.x] + e.y_coef * slope_y[e.y];
    }
    double coef[7];
    VertexStatus status = VertexStatus::ok;
    if (const Ldlt<7> ldlt(ata); ldlt.full_rank(kCubicTolerance2)) {
      ldlt.solve(atb, coef);
    } else {
      // The quadratic fallback: the same rows restricted to (A, B, C), i.e. the upper-left 3x3
      // block of the normal equations (the cubic coefficients set to zero).
      const Ldlt<3> ldlt3(ata);
      if (!ldlt3.full_rank(kQuadraticTolerance2)) {
        set_failed(1.0, points, out);
        return;
      }
      ldlt3.solve(atb, coef);
      status = VertexStatus::degree_reduced;
    }
    const Curvature c = curvature_from_tangent_tensor(frame.m, coef[0] / s, coef[1] / s,
                                                      coef[2] / s, frame.t1, frame.t2);
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
