// Taubin: G. Taubin, "Estimating the tensor of curvature of a surface from a polyhedral
// approximation", Proc. ICCV 1995, 902-907. Degree-free; label "Taubin".
//
// Per interior vertex v_i with unit normal N (see "Choices") and neighbours v_j (§3-4):
//   T_ij   = (I - N N^T)(v_j - v_i), normalised: the unit tangent direction of edge ij
//   k_ij   = 2 N^T (v_j - v_i) / |v_j - v_i|^2: the normal curvature of the circle through
//            v_i and v_j with normal N at v_i (Taubin's sign is ours: -1/r on a sphere)
//   w_ij   = the summed area of the (one or two) faces of edge ij, normalised so that
//            sum_j w_ij = 1
//   M      = sum_j w_ij k_ij T_ij T_ij^T, restricted to the tangent plane (the frame (t1, t2) of
//            N instead of the paper's Householder reflection; the 2x2 block is the same up to a
//            rotation)
//   M's eigenvalues m1 >= m2 with eigenvectors e1, e2:
//   k1 = 3 m1 - m2,  k2 = 3 m2 - m1,  d1 = e1, d2 = e2                                  (§4)
//   (k1 - k2 = 4 (m1 - m2) >= 0, so the larger eigenvalue gives k1), H = (k1 + k2)/2 = m1 + m2,
//   K = k1 k2.
// Choices: N is the area-weighted vertex normal, Taubin's own choice (§4: face normals
// averaged with area weights); option EstimatorOptions::vertex_normals. The reported normal is N.
// Boundary vertices: the factor 3 of §4 integrates the directional curvature over the full circle
// of directions, which a boundary vertex's 1-ring does not cover, and the paper gives no boundary
// variant: status excluded, values NaN. Non-finite values (degenerate faces): failed.
// Cost: one pass over the incident faces per vertex.
#include <cmath>
#include <memory>
#include <string>

#include "core/shape_operator.h"
#include "methods/local_frame.h"
#include "methods/operators/face_geometry.h"
#include "methods/operators/operator_estimator.h"
#include "methods/vertex_result.h"

namespace curvbench {

namespace {

class TaubinEstimator final : public OperatorEstimator {
 public:
  explicit TaubinEstimator(EstimatorOptions options)
      : OperatorEstimator(options, VertexNormals::area) {}

  std::string name() const override { return "taubin"; }
  std::string display_name() const override { return "Taubin"; }
  /// Boundary vertices are excluded by design (below): scored over the interior, like Xu.
  bool scores_interior_only() const override { return true; }

  void estimate(const MeshContext& ctx, int v, Workspace&, VertexEstimate& out) const override {
    const Mesh& mesh = ctx.mesh;
    if (!interior_with_faces(mesh, v, out)) return;
    const auto faces = mesh.vertex_faces(v);
    const OperatorMeshData& data = mesh_data(ctx);
    const Vec3 n = data.normal(ctx, v);
    const LocalFrame frame = make_local_frame(n);
    const Vec3 xi = mesh.position(v);
    // Each face adds its area to the weights of its two edges at v.
    double m11 = 0.0, m12 = 0.0, m22 = 0.0, total = 0.0;
    const auto add_edge = [&](const Vec3& xj, double w) {
      const Vec3 e = xj - xi;
      const double kappa = 2.0 * e.dot(n) / e.squaredNorm();
      const double u = e.dot(frame.t1), t = e.dot(frame.t2);
      const double s = w * kappa / (u * u + t * t);  // T T^T = (u, t)(u, t)^T / (u^2 + t^2)
      m11 += s * u * u;
      m12 += s * u * t;
      m22 += s * t * t;
      total += w;
    };
    for (int f : faces) {
      const int i = corner_of(mesh, f, v);
      const Vec3 xj = mesh.position(mesh.face_vertex(f, (i + 1) % 3));
      const Vec3 xk = mesh.position(mesh.face_vertex(f, (i + 2) % 3));
      const double area = 0.5 * (xj - xi).cross(xk - xi).norm();
      add_edge(xj, area);
      add_edge(xk, area);
    }
    Curvature c;
    c.normal = n;
    double e1, e2;
    principal_from_symmetric(m11 / total, m12 / total, m22 / total, frame.t1, frame.t2, e1, e2,
                             c.d1, c.d2);
    c.k1 = 3.0 * e1 - e2;
    c.k2 = 3.0 * e2 - e1;
    c.H = 0.5 * (c.k1 + c.k2);
    c.K = c.k1 * c.k2;
    const int points = static_cast<int>(faces.size());
    if (!set_operator_quantities(c, computes(), points, 1.0, out)) set_failed(1.0, points, out);
  }
};

}  // namespace

std::unique_ptr<Estimator> make_taubin_estimator(EstimatorOptions options) {
  return std::make_unique<TaubinEstimator>(options);
}

}  // namespace curvbench
