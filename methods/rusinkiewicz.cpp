// Rusinkiewicz: S. Rusinkiewicz, "Estimating curvatures and their derivatives on triangle
// meshes", Proc. 3DPVT 2004, 486-493. Degree-free; label "Rusinkiewicz".
//
// prepare() (once per mesh, in parallel over faces):
//   vertex normals n_v (see "Choices");
//   per face with corners x0, x1, x2, edges e_j = x_{j+2} - x_{j+1} (opposite corner j), frame
//   t = e_0/|e_0|, m = e_0 x e_1 / |...|, b = m x t;
//   the face's second fundamental form II = [A B; B C] in (t, b), least squares over its three
//   edges of  II (e_j . t, e_j . b)^T = ((n_{j+2} - n_{j+1}) . t, (n_{j+2} - n_{j+1}) . b)^T  (§3,
//   eq. 4: the change of the normal along each edge), 3 unknowns, 6 equations, normal equations.
// Per vertex v (frame (t1, t2) of n_v):
//   each incident face's tensor is carried into the vertex frame: its frame (t, b) is rotated
//   about m x n_v until m coincides with n_v (§3.2), then re-expressed in (t1, t2); the
//   tensors are averaged with the weights mixed_area(f, v) / sum_f mixed_area(f, v) (§3.3: the
//   Voronoi area of the corner, Meyer et al. 2003; face_geometry.h); eqs. (7)-(8) give
//   k1 >= k2, d1, d2 (principal_from_symmetric); H = (k1 + k2)/2, K = k1 k2; the normal is n_v.
// Sign convention (estimator.h): with outward normals the paper's II (the derivative of the
// normal) is +1/r on a sphere; B = n . x_uu = -II, so the face tensors are negated.
// Choices (following the authors' code, trimesh2's TriMesh::need_curvatures):
//   normals  Max's weights (each face normal weighted by sin(angle) / (|a| |b|) at the vertex,
//            trimesh2's vertex normals); option EstimatorOptions::vertex_normals.
//   weights  the corner's share of the mixed Voronoi area. trimesh2 splits obtuse triangles
//            slightly differently from Meyer et al.'s A_mixed (which we use); both agree on
//            non-obtuse triangles.
// Boundary vertices: the method is a weighted average over the incident faces and needs no
// full 1-ring; a boundary vertex averages the faces it has (as trimesh2 does), status ok.
// Failed: a vertex without faces, zero total area, or non-finite values.
// Cost: O(1) per face in prepare() (a 3x3 solve), O(1) per incident face per vertex.
#include <cmath>
#include <memory>
#include <string>
#include <vector>

#include <Eigen/Cholesky>

#include "core/shape_operator.h"
#include "methods/local_frame.h"
#include "methods/operator_estimator.h"
#include "methods/vertex_result.h"

namespace curvbench {

namespace {

/// Per face: the frame (t, b, m) and the tensor (A, B, C) = -II in (t, b).
struct FaceTensor {
  Vec3 t, b, m;
  double A = 0.0, B = 0.0, C = 0.0;
};

struct RusinkiewiczData final : OperatorMeshData {
  std::vector<FaceTensor> tensors;
};

FaceTensor face_tensor(const Vec3 x[3], const Vec3 n[3]) {
  FaceTensor ft;
  const Vec3 e[3] = {x[2] - x[1], x[0] - x[2], x[1] - x[0]};
  ft.t = e[0].normalized();
  ft.m = e[0].cross(e[1]).normalized();
  ft.b = ft.m.cross(ft.t);
  Mat3 w = Mat3::Zero();
  Vec3 rhs = Vec3::Zero();
  for (int j = 0; j < 3; ++j) {
    const double u = e[j].dot(ft.t), v = e[j].dot(ft.b);
    const Vec3 dn = n[(j + 2) % 3] - n[(j + 1) % 3];
    const double dnu = dn.dot(ft.t), dnv = dn.dot(ft.b);
    // Rows (u, v, 0) . (A, B, C) = dnu and (0, u, v) . (A, B, C) = dnv.
    w(0, 0) += u * u;
    w(0, 1) += u * v;
    w(1, 1) += u * u + v * v;
    w(1, 2) += u * v;
    w(2, 2) += v * v;
    rhs(0) += dnu * u;
    rhs(1) += dnu * v + dnv * u;
    rhs(2) += dnv * v;
  }
  w(1, 0) = w(0, 1);
  w(2, 1) = w(1, 2);
  const Vec3 ii = w.ldlt().solve(rhs);
  ft.A = -ii(0);
  ft.B = -ii(1);
  ft.C = -ii(2);
  return ft;
}

// Rotates the vector x by the rotation that takes the unit vector a to the unit vector b about
// a x b (Rodrigues); opposite a and b: -x (the tensor's quadratic form is unchanged).
Vec3 rotate(const Vec3& x, const Vec3& a, const Vec3& b) {
  const double c = a.dot(b);
  if (c <= -1.0 + 1e-12) return -x;
  const Vec3 k = a.cross(b);
  const Vec3 kx = k.cross(x);
  return x + kx + k.cross(kx) / (1.0 + c);
}

class RusinkiewiczEstimator final : public OperatorEstimator {
 public:
  explicit RusinkiewiczEstimator(EstimatorOptions options)
      : OperatorEstimator(options, VertexNormals::max, /*needs_face_geometry=*/true) {}

