// Normal cycle: the curvature tensor of D. Cohen-Steiner and J.-M. Morvan, "Restricted Delaunay
// triangulations and normal cycle", Proc. 19th ACM Symposium on Computational Geometry (2003),
// 312-321. Degree-free; label "Normal-cycle".
//
// Per vertex v with region B (see below) and unit vertex normal n:
//   T = 1/|B| sum over the edges e of  beta(e) |e n B| e^ e^^T                        (§5)
//   e^       the unit edge vector; beta(e) the signed angle between the normals of the two faces
//            of e, positive on a convex edge (beta = atan2((n_f x n_g) . e^, n_f . n_g), e^
//            oriented as in face f); |e n B| the length of e inside B
//   T is restricted to the tangent plane of n (2x2 in the frame (t1, t2)); its eigenvalues
//   l1 >= l2 with eigenvectors e1, e2. The eigenvectors are swapped (the paper: the direction of
//   the larger bending is across the edges): with the paper's convex-positive sign the maximal
//   curvature l1 lies along e2; in our sign (B = n . x_uu, estimator.h) k = -l, so
//   k1 = -l2 with d1 = e1 and k2 = -l1 with d2 = e2; H = (k1 + k2)/2, K = k1 k2.
// Regions (option EstimatorOptions::ball_factor = c):
//   c = 0 (default), the 1-ring: B = the faces at v; the edges at v count fully and the edges of
//          the link (on the border of B, shared with the neighbours' regions) with half their
//          length, so that every edge is counted once per unit area on a regular mesh; |B| = the
//          area of the faces at v.
//   c > 0, the ball of radius r = c h (h = the mesh's mean edge length) centred at v: every edge
//          with a part inside the ball counts with the length of that part; |B| = pi r^2 (the
//          area of the surface inside the ball up to O(r^2 kappa^2)).
// Choices: the paper leaves the normal open (T's third eigenvector estimates it); we use the
// area-weighted vertex normal (option EstimatorOptions::vertex_normals, which may also name a
// fit whose normals to take, e.g. lhf-3: status normal_fallback where it gives none) for the
// tangent plane and report it. No public code of the authors exists; the 1-ring variant is the
// one of Alliez et al. 2003 ("Anisotropic polygonal remeshing"), the ball one the paper's.
// Boundary: an edge of B without a second face has no dihedral angle; a vertex whose region
// reaches the boundary is excluded (values NaN). Non-finite values: failed.
// Cost: prepare(), one unit normal per face and one atan2 per interior edge; estimate(), 1-ring,
// O(1) per incident face; ball, O(faces in the ball).
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <memory>
#include <numbers>
#include <string>
#include <vector>

#include "core/errors.h"
#include "core/huge_pages.h"
#include "core/shape_operator.h"
#include "core/text.h"
#include "methods/local_frame.h"
#include "methods/operators/face_ball.h"
#include "methods/operators/face_geometry.h"
#include "methods/operators/operator_estimator.h"
#include "methods/vertex_result.h"

namespace curvbench {

namespace {

/// Per-mesh data: the signed dihedral angle of every face edge, computed once per mesh (each
/// interior edge is visited from 2 faces at each of 4 vertices by estimate()).
struct NormalCycleData final : OperatorMeshData {
  /// beta[3 f + k] of edge k of face f (F(f,k) -> F(f,k+1)); NaN on the boundary
  std::vector<double> beta;
};

Vec3 face_normal(const Mesh& mesh, int f) {
  const Vec3 a = mesh.position(mesh.face_vertex(f, 0));
  return (mesh.position(mesh.face_vertex(f, 1)) - a)
      .cross(mesh.position(mesh.face_vertex(f, 2)) - a)
      .normalized();
}

// Signed dihedral angle of edge k of face f (f's orientation) with the face of unit normal ng
// across it, positive when convex; nf: f's unit normal.
double dihedral(const Mesh& mesh, int f, int k, const Vec3& nf, const Vec3& ng) {
  const Vec3 a = mesh.position(mesh.face_vertex(f, k));
  const Vec3 e = mesh.position(mesh.face_vertex(f, (k + 1) % 3)) - a;
  const Vec3 edge_unit = e / e.norm();
  return std::atan2(nf.cross(ng).dot(edge_unit), nf.dot(ng));
}

// Length of the segment [a, b] inside the ball of radius r centred at c.
double length_in_ball(const Vec3& a, const Vec3& b, const Vec3& c, double r) {
  const Vec3 d = b - a;
  const double len2 = d.squaredNorm();
  if (!(len2 > 0.0)) return 0.0;
  // |a + t d - c|^2 = r^2: t^2 len2 + 2 t d.(a - c) + |a - c|^2 - r^2 = 0.
  const Vec3 ac = a - c;
  const double p = d.dot(ac) / len2, q = (ac.squaredNorm() - r * r) / len2;
  const double disc = p * p - q;
  if (disc <= 0.0) return 0.0;
  const double s = std::sqrt(disc);
  const double t0 = std::max(0.0, -p - s), t1 = std::min(1.0, -p + s);
  return t1 > t0 ? (t1 - t0) * std::sqrt(len2) : 0.0;
}

class NormalCycleEstimator final : public OperatorEstimator {
 public:
  explicit NormalCycleEstimator(EstimatorOptions options)
      : OperatorEstimator(options, VertexNormals::area, false, FittedNormals::accepted) {}

