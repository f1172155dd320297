// surfaces/cylinder: finite differences of the parameterization, the sign convention, projection.
#include "surfaces/cylinder.h"

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

TEST(Cylinder, ConstructionAndName) {
  const Cylinder c(2.0);
  EXPECT_EQ(c.name(), "cylinder");
  EXPECT_EQ(c.radius(), 2.0);
  EXPECT_EQ(make_cylinder()->name(), "cylinder");
  EXPECT_THROW(Cylinder(0.0), UsageError);
  EXPECT_THROW(Cylinder(-1.0), UsageError);
  EXPECT_THROW(Cylinder(std::numeric_limits<double>::infinity()), UsageError);
}

TEST(Cylinder, MatchesFiniteDifferences) {
  for (double a : {1.0, 0.5}) {
    const Cylinder c(a);
    int compared = 0;
    for (int i = 0; i < 24; ++i) {
      for (int j = 0; j < 5; ++j) {
        const double u = 2 * kPi * (i + 0.37) / 24, v = -1.0 + 0.5 * j;
        const SurfacePoint e = c.evaluate(c.position(u, v));
        const test::Reference ref = test::fd_reference(c, u, v);
        const std::string where =
            "a=" + std::to_string(a) + " u=" + std::to_string(u) + " v=" + std::to_string(v);
        compared += test::expect_matches_reference(e, ref, 1e-6, 1e-2, where.c_str());
      }
    }
    EXPECT_EQ(compared, 24 * 5);  // no umbilics: every direction is compared
  }
}

TEST(Cylinder, SignConventionAndClosedForms) {
  const Cylinder c(2.0);
  std::mt19937_64 rng(11);
  for (int k = 0; k < 500; ++k) {
    const double u = test::uniform(rng, -kPi, kPi), v = test::uniform(rng, -3, 3);
    const Vec3 p = c.position(u, v);
    const SurfacePoint s = c.evaluate(p);
    test::expect_frame_conventions(s, "cylinder");
    EXPECT_LE((s.point - p).norm(), 1e-15);
    // Outward radial normal; k along the circle -1/a, along the axis 0 (B = n . x_uu).
    EXPECT_LE((s.normal - Vec3(std::cos(u), std::sin(u), 0.0)).norm(), 1e-15);
    EXPECT_EQ(s.k1, 0.0);
    EXPECT_EQ(s.k2, -0.5);
    EXPECT_EQ(s.H, -0.25);
    EXPECT_EQ(s.K, 0.0);
    EXPECT_EQ(s.d1, Vec3(0, 0, 1));
    EXPECT_FALSE(s.umbilic);
  }
}

TEST(Cylinder, ProjectsRadiallyKeepingTheHeight) {
  const Cylinder c(1.5);
  EXPECT_LE((c.project(Vec3(3, 4, 7)) - Vec3(0.9, 1.2, 7)).norm(), 1e-15);
  EXPECT_LE((c.project(Vec3(0.3, 0, -2)) - Vec3(1.5, 0, -2)).norm(), 1e-15);
  EXPECT_EQ(c.project(Vec3(0, 0, 1)), Vec3(1.5, 0, 1));  // the axis: a fixed choice
  EXPECT_TRUE(std::isnan(c.evaluate(Vec3(std::nan(""), 0, 0)).H));
}

}  // namespace
}  // namespace curvbench
