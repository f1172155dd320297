// Rusinkiewicz: S. Rusinkiewicz, "Estimating curvatures and their derivatives on triangle
// meshes", Proc. 3DPVT 2004, 486-493. Degree-free; label "Rusinkiewicz".
//
// prepare() (once per mesh, one pass over the faces):
//   vertex normals n_v (see "Choices"), each with its frame (t1, t2);
//   per face with corners x0, x1, x2, edges e_j = x_{j+2} - x_{j+1} (opposite corner j), frame
//   t = e_0/|e_0|, m = e_0 x e_1 / |...|, b = m x t;
//   the face's second fundamental form II = [A B; B C] in (t, b), least squares over its three
//   edges of  II (e_j . t, e_j . b)^T = ((n_{j+2} - n_{j+1}) . t, (n_{j+2} - n_{j+1}) . b)^T  (§3,
//   eq. 4: the change of the normal along each edge), 3 unknowns, 6 equations, normal equations.
//   the face's tensor is carried into the frame of each of its corners v: its frame (t, b) is
//   rotated about m x n_v until m coincides with n_v (§3.2), then re-expressed in (t1, t2), and
//   added with the weight mixed_area(f, v) (§3.3: the Voronoi area of the corner, Meyer et al.
//   2003; face_geometry.h) to v's sums.
// Per vertex v: the sums divided by sum_f mixed_area(f, v) (the weighted average over the
//   incident faces); eqs. (7)-(8) give k1 >= k2, d1, d2 (principal_from_symmetric);
//   H = (k1 + k2)/2, K = k1 k2; the normal is n_v.
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
// Cost: O(1) per face in prepare() (a 3x3 solve in closed form, dot products per corner, no
// rotation matrix), no per-face arrays; O(1) per vertex. Each vertex sums its faces in increasing
// face order for any number of threads (bit-identical to a gather over its faces).
#include <algorithm>
#include <cmath>
#include <memory>
#include <string>
#include <vector>

#include "core/huge_pages.h"
#include "core/shape_operator.h"
#include "methods/local_frame.h"
#include "methods/operators/face_geometry.h"
#include "methods/operators/operator_estimator.h"
#include "methods/vertex_result.h"

namespace curvbench {

namespace {

/// Per face: the frame (t, b, m) and the tensor (A, B, C) = -II in (t, b).
struct FaceTensor {
  Vec3 t, b, m;
  double A = 0.0, B = 0.0, C = 0.0;
};

/// Per vertex: the frame (t1, t2) of its normal, the total weight and the weighted sums w11, w12,
/// w22 of the face tensors carried into that frame (divided by the total in estimate()).
struct VertexSums {
  LocalFrame frame;
  double total = 0.0, w11 = 0.0, w12 = 0.0, w22 = 0.0;
};

struct RusinkiewiczData final : OperatorMeshData {
  std::vector<VertexSums> sums;
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

/// Adds the face tensor ft, weighted, carried into the frame (t1, t2) of the vertex normal n, to
/// the vertex's sums.
void add_face_tensor(const FaceTensor& ft, double weight, const Vec3& n, VertexSums& sums) {
  const LocalFrame& frame = sums.frame;
  // The face's axes t, b rotated about m x n until m coincides with n (§3.2): the rotation R
  // taking m to n, c = m . n, is R x = x - (m + n) (n . x) / (1 + c) for x orthogonal to m
  // (Rodrigues), so t_i . R x = t_i . x - (t_i . m)(n . x) / (1 + c) (t_i . n = 0). Opposite
  // normals: R x = -x (the quadratic form is unchanged).
  const double c = ft.m.dot(n);
  double u1, v1, u2, v2;
  if (c <= -1.0 + 1e-12) {
    u1 = -frame.t1.dot(ft.t);
    v1 = -frame.t1.dot(ft.b);
    u2 = -frame.t2.dot(ft.t);
    v2 = -frame.t2.dot(ft.b);
  } else {
    const double inv = 1.0 / (1.0 + c);  // one division per corner
    const double nt = n.dot(ft.t) * inv, nb = n.dot(ft.b) * inv;
    const double m1 = frame.t1.dot(ft.m), m2 = frame.t2.dot(ft.m);
    u1 = frame.t1.dot(ft.t) - m1 * nt;
    v1 = frame.t1.dot(ft.b) - m1 * nb;
    u2 = frame.t2.dot(ft.t) - m2 * nt;
    v2 = frame.t2.dot(ft.b) - m2 * nb;
  }
  sums.total += weight;
  sums.w11 += weight * (ft.A * u1 * u1 + 2.0 * ft.B * u1 * v1 + ft.C * v1 * v1);
  sums.w12 += weight * (ft.A * u1 * u2 + ft.B * (u1 * v2 + u2 * v1) + ft.C * v1 * v2);
  sums.w22 += weight * (ft.A * u2 * u2 + 2.0 * ft.B * u2 * v2 + ft.C * v2 * v2);
}

class RusinkiewiczEstimator final : public OperatorEstimator {
 public:
  explicit RusinkiewiczEstimator(EstimatorOptions options)
      : OperatorEstimator(options, VertexNormals::max) {}

