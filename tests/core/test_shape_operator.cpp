// core/shape_operator: eqs. (7)-(8) on known matrices, the parametric route against the
// classical W = G^-1 B, the height route against the parametric route, degenerate input.
#include "core/shape_operator.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <numbers>
#include <random>

#include "tests/surfaces/surface_test_util.h"

namespace curvbench {
namespace {

using test::line_angle;
using test::uniform;

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
constexpr double kInf = std::numeric_limits<double>::infinity();

// A random right-handed orthonormal frame (columns t1, t2, m).
Mat3 random_frame(std::mt19937_64& rng) {
  Vec3 a(uniform(rng, -1, 1), uniform(rng, -1, 1), uniform(rng, -1, 1));
  Vec3 b(uniform(rng, -1, 1), uniform(rng, -1, 1), uniform(rng, -1, 1));
  const Vec3 t1 = a.normalized();
  Vec3 t2 = (b - b.dot(t1) * t1).normalized();
  t2 = (t2 - t2.dot(t1) * t1).normalized();  // twice is enough (Kahan)
  Mat3 U;
  U << t1, t2, t1.cross(t2);
  return U;
}

void expect_all_nan(const Curvature& c) {
  EXPECT_TRUE(c.normal.array().isNaN().all());
  EXPECT_TRUE(std::isnan(c.k1));
  EXPECT_TRUE(std::isnan(c.k2));
  EXPECT_TRUE(std::isnan(c.H));
  EXPECT_TRUE(std::isnan(c.K));
  EXPECT_TRUE(c.d1.array().isNaN().all());
  EXPECT_TRUE(c.d2.array().isNaN().all());
}

struct Principal {
  double k1, k2;
  Vec3 d1, d2;
};

Principal principal(double w11, double w12, double w22, const Vec3& q1, const Vec3& q2) {
  Principal p;
  principal_from_symmetric(w11, w12, w22, q1, q2, p.k1, p.k2, p.d1, p.d2);
  return p;
}

TEST(PrincipalFromSymmetric, DiagonalBothOrders) {
  const Vec3 q1 = Vec3(1, 2, 2) / 3.0;
  const Vec3 q2 = Vec3(2, 1, -2) / 3.0;  // orthonormal to q1
  ASSERT_NEAR(q1.dot(q2), 0.0, 1e-16);
  Principal p = principal(3.0, 0.0, -1.0, q1, q2);
  EXPECT_EQ(p.k1, 3.0);
  EXPECT_EQ(p.k2, -1.0);
  EXPECT_LE(line_angle(p.d1, q1), 1e-15);
  EXPECT_LE(line_angle(p.d2, q2), 1e-15);
  EXPECT_LE((p.d1.cross(p.d2) - q1.cross(q2)).norm(), 1e-15);

  p = principal(-1.0, 0.0, 3.0, q1, q2);  // larger eigenvalue on q2
  EXPECT_EQ(p.k1, 3.0);
  EXPECT_EQ(p.k2, -1.0);
  EXPECT_LE(line_angle(p.d1, q2), 1e-15);
  EXPECT_LE(line_angle(p.d2, q1), 1e-15);
  EXPECT_LE((p.d1.cross(p.d2) - q1.cross(q2)).norm(), 1e-15);
}

TEST(PrincipalFromSymmetric, RotatedMatrices) {
  const Vec3 q1 = Vec3::UnitX();
  const Vec3 q2 = Vec3::UnitY();
  const double lambda1 = 2.5, lambda2 = -0.75;
  for (int i = 0; i < 64; ++i) {
    const double theta = 2.0 * std::numbers::pi * i / 64.0 + 0.01;
    const double c = std::cos(theta), s = std::sin(theta);
    // W = R diag(l1, l2) R^T with R = [c -s; s c].
    const double w11 = c * c * lambda1 + s * s * lambda2;
    const double w12 = c * s * (lambda1 - lambda2);
    const double w22 = s * s * lambda1 + c * c * lambda2;
    const Principal p = principal(w11, w12, w22, q1, q2);
    EXPECT_NEAR(p.k1, lambda1, 1e-14);
    EXPECT_NEAR(p.k2, lambda2, 1e-14);
    EXPECT_LE(line_angle(p.d1, Vec3(c, s, 0)), 1e-14) << theta;
    EXPECT_LE(line_angle(p.d2, Vec3(-s, c, 0)), 1e-14) << theta;
    EXPECT_NEAR(p.d1.norm(), 1.0, 1e-15);
    EXPECT_NEAR(p.d2.norm(), 1.0, 1e-15);
    EXPECT_NEAR(p.d1.cross(p.d2).z(), 1.0, 1e-15);  // right-handed with q1 x q2 = +z
  }
}

TEST(PrincipalFromSymmetric, EqualEigenvaluesGiveTheBasis) {
  const Vec3 q1 = Vec3(0, 0.6, 0.8);
  const Vec3 q2 = Vec3(-1, 0, 0);
  const Principal p = principal(-4.0, 0.0, -4.0, q1, q2);
  EXPECT_EQ(p.k1, -4.0);
  EXPECT_EQ(p.k2, -4.0);
  EXPECT_EQ(p.d1, q1);
  EXPECT_EQ(p.d2, q2);
  EXPECT_TRUE(is_umbilic(p.k1, p.k2));
}

TEST(PrincipalFromSymmetric, NearlyEqualEigenvaluesStayOrthonormal) {
  const Vec3 q1 = Vec3::UnitX(), q2 = Vec3::UnitY();
  for (double w12 : {1e-300, 1e-20, 1e-12, 1e-8}) {
    const Principal p = principal(1.0, w12, 1.0 + 1e-15, q1, q2);
    EXPECT_GE(p.k1, p.k2);
    EXPECT_NEAR(p.d1.norm(), 1.0, 1e-15);
    EXPECT_NEAR(p.d2.norm(), 1.0, 1e-15);
    EXPECT_NEAR(p.d1.dot(p.d2), 0.0, 1e-15);
    EXPECT_NEAR(p.d1.cross(p.d2).z(), 1.0, 1e-15);
  }
}

TEST(PrincipalFromSymmetric, NonFiniteInputGivesNaN) {
  for (double bad : {kNaN, kInf, -kInf}) {
    const Principal p = principal(bad, 0.5, 1.0, Vec3::UnitX(), Vec3::UnitY());
    EXPECT_TRUE(std::isnan(p.k1) || std::isnan(p.k2));
    EXPECT_TRUE(p.d1.array().isNaN().all());
    EXPECT_TRUE(p.d2.array().isNaN().all());
  }
}

TEST(IsUmbilic, RelativeTolerance) {
  EXPECT_TRUE(is_umbilic(2.0, 2.0));
  EXPECT_TRUE(is_umbilic(0.0, 0.0));
  EXPECT_TRUE(is_umbilic(-10.0, -10.0 + 5e-8));
  EXPECT_FALSE(is_umbilic(-10.0, -10.0 + 2e-7));
  EXPECT_FALSE(is_umbilic(1.0, -1.0));
  EXPECT_FALSE(is_umbilic(kNaN, kNaN));
}

// Sphere of radius 2 with outward x_u x x_v (longitude u, latitude v): k1 = k2 = H = -1/2.
TEST(CurvatureFromParametric, SphereSignConvention) {
  const double a = 2.0;
  for (double u : {0.3, 2.0, -1.1}) {
    for (double v : {-1.2, 0.0, 0.7}) {
      const double cu = std::cos(u), su = std::sin(u), cv = std::cos(v), sv = std::sin(v);
      const Vec3 xu = a * Vec3(-cv * su, cv * cu, 0);
      const Vec3 xv = a * Vec3(-sv * cu, -sv * su, cv);
      const Vec3 xuu = a * Vec3(-cv * cu, -cv * su, 0);
      const Vec3 xuv = a * Vec3(sv * su, -sv * cu, 0);
      const Vec3 xvv = a * Vec3(-cv * cu, -cv * su, -sv);
      const Curvature c = curvature_from_parametric(xu, xv, xuu, xuv, xvv);
      EXPECT_LE((c.normal - Vec3(cv * cu, cv * su, sv)).norm(), 1e-15);
      EXPECT_NEAR(c.k1, -0.5, 1e-14);
      EXPECT_NEAR(c.k2, -0.5, 1e-14);
      EXPECT_NEAR(c.H, -0.5, 1e-14);
      EXPECT_NEAR(c.K, 0.25, 1e-14);
    }
  }
}

// Random general parametric input against the classical route W = G^-1 B (eqs. 1-3).
TEST(CurvatureFromParametric, MatchesClassicalWeingarten) {
  std::mt19937_64 rng(20090101);
  int compared = 0;
  for (int trial = 0; trial < 2000; ++trial) {
    auto rv = [&] { return Vec3(uniform(rng, -1, 1), uniform(rng, -1, 1), uniform(rng, -1, 1)); };
    const Vec3 xu = rv(), xv = rv(), xuu = rv(), xuv = rv(), xvv = rv();
    const double ell = xu.cross(xv).norm();
    if (ell < 0.2 * xu.norm() * xv.norm()) continue;  // keep J well conditioned (kappa < ~10)
    const Curvature c = curvature_from_parametric(xu, xv, xuu, xuv, xvv);
    const test::Reference r = test::reference_from_derivatives(xu, xv, xuu, xuv, xvv);
    const double scale = std::max(std::abs(r.k1), std::abs(r.k2));
    EXPECT_LE((c.normal - r.normal).norm(), 1e-14);
    EXPECT_NEAR(c.k1, r.k1, 1e-12 * scale);
    EXPECT_NEAR(c.k2, r.k2, 1e-12 * scale);
    EXPECT_NEAR(c.H, r.H, 1e-12 * scale);
    EXPECT_NEAR(c.K, r.K, 1e-12 * scale * scale);
    const double gap = (r.k1 - r.k2) / scale;
    if (gap > 1e-3) {
      EXPECT_LE(line_angle(c.d1, r.d1), 1e-12 / gap);
      EXPECT_LE(line_angle(c.d2, r.d2), 1e-12 / gap);
    }
    EXPECT_LE((c.d1.cross(c.d2) - c.normal).norm(), 1e-14);
    EXPECT_NEAR(c.d1.dot(c.d2), 0.0, 1e-14);
    ++compared;
  }
  EXPECT_GT(compared, 1000);
}

// The height route (Table 1 + basis of docs/algorithms.md §6.1) against the parametric route on
// x(u, v) = origin + u t1 + v t2 + f(u, v) m.
TEST(CurvatureFromHeight, AgreesWithParametricRoute) {
  std::mt19937_64 rng(42);
  double worst_k = 0, worst_hk = 0, worst_n = 0, worst_d = 0;
  for (int trial = 0; trial < 5000; ++trial) {
    const Mat3 U = random_frame(rng);
    const Vec3 t1 = U.col(0), t2 = U.col(1), m = U.col(2);
    const double range = trial % 2 == 0 ? 1.0 : 4.0;
    const double fu = uniform(rng, -range, range), fv = uniform(rng, -range, range);
    const double fuu = uniform(rng, -3, 3), fuv = uniform(rng, -3, 3), fvv = uniform(rng, -3, 3);
    const Curvature h = curvature_from_height(t1, t2, m, fu, fv, fuu, fuv, fvv);
    const Curvature p =
        curvature_from_parametric(t1 + fu * m, t2 + fv * m, fuu * m, fuv * m, fvv * m);
    const double scale = std::max(std::abs(p.k1), std::abs(p.k2));
    worst_n = std::max(worst_n, (h.normal - p.normal).norm());
    worst_k = std::max({worst_k, std::abs(h.k1 - p.k1) / scale, std::abs(h.k2 - p.k2) / scale});
    worst_hk =
        std::max({worst_hk, std::abs(h.H - p.H) / scale, std::abs(h.K - p.K) / (scale * scale)});
    const double gap = (p.k1 - p.k2) / scale;
    if (gap > 1e-3) {
      worst_d = std::max({worst_d, gap * line_angle(h.d1, p.d1), gap * line_angle(h.d2, p.d2)});
    }
    EXPECT_LE((h.d1.cross(h.d2) - h.normal).norm(), 1e-14);
    EXPECT_NEAR(h.d1.dot(h.normal), 0.0, 1e-14);
  }
  EXPECT_LE(worst_n, 1e-14);
  EXPECT_LE(worst_k, 1e-12);
  EXPECT_LE(worst_hk, 1e-12);
  EXPECT_LE(worst_d, 1e-12);
  RecordProperty("worst_relative_k", std::to_string(worst_k));
  RecordProperty("worst_relative_HK", std::to_string(worst_hk));
}

TEST(CurvatureFromHeight, FlatGradientUsesTheFrame) {
  // grad f = 0: q1 = t1, q2 = t2, normal = m; Hess diagonal.
  const Vec3 t1 = Vec3(0, 1, 0), t2 = Vec3(0, 0, 1), m = Vec3(1, 0, 0);
  const Curvature c = curvature_from_height(t1, t2, m, 0, 0, -1.0, 0.0, -3.0);
  EXPECT_EQ(c.normal, m);
  EXPECT_EQ(c.k1, -1.0);
  EXPECT_EQ(c.k2, -3.0);
  EXPECT_EQ(c.H, -2.0);
  EXPECT_EQ(c.K, 3.0);
  EXPECT_LE(line_angle(c.d1, t1), 1e-16);
  EXPECT_LE(line_angle(c.d2, t2), 1e-16);
}

TEST(CurvatureFromParametric, DegenerateJacobianGivesNaN) {
  const Vec3 z = Vec3::Zero(), ex = Vec3::UnitX(), ey = Vec3::UnitY(), ez = Vec3::UnitZ();
  expect_all_nan(curvature_from_parametric(z, ey, ez, ez, ez));         // x_u = 0
  expect_all_nan(curvature_from_parametric(ex, 2.0 * ex, ez, ez, ez));  // parallel
  expect_all_nan(curvature_from_parametric(ex, ey, Vec3(kNaN, 0, 0), ez, ez));
  expect_all_nan(curvature_from_parametric(ex, Vec3(0, kInf, 0), ez, ez, ez));
  expect_all_nan(curvature_from_parametric(z, z, z, z, z));
}

TEST(CurvatureFromHeight, NonFiniteInputGivesNaN) {
  const Vec3 ex = Vec3::UnitX(), ey = Vec3::UnitY(), ez = Vec3::UnitZ();
  expect_all_nan(curvature_from_height(ex, ey, ez, kNaN, 0, 1, 0, 1));
  expect_all_nan(curvature_from_height(ex, ey, ez, 0, 0, kInf, 0, 1));
  expect_all_nan(curvature_from_height(ex, Vec3(kNaN, 0, 0), ez, 0, 0, 1, 0, 1));
  expect_all_nan(curvature_from_height(ex, ey, ez, 1e200, 1e200, 1, 0, 1));  // l overflows
}

}  // namespace
}  // namespace curvbench
