// Interpolated corrected curvature measures (ICC): J.-O. Lachaud, P. Romon, B. Thibert,
// D. Coeurjolly, "Interpolated corrected curvature measures for polygonal surfaces", Computer
// Graphics Forum 39(5), 2020, and "Corrected curvature measures", Discrete & Computational
// Geometry 68, 2022. Degree-free; label "ICC".
//
// The unit vertex normals u (n x 3, see "Choices") are interpolated linearly over each triangle;
// the measures of a triangle are closed forms in its corners and their normals (CGF 2020 §4, the
// triangle case; methods/operators/icc.h lists them):
//   mu0 (corrected area), mu1 (mean curvature), mu2 (Gaussian curvature), M (the anisotropic
//   measure mu^{X,Y} as a 3x3 matrix, stored symmetrised).
// prepare(): the measures of every face, once per mesh (9 doubles per face: an m-vector of
// IccMeasures, m = number of faces).
// Per vertex v with region B (option EstimatorOptions::ball_factor = c):
//   c = 0 (default)  B = the faces at v, each fully;
//   c > 0            B = the faces meeting the ball of radius r = c h centred at v (h = the
//                    mesh's mean edge length), reached face to face from v's faces, each
//                    weighted by an approximation of the fraction of it inside the ball.
//   mu_k(B) = sum over B of (weight) mu_k(f); then (icc.h, icc_curvature):
//   H = -mu1(B) / (2 mu0(B)), K = mu2(B) / mu0(B); the tangent part of M(B)/mu0(B) in the frame
//   of u_v has eigenvalues l1 >= l2, eigenvectors d1, d2; k1,2 = H +- (l1 - l2)/2. Normal: u_v.
// Sign convention (estimator.h): the papers' mu1 is 2 H_c area with H_c = +1/r on a sphere with
// outward normals; ours is H = -1/r, so H = -mu1/(2 mu0). M/mu0 tends to -dn (no rotation of the
// eigenvectors, unlike the normal cycle), which is our shape operator: its eigenvalues are our
// principal curvatures as they are. K = k1 k2 has the same sign in both conventions.
// Choices (the papers leave them open):
//   scale of H      the factor 1/2 of H = mu1/(2 mu0) and the sign follow CGAL 6
//                   (Polygon_mesh_processing/interpolated_corrected_curvatures.h, which returns
//                   H = 0.5 mu1/mu0 positive on a convex surface), negated for our convention.
//   principal pair  CGAL and DGtal take the eigenvalues of the symmetrised M/mu0 (CGAL adds a
//                   large multiple of u u^T so that the normal's eigenvector comes last; we
//                   project onto the tangent plane of u_v instead, the same subspace, 2x2
//                   eigenproblem of core/shape_operator.h). We keep the split l1 - l2 and the
//                   directions of that tensor but centre the pair on the mu1 estimate, so that
//                   H = (k1 + k2)/2 holds as for every method of curvbench; the tangent trace of
//                   M/mu0 and -mu1/mu0 differ only by the normal part of M (CGAL reports both
//                   unreconciled). K = mu2/mu0 is kept (CGAL's and DGtal's Gaussian curvature).
//   ball fraction   the fraction of a face inside the ball follows CGAL's face_in_ball_ratio
//                   and DGtal's SurfaceMesh::faceInclusionRatio: with d_min, d_max the least
//                   and greatest distances from the centre to the face's corners and centroid,
//                   1 if d_max <= r, 0 if d_min >= r, else (r - d_min)/(d_max - d_min); the
//                   region grows face to face from v's faces (CGAL's breadth-first search) and
//                   stops at faces of fraction 0. Normalised by the weighted mu0, not pi r^2.
//   normals         Max's weights by default (option vertex-normals; or a fit's normals, e.g.
//                   vertex-normals=lhf-3, operator_estimator.h: LHF-3's normals are O(h^3), and
//                   H converges on the well-shaped torus, tests/methods/test_icc.cpp). The
//                   measures differentiate the normal field across each face, so an O(eps)
//                   error of the vertex normals becomes an O(eps/h) error of H and K: with area
//                   weights, whose normals are
//                   only first-order on the icosphere (error 5.9e-3 at level 4) and on jittered
//                   meshes, H does not converge (sphere of radius 2, levels 2-4: 4.7%, 5.9%,
//                   6.3%; jittered torus 31-37%), while Max's normals are exact at the vertices
//                   of a sphere (H, K exact to rounding) and give 7-9% on the jittered torus.
//                   Neither CGAL nor DGtal prescribes area weights: CGAL's default,
//                   compute_vertex_normals, takes the "most visible" normal of the incident faces
//                   (not offered here); DGtal's examples pass the normals in.
// Boundary vertices: the measures are additive and need no closed 1-ring; a boundary vertex sums
// the faces it has (as CGAL skips the null face), status ok, scored over every vertex.
// Failed: a vertex without faces, mu0(B) <= 0, or non-finite values. normal_fallback: with a
// fit's normals, a corner of a summed face had none from the fit (its own normal stood in).
// Determinism: every face's measures are computed by one thread into their own slot; a vertex
// sums its faces in the order of Mesh::vertex_faces (1-ring) or of the breadth-first search
// (ball), whatever the number of threads.
// Cost: prepare(), O(1) per face (four cross products); estimate(), 1-ring, 9 additions per
// incident face and one 2x2 eigenproblem; ball, O(faces in the ball).
#include "methods/operators/icc.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "core/huge_pages.h"
#include "methods/local_frame.h"
#include "methods/operators/face_ball.h"
#include "methods/operators/operator_estimator.h"
#include "methods/vertex_result.h"