  std::string name() const override { return "rusinkiewicz"; }
  std::string display_name() const override { return "Rusinkiewicz"; }

  std::unique_ptr<MeshData> prepare(const Mesh& mesh, const VertexMatrix& approx_normals,
                                    int threads) const override {
    auto data = std::make_unique<RusinkiewiczData>();
    fill_mesh_data(mesh, threads, *data);
    const VertexMatrix& normals = data->normals.rows() > 0 ? data->normals : approx_normals;
    const int n = mesh.num_vertices();
    reserve_huge(data->sums, static_cast<size_t>(n));
    data->sums.resize(static_cast<size_t>(n));
    VertexSums* sums = data->sums.data();
    // One pass over the faces (as trimesh2 does): each face's tensor is computed once and added
    // to its corners; a thread computes the faces touching its vertex range, so each vertex sums
    // its faces in increasing face order whatever the number of threads (for_each_vertex_range).
    for_each_vertex_range(n, threads, [&](int lo, int hi) {
      for (int v = lo; v < hi; ++v) sums[v].frame = make_local_frame(normals.row(v).transpose());
      for_each_face_touching(mesh, lo, hi, [&](int, const int(&vs)[3]) {
        Vec3 x[3], nv[3];
        for (int k = 0; k < 3; ++k) {
          x[k] = mesh.position(vs[k]);
          nv[k] = normals.row(vs[k]).transpose();
        }
        const FaceTensor ft = face_tensor(x, nv);
        const CornerGeometry g = corner_geometry(x[0], x[1], x[2]);
        for (int k = 0; k < 3; ++k)
          if (vs[k] >= lo && vs[k] < hi) add_face_tensor(ft, mixed_area(g, k), nv[k], sums[vs[k]]);
      });
    });
    return data;
  }

  void estimate(const MeshContext& ctx, int v, Workspace&, VertexEstimate& out) const override {
    const int points = static_cast<int>(ctx.mesh.vertex_faces(v).size());
    const auto& data = static_cast<const RusinkiewiczData&>(*ctx.data);
    const VertexSums& sums = data.sums[static_cast<size_t>(v)];
    const double total = sums.total;
    if (points == 0 || !(total > 0.0)) {  // no face tensor to average: the normal only
      set_normal_only(data.normal(ctx, v), points, 1.0, out);
      return;
    }
    const Curvature c =
        curvature_from_tangent_tensor(data.normal(ctx, v), sums.w11 / total, sums.w12 / total,
                                      sums.w22 / total, sums.frame.t1, sums.frame.t2);
    if (!set_operator_quantities(c, computes(), points, 1.0, out)) set_failed(1.0, points, out);
  }
};

}  // namespace

std::unique_ptr<Estimator> make_rusinkiewicz_estimator(EstimatorOptions options) {
  return std::make_unique<RusinkiewiczEstimator>(options);
}

}  // namespace curvbench
