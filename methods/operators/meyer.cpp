// Meyer: the discrete differential-geometry operators of M. Meyer, M. Desbrun, P. Schröder and
// A. H. Barr, "Discrete differential-geometry operators for triangulated 2-manifolds",
// Visualization and Mathematics III (2003), 35-57. Degree-free; label "Meyer".
//
// Per interior vertex x_i with 1-ring faces f = (x_i, x_j, x_k) (cotangents and mixed areas of
// face_geometry.h), unit vertex normal n (see "Choices"):
//   A_mixed   = sum_f mixed_area(f, i)                                         (§3.3, Fig. 4)
//   K(x_i)    = 1/(2 A_mixed) sum_j (cot a_ij + cot b_ij) (x_i - x_j)                 (eq. 8)
//             (per face: cot(angle at x_k) (x_i - x_j) + cot(angle at x_j) (x_i - x_k))
//   H         = -K(x_i) . n / 2              (the paper's kappa_H = K . n / 2, sign converted)
//   K_G       = (2 pi - sum_f theta_f) / A_mixed                                      (eq. 9)
//   k1,2      = H +- sqrt(max(0, H^2 - K_G))                                 (eqs. 10-11)
//   d1, d2    (§5.2): the symmetric tangent tensor B = [a b; b c] in the frame (t1, t2) of n,
//             with a + c = 2 H, fitted by weighted least squares to the normal curvatures of the
//             edges, kappa_ij = 2 (x_j - x_i) . n / |x_j - x_i|^2 (sign converted), in the unit
//             tangent directions of the edges, each face's mixed area at x_i shared equally by
//             its two edges at x_i as the weights (see "Choices"); d1 is the
//             eigenvector of the larger eigenvalue of B (the eigenvalues themselves are not used:
//             k1, k2 come from H and K_G as above).
// Sign convention (estimator.h): the paper's mean curvature normal K(x) points along the
// outward normal on a sphere (kappa_H = +1/r); we report H = -K . n / 2 = -1/r. K_G, k1 >= k2
// and (d1, d2, n) right-handed follow from the formulas above and principal_from_symmetric.
//
// Choices (the paper leaves them open; Meyer et al.'s own code is not public, so we follow the
// implementation most users run, libigl's cotmatrix/massmatrix(VORONOI) with per_vertex_normals):
//   normal  the area-weighted vertex normal (libigl's per_vertex_normals default); option
//           EstimatorOptions::vertex_normals (area, angle, max). The reported normal is this one.
//   H sign  the projection of K(x_i) on n (signed), not |K(x_i)| / 2.
//   weights of the direction fit: the paper weights the edges by their Voronoi share; the
//           cotangent form of that share, (cot a_ij + cot b_ij) |x_i - x_j|^2 / 8, vanishes on
//           the diagonals of a right-angled grid and turns negative across obtuse angles, which
//           leaves the 2x2 fit singular or indefinite on such meshes. We use the mixed areas
//           (positive on every mesh, equal to the Voronoi share where no angle is obtuse, summed
//           over an edge's two faces).
// Boundary vertices: the paper's formulas need the full 1-ring (a boundary vertex's angle
// deficit and cotangent sum measure the boundary curve as well), and it gives no boundary
// variant: status excluded, values NaN. A vertex whose tensor fit of the directions is singular
// (two edge directions only, as at a valence-4 vertex of a flat grid) keeps H, K, k1, k2 and the
// normal with d1, d2 NaN: status partial. A vertex whose values are not finite (degenerate faces)
// is failed.
// Cost: one pass over the incident faces (each face's cotangents and mixed area computed there,
// no per-mesh arrays) and one atan2 per vertex.
#include <cmath>
#include <memory>
#include <numbers>
#include <string>

#include "core/shape_operator.h"
#include "methods/local_frame.h"
#include "methods/operators/face_geometry.h"
#include "methods/operators/operator_estimator.h"
#include "methods/vertex_result.h"

namespace curvbench {

namespace {

class MeyerEstimator final : public OperatorEstimator {
 public:
  explicit MeyerEstimator(EstimatorOptions options)
      : OperatorEstimator(options, VertexNormals::area) {}

  std::string name() const override { return "meyer"; }
  std::string display_name() const override { return "Meyer"; }
  /// Boundary vertices are excluded by design (below): scored over the interior, like Xu.
  bool scores_interior_only() const override { return true; }