namespace curvbench {

Curvature icc_curvature(const IccMeasures& s, const Vec3& n) {
  Curvature c;
  if (!(s.mu0 > 0.0) || !std::isfinite(s.mu0) || !n.allFinite() || !(n.squaredNorm() > 0.0))
    return c;
  const LocalFrame frame = make_local_frame(n);
  const double* m = s.m;
  // a^T M b for the symmetric M of the six entries.
  const auto form = [m](const Vec3& a, const Vec3& b) {
    return a.x() * (m[0] * b.x() + m[1] * b.y() + m[2] * b.z()) +
           a.y() * (m[1] * b.x() + m[3] * b.y() + m[4] * b.z()) +
           a.z() * (m[2] * b.x() + m[4] * b.y() + m[5] * b.z());
  };
  const double inv = 1.0 / s.mu0;
  double l1, l2;
  principal_from_symmetric(form(frame.t1, frame.t1) * inv, form(frame.t1, frame.t2) * inv,
                           form(frame.t2, frame.t2) * inv, frame.t1, frame.t2, l1, l2, c.d1, c.d2);
  c.normal = frame.m;
  c.H = -0.5 * s.mu1 * inv;
  c.K = s.mu2 * inv;
  const double half_split = 0.5 * (l1 - l2);
  c.k1 = c.H + half_split;
  c.k2 = c.H - half_split;
  return c;
}

namespace {

/// Per-mesh data: the measures of every face (an m-vector, m = number of faces).
struct IccData final : OperatorMeshData {
  std::vector<IccMeasures> faces;
};

// Approximate fraction of face f inside the ball of radius r centred at c (see the doc block).
double fraction_in_ball(const Mesh& mesh, int f, const Vec3& c, double r) {
  const Vec3 a = mesh.position(mesh.face_vertex(f, 0));
  const Vec3 b = mesh.position(mesh.face_vertex(f, 1));
  const Vec3 d = mesh.position(mesh.face_vertex(f, 2));
  const double da = (a - c).squaredNorm(), db = (b - c).squaredNorm(), dd = (d - c).squaredNorm();
  const double dg = ((a + b + d) / 3.0 - c).squaredNorm();
  const double lo2 = std::min({da, db, dd, dg}), hi2 = std::max({da, db, dd, dg});
  if (hi2 <= r * r) return 1.0;
  if (lo2 >= r * r) return 0.0;
  const double lo = std::sqrt(lo2), hi = std::sqrt(hi2);
  return (r - lo) / (hi - lo);
}

class IccEstimator final : public OperatorEstimator {
 public:
  explicit IccEstimator(EstimatorOptions options)
      : OperatorEstimator(options, VertexNormals::max, false, FittedNormals::accepted) {}

