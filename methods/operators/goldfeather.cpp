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
// The quadratic numerically singular too (e.g. the neighbours on two lines through p): the normal
// n only, status partial; also where fewer than 3 neighbours leave nothing to fit. Failed: no
// vertex normal (an isolated vertex).
// Boundary vertices: the fit needs no closed 1-ring (at least 3 neighbours give 9 >= 7 equations):
// computed on the neighbours they have, status ok (degree_reduced as above).
// Cost: per neighbour 47 monomial sums; per vertex one 7x7 system (and a 3x3 one where the 7x7 is
// ill-conditioned). estimate_mesh() runs kBatchLanes vertices at once, one per SIMD lane
// (estimate_batch, goldfeather_batch.h): the frames, the sums, the normal equations, the pivoted
// LDL^T of the cubic and the curvature of the tensor lane-wise, with the scalar path's bits
// (tests/methods/test_goldfeather.cpp); 1.2x LHF-2's throughput on the level-4 torus instead of
// 0.7x.
#include <algorithm>
#include <cmath>
#include <memory>
#include <string>
#include <vector>

#include "core/shape_operator.h"
#include "mesh/rings.h"
#include "methods/kernels/batched_curvature.h"
#include "methods/kernels/goldfeather_batch.h"
#include "methods/local_frame.h"
#include "methods/operators/operator_estimator.h"
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

struct GoldfeatherWorkspace final : Workspace {
  explicit GoldfeatherWorkspace(const Mesh& mesh) : rings(mesh) { local.reserve(32); }
  RingCollector rings;      ///< the 1-ring: each neighbour once, in the order the faces list them
  std::vector<Vec3> local;  ///< q_j - p in the frame (t1, t2, n), unscaled
  std::unique_ptr<GoldfeatherBatch> batch = std::make_unique<GoldfeatherBatch>();
};

// The neighbours in the frame (t1, t2, n) into ws.local, unscaled; returns their RMS distance
// s in the tangent plane (the scale of the fit), or 0 if it is not positive and finite.
double local_coordinates(const Mesh& mesh, int v, const LocalFrame& frame,
                         GoldfeatherWorkspace& ws) {
  const Vec3 p = mesh.position(v);
  ws.local.clear();
  double s2 = 0.0;
  for (int w : ws.rings.neighbours()) {
    const Vec3 d = mesh.position(w) - p;
    const Vec3 q(d.dot(frame.t1), d.dot(frame.t2), d.dot(frame.m));
    ws.local.push_back(q);
    s2 += q.x() * q.x() + q.y() * q.y();
  }
  const double s = std::sqrt(s2 / static_cast<double>(ws.rings.neighbours().size()));
  return s > 0.0 && std::isfinite(s) ? s : 0.0;
}

// Neighbour j's scaled coordinates X = x/s, Y, Z and, if its normal is used, its slopes.
struct NeighbourTerms {
  double x, y, z;
  bool use_normal;
  double zx, zy;
};

