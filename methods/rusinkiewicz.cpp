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
// Cost: O(1) per face in prepare() (a 3x3 solve in closed form), O(1) per incident face per
// vertex (dot products, no rotation matrix).
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
  // Normal equations M (A, B, C)^T = rhs with M = [p q 0; q p+r q; 0 q r], p = sum u^2,
  // q = sum u v, r = sum v^2: det M = (p + r)(p r - q^2) (a Gram determinant of the edges,
  // positive on a non-degenerate face); solved by the adjugate.
  double p = 0.0, q = 0.0, r = 0.0;
  Vec3 rhs = Vec3::Zero();
  for (int j = 0; j < 3; ++j) {
    const double u = e[j].dot(ft.t), v = e[j].dot(ft.b);
    const Vec3 dn = n[(j + 2) % 3] - n[(j + 1) % 3];
    const double dnu = dn.dot(ft.t), dnv = dn.dot(ft.b);
    // Rows (u, v, 0) . (A, B, C) = dnu and (0, u, v) . (A, B, C) = dnv.
    p += u * u;
    q += u * v;
    r += v * v;
    rhs(0) += dnu * u;
    rhs(1) += dnu * v + dnv * u;
    rhs(2) += dnv * v;
  }
  const double s = p + r, inv_det = 1.0 / (s * (p * r - q * q));
  const Vec3 ii = inv_det * Vec3((s * r - q * q) * rhs(0) - q * r * rhs(1) + q * q * rhs(2),
                                 -q * r * rhs(0) + p * r * rhs(1) - p * q * rhs(2),
                                 q * q * rhs(0) - p * q * rhs(1) + (p * s - q * q) * rhs(2));
  ft.A = -ii(0);
  ft.B = -ii(1);
  ft.C = -ii(2);
  return ft;
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
    if (faces.empty()) {
      set_failed(1.0, points, out);
      return;
    }
    const LocalFrame frame = make_local_frame(n);
    // One pass: the weighted sums, divided by the total weight at the end.
    double total = 0.0, w11 = 0.0, w12 = 0.0, w22 = 0.0;
    for (int f : faces) {
      const FaceTensor& ft = data.tensors[static_cast<size_t>(f)];
      const double weight = data.faces.mixed_area(f, corner_of(mesh, f, v));
      total += weight;
      // The face's axes t, b rotated about m x n until m coincides with n (§3.2): the rotation
      // R taking m to n, c = m . n, is R x = x - (m + n) (n . x) / (1 + c) for x orthogonal to
      // m (Rodrigues), so t_i . R x = t_i . x - (t_i . m)(n . x) / (1 + c) (t_i . n = 0). Opposite
      // normals: R x = -x (the quadratic form is unchanged).
      const double c = ft.m.dot(n);
      double u1, v1, u2, v2;
      if (c <= -1.0 + 1e-12) {
        u1 = -frame.t1.dot(ft.t);
        v1 = -frame.t1.dot(ft.b);
        u2 = -frame.t2.dot(ft.t);
        v2 = -frame.t2.dot(ft.b);
      } else {
        const double nt = n.dot(ft.t) / (1.0 + c), nb = n.dot(ft.b) / (1.0 + c);
        const double m1 = frame.t1.dot(ft.m), m2 = frame.t2.dot(ft.m);
        u1 = frame.t1.dot(ft.t) - m1 * nt;
        v1 = frame.t1.dot(ft.b) - m1 * nb;
        u2 = frame.t2.dot(ft.t) - m2 * nt;
        v2 = frame.t2.dot(ft.b) - m2 * nb;
      }
      w11 += weight * (ft.A * u1 * u1 + 2.0 * ft.B * u1 * v1 + ft.C * v1 * v1);
      w12 += weight * (ft.A * u1 * u2 + ft.B * (u1 * v2 + u2 * v1) + ft.C * v1 * v2);
      w22 += weight * (ft.A * u2 * u2 + 2.0 * ft.B * u2 * v2 + ft.C * v2 * v2);
    }
    if (!(total > 0.0)) {
      set_failed(1.0, points, out);
      return;
    }
    w11 /= total;
    w12 /= total;
    w22 /= total;
    const Curvature c = curvature_from_tangent_tensor(n, w11, w12, w22, frame.t1, frame.t2);
    if (!set_operator_quantities(c, computes(), points, 1.0, out)) set_failed(1.0, points, out);
  }
};

}  // namespace

std::unique_ptr<Estimator> make_rusinkiewicz_estimator(EstimatorOptions options) {
  return std::make_unique<RusinkiewiczEstimator>(options);
}

}  // namespace curvbench
