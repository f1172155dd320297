// surfaces/height_field and surfaces/gaussian_bump: exact quantities against finite
// differences, the bump's closed forms and umbilic (docs/algorithms.md §11.2), projection.
#include "surfaces/height_field.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <memory>
#include <random>
#include <string>

#include "core/errors.h"
#include "surface_test_util.h"
#include "surfaces/gaussian_bump.h"

namespace curvbench {
namespace {

// A cubic with a saddle region and a skew Hessian, on [-1, 1]^2:
// f = 0.4 x^3 - 0.3 x y^2 + 0.5 x y - 0.2 y^2 + 0.1 x.
HeightField make_cubic() {
  HeightFunction fn;
  fn.f = [](double x, double y) {
    return 0.4 * x * x * x - 0.3 * x * y * y + 0.5 * x * y - 0.2 * y * y + 0.1 * x;
  };
  fn.fx = [](double x, double y) { return 1.2 * x * x - 0.3 * y * y + 0.5 * y + 0.1; };
  fn.fy = [](double x, double y) { return -0.6 * x * y + 0.5 * x - 0.4 * y; };
  fn.fxx = [](double x, double) { return 2.4 * x; };
  fn.fxy = [](double, double y) { return -0.6 * y + 0.5; };
  fn.fyy = [](double x, double) { return -0.6 * x - 0.4; };
  return HeightField("cubic", std::move(fn), -1.0, 1.0, -1.0, 1.0);
}

void check_against_fd(const Surface& s, double x0, double x1, int n, int* compared, int* skipped) {
  for (int i = 0; i <= n; ++i) {
    for (int j = 0; j <= n; ++j) {
      const double x = x0 + (x1 - x0) * i / n, y = x0 + (x1 - x0) * j / n;
      const SurfacePoint e = s.evaluate(s.position(x, y));
      const std::string where = s.name() + " x=" + std::to_string(x) + " y=" + std::to_string(y);
      test::expect_frame_conventions(e, where.c_str());
      EXPECT_GT(e.normal.z(), 0.0);  // upward
      if (test::expect_matches_reference(e, test::fd_reference(s, x, y), 1e-6, 1e-2,
                                         where.c_str())) {
        ++*compared;
      } else {
        ++*skipped;
      }
    }
  }
}

TEST(HeightField, BumpMatchesFiniteDifferences) {
  const SurfacePtr bump = make_gaussian_bump();
  EXPECT_EQ(bump->name(), "bump");
  int compared = 0, skipped = 0;
  check_against_fd(*bump, 0.0, 1.0, 24, &compared, &skipped);
  EXPECT_EQ(skipped, 1);  // only the peak (1/2, 1/2) has |k1 - k2| < 1e-2
}

TEST(HeightField, CubicMatchesFiniteDifferences) {
  const HeightField cubic = make_cubic();
  int compared = 0, skipped = 0;
  check_against_fd(cubic, -1.0, 1.0, 20, &compared, &skipped);
  EXPECT_GE(compared, 21 * 21 - 5);
}

// §11.2: the bump is a surface of revolution; meridian and parallel curvatures in closed form.
TEST(HeightField, BumpClosedForms) {
  const SurfacePtr bump = make_gaussian_bump();
  const double a = kBumpExponent;
  std::mt19937_64 rng(5);
  for (int k = 0; k < 1000; ++k) {
    const double x = test::uniform(rng, 0, 1), y = test::uniform(rng, 0, 1);
    const double dx = x - 0.5, dy = y - 0.5, r = std::hypot(dx, dy);
    const double g = std::exp(-a * r * r), g1 = -2 * a * r * g,
                 g2 = (4 * a * a * r * r - 2 * a) * g;
    const double km = g2 / std::pow(1 + g1 * g1, 1.5);
    const double kp = -2 * a * g / std::sqrt(1 + g1 * g1);
    const Vec3 em = Vec3(dx / r, dy / r, g1) / std::sqrt(1 + g1 * g1);
    const Vec3 ep(-dy / r, dx / r, 0);
    const SurfacePoint s = bump->evaluate(Vec3(x, y, g));
    const double scale = std::max(std::abs(km), std::abs(kp));
    EXPECT_NEAR(s.k1, std::max(km, kp), 1e-13 * scale);
    EXPECT_NEAR(s.k2, std::min(km, kp), 1e-13 * scale);
    const double gap = std::abs(km - kp);
    EXPECT_LE(test::line_angle(s.d1, km >= kp ? em : ep), 1e-13 * scale / gap);
    EXPECT_LE(test::line_angle(s.d2, km >= kp ? ep : em), 1e-13 * scale / gap);
    const double W = std::sqrt(1 + g1 * g1);
    EXPECT_LE((s.normal - Vec3(-g1 * dx / r, -g1 * dy / r, 1) / W).norm(), 1e-14);
  }
}

TEST(HeightField, BumpPeakIsTheOnlyUmbilic) {
  const SurfacePtr bump = make_gaussian_bump();
  const SurfacePoint peak = bump->evaluate(Vec3(0.5, 0.5, 1.0));
  EXPECT_TRUE(peak.umbilic);
  EXPECT_EQ(peak.k1, -81.0 / 8.0);
  EXPECT_EQ(peak.k2, -81.0 / 8.0);
  EXPECT_EQ(peak.H, -81.0 / 8.0);
  EXPECT_EQ(peak.K, (81.0 / 8.0) * (81.0 / 8.0));
  EXPECT_EQ(peak.normal, Vec3::UnitZ());
  test::expect_frame_conventions(peak, "peak");
  int umbilics = 0;
  const int n = 200;
  for (int i = 0; i <= n; ++i) {
    for (int j = 0; j <= n; ++j) {
      if (2 * i == n && 2 * j == n) continue;
      const double x = static_cast<double>(i) / n, y = static_cast<double>(j) / n;
      umbilics += bump->evaluate(bump->position(x, y)).umbilic;
    }
  }
  EXPECT_EQ(umbilics, 0);
  // Also just next to the peak: k1 - k2 = O(r^2) but still far above 1e-8 relative at r = 1e-3.
  EXPECT_FALSE(bump->evaluate(bump->position(0.501, 0.5)).umbilic);
}

TEST(HeightField, ProjectFindsTheFootPoint) {
  const SurfacePtr bump = make_gaussian_bump();
  std::mt19937_64 rng(9);
  for (int k = 0; k < 500; ++k) {
    const double x = test::uniform(rng, 0.05, 0.95), y = test::uniform(rng, 0.05, 0.95);
    const Vec3 q = bump->position(x, y);
    // A point on the surface is returned unchanged.
    EXPECT_EQ(bump->project(q), q);
    const SurfacePoint s = bump->evaluate(q);
    // Off-surface along the normal, within the focal distance 1/|k|: the foot point comes back.
    for (double delta : {1e-6, -1e-3, 2e-2, -3e-2}) {
      const Vec3 p = q + delta * s.normal;
      const Vec3 f = bump->project(p);
      EXPECT_LE((f - q).norm(), 1e-12) << "delta " << delta << " at " << x << "," << y;
      EXPECT_LE((bump->project(f) - f).norm(), 1e-15);
      EXPECT_LE((bump->evaluate(p).point - q).norm(), 1e-12);
    }
  }
}

TEST(HeightField, ProjectMatchesBruteForceAndClampsToTheDomain) {
  const HeightField cubic = make_cubic();
  auto brute = [&](const Vec3& p) {
    double best = std::numeric_limits<double>::infinity();
    const int n = 800;
    for (int i = 0; i <= n; ++i) {
      for (int j = 0; j <= n; ++j) {
        const double x = -1 + 2.0 * i / n, y = -1 + 2.0 * j / n;
        best = std::min(best, (cubic.position(x, y) - p).squaredNorm());
      }
    }
    return std::sqrt(best);
  };
  const Vec3 points[] = {Vec3(0.2, 0.3, 0.5), Vec3(-0.7, 0.1, -0.4), Vec3(0.5, -0.5, 0.0),
                         Vec3(1.5, 0.2, 0.8), Vec3(-2.0, -2.0, 0.0)};
  for (const Vec3& p : points) {
    const Vec3 q = cubic.project(p);
    EXPECT_GE(q.x(), -1.0);
    EXPECT_LE(q.x(), 1.0);
    EXPECT_GE(q.y(), -1.0);
    EXPECT_LE(q.y(), 1.0);
    EXPECT_NEAR(q.z(), cubic.function().f(q.x(), q.y()), 1e-15);
    const double d = (q - p).norm(), b = brute(p);
    EXPECT_LE(d, b + 1e-12) << p.transpose();
    EXPECT_NEAR(d, b, 2e-5) << p.transpose();  // grid spacing 2.5e-3: error O(h^2)
  }
  // Interior foot points: p - q is normal to the surface.
  for (const Vec3& p : {points[0], points[1], points[2]}) {
    const Vec3 q = cubic.project(p);
    EXPECT_LE((p - q).cross(cubic.evaluate(q).normal).norm(), 1e-12);
  }
  const double nan = std::numeric_limits<double>::quiet_NaN();
  EXPECT_TRUE(cubic.project(Vec3(nan, 0, 0)).array().isNaN().all());
  EXPECT_TRUE(std::isnan(cubic.evaluate(Vec3(0, 0, nan)).k1));
}

TEST(HeightField, ConstructorErrors) {
  HeightFunction partial;
  partial.f = [](double, double) { return 0.0; };
  EXPECT_THROW(HeightField("x", partial, 0, 1, 0, 1), UsageError);
  HeightFunction full = make_cubic().function();
  EXPECT_NO_THROW(HeightField("x", full, 0, 1, 0, 1));
  EXPECT_THROW(HeightField("x", full, 1, 0, 0, 1), UsageError);
  EXPECT_THROW(HeightField("x", full, 0, 1, 0, 0), UsageError);
  EXPECT_THROW(HeightField("x", full, 0, std::numeric_limits<double>::infinity(), 0, 1),
               UsageError);
}

}  // namespace
}  // namespace curvbench
