// Shared checks of the degree-free discrete operators (meyer, taubin, rusinkiewicz, quadric):
// sphere errors, conventions, and hand-made 1-ring stencils with closed-form values.
#pragma once

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <functional>
#include <numbers>
#include <string>
#include <utility>
#include <vector>

#include "meshgen/torus_structured.h"
#include "method_test_util.h"
#include "methods/estimator.h"

namespace curvbench::testing {

/// Options with the ball of radius c times the mean edge length (normal cycle, ICC).
inline EstimatorOptions ball(double c) {
  EstimatorOptions o;
  o.ball_factor = c;
  return o;
}

/// Max errors on an icosphere of radius a (exact: k1 = k2 = H = -1/a, K = 1/a^2, outward n).
struct SphereErrors {
  double h = 0.0;  ///< mean edge length
  double H = 0.0;  ///< max |H + 1/a| a        (relative)
  double K = 0.0;  ///< max |K - 1/a^2| a^2    (relative)
  double k = 0.0;  ///< max |k_i + 1/a| a      (relative)
  double n = 0.0;  ///< max |n - x/|x||
};

/// Runs `est` on icosphere(level, a), checks the conventions at every vertex (status ok,
/// k1 >= k2, H = (k1+k2)/2, K = k1 k2 unless `k_is_product` is false (Meyer's angle-deficit K),
/// unit d1 tangent, (d1, d2, n) right-handed away from umbilics, where directions are noise) and
/// returns the errors.
inline SphereErrors sphere_errors(const Estimator& est, int level, double a,
                                  bool k_is_product = true) {
  const Mesh mesh = icosphere(level, a);
  const auto r = estimate_mesh(mesh, est);
  SphereErrors e;
  e.h = mesh.mean_edge_length();
  for (int v = 0; v < mesh.num_vertices(); ++v) {
    const VertexEstimate& q = r[static_cast<size_t>(v)];
    EXPECT_EQ(q.status, VertexStatus::ok) << "vertex " << v;
    EXPECT_EQ(q.degree, 0);
    EXPECT_GE(q.k1, q.k2);
    EXPECT_NEAR(q.H, 0.5 * (q.k1 + q.k2), 1e-12 / a);
    if (k_is_product) {
      EXPECT_NEAR(q.K, q.k1 * q.k2, 1e-12 / (a * a));
    }
    EXPECT_NEAR(q.d1.norm(), 1.0, 1e-12);
    EXPECT_NEAR(q.d1.dot(q.normal), 0.0, 1e-12);
    if (q.k1 - q.k2 > 1e-6 / a) {
      EXPECT_NEAR((q.d1.cross(q.d2) - q.normal).norm(), 0.0, 1e-9);
    }
    e.H = std::max(e.H, std::abs(q.H + 1.0 / a) * a);
    e.K = std::max(e.K, std::abs(q.K - 1.0 / (a * a)) * a * a);
    e.k = std::max({e.k, std::abs(q.k1 + 1.0 / a) * a, std::abs(q.k2 + 1.0 / a) * a});
    e.n = std::max(e.n, (q.normal - mesh.position(v).normalized()).norm());
  }
  return e;
}

/// Max |H error| over the vertices of the jittered structured torus (R = 1, r = 0.3) of a level,
/// and its mean edge length.
inline std::pair<double, double> torus_H_error(const Estimator& est, int level) {
  const GeneratedMesh g = torus_structured(level, true, 7);
  const auto r = estimate_mesh(g.mesh, est);
  double err = 0.0;
  for (int v = 0; v < g.mesh.num_vertices(); ++v) {
    const SurfacePoint x = g.surface->evaluate(g.exact_points.row(v).transpose());
    err = std::max(err, std::abs(r[static_cast<size_t>(v)].H - x.H));
  }
  return {err, g.mesh.mean_edge_length()};
}

/// Observed order log(e1/e2)/log(h1/h2).
inline double order(double e1, double e2, double h1, double h2) {
  return std::log(e1 / e2) / std::log(h1 / h2);
}

/// A closed fan: centre (index 0) at `centre`, n neighbours p_j = (rho cos t_j, rho sin t_j,
/// z(x, y)) with t_j = 2 pi j / n, faces (0, j, j+1) counter-clockwise seen from +z. Vertex 0 is
/// the only interior vertex.
inline Mesh fan(int n, double rho, const Vec3& centre,
                const std::function<double(double, double)>& z) {
  VertexMatrix V(n + 1, 3);
  V.row(0) = centre.transpose();
  for (int j = 0; j < n; ++j) {
    const double t = 2.0 * std::numbers::pi * j / n;
    const double x = rho * std::cos(t), y = rho * std::sin(t);
    V.row(j + 1) << x, y, z(x, y);
  }
  FaceMatrix F(n, 3);
  for (int j = 0; j < n; ++j) F.row(j) << 0, 1 + j, 1 + (j + 1) % n;
  return Mesh(V, F, "fan");
}

/// The closed fan of a cone apex: centre (0, 0, delta), neighbours on the circle of radius rho in
/// z = 0. By symmetry the vertex normal is +z, and with L^2 = rho^2 + delta^2 the edge normal
/// curvature 2 n.(p_j - x)/|p_j - x|^2 is -2 delta / L^2 for every edge.
inline Mesh cone_fan(int n, double rho, double delta) {
  return fan(n, rho, Vec3(0.0, 0.0, delta), [](double, double) { return 0.0; });
}

/// Checks the convention on a fan bent about the y axis, z = -kappa x^2 / 2 (kappa > 0): the
/// surface curves down along x (k2 < 0, d2 = +-x) and is straight along y (k1 > k2, d1 = +-y);
/// the symmetries x -> -x and y -> -y make the directions exact. The centre is vertex 0.
inline void expect_bent_fan_directions(const Estimator& est) {
  const double kappa = 0.8;
  const Mesh m =
      fan(6, 0.1, Vec3::Zero(), [kappa](double x, double) { return -0.5 * kappa * x * x; });
  const VertexEstimate q = estimate_mesh(m, est)[0];
  ASSERT_EQ(q.status, VertexStatus::ok);
  EXPECT_NEAR((q.normal - Vec3::UnitZ()).norm(), 0.0, 1e-12);
  EXPECT_LT(q.k2, 0.0);
  EXPECT_GT(q.k1, q.k2);
  EXPECT_NEAR(std::abs(q.d1.y()), 1.0, 1e-12);
  EXPECT_NEAR(std::abs(q.d2.x()), 1.0, 1e-12);
  EXPECT_NEAR((q.d1.cross(q.d2) - q.normal).norm(), 0.0, 1e-12);
}

/// Faces reversed: the normals point inward and every curvature changes sign.
inline void expect_inward_flips_sign(const Estimator& est) {
  const Mesh out = icosphere(2, 2.0);
  FaceMatrix F = out.faces();
  for (int f = 0; f < F.rows(); ++f) std::swap(F(f, 1), F(f, 2));
  const Mesh in(out.vertices(), F, "inward");
  const auto a = estimate_mesh(out, est);
  const auto b = estimate_mesh(in, est);
  for (int v = 0; v < out.num_vertices(); ++v) {
    const VertexEstimate& p = a[static_cast<size_t>(v)];
    const VertexEstimate& q = b[static_cast<size_t>(v)];
    EXPECT_NEAR((p.normal + q.normal).norm(), 0.0, 1e-12);
    EXPECT_NEAR(p.H, -q.H, 1e-12);
    EXPECT_NEAR(p.K, q.K, 1e-12);
    EXPECT_NEAR(p.k1, -q.k2, 1e-12);
    EXPECT_GT(q.H, 0.0);
  }
}

/// Same bytes for 1 and 2 threads (prepare() and the per-vertex loop).
inline void expect_thread_independent(const std::string& name, EstimatorOptions o, const Mesh& m) {
  o.threads = 1;
  const auto a = estimate_mesh(m, *make_estimator(name, o));
  o.threads = 2;
  const auto b = estimate_mesh(m, *make_estimator(name, o));
  ASSERT_EQ(a.size(), b.size());
  for (size_t i = 0; i < a.size(); ++i) {
    EXPECT_EQ(a[i].status, b[i].status);
    EXPECT_TRUE((a[i].normal.array() == b[i].normal.array() ||
                 (a[i].normal.array().isNaN() && b[i].normal.array().isNaN()))
                    .all());
    EXPECT_TRUE(a[i].H == b[i].H || (std::isnan(a[i].H) && std::isnan(b[i].H)));
    EXPECT_TRUE(a[i].K == b[i].K || (std::isnan(a[i].K) && std::isnan(b[i].K)));
    EXPECT_TRUE(
        (a[i].d1.array() == b[i].d1.array() || (a[i].d1.array().isNaN() && b[i].d1.array().isNaN()))
            .all());
  }
}

}  // namespace curvbench::testing