  std::string name() const override { return "icc"; }
  std::string display_name() const override { return "ICC"; }
  // icc_curvature divides by the corrected area mu0 of the region.
  std::string failure_without_defect() const override {
    return "a corrected area measure that is not positive";
  }

  std::unique_ptr<Workspace> make_workspace(const Mesh& mesh) const override {
    if (options_.ball_factor > 0.0) return std::make_unique<FaceBallWorkspace>(mesh);
    return std::make_unique<Workspace>();
  }

  std::unique_ptr<MeshData> prepare(const Mesh& mesh, const VertexMatrix& approx_normals,
                                    int threads) const override {
    auto data = std::make_unique<IccData>();
    fill_mesh_data(mesh, threads, *data);
    const VertexMatrix& u = data->normals.rows() > 0 ? data->normals : approx_normals;
    const int m = mesh.num_faces();
    reserve_huge(data->faces, static_cast<size_t>(m));
    data->faces.resize(static_cast<size_t>(m));
    IccMeasures* out = data->faces.data();
    const int t = threads > 0 ? threads : 1;
#pragma omp parallel for num_threads(t) schedule(static)
    for (int f = 0; f < m; ++f) {
      const int i0 = mesh.face_vertex(f, 0), i1 = mesh.face_vertex(f, 1),
                i2 = mesh.face_vertex(f, 2);
      out[f] = icc_triangle_measures(mesh.position(i0), mesh.position(i1), mesh.position(i2),
                                     u.row(i0).transpose(), u.row(i1).transpose(),
                                     u.row(i2).transpose());
    }
    return data;
  }

  void estimate(const MeshContext& ctx, int v, Workspace& base,
                VertexEstimate& out) const override {
    const Mesh& mesh = ctx.mesh;
    const auto faces = mesh.vertex_faces(v);
    const bool ball = options_.ball_factor > 0.0;
    const double ring = ball ? 0.0 : 1.0;
    if (faces.empty()) {
      set_failed(ring, 0, out);
      return;
    }
    const auto& data = static_cast<const IccData&>(*ctx.data);
    IccMeasures sum;
    int used = 0;
    // Whether a summed face has a corner whose fitted normal was replaced (normal_fallback).
    bool fell_back = false;
    const auto corners_fell_back = [&](int f) {
      return data.fell_back(mesh.face_vertex(f, 0)) || data.fell_back(mesh.face_vertex(f, 1)) ||
             data.fell_back(mesh.face_vertex(f, 2));
    };
    if (!ball) {
      for (int f : faces) {
        sum.add(data.faces[static_cast<size_t>(f)]);
        fell_back = fell_back || corners_fell_back(f);
      }
      used = static_cast<int>(faces.size());
    } else {
      auto& ws = static_cast<FaceBallWorkspace&>(base);
      const double r = options_.ball_factor * mesh.mean_edge_length();
      const Vec3 c = mesh.position(v);
      walk_face_ball(faces, ws, [&](int f, auto&& enqueue) {
        const double w = fraction_in_ball(mesh, f, c, r);
        if (!(w > 0.0)) return;
        sum.add(data.faces[static_cast<size_t>(f)], w);
        fell_back = fell_back || corners_fell_back(f);
        ++used;
        for (int k = 0; k < 3; ++k) enqueue(mesh.face_neighbor(f, k));
      });
    }
    const Curvature cv = icc_curvature(sum, data.normal(ctx, v));
    if (!set_operator_quantities(cv, computes(), used, ring, out)) set_failed(ring, used, out);
    mark_fallback(fell_back, out);
  }
};

}  // namespace

std::unique_ptr<Estimator> make_icc_estimator(EstimatorOptions options) {
  return std::make_unique<IccEstimator>(options);
}

}  // namespace curvbench
