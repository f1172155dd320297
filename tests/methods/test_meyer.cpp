// Meyer (methods/operators/meyer.cpp): Meyer, Desbrun, Schröder & Barr 2003 in the project's
// conventions.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <numbers>

#include "core/errors.h"
#include "method_test_util.h"
#include "methods/estimator.h"
#include "operator_test_util.h"

namespace curvbench {
namespace {

using testing::cone_fan;
using testing::expect_bent_fan_directions;
using testing::expect_inward_flips_sign;
using testing::expect_thread_independent;
using testing::grid_mesh;
using testing::order;
using testing::sphere_errors;
using testing::SphereErrors;

TEST(Meyer, RegistryAndLabel) {
  const auto est = make_estimator("Meyer", {});
  EXPECT_EQ(est->name(), "meyer");
  EXPECT_EQ(est->label(), "Meyer");
  EXPECT_FALSE(est->takes_degree());
  EXPECT_EQ(est->options().degree, 0);
  EXPECT_THROW(make_estimator("meyer-2", {}), UsageError);
  EstimatorOptions o;
  o.degree = 2;
  EXPECT_THROW(make_estimator("meyer", o), UsageError);
  o = {};
  o.rings = 2;
  EXPECT_THROW(make_estimator("meyer", o), UsageError);
}

// Sphere of radius 2: H and K converge to -1/2 and 1/4 as the icosphere refines, at the order
// measured here (1.9-2.0 for both between levels 2 and 4; level 1 is exact by symmetry). K is
// the angle deficit, not k1 k2 (k1 = k2 = H where H^2 < K).
TEST(Meyer, SphereConvergesAtSecondOrder) {
  const auto est = make_estimator("meyer", {});
  SphereErrors prev;
  for (int level = 2; level <= 4; ++level) {
    const SphereErrors e = sphere_errors(*est, level, 2.0, /*k_is_product=*/false);
    std::printf("meyer sphere level %d: h %.3e  H %.3e  K %.3e  k %.3e  n %.3e\n", level, e.h, e.H,
                e.K, e.k, e.n);
    if (level > 2) {
      EXPECT_GT(order(prev.H, e.H, prev.h, e.h), 1.8);
      EXPECT_GT(order(prev.K, e.K, prev.h, e.h), 1.8);
    }
    prev = e;
  }
  EXPECT_LT(prev.H, 1e-3);
}

// Cone apex x = (0, 0, delta) over a regular hexagon of radius rho (L^2 = rho^2 + delta^2):
// every face is isosceles with base angles beta and apex angle phi, non-obtuse, so
//   A_mixed = 6 L^2 cot(beta) / 4,  K(x) = (cot beta / A) sum_j (x - p_j) = (6 delta cot beta / A)
//   z H = -K(x).z / 2 = -2 delta / L^2,  K_G = (2 pi - 6 phi) / A_mixed.
TEST(Meyer, ConeApexMatchesTheFormula) {
  for (double delta : {0.05, -0.03}) {
    const double rho = 0.2, L2 = rho * rho + delta * delta;
    const double phi = 2.0 * std::asin(rho * std::sin(std::numbers::pi / 6.0) / std::sqrt(L2));
    const double beta = 0.5 * (std::numbers::pi - phi);
    const double area = 6.0 * L2 / std::tan(beta) / 4.0;
    const double H = -2.0 * delta / L2;
    const double K = (2.0 * std::numbers::pi - 6.0 * phi) / area;
    const VertexEstimate q =
        estimate_mesh(cone_fan(6, rho, delta), *make_estimator("meyer", {}))[0];
    ASSERT_EQ(q.status, VertexStatus::ok);
    EXPECT_NEAR(q.H, H, 1e-12 * std::abs(H));
    EXPECT_NEAR(q.K, K, 1e-12 * std::abs(K));
    // k1,2 = H +- sqrt(max(0, H^2 - K)).
    const double disc = std::sqrt(std::max(0.0, H * H - K));
    EXPECT_NEAR(q.k1, H + disc, 1e-10 * std::abs(H));
    EXPECT_NEAR(q.k2, H - disc, 1e-10 * std::abs(H));
    EXPECT_EQ(q.points, 6);
  }
}

TEST(Meyer, Conventions) {
  const auto est = make_estimator("meyer", {});
  expect_bent_fan_directions(*est);
  expect_inward_flips_sign(*est);
}

// Boundary vertices have no Meyer formula: excluded with NaN; interior vertices are finite.
TEST(Meyer, BoundaryVerticesExcluded) {
  const Mesh m = grid_mesh(8, 0.1, false, 0.2, 3, [](double x, double y) {
    return Vec3(x, y, 0.3 * x * x - 0.2 * y * y);
  });
  const auto r = estimate_mesh(m, *make_estimator("meyer", {}));
  for (int v = 0; v < m.num_vertices(); ++v) {
    const VertexEstimate& q = r[static_cast<size_t>(v)];
    if (m.is_boundary_vertex(v)) {
      EXPECT_EQ(q.status, VertexStatus::excluded);
      EXPECT_TRUE(std::isnan(q.H) && std::isnan(q.k1) && q.normal.array().isNaN().all());
    } else {
      EXPECT_EQ(q.status, VertexStatus::ok);
      EXPECT_TRUE(std::isfinite(q.H) && q.d1.allFinite());
    }
  }
  expect_thread_independent("meyer", {}, m);
}

}  // namespace
}  // namespace curvbench
