// Quadric: the k-ring quadric fit of libigl's principal_curvature (D. Panozzo, E. Puppo,
// L. Rocca, "Efficient multi-scale curvature and crease estimation", Proc. Computer Graphics,
// Visualization, Computer Vision and Image Processing 2010, 9-16). Degree-free; label "Quadric".
//
// Per vertex v with unit normal n (see "Choices") and its local frame (t1, t2, n):
//   neighbourhood  the k-ring of v (k = options().rings, default 5, libigl's default radius in
//                  k-ring mode), centre included; fewer than 6 points: the normal n only,
//                  status partial (libigl fails the vertex);
//                  neighbours whose normal faces away (n_i . n <= 0) are dropped when at least
//                  6 points remain (libigl's projection-plane check)
//   points         (u, v, w) = ((x - x_v) . t1, (x - x_v) . t2, (x - x_v) . n)
//   fit            w = a u^2 + b u v + c v^2 + d u + e v  (+ f with quadric_constant), unweighted
//                  least squares (coordinates scaled by their RMS distance for conditioning;
//                  normal equations); where the facing points give a rank-deficient system,
//                  the fit is redone over the whole k-ring; rank-deficient there too (e.g. a
//                  boundary vertex of a strip one triangle wide: points on two lines) gives
//                  the normal n only, status partial, where libigl's SVD would return its
//                  minimum-norm solution
//   quantities     the height-function column of paper Table 1 at (0, 0) with f_u = d, f_v = e,
//                  f_uu = 2a, f_uv = b, f_vv = 2c (curvature_from_height): libigl's fundamental
//                  forms E, F, G, L, M, N of the quadric give the same shape operator. The
//                  normal is the quadric's, (-d, -e, 1) normalised in the frame.
// Sign convention (estimator.h): with the outward normal as the w axis a sphere gives
// w ~ -(u^2 + v^2)/(2r), so k = -1/r directly (libigl negates its eigenvalues and reports +1/r).
// Choices (libigl's defaults): the area-weighted vertex normal for the frame and the
// projection-plane check (option EstimatorOptions::vertex_normals); 5 coefficients through the
// vertex (option EstimatorOptions::quadric_constant: 6); ring 5 (option rings, `--rings`, an
// integer 1..64).
// Boundary vertices: the k-ring is one-sided but the fit is defined (as in libigl): status ok.
// Cost: O(k^2) points per vertex; the k-ring by a breadth-first search over per-mesh neighbour
// lists (prepare()), in the order of mesh/rings.h, without branches on the visited marks.
#include <Eigen/Cholesky>
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <memory>
#include <span>
#include <string>
#include <vector>

#include "core/errors.h"
#include "core/shape_operator.h"
#include "core/text.h"
#include "methods/local_frame.h"
#include "methods/operators/operator_estimator.h"
#include "methods/vertex_result.h"

namespace curvbench {

namespace {

constexpr int kMinPoints = 6;  // libigl: at least 6 points, centre included
constexpr double kDefaultRing = 5.0;

/// Per-mesh data: the edge neighbours of every vertex, in the order in which a k-ring search
/// through the faces (mesh/rings.h) meets them (faces in increasing index, corners 0, 1, 2), so
/// that a breadth-first search over these lists finds the k-ring in RingCollector's order.
struct QuadricData final : OperatorMeshData {
  std::vector<int> offsets;  ///< n + 1
  std::vector<int> adjacent;
  std::span<const int> neighbours(int v) const {
    return {adjacent.data() + offsets[static_cast<size_t>(v)],
            adjacent.data() + offsets[static_cast<size_t>(v) + 1]};
  }
};

struct QuadricWorkspace final : Workspace {
  explicit QuadricWorkspace(const Mesh& mesh)
      : stamp(static_cast<size_t>(mesh.num_vertices()), 0),
        ring(static_cast<size_t>(mesh.num_vertices()) + 1) {
    keep.reserve(256);
    local.reserve(3 * 256);
  }
  std::vector<std::uint32_t> stamp;  ///< == current: in the ring being collected
  std::uint32_t current = 0;
  /// The centre, then the k-ring in discovery order (room for every vertex, so that the search
  /// can write without a branch)
  std::vector<int> ring;
  std::vector<int> keep;
  std::vector<double> local;  ///< (u, v, w) of each kept point, 3 per point
};

/// Appends to `out` the neighbours of v (see QuadricData), each once; returns how many.
int list_neighbours(const Mesh& mesh, int v, int* out) {
  int count = 0;
  for (int f : mesh.vertex_faces(v))
    for (int k = 0; k < 3; ++k) {
      const int w = mesh.face_vertex(f, k);
      bool seen = w == v;
      for (int i = 0; i < count && !seen; ++i) seen = out[i] == w;
      if (!seen) out[count++] = w;
    }
  return count;
}

class QuadricEstimator final : public OperatorEstimator {
 public:
  explicit QuadricEstimator(EstimatorOptions options)
      : OperatorEstimator(options, VertexNormals::area, /*ring_option=*/true) {
    const double r = options_.rings;
    if (!(r == 0.0 || (std::isfinite(r) && r >= 1.0 && r == std::round(r) && r <= 64.0)))
      throw UsageError("quadric: ring " + format_g(r) +
                       " is not supported (valid: 0 = default 5, or an integer 1..64)");
  }