  void estimate(const MeshContext& ctx, int v, Workspace&, VertexEstimate& out) const override {
    const Mesh& mesh = ctx.mesh;
    if (!interior_with_faces(mesh, v, out)) return;
    const auto faces = mesh.vertex_faces(v);
    const Vec3 n = mesh_data(ctx).normal(ctx, v);
    const LocalFrame frame = make_local_frame(n);
    const Vec3 xi = mesh.position(v);
    double area = 0.0;
    Vec3 k_vec = Vec3::Zero();
    // The angle sum as the argument of prod_f (cot theta_f + i) (each factor has argument
    // theta_f in (0, pi)): one atan2 per vertex instead of one per corner. `turns` counts the
    // passes of the running argument through pi; the sum is 2 pi turns + arg(z).
    double zr = 1.0, zi = 0.0;
    int turns = 0;
    // §5.2, B = [a b; b 2H - a]: per edge a (u^2 - v^2) + b (2 u v) = kappa - 2 H v^2 with (u, v)
    // the unit tangent direction. H is not known before the loop, so the right-hand side is
    // gathered as two sums, r = rk - 2 H rv.
    double s11 = 0.0, s12 = 0.0, s22 = 0.0, rk1 = 0.0, rk2 = 0.0, rv1 = 0.0, rv2 = 0.0;
    const auto add_edge = [&](const Vec3& e, double w) {
      const double kappa = 2.0 * e.dot(n) / e.squaredNorm();
      const double u = e.dot(frame.t1), t = e.dot(frame.t2);
      const double inv = 1.0 / (u * u + t * t);  // (u, t) / |(u, t)| is the unit direction
      const double p = (u * u - t * t) * inv, q = 2.0 * u * t * inv, wp = w * p, wq = w * q;
      const double v2 = t * t * inv;
      s11 += wp * p;
      s12 += wp * q;
      s22 += wq * q;
      rk1 += wp * kappa;
      rk2 += wq * kappa;
      rv1 += wp * v2;
      rv2 += wq * v2;
    };
    for (int f : faces) {
      const int i = corner_of(mesh, f, v);
      const CornerGeometry g = corner_geometry(xi, mesh.position(mesh.face_vertex(f, (i + 1) % 3)),
                                               mesh.position(mesh.face_vertex(f, (i + 2) % 3)));
      const double corner_area = mixed_area(g, 0);
      area += corner_area;
      const double cot = g.cot[0];
      const double r = zr * cot - zi, t = zr + zi * cot;
      const double scale = 1.0 / (std::abs(r) + std::abs(t));  // keeps |z| near 1
      // A pass through pi: from the upper half plane, or from the negative real axis itself (a
      // partial sum of exactly pi, as after two right angles), into the lower one.
      if (zi >= 0.0 && t < 0.0) ++turns;
      zr = r * scale;
      zi = t * scale;
      // cot(angle at x_k) (x_i - x_j) + cot(angle at x_j) (x_i - x_k), x_j - x_i = a.
      k_vec -= g.cot[2] * g.a + g.cot[1] * g.b;
      // Each face's mixed area at x_i, shared by its two edges at x_i.
      add_edge(g.a, 0.5 * corner_area);
      add_edge(g.b, 0.5 * corner_area);
    }
    k_vec /= 2.0 * area;
    Curvature c;
    c.normal = n;
    c.H = -0.5 * k_vec.dot(n);
    // Eq. 9: 2 pi - sum theta = 2 pi (1 - turns) - arg(z), accurate near a flat vertex (turns = 1,
    // arg(z) small) where the sum of the angles would cancel.
    c.K = (2.0 * std::numbers::pi * (1 - turns) - std::atan2(zi, zr)) / area;
    const double disc = std::sqrt(std::max(0.0, c.H * c.H - c.K));
    c.k1 = c.H + disc;
    c.k2 = c.H - disc;

    // det >= 0 (Cauchy-Schwarz), 0 when every edge direction lies on one line or on two
    // perpendicular lines; relative to (s11 + s22)^2 (the summed weights squared), rounding leaves
    // it near 1e-32 there, a genuine direction spread of angle delta leaves about delta^2.
    const double det = s11 * s22 - s12 * s12;
    const double scale = (s11 + s22) * (s11 + s22);
    const int points = static_cast<int>(faces.size());
    if (!(det > 1e-12 * scale)) {
      // The tensor fit of the directions is singular (e.g. valence 4 with two collinear pairs of
      // edges: two edge directions only); H, K, k1 and k2 do not need it: status partial.
      ComputedQuantities determined = computes();
      determined.directions = false;
      if (set_operator_quantities(c, determined, points, 1.0, out))
        out.status = VertexStatus::partial;
      else
        set_failed(1.0, points, out);
      return;
    }
    const double r1 = rk1 - 2.0 * c.H * rv1, r2 = rk2 - 2.0 * c.H * rv2;
    const double a = (s22 * r1 - s12 * r2) / det;
    const double b = (s11 * r2 - s12 * r1) / det;
    double e1, e2;
    principal_from_symmetric(a, b, 2.0 * c.H - a, frame.t1, frame.t2, e1, e2, c.d1, c.d2);
    if (!set_operator_quantities(c, computes(), points, 1.0, out)) set_failed(1.0, points, out);
  }
};

}  // namespace

std::unique_ptr<Estimator> make_meyer_estimator(EstimatorOptions options) {
  return std::make_unique<MeyerEstimator>(options);
}

}  // namespace curvbench
