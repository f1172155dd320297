// surfaces/ellipsoid: finite differences of the parameterization, closed forms of H and K,
// the closest point, the umbilics.
#include "surfaces/ellipsoid.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <random>
#include <string>

#include "core/errors.h"
#include "surface_test_util.h"

namespace curvbench {
namespace {

using test::kPi;
constexpr double kA = 1.0, kB = 0.8, kC = 0.6;

TEST(Ellipsoid, ConstructionAndName) {
  const Ellipsoid e(kA, kB, kC);
  EXPECT_EQ(e.name(), "ellipsoid");
  EXPECT_EQ(e.a(), kA);
  EXPECT_EQ(e.b(), kB);
  EXPECT_EQ(e.c(), kC);
  EXPECT_THROW(Ellipsoid(0.8, 1.0, 0.6), UsageError);  // a < b
  EXPECT_THROW(Ellipsoid(1.0, 0.6, 0.8), UsageError);  // b < c
  EXPECT_THROW(Ellipsoid(1.0, 0.8, 0.0), UsageError);
  EXPECT_THROW(Ellipsoid(std::nan(""), 0.8, 0.6), UsageError);
  EXPECT_NO_THROW(Ellipsoid(1.0, 1.0, 1.0));  // a sphere is allowed
}

TEST(Ellipsoid, MatchesFiniteDifferences) {
  const Ellipsoid e(kA, kB, kC);
  int compared = 0;
  for (int i = 0; i < 24; ++i) {
    for (int j = 0; j < 15; ++j) {  // latitudes in (-1.3, 1.3): away from the poles
      const double u = 2 * kPi * (i + 0.37) / 24, v = -1.3 + 2.6 * (j + 0.5) / 15;
      const SurfacePoint s = e.evaluate(e.position(u, v));
      const test::Reference ref = test::fd_reference(e, u, v);
      const std::string where = "u=" + std::to_string(u) + " v=" + std::to_string(v);
      compared += test::expect_matches_reference(s, ref, 1e-6, 1e-2, where.c_str());
      test::expect_frame_conventions(s, where.c_str());
    }
  }
  EXPECT_GT(compared, 24 * 15 - 8);  // directions everywhere but near the four umbilics
}

TEST(Ellipsoid, ClosedFormsSignConventionAndUmbilics) {
  const Ellipsoid e(kA, kB, kC);
  std::mt19937_64 rng(5);
  for (int k = 0; k < 1000; ++k) {
    const double u = test::uniform(rng, -kPi, kPi), v = test::uniform(rng, -1.57, 1.57);
    const Vec3 p = e.position(u, v);
    const SurfacePoint s = e.evaluate(p);
    test::expect_frame_conventions(s, "ellipsoid");
    EXPECT_LE((s.point - p).norm(), 1e-14);
    // Outward (the ellipsoid is convex about the origin) and both curvatures negative.
    EXPECT_GT(s.normal.dot(p), 0.0);
    EXPECT_LT(s.k1, 0.0);
    // Closed forms with D p = (x/a^2, y/b^2, z/c^2): K = 1 / (a b c |D p|^2)^2 and
    // H = (|p|^2 - a^2 - b^2 - c^2) / (2 a^2 b^2 c^2 |D p|^3) (negative: outward normal).
    const Vec3 g(p.x() / (kA * kA), p.y() / (kB * kB), p.z() / (kC * kC));
    const double K = 1.0 / std::pow(kA * kB * kC * g.squaredNorm(), 2);
    EXPECT_NEAR(s.K, K, 1e-12 * K);
    const double H = (p.squaredNorm() - kA * kA - kB * kB - kC * kC) /
                     (2.0 * kA * kA * kB * kB * kC * kC * std::pow(g.norm(), 3));
    EXPECT_NEAR(s.H, H, 1e-12 * std::abs(H));
  }
  // The four umbilics in the plane y = 0.
  const double x = kA * std::sqrt((kA * kA - kB * kB) / (kA * kA - kC * kC));
  const double z = kC * std::sqrt((kB * kB - kC * kC) / (kA * kA - kC * kC));
  for (const Vec3& p : {Vec3(x, 0, z), Vec3(-x, 0, z), Vec3(x, 0, -z), Vec3(-x, 0, -z)}) {
    const SurfacePoint s = e.evaluate(p);
    EXPECT_NEAR(s.k1, s.k2, 1e-12);
    EXPECT_NEAR(s.k1, -kA * kC / (kB * kB * kB), 1e-12);  // k = -a c / b^3 there
  }
  EXPECT_FALSE(e.evaluate(Vec3(kA, 0, 0)).umbilic);
}

// The closest point: on the surface, p - q along the normal at q, and no sampled surface point
// closer; for points inside, outside and on the coordinate planes.
TEST(Ellipsoid, ClosestPoint) {
  const Ellipsoid e(kA, kB, kC);
  std::mt19937_64 rng(9);
  const auto check = [&](const Vec3& p) {
    const Vec3 q = e.project(p);
    SCOPED_TRACE(::testing::PrintToString(p.transpose()));
    EXPECT_NEAR(e.implicit(q), 0.0, 1e-14);
    const Vec3 n = e.evaluate(q).normal;
    EXPECT_LE((p - q).cross(n).norm(), 1e-12 * std::max(1.0, (p - q).norm()));
    const double d = (p - q).norm();
    for (int i = 0; i < 64; ++i)
      for (int j = 1; j < 32; ++j)
        ASSERT_GE((e.position(2 * kPi * i / 64, -kPi / 2 + kPi * j / 32) - p).norm(), d - 1e-12);
  };
  for (int k = 0; k < 200; ++k)
    check(Vec3(test::uniform(rng, -1.5, 1.5), test::uniform(rng, -1.2, 1.2),
               test::uniform(rng, -1.0, 1.0)));
  for (int k = 0; k < 50; ++k) {  // on the coordinate planes and axes, inside and out
    const double s = test::uniform(rng, -1.2, 1.2), t = test::uniform(rng, -1.2, 1.2);
    check(Vec3(0, s, t));
    check(Vec3(s, 0, t));
    check(Vec3(s, t, 0));
    check(Vec3(s, 0, 0));
    check(Vec3(0, s, 0));
    check(Vec3(0, 0, s));
  }
  const Vec3 on = e.position(0.3, 0.4);
  EXPECT_LE((e.project(on) - on).norm(), 1e-15);
  EXPECT_TRUE(std::isnan(e.evaluate(Vec3(0, std::nan(""), 0)).K));
}

}  // namespace
}  // namespace curvbench