  std::string name() const override { return "rusinkiewicz"; }
  std::string display_name() const override { return "Rusinkiewicz"; }

  std::unique_ptr<MeshData> prepare(const Mesh& mesh, const VertexMatrix& approx_normals,
                                    int threads) const override {
    auto data = std::make_unique<RusinkiewiczData>();
    fill_mesh_data(mesh, threads, *data);
    const VertexMatrix& normals = data->normals.rows() > 0 ? data->normals : approx_normals;
    const int m = mesh.num_faces();
    data->tensors.resize(static_cast<size_t>(m));
#pragma omp parallel for num_threads(threads > 0 ? threads : 1) schedule(static)
    for (int f = 0; f < m; ++f) {
      Vec3 x[3], n[3];
      for (int k = 0; k < 3; ++k) {
        x[k] = mesh.position(mesh.face_vertex(f, k));
        n[k] = normals.row(mesh.face_vertex(f, k)).transpose();
      }
      data->tensors[static_cast<size_t>(f)] = face_tensor(x, n);
    }
    return data;
  }

  void estimate(const MeshContext& ctx, int v, Workspace&, VertexEstimate& out) const override {
    const Mesh& mesh = ctx.mesh;
    const auto faces = mesh.vertex_faces(v);
    const int points = static_cast<int>(faces.size());
    const auto& data = static_cast<const RusinkiewiczData&>(*ctx.data);
    const Vec3 n = data.normal(ctx, v);
    double total = 0.0;
    for (int f : faces) total += data.faces.mixed_area(f, corner_of(mesh, f, v));
    if (faces.empty() || !(total > 0.0)) {
      set_failed(1.0, points, out);
      return;
    }
    const LocalFrame frame = make_local_frame(n);
    double w11 = 0.0, w12 = 0.0, w22 = 0.0;
    for (int f : faces) {
      const FaceTensor& ft = data.tensors[static_cast<size_t>(f)];
      const double weight = data.faces.mixed_area(f, corner_of(mesh, f, v)) / total;
      const Vec3 ru = rotate(ft.t, ft.m, n), rv = rotate(ft.b, ft.m, n);
      const double u1 = frame.t1.dot(ru), v1 = frame.t1.dot(rv);
      const double u2 = frame.t2.dot(ru), v2 = frame.t2.dot(rv);
      w11 += weight * (ft.A * u1 * u1 + 2.0 * ft.B * u1 * v1 + ft.C * v1 * v1);
      w12 += weight * (ft.A * u1 * u2 + ft.B * (u1 * v2 + u2 * v1) + ft.C * v1 * v2);
      w22 += weight * (ft.A * u2 * u2 + 2.0 * ft.B * u2 * v2 + ft.C * v2 * v2);
    }
    Curvature c;
    c.normal = n;
    principal_from_symmetric(w11, w12, w22, frame.t1, frame.t2, c.k1, c.k2, c.d1, c.d2);
    c.H = 0.5 * (c.k1 + c.k2);
    c.K = c.k1 * c.k2;
    if (!set_operator_quantities(c, computes(), points, 1.0, out)) set_failed(1.0, points, out);
  }
};

}  // namespace

std::unique_ptr<Estimator> make_rusinkiewicz_estimator(EstimatorOptions options) {
  return std::make_unique<RusinkiewiczEstimator>(options);
}

}  // namespace curvbench