NeighbourTerms neighbour_terms(const MeshContext& ctx, const OperatorMeshData& data,
                               const LocalFrame& frame, const GoldfeatherWorkspace& ws, size_t j,
                               double inv_s) {
  const Vec3 q = ws.local[j] * inv_s;
  const Vec3 nw = data.normal(ctx, ws.rings.neighbours()[j]);
  const double a = nw.dot(frame.t1), b = nw.dot(frame.t2), c = nw.dot(frame.m);
  if (!(c >= kMinNormalCosine))  // across a crease or facing away: position only
    return {q.x(), q.y(), q.z(), false, 0.0, 0.0};
  const double inv_c = -1.0 / c;
  return {q.x(), q.y(), q.z(), true, a * inv_c, b * inv_c};
}

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

  std::unique_ptr<Workspace> make_workspace(const Mesh& mesh) const override {
    return std::make_unique<GoldfeatherWorkspace>(mesh);
  }

  void estimate(const MeshContext& ctx, int v, Workspace& base,
                VertexEstimate& out) const override {
    auto& ws = static_cast<GoldfeatherWorkspace&>(base);
    ws.rings.collect_integer(v, 1);
    const int points = static_cast<int>(ws.rings.neighbours().size());
    const OperatorMeshData& data = mesh_data(ctx);
    const Vec3 n = data.normal(ctx, v);
    if (points < 3 || !n.allFinite()) {
      set_normal_only(n, points, 1.0, out);
      return;
    }
    const LocalFrame frame = make_local_frame(n);
    const double s = local_coordinates(ctx.mesh, v, frame, ws);
    if (s == 0.0) {
      set_normal_only(n, points, 1.0, out);
      return;
    }
    // Scaled coordinates X = x/s, Z = z/s: unknowns (A s, B s, C s, D s^2, E s^2, F s^2, G s^2);
    // a position residual in length units is s times its scaled residual, a slope residual is
    // the same in both. Every entry of the normal equations is a sum over the neighbours of a
    // monomial X^a Y^b (times Z or a slope on the right-hand side), so the sums are accumulated
    // once per monomial (goldfeather_batch.h).
    const double inv_s = 1.0 / s;
    GoldfeatherSums sums;
    for (size_t j = 0; j < ws.local.size(); ++j) {
      const NeighbourTerms t = neighbour_terms(ctx, data, frame, ws, j, inv_s);
      add_goldfeather_neighbour(t.x, t.y, t.z, t.use_normal, t.zx, t.zy, sums);
    }
    double w[3];
    VertexStatus status = VertexStatus::ok;
    if (!solve(sums, s, w, status)) {
      set_normal_only(frame.m, points, 1.0, out);
      return;
    }
    set_result(curvature_from_tangent_tensor(frame.m, w[0], w[1], w[2], frame.t1, frame.t2), status,
               points, out);
  }

  // Estimates kBatchLanes vertices at a time, one per lane (goldfeather_batch.h,
  // batched_curvature.h; the scalar path's bits): the frames, the fit of the cubic and the
  // curvature of its tensor lane-wise, the 1-ring, the local coordinates and the quadratic
  // fallback per vertex. A vertex the batch does not take (fewer than 3 or more than
  // kGoldfeatherMaxNeighbours neighbours, a frame the lane-wise code leaves out, a zero scale)
  // goes through estimate().
  void estimate_batch(const MeshContext& ctx, int first, int count, Workspace& base,
                      VertexEstimate* out) const override {
    auto& ws = static_cast<GoldfeatherWorkspace&>(base);
    const OperatorMeshData& data = mesh_data(ctx);
    GoldfeatherBatch& batch = *ws.batch;
    batch.cubic_tolerance2 = kCubicTolerance2;
    constexpr int L = kBatchLanes;
    alignas(64) double normals[3 * L] = {};
    BatchedFrames frames;
    for (int b = 0; b < count; b += L) {
      const int lanes = std::min(L, count - b);
      for (int l = 0; l < lanes; ++l) {
        const Vec3 n = data.normal(ctx, first + b + l);
        for (int c = 0; c < 3; ++c) normals[c * L + l] = n(c);
      }
      batched_local_frames(normals, frames);
      int points[L] = {};     // 0: the lane goes through estimate()
      batch.scale.fill(1.0);  // an unused lane's scale
      batch.slots = 0;
      for (int l = 0; l < lanes; ++l) {
        const int v = first + b + l;
        ws.rings.collect_integer(v, 1);
        const int n = static_cast<int>(ws.rings.neighbours().size());
        if (n < 3 || n > kGoldfeatherMaxNeighbours || !frames.regular[static_cast<size_t>(l)])
          continue;
        const LocalFrame frame = frames.frame(l);
        const double s = local_coordinates(ctx.mesh, v, frame, ws);
        if (s == 0.0) continue;
        const double inv_s = 1.0 / s;
        for (int j = 0; j < n; ++j) {
          const NeighbourTerms t =
              neighbour_terms(ctx, data, frame, ws, static_cast<size_t>(j), inv_s);
          const auto at = static_cast<size_t>(j * L + l);
          batch.x[at] = t.x;
          batch.y[at] = t.y;
          batch.z[at] = t.z;
          batch.use[at] = t.use_normal ? 1.0 : 0.0;
          batch.zx[at] = t.zx;
          batch.zy[at] = t.zy;
        }
        points[l] = n;
        batch.scale[static_cast<size_t>(l)] = s;
        batch.slots = std::max(batch.slots, n);
      }
      // Padding: zero slots add nothing to a lane's sums.
      for (int l = 0; l < L; ++l)
        for (int j = points[l]; j < batch.slots; ++j) {
          const auto at = static_cast<size_t>(j * L + l);
          batch.x[at] = batch.y[at] = batch.z[at] = batch.use[at] = batch.zx[at] = batch.zy[at] =
              0.0;
        }
      goldfeather_fit_lanes(batch);
      // The cubic's tensor, or the quadratic fallback per vertex.
      alignas(64) double w11[L] = {}, w12[L] = {}, w22[L] = {};
      VertexStatus status[L] = {};
      bool solved[L] = {};
      for (int l = 0; l < lanes; ++l) {
        if (points[l] == 0) continue;
        double w[3] = {};
        if (batch.cubic_ok[static_cast<size_t>(l)] != 0.0) {
          for (int c = 0; c < 3; ++c) w[c] = batch.w[static_cast<size_t>(c * L + l)];
          status[l] = VertexStatus::ok;
          solved[l] = true;
        } else {
          double ata[7][7], atb[7];
          for (int r = 0; r < 7; ++r) {
            for (int c = 0; c < 7; ++c)
              ata[r][c] = batch.ata[static_cast<size_t>((r * 7 + c) * L + l)];
            atb[r] = batch.atb[static_cast<size_t>(r * L + l)];
          }
          status[l] = VertexStatus::degree_reduced;
          solved[l] = solve_quadratic(ata, atb, batch.scale[static_cast<size_t>(l)], w);
        }
        w11[l] = w[0];
        w12[l] = w[1];
        w22[l] = w[2];
      }
      BatchedCurvature curvature;
      batched_curvature_from_tangent_tensor(frames, w11, w12, w22, curvature);
      for (int l = 0; l < lanes; ++l) {
        VertexEstimate& o = out[b + l];
        if (points[l] == 0) {
          estimate(ctx, first + b + l, base, o);
        } else if (!solved[l]) {
          set_normal_only(frames.frame(l).m, points[l], 1.0, o);
        } else if (curvature.regular[static_cast<size_t>(l)]) {
          set_result(curvature.curvature(l), status[l], points[l], o);
        } else {
          const LocalFrame f = frames.frame(l);
          set_result(curvature_from_tangent_tensor(f.m, w11[l], w12[l], w22[l], f.t1, f.t2),
                     status[l], points[l], o);
        }
      }
    }
  }

 private:
  void set_result(const Curvature& c, VertexStatus status, int points, VertexEstimate& out) const {
    if (set_operator_quantities(c, computes(), points, 1.0, out) && out.status == VertexStatus::ok)
      out.status = status;
  }

  // The normal equations from the sums and the cubic (or the quadratic fallback): the Weingarten
  // tensor [A B; B C] in w and the status, or false if both fits are singular.
  static bool solve(const GoldfeatherSums& sums, double s, double (&w)[3], VertexStatus& status) {
    double ata[7][7], atb[7];
    goldfeather_normal_equations(sums, s, ata, atb);
    status = VertexStatus::ok;
    if (const Ldlt<7> ldlt(ata); ldlt.full_rank(kCubicTolerance2)) {
      double coef[7];
      ldlt.solve(atb, coef);
      for (int i = 0; i < 3; ++i) w[i] = coef[i] / s;
      return true;
    }
    status = VertexStatus::degree_reduced;
    return solve_quadratic(ata, atb, s, w);
  }

  // The quadratic fallback: the same rows restricted to (A, B, C), i.e. the upper-left 3x3 block
  // of the normal equations (the cubic coefficients set to zero); false if it is singular too.
  static bool solve_quadratic(const double (&ata)[7][7], const double (&atb)[7], double s,
                              double (&w)[3]) {
    const Ldlt<3> ldlt3(ata);
    if (!ldlt3.full_rank(kQuadraticTolerance2)) return false;
    double coef[7];
    ldlt3.solve(atb, coef);
    for (int i = 0; i < 3; ++i) w[i] = coef[i] / s;
    return true;
  }
};

}  // namespace

std::unique_ptr<Estimator> make_goldfeather_estimator(EstimatorOptions options) {
  return std::make_unique<GoldfeatherEstimator>(options);
}

}  // namespace curvbench