  std::string name() const override { return "normal-cycle"; }
  std::string display_name() const override { return "Normal-cycle"; }
  /// Vertices whose region reaches the boundary are excluded by design: scored over the
  /// interior, like Xu (the excluded vertices next to the boundary are still counted).
  bool scores_interior_only() const override { return true; }

  std::unique_ptr<Workspace> make_workspace(const Mesh& mesh) const override {
    if (options_.ball_factor > 0.0) return std::make_unique<FaceBallWorkspace>(mesh);
    return std::make_unique<Workspace>();
  }

  std::unique_ptr<MeshData> prepare(const Mesh& mesh, const VertexMatrix&,
                                    int threads) const override {
    auto data = std::make_unique<NormalCycleData>();
    fill_mesh_data(mesh, threads, *data);
    const int m = mesh.num_faces();
    reserve_huge(data->beta, 3 * static_cast<size_t>(m));
    data->beta.resize(3 * static_cast<size_t>(m));
    double* beta = data->beta.data();
    // Each interior edge once, from its face of smaller index f, written to both faces' slots:
    // seen from g the edge and the cross product of the normals both change sign (an
    // inconsistently oriented pair: only the cross product does, so beta does).
    // The unit face normals first, once each (an edge needs both of its faces' normals).
    std::vector<Vec3> normals;
    reserve_huge(normals, static_cast<size_t>(m));
    normals.resize(static_cast<size_t>(m));  // Eigen leaves the entries uninitialised
    const int t = threads > 0 ? threads : 1;
#pragma omp parallel num_threads(t)
    {
#pragma omp for schedule(static)
      for (int f = 0; f < m; ++f) normals[static_cast<size_t>(f)] = face_normal(mesh, f);
#pragma omp for schedule(static)
      for (int f = 0; f < m; ++f) {
        const Vec3& nf = normals[static_cast<size_t>(f)];
        for (int k = 0; k < 3; ++k) {
          const int g = mesh.face_neighbor(f, k);
          if (g < 0) {
            beta[3 * static_cast<size_t>(f) + k] = std::numeric_limits<double>::quiet_NaN();
            continue;
          }
          if (g < f) continue;
          const double b = dihedral(mesh, f, k, nf, normals[static_cast<size_t>(g)]);
          beta[3 * static_cast<size_t>(f) + k] = b;
          // g's copy of the edge (its end points, either way round; it exists since g is f's
          // neighbour across it).
          const int a = mesh.face_vertex(f, k), b_end = mesh.face_vertex(f, (k + 1) % 3);
          int kg = 0;
          while (kg < 2 && !((mesh.face_vertex(g, kg) == a || mesh.face_vertex(g, kg) == b_end) &&
                             (mesh.face_vertex(g, (kg + 1) % 3) == a ||
                              mesh.face_vertex(g, (kg + 1) % 3) == b_end)))
            ++kg;
          const bool reversed = mesh.face_vertex(g, kg) == b_end;
          beta[3 * static_cast<size_t>(g) + kg] = reversed ? b : -b;
        }
      }
    }
    return data;
  }

