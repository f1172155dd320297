// surfaces/torus: closed forms of docs/algorithms.md §11.1 against finite differences of
// position(u, v), conventions, and the closest-point projection.
#include "surfaces/torus.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <random>
#include <string>
#include <utility>

#include "core/errors.h"
#include "surface_test_util.h"

namespace curvbench {
namespace {

using test::kPi;

// Distance from p to the torus surface, | |(rho - R, z)| - r |.
double torus_distance(const Torus& t, const Vec3& p) {
  const double rho = std::hypot(p.x(), p.y());
  return std::abs(std::hypot(rho - t.major_radius(), p.z()) - t.minor_radius());
}

TEST(Torus, BasicsAndErrors) {
  const Torus t;
  EXPECT_EQ(t.name(), "torus");
  EXPECT_EQ(t.major_radius(), 1.0);
  EXPECT_EQ(t.minor_radius(), 0.3);
  EXPECT_EQ(make_torus()->name(), "torus");
  EXPECT_THROW(Torus(0.3, 1.0), UsageError);  // R < r: self-intersecting
  EXPECT_THROW(Torus(1.0, 0.0), UsageError);
  EXPECT_THROW(Torus(1.0, -0.1), UsageError);
  EXPECT_THROW(Torus(std::numeric_limits<double>::quiet_NaN(), 0.3), UsageError);
}

TEST(Torus, MatchesFiniteDifferences) {
  for (const auto& [R, r] : {std::pair{1.0, 0.3}, std::pair{2.0, 0.5}}) {
    const Torus t(R, r);
    int compared = 0;
    for (int i = 0; i < 24; ++i) {
      for (int j = 0; j < 16; ++j) {
        const double u = 2 * kPi * (i + 0.37) / 24, v = 2 * kPi * (j + 0.21) / 16;
        const SurfacePoint e = t.evaluate(t.position(u, v));
        const test::Reference ref = test::fd_reference(t, u, v);
        const std::string where =
            "R=" + std::to_string(R) + " u=" + std::to_string(u) + " v=" + std::to_string(v);
        compared += test::expect_matches_reference(e, ref, 1e-6, 1e-2, where.c_str());
      }
    }
    EXPECT_EQ(compared, 24 * 16);  // no umbilics: every direction is compared
  }
}

TEST(Torus, ClosedFormsAndConventions) {
  const Torus t;  // R = 1, r = 0.3
  const double R = 1.0, r = 0.3;
  std::mt19937_64 rng(7);
  for (int k = 0; k < 500; ++k) {
    const double u = test::uniform(rng, -kPi, kPi), v = test::uniform(rng, -kPi, kPi);
    const Vec3 p = t.position(u, v);
    const SurfacePoint s = t.evaluate(p);
    test::expect_frame_conventions(s, "torus");
    const double rho = std::hypot(p.x(), p.y());
    EXPECT_NEAR(s.k1, -(rho - R) / (r * rho), 1e-13);
    EXPECT_NEAR(s.k2, -1.0 / r, 1e-13);
    EXPECT_NEAR(s.H, -(2 * rho - R) / (2 * r * rho), 1e-13);
    EXPECT_NEAR(s.K, (rho - R) / (r * r * rho), 1e-13);
    EXPECT_GE(s.H, -2.0513);  // ranges quoted in §11.1
    EXPECT_LE(s.H, -0.9523);
    EXPECT_GE(s.K, -4.762);
    EXPECT_LE(s.K, 2.565);
    EXPECT_FALSE(s.umbilic);
    // Outward: the normal points away from the core circle.
    const Vec3 c = R * Vec3(p.x() / rho, p.y() / rho, 0);
    EXPECT_LE((s.normal - (p - c) / r).norm(), 1e-13);
    // d1 along the parallel (horizontal), d2 along the meridian.
    EXPECT_NEAR(s.d1.z(), 0.0, 1e-15);
    EXPECT_NEAR(s.d2.dot(Vec3(-p.y(), p.x(), 0)), 0.0, 1e-13);
    EXPECT_LE((s.point - p).norm(), 1e-15);
  }
}

TEST(Torus, ProjectLandsOnTorusAndIsIdempotent) {
  const Torus t;
  std::mt19937_64 rng(11);
  for (int k = 0; k < 2000; ++k) {
    const Vec3 p(test::uniform(rng, -2, 2), test::uniform(rng, -2, 2), test::uniform(rng, -1, 1));
    const Vec3 q = t.project(p);
    EXPECT_LE(torus_distance(t, q), 1e-15);
    const Vec3 qq = t.project(q);
    EXPECT_LE((qq - q).norm(), 1e-15);
    // p - q is along the normal at q, and evaluate(p) is evaluate(q).
    const SurfacePoint sp = t.evaluate(p), sq = t.evaluate(q);
    EXPECT_LE((p - q).cross(sq.normal).norm(), 1e-14);
    EXPECT_LE((sp.point - sq.point).norm(), 1e-15);
    EXPECT_NEAR(sp.k1, sq.k1, 1e-13);
  }
}

TEST(Torus, ProjectIsTheClosestPoint) {
  const Torus t;
  // Brute-force minimum over a fine (u, v) grid, refined once around the best sample.
  auto brute = [&](const Vec3& p) {
    double best = std::numeric_limits<double>::infinity();
    double bu = 0, bv = 0;
    const int nu = 720, nv = 360;
    for (int i = 0; i < nu; ++i) {
      for (int j = 0; j < nv; ++j) {
        const double u = 2 * kPi * i / nu, v = 2 * kPi * j / nv;
        const double d = (t.position(u, v) - p).squaredNorm();
        if (d < best) best = d, bu = u, bv = v;
      }
    }
    const double hu = 2 * kPi / nu, hv = 2 * kPi / nv;
    for (int i = -50; i <= 50; ++i) {
      for (int j = -50; j <= 50; ++j) {
        const double u = bu + hu * i / 50.0, v = bv + hv * j / 50.0;
        best = std::min(best, (t.position(u, v) - p).squaredNorm());
      }
    }
    return std::sqrt(best);
  };
  const Vec3 points[] = {Vec3(1.5, 0.2, 0.4),  Vec3(0.9, 0.05, 0.02), Vec3(-0.3, 0.4, -0.5),
                         Vec3(0.1, -1.2, 0.9), Vec3(0.0, 0.6, 0.0),   Vec3(2.0, 2.0, -1.0)};
  for (const Vec3& p : points) {
    const double d = (t.project(p) - p).norm();
    const double b = brute(p);
    EXPECT_LE(d, b + 1e-14) << p.transpose();
    EXPECT_NEAR(d, b, 1e-6) << p.transpose();
  }
}

TEST(Torus, DegenerateProjections) {
  const Torus t;
  // On the axis every core point is closest (distance hypot(R, z) - r); on the core circle
  // every tube point is (distance r). The result must still be a closest point on the torus.
  const std::pair<Vec3, double> cases[] = {{Vec3(0, 0, 0), 1.0 - 0.3},
                                           {Vec3(0, 0, 0.7), std::hypot(1.0, 0.7) - 0.3},
                                           {Vec3(1, 0, 0), 0.3},
                                           {Vec3(0, -1, 0), 0.3}};
  for (const auto& [p, dist] : cases) {
    const Vec3 q = t.project(p);
    ASSERT_TRUE(q.allFinite()) << p.transpose();
    EXPECT_LE(torus_distance(t, q), 1e-15);
    EXPECT_NEAR((q - p).norm(), dist, 1e-15);
    EXPECT_TRUE(t.evaluate(p).normal.allFinite());
  }
  const double nan = std::numeric_limits<double>::quiet_NaN();
  EXPECT_TRUE(t.project(Vec3(nan, 0, 0)).array().isNaN().all());
  const SurfacePoint s = t.evaluate(Vec3(0, nan, 0));
  EXPECT_TRUE(std::isnan(s.k1));
  EXPECT_TRUE(s.normal.array().isNaN().all());
}

}  // namespace
}  // namespace curvbench