  std::string name() const override { return "quadric"; }
  std::string display_name() const override { return "Quadric"; }
  double default_ring() const override { return kDefaultRing; }

  std::unique_ptr<Workspace> make_workspace(const Mesh& mesh) const override {
    return std::make_unique<QuadricWorkspace>(mesh);
  }

  std::unique_ptr<MeshData> prepare(const Mesh& mesh, const VertexMatrix&,
                                    int threads) const override {
    auto data = std::make_unique<QuadricData>();
    fill_mesh_data(mesh, threads, *data);
    const int n = mesh.num_vertices();
    data->offsets.assign(static_cast<size_t>(n) + 1, 0);
    // Counts, offsets, then the lists (a vertex has at most 2 neighbours per face).
    int max_valence = 0;
    for (int v = 0; v < n; ++v)
      max_valence = std::max(max_valence, static_cast<int>(mesh.vertex_faces(v).size()));
    const int t = std::max(1, threads);
#pragma omp parallel num_threads(t)
    {
      std::vector<int> buffer(2 * static_cast<size_t>(max_valence) + 1);
#pragma omp for schedule(static)
      for (int v = 0; v < n; ++v)
        data->offsets[static_cast<size_t>(v) + 1] = list_neighbours(mesh, v, buffer.data());
#pragma omp single
      {
        for (int v = 0; v < n; ++v)
          data->offsets[static_cast<size_t>(v) + 1] += data->offsets[static_cast<size_t>(v)];
        data->adjacent.resize(static_cast<size_t>(data->offsets.back()));
      }
#pragma omp for schedule(static)
      for (int v = 0; v < n; ++v)
        list_neighbours(mesh, v, data->adjacent.data() + data->offsets[static_cast<size_t>(v)]);
    }
    return data;
  }

  void estimate(const MeshContext& ctx, int v, Workspace& base,
                VertexEstimate& out) const override {
    auto& ws = static_cast<QuadricWorkspace&>(base);
    const Mesh& mesh = ctx.mesh;
    const auto& data = static_cast<const QuadricData&>(*ctx.data);
    const double ring = options_.rings > 0.0 ? options_.rings : kDefaultRing;
    // The integer k-ring (the vertices within k edges of v), breadth first.
    if (++ws.current == 0) {  // stamps wrapped: clear
      std::fill(ws.stamp.begin(), ws.stamp.end(), 0);
      ws.current = 1;
    }
    int* found = ws.ring.data();
    std::uint32_t* stamp = ws.stamp.data();
    const std::uint32_t current = ws.current;
    found[0] = v;
    stamp[v] = current;
    size_t size = 1, layer_begin = 0;
    for (int step = 0; step < static_cast<int>(ring); ++step) {
      const size_t layer_end = size;
      for (size_t i = layer_begin; i < layer_end; ++i)
        for (int w : data.neighbours(found[i])) {
          // Always written, kept only if new (size grows by 0 or 1): no mispredicted branch.
          const size_t fresh = stamp[w] != current ? 1 : 0;
          stamp[w] = current;
          found[size] = w;
          size += fresh;
        }
      layer_begin = layer_end;
    }
    const std::span<const int> nb(found + 1, size - 1);
    const VertexMatrix& normals = data.normals.rows() > 0 ? data.normals : ctx.approx_normals;
    const Vec3 n = normals.row(v).transpose();
    if (1 + static_cast<int>(nb.size()) < kMinPoints) {
      set_normal_only(n, 1 + static_cast<int>(nb.size()), ring, out);
      return;
    }
    ws.keep.clear();
    for (int w : nb)
      if (normals.row(w).dot(n) > 0.0) ws.keep.push_back(w);
    if (1 + static_cast<int>(ws.keep.size()) < kMinPoints) ws.keep.assign(nb.begin(), nb.end());
    const LocalFrame frame = make_local_frame(n);
    if (fit(mesh, v, frame, ring, ws, out)) return;
    // The facing points alone do not determine the quadric (e.g. a thin wall whose far side
    // turns away, leaving points on a line): the whole k-ring, as when too few of them face.
    if (ws.keep.size() < nb.size()) {
      ws.keep.assign(nb.begin(), nb.end());
      if (fit(mesh, v, frame, ring, ws, out)) return;
    }
    set_normal_only(n, 1 + static_cast<int>(ws.keep.size()), ring, out);
  }