  void estimate(const MeshContext& ctx, int v, Workspace& base,
                VertexEstimate& out) const override {
    const Mesh& mesh = ctx.mesh;
    const auto faces = mesh.vertex_faces(v);
    if (faces.empty()) {
      set_failed(1.0, 0, out);
      return;
    }
    const auto& data = static_cast<const NormalCycleData&>(*ctx.data);
    const Vec3 n = data.normal(ctx, v);
    const LocalFrame frame = make_local_frame(n);
    double t11 = 0.0, t12 = 0.0, t22 = 0.0, area = 0.0;
    bool boundary = false;
    int edges = 0;
    // beta |e n B| e^ e^^T in the tangent frame: e^ = e / |e|, w = beta |e n B| / |e|^2.
    const auto add = [&](const Vec3& e, double beta, double length, double len2) {
      if (std::isnan(beta)) {
        boundary = true;
        return;
      }
      const double u = e.dot(frame.t1), t = e.dot(frame.t2), w = beta * length / len2;
      t11 += w * u * u;
      t12 += w * u * t;
      t22 += w * t * t;
      ++edges;
    };
    if (options_.ball_factor == 0.0) {
      for (int f : faces) {
        const int i = corner_of(mesh, f, v);
        const Vec3 x0 = mesh.position(v);
        const Vec3 x1 = mesh.position(mesh.face_vertex(f, (i + 1) % 3));
        const Vec3 x2 = mesh.position(mesh.face_vertex(f, (i + 2) % 3));
        area += 0.5 * (x1 - x0).cross(x2 - x0).norm();
        // The edge v -> x1 (edge i of f): each edge at v is edge "from v" of exactly one face;
        // the edge x2 -> v of a boundary fan has no second face.
        const Vec3 e01 = x1 - x0;
        const double len2_01 = e01.squaredNorm();
        add(e01, data.beta[3 * static_cast<size_t>(f) + i], std::sqrt(len2_01), len2_01);
        if (mesh.face_neighbor(f, (i + 2) % 3) < 0) boundary = true;
        // The link edge x1 -> x2 (edge i+1 of f), half its length.
        const Vec3 e12 = x2 - x1;
        const double len2_12 = e12.squaredNorm();
        add(e12, data.beta[3 * static_cast<size_t>(f) + (i + 1) % 3], 0.5 * std::sqrt(len2_12),
            len2_12);
      }
    } else {
      auto& ws = static_cast<FaceBallWorkspace&>(base);
      const double r = options_.ball_factor * mesh.mean_edge_length();
      area = std::numbers::pi * r * r;
      const Vec3 c = mesh.position(v);
      walk_face_ball(faces, ws, [&](int f, auto&& enqueue) {
        for (int k = 0; k < 3; ++k) {
          const Vec3 a = mesh.position(mesh.face_vertex(f, k));
          const Vec3 b = mesh.position(mesh.face_vertex(f, (k + 1) % 3));
          const double inside = length_in_ball(a, b, c, r);
          if (!(inside > 0.0)) continue;
          const int g = mesh.face_neighbor(f, k);
          if (g < 0) {
            boundary = true;
            continue;
          }
          if (f < g)
            add(b - a, data.beta[3 * static_cast<size_t>(f) + k], inside, (b - a).squaredNorm());
          enqueue(g);
        }
      });
    }
    const double ring = options_.ball_factor > 0.0 ? 0.0 : 1.0;
    if (boundary) {
      set_excluded(ring, edges, out);
      return;
    }
    double l1, l2;
    Curvature cv;
    cv.normal = frame.m;
    principal_from_symmetric(t11 / area, t12 / area, t22 / area, frame.t1, frame.t2, l1, l2, cv.d1,
                             cv.d2);
    cv.k1 = -l2;
    cv.k2 = -l1;
    cv.H = 0.5 * (cv.k1 + cv.k2);
    cv.K = cv.k1 * cv.k2;
    if (!set_operator_quantities(cv, computes(), edges, ring, out)) set_failed(ring, edges, out);
    mark_fallback(data.fell_back(v), out);  // only v's own normal is read
  }
};

}  // namespace

std::unique_ptr<Estimator> make_normal_cycle_estimator(EstimatorOptions options) {
  return std::make_unique<NormalCycleEstimator>(options);
}

}  // namespace curvbench
