// surfaces/sphere: the sign convention of docs/algorithms.md §0 and finite differences.
#include "surfaces/sphere.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <numbers>
#include <random>
#include <string>

#include "core/errors.h"
#include "surface_test_util.h"

namespace curvbench {
namespace {

TEST(Sphere, RadiusTwoSignConvention) {
  const Sphere s(2.0);
  EXPECT_EQ(s.name(), "sphere");
  EXPECT_EQ(s.radius(), 2.0);
  std::mt19937_64 rng(3);
  for (int k = 0; k < 500; ++k) {
    const double u = test::uniform(rng, -4, 4), v = test::uniform(rng, -1.6, 1.6);
    const Vec3 p = s.position(u, v);
    EXPECT_NEAR(p.norm(), 2.0, 1e-15);
    const SurfacePoint e = s.evaluate(p);
    EXPECT_EQ(e.k1, -0.5);
    EXPECT_EQ(e.k2, -0.5);
    EXPECT_EQ(e.H, -0.5);
    EXPECT_EQ(e.K, 0.25);
    EXPECT_TRUE(e.umbilic);
    EXPECT_LE((e.normal - p / 2.0).norm(), 1e-15);  // outward
    EXPECT_GT(e.normal.dot(p), 0.0);
    test::expect_frame_conventions(e, "sphere");
  }
  // The poles and the Duff basis' switch at z = 0 (both signs).
  for (const Vec3& p : {Vec3(0, 0, 2), Vec3(0, 0, -2), Vec3(2, 0, 0), Vec3(0, 2, -1e-300),
                        Vec3(0, 2, 1e-300), Vec3(1e-9, 0, -2)}) {
    const SurfacePoint e = s.evaluate(p);
    test::expect_frame_conventions(e, "sphere pole/equator");
    EXPECT_LE((e.normal - p.normalized()).norm(), 1e-15);
  }
}

TEST(Sphere, MatchesFiniteDifferences) {
  for (double a : {1.0, 2.0, 0.25}) {
    const Sphere s(a);
    for (int i = 0; i < 16; ++i) {
      for (int j = 0; j < 11; ++j) {
        const double u = 2 * std::numbers::pi * (i + 0.3) / 16, v = -1.4 + 2.8 * j / 10;
        const SurfacePoint e = s.evaluate(s.position(u, v));
        const test::Reference ref = test::fd_reference(s, u, v);
        const std::string where =
            "a=" + std::to_string(a) + " u=" + std::to_string(u) + " v=" + std::to_string(v);
        // Umbilic everywhere: directions are arbitrary, so only n, k1, k2, H, K are compared.
        EXPECT_FALSE(test::expect_matches_reference(e, ref, 1e-6, 1e-2, where.c_str()));
      }
    }
  }
}

TEST(Sphere, ProjectAndErrors) {
  const Sphere s(2.0);
  EXPECT_LE((s.project(Vec3(3, 4, 0)) - Vec3(1.2, 1.6, 0)).norm(), 1e-15);
  EXPECT_LE((s.project(Vec3(0.1, -0.2, 0.05)).norm() - 2.0), 1e-15);
  EXPECT_EQ(s.project(Vec3::Zero()), Vec3(0, 0, 2));
  const Vec3 q = s.project(Vec3(-1, 2, 3));
  EXPECT_LE((s.project(q) - q).norm(), 1e-15);
  const double nan = std::numeric_limits<double>::quiet_NaN();
  EXPECT_TRUE(s.project(Vec3(nan, 0, 0)).array().isNaN().all());
  EXPECT_TRUE(std::isnan(s.evaluate(Vec3(0, 0, nan)).H));
  EXPECT_THROW(Sphere(0.0), UsageError);
  EXPECT_THROW(Sphere(-1.0), UsageError);
  EXPECT_EQ(make_sphere(3.0)->evaluate(Vec3(0, 0, 1)).k1, -1.0 / 3.0);
}

}  // namespace
}  // namespace curvbench