 private:
  // The fit over the points ws.keep (and the centre v) in `frame`; false, with `out` untouched
  // or partly written, if the system is rank-deficient or the result not finite.
  bool fit(const Mesh& mesh, int v, const LocalFrame& frame, double ring, QuadricWorkspace& ws,
           VertexEstimate& out) const {
    const Vec3 x0 = mesh.position(v);
    // Local coordinates (u, v, w) of the points, once; RMS tangent distance s: the scale of the
    // (u, v) coordinates.
    const size_t count = ws.keep.size();
    ws.local.resize(3 * count);
    double s2 = 0.0;
    for (size_t i = 0; i < count; ++i) {
      const Vec3 d = mesh.position(ws.keep[i]) - x0;
      const double u = d.dot(frame.t1), t = d.dot(frame.t2);
      ws.local[3 * i] = u;
      ws.local[3 * i + 1] = t;
      ws.local[3 * i + 2] = d.dot(frame.m);
      s2 += u * u + t * t;
    }
    const double s = std::sqrt(s2 / static_cast<double>(count));
    const int points = 1 + static_cast<int>(count);
    if (!(s > 0.0) || !std::isfinite(s)) return false;
    const bool constant = options_.quadric_constant;
    const double inv = 1.0 / s;
    Eigen::Matrix<double, 6, 6> ata;
    Eigen::Matrix<double, 6, 1> atb;
    if (constant)
      normal_equations<6>(ws.local, inv, ata, atb);
    else
      normal_equations<5>(ws.local, inv, ata, atb);
    Eigen::Matrix<double, 6, 1> coef = Eigen::Matrix<double, 6, 1>::Zero();
    if (constant) {
      const Eigen::LDLT<Eigen::Matrix<double, 6, 6>> ldlt(ata);
      if (!solvable(ldlt.vectorD())) return false;
      coef = ldlt.solve(atb);
    } else {
      const Eigen::LDLT<Eigen::Matrix<double, 5, 5>> ldlt(ata.topLeftCorner<5, 5>());
      if (!solvable(ldlt.vectorD())) return false;
      coef.head<5>() = ldlt.solve(atb.head<5>());
    }
    // Back to unscaled coordinates: w = s W(u/s, v/s), so second derivatives divide by s.
    const Curvature c =
        curvature_from_height(frame.t1, frame.t2, frame.m, coef(3), coef(4), 2.0 * coef(0) * inv,
                              coef(1) * inv, 2.0 * coef(2) * inv);
    return set_operator_quantities(c, computes(), points, ring, out) &&
           out.status == VertexStatus::ok;
  }

  // The normal equations of the rows (u^2, u v, v^2, u, v[, 1]) . coef = w over the points
  // (u, v, w) = inv * local[3i .. 3i+2] and the centre (0, 0, 0), in one pass: the upper
  // triangle of the N x N matrix is accumulated, then mirrored.
  template <int N>
  static void normal_equations(const std::vector<double>& local, double inv,
                               Eigen::Matrix<double, 6, 6>& ata, Eigen::Matrix<double, 6, 1>& atb) {
    double a[N * (N + 1) / 2] = {};
    double b[N] = {};
    // The products written out (a row array here made GCC store and reload it every point).
    // Upper-triangle index of (r, c): row r starts at r N - r (r - 1) / 2.
    for (size_t i = 0; i < local.size(); i += 3) {
      const double u = local[i] * inv, t = local[i + 1] * inv, w = local[i + 2] * inv;
      const double uu = u * u, ut = u * t, tt = t * t;
      constexpr int r1 = N, r2 = 2 * N - 1, r3 = 3 * N - 3, r4 = 4 * N - 6;
      a[0] += uu * uu;
      a[1] += uu * ut;
      a[2] += uu * tt;
      a[3] += uu * u;
      a[4] += uu * t;
      a[r1] += ut * ut;
      a[r1 + 1] += ut * tt;
      a[r1 + 2] += ut * u;
      a[r1 + 3] += ut * t;
      a[r2] += tt * tt;
      a[r2 + 1] += tt * u;
      a[r2 + 2] += tt * t;
      a[r3] += u * u;
      a[r3 + 1] += u * t;
      a[r4] += t * t;
      if constexpr (N == 6) {  // the column of the constant term: row[5] = 1
        a[5] += uu;
        a[r1 + 4] += ut;
        a[r2 + 3] += tt;
        a[r3 + 2] += u;
        a[r4 + 1] += t;
        a[r4 + 2] += 1.0;
        b[5] += w;
      }
      b[0] += w * uu;
      b[1] += w * ut;
      b[2] += w * tt;
      b[3] += w * u;
      b[4] += w * t;
    }
    if (N == 6) a[N * (N + 1) / 2 - 1] += 1.0;  // the centre row (0, 0, 0, 0, 0, 1), w = 0
    ata.setZero();
    atb.setZero();
    int k = 0;
    for (int r = 0; r < N; ++r) {
      for (int c = r; c < N; ++c) ata(r, c) = ata(c, r) = a[k++];
      atb(r) = b[r];
    }
  }

  // Full rank: every pivot of the LDLT is clearly positive.
  template <class D>
  static bool solvable(const D& d) {
    const double big = d.cwiseAbs().maxCoeff();
    return big > 0.0 && std::isfinite(big) && d.minCoeff() > 1e-12 * big;
  }
};

}  // namespace

std::unique_ptr<Estimator> make_quadric_estimator(EstimatorOptions options) {
  return std::make_unique<QuadricEstimator>(options);
}

}  // namespace curvbench
