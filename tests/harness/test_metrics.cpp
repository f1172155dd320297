// Error metrics and rates on hand-made inputs with known answers.
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "core/errors.h"
#include "harness/model/metrics.h"

namespace curvbench {
namespace {

struct Fixture {
  std::vector<SurfacePoint> exact;
  std::vector<VertexEstimate> est;
  std::vector<int> all;
};

// n points with H = K = k1 = k2 = i+1, normal +z, d1 = x; the estimates start equal to exact.
Fixture make(int n) {
  Fixture f;
  for (int i = 0; i < n; ++i) {
    SurfacePoint p;
    p.normal = Vec3(0, 0, 1);
    p.k1 = 2.0 * (i + 1);
    p.k2 = -1.0 * (i + 1);
    p.H = 0.5 * (p.k1 + p.k2);
    p.K = p.k1 * p.k2;
    p.d1 = Vec3(1, 0, 0);
    p.d2 = Vec3(0, 1, 0);
    f.exact.push_back(p);
    VertexEstimate e;
    e.normal = p.normal;
    e.k1 = p.k1;
    e.k2 = p.k2;
    e.H = p.H;
    e.K = p.K;
    e.d1 = p.d1;
    e.d2 = p.d2;
    e.status = VertexStatus::ok;
    f.est.push_back(e);
    f.all.push_back(i);
  }
  return f;
}

TEST(Metrics, ExactEstimatesHaveZeroError) {
  Fixture f = make(10);
  for (Quantity q :
       {Quantity::normal, Quantity::H, Quantity::K, Quantity::k1, Quantity::k2, Quantity::d1})
    for (Norm n : {Norm::L2, Norm::Linf})
      EXPECT_EQ(compute_error(q, n, f.est, f.exact, f.all).value, 0.0) << to_string(q);
}

// A quantity that is zero on every scored vertex (k1 and K on a cylinder of radius 2: k2 = -1/2)
// is measured against the curvature scale s = max(|k1|, |k2|) (s^2 for K); one that is not keeps
// its relative error; with s = 0 too (a plane) the error is NaN.
TEST(Metrics, ZeroExactNormFallsBackToTheCurvatureScale) {
  Fixture f = make(4);
  for (size_t i = 0; i < f.exact.size(); ++i) {
    f.exact[i].k1 = 0.0;
    f.exact[i].k2 = -0.5;
    f.exact[i].H = -0.25;
    f.exact[i].K = 0.0;
    f.est[i].k1 = i % 2 ? 0.1 : -0.1;
    f.est[i].k2 = -0.5;
    f.est[i].H = -0.25 + 0.05 * (i % 2 ? 1 : -1);
    f.est[i].K = i == 3 ? 0.2 : 0.1;
  }
  const ErrorValue k1 = compute_error(Quantity::k1, Norm::L2, f.est, f.exact, f.all);
  EXPECT_TRUE(k1.zero_exact_norm);
  EXPECT_NEAR(k1.value, 0.1 / 0.5, 1e-15);
  const ErrorValue kl2 = compute_error(Quantity::K, Norm::L2, f.est, f.exact, f.all);
  EXPECT_TRUE(kl2.zero_exact_norm);
  EXPECT_NEAR(kl2.value, std::sqrt((3 * 0.01 + 0.04) / (4 * 0.0625)), 1e-15);
  const ErrorValue klinf = compute_error(Quantity::K, Norm::Linf, f.est, f.exact, f.all);
  EXPECT_TRUE(klinf.zero_exact_norm);
  EXPECT_NEAR(klinf.value, 0.2 / 0.25, 1e-15);
  const ErrorValue h = compute_error(Quantity::H, Norm::L2, f.est, f.exact, f.all);
  EXPECT_FALSE(h.zero_exact_norm);
  EXPECT_NEAR(h.value, 0.05 / 0.25, 1e-15);
  EXPECT_FALSE(compute_error(Quantity::normal, Norm::L2, f.est, f.exact, f.all).zero_exact_norm);
  for (auto& p : f.exact) p.k2 = p.H = 0.0;  // a plane: no scale either
  EXPECT_TRUE(std::isnan(compute_error(Quantity::K, Norm::L2, f.est, f.exact, f.all).value));
  // One vertex with K != 0 is enough for the relative error.
  Fixture g = make(4);
  for (auto& p : g.exact) p.K = 0.0;
  g.exact[2].K = 2.0;
  for (auto& e : g.est) e.K = 0.0;
  const ErrorValue rel = compute_error(Quantity::K, Norm::L2, g.est, g.exact, g.all);
  EXPECT_FALSE(rel.zero_exact_norm);
  EXPECT_NEAR(rel.value, 1.0, 1e-15);
}

TEST(Metrics, ConstantOffsetInMeanCurvature) {
  Fixture f = make(4);  // H = 0.5, 1, 1.5, 2
  for (auto& e : f.est) e.H += 0.1;
  const double sum_sq = 0.25 + 1 + 2.25 + 4;
  EXPECT_NEAR(compute_error(Quantity::H, Norm::L2, f.est, f.exact, f.all).value,
              std::sqrt(4 * 0.01) / std::sqrt(sum_sq), 1e-15);
  EXPECT_NEAR(compute_error(Quantity::H, Norm::Linf, f.est, f.exact, f.all).value, 0.1 / 2.0,
              1e-15);
}

TEST(Metrics, SingleBadVertexDominatesLinf) {
  Fixture f = make(100);
  f.est[37].normal = Vec3(0, 0.6, 0.8);  // |n~ - n| = sqrt(0.36 + 0.04)
  const double bad = std::sqrt(0.4);
  EXPECT_NEAR(compute_error(Quantity::normal, Norm::Linf, f.est, f.exact, f.all).value, bad, 1e-15);
  EXPECT_NEAR(compute_error(Quantity::normal, Norm::L2, f.est, f.exact, f.all).value,
              bad / std::sqrt(100.0), 1e-15);
}

TEST(Metrics, DirectionErrorIsSignInvariantAndSkipsUmbilics) {
  Fixture f = make(3);
  f.est[0].d1 = -f.exact[0].d1;  // opposite sign: no error
  f.est[1].d1 = Vec3(0, 1, 0);   // 90 degrees off: sqrt(2)
  f.exact[2].umbilic = true;     // skipped whatever its estimate
  f.est[2].d1 = Vec3(0, 0, 1);
  const ErrorValue e = compute_error(Quantity::d1, Norm::L2, f.est, f.exact, f.all);
  EXPECT_EQ(e.vertices, 2);
  EXPECT_NEAR(e.value, std::sqrt(2.0 / 2.0), 1e-15);
}

TEST(Metrics, ExcludedVerticesAreCountedNotSummed) {
  Fixture f = make(5);
  f.est[2] = VertexEstimate{};  // NaN everywhere
  f.est[2].status = VertexStatus::excluded;
  const ErrorValue e = compute_error(Quantity::H, Norm::L2, f.est, f.exact, f.all);
  EXPECT_EQ(e.vertices, 4);
  EXPECT_EQ(e.excluded, 1);
  EXPECT_EQ(e.value, 0.0);
}

TEST(Metrics, ConvergenceRates) {
  // e = C h^2 exactly gives rate 2 for any h sequence.
  const std::vector<double> h{0.2, 0.09, 0.05, 0.026};
  std::vector<double> e;
  for (double x : h) e.push_back(3.0 * x * x);
  EXPECT_NEAR(convergence_rate(e.front(), e.back(), h.front(), h.back()), 2.0, 1e-12);
  for (double r : pairwise_rates(e, h)) EXPECT_NEAR(r, 2.0, 1e-12);
  // Halving h three times and the paper's (1/3) log2(e1/e4): e1/e4 = 64 -> 2.
  EXPECT_NEAR(convergence_rate(64.0, 1.0, 0.8, 0.1), 2.0, 1e-12);
  EXPECT_TRUE(std::isnan(convergence_rate(0.0, 1.0, 1.0, 0.5)));
  EXPECT_TRUE(std::isnan(convergence_rate(1.0, 1.0, 1.0, 1.0)));
}

TEST(Metrics, ParsersRejectUnknownNames) {
  EXPECT_EQ(parse_quantity("K"), Quantity::K);
  EXPECT_EQ(parse_norm("Linf"), Norm::Linf);
  EXPECT_EQ(parse_vertex_set("boundary-ring"), VertexSet::boundary_ring);
  EXPECT_EQ(parse_vertex_set("valence-4-or-less"), VertexSet::valence_4_or_less);
  EXPECT_EQ(parse_vertex_set("valence-5-or-more"), VertexSet::valence_5_or_more);
  EXPECT_THROW(parse_quantity("curv"), UsageError);
  EXPECT_THROW(parse_norm("L3"), UsageError);
  EXPECT_THROW(parse_vertex_set("edge"), UsageError);
}

TEST(Metrics, VertexSets) {
  // 4 x 4 squares: 25 vertices, 16 on the boundary, 9 interior.
  const int n = 4;
  VertexMatrix V((n + 1) * (n + 1), 3);
  for (int j = 0; j <= n; ++j)
    for (int i = 0; i <= n; ++i) V.row(j * (n + 1) + i) << i, j, 0;
  FaceMatrix F(2 * n * n, 3);
  int f = 0;
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i) {
      const int a = j * (n + 1) + i;
      F.row(f++) << a, a + 1, a + n + 2;
      F.row(f++) << a, a + n + 2, a + n + 1;
    }
  const Mesh mesh(V, F);
  EXPECT_EQ(select_vertices(mesh, VertexSet::all).size(), 25u);
  EXPECT_EQ(select_vertices(mesh, VertexSet::interior).size(), 9u);
  // Boundary (16) plus the interior vertices adjacent to it (the 8 around the centre).
  EXPECT_EQ(select_vertices(mesh, VertexSet::boundary_ring).size(), 24u);
  // Valences: 6 inside, 4 along the sides, 2 or 3 at the corners.
  EXPECT_EQ(select_vertices(mesh, VertexSet::valence_4_or_less).size(), 16u);
  EXPECT_EQ(select_vertices(mesh, VertexSet::valence_5_or_more),
            select_vertices(mesh, VertexSet::interior));
}

}  // namespace
}  // namespace curvbench

namespace curvbench {
namespace {

// A method that does not compute normals or directions (ComputedQuantities) leaves them NaN with
// status ok: its H is still scored over every vertex, and the runner asks computes() to skip the
// normal and d1 rows instead of counting every vertex as excluded.
TEST(Metrics, QuantitiesAreJudgedOneByOne) {
  Fixture f = make(4);
  for (VertexEstimate& e : f.est) {
    e.normal = Vec3::Constant(std::nan(""));
    e.d1 = e.d2 = Vec3::Constant(std::nan(""));
  }
  f.est[1].H += 1.0;
  const ErrorValue h = compute_error(Quantity::H, Norm::Linf, f.est, f.exact, f.all);
  EXPECT_EQ(h.vertices, 4);
  EXPECT_EQ(h.excluded, 0);
  EXPECT_DOUBLE_EQ(h.value, 1.0 / 2.0);  // max |H error| 1 over max |H| = 4 * 0.5
  const ErrorValue n = compute_error(Quantity::normal, Norm::L2, f.est, f.exact, f.all);
  EXPECT_EQ(n.vertices, 0);
  EXPECT_EQ(n.excluded, 4);
  ComputedQuantities only_h;
  only_h.normal = only_h.principal = only_h.gaussian = only_h.directions = false;
  EXPECT_TRUE(computes(only_h, Quantity::H));
  for (Quantity q : {Quantity::normal, Quantity::K, Quantity::k1, Quantity::k2, Quantity::d1})
    EXPECT_FALSE(computes(only_h, q)) << to_string(q);
  for (Quantity q :
       {Quantity::normal, Quantity::H, Quantity::K, Quantity::k1, Quantity::k2, Quantity::d1})
    EXPECT_TRUE(computes(ComputedQuantities{}, q)) << to_string(q);
}

// The point-cloud literature's norms. PCPNet's RMS angle: normals turned by 3 and 4 degrees about
// x, a third one exactly reversed (unoriented: no error), the rest exact, over 4 points:
// sqrt((9 + 16) / 4) = 2.5 degrees. The rectified error: H = 0.5, 1, 1.5, 2 (make(4)) estimated
// 0.6, 1, 1.5, 2.4: (0.1 / 1 + 0.4 / 2) / 4 = 0.075.
TEST(Metrics, AngleRmsAndRectifiedErrors) {
  Fixture f = make(4);
  const auto turned = [](double degrees) {
    const double a = degrees * M_PI / 180.0;
    return Vec3(0, std::sin(a), std::cos(a));
  };
  f.est[0].normal = turned(3.0);
  f.est[1].normal = turned(4.0);
  f.est[2].normal = -f.exact[2].normal;
  EXPECT_NEAR(compute_error(Quantity::normal, Norm::angle_rms, f.est, f.exact, f.all).value, 2.5,
              1e-12);
  f.est[0].H = 0.6;
  f.est[3].H = 2.4;
  EXPECT_NEAR(compute_error(Quantity::H, Norm::rectified, f.est, f.exact, f.all).value, 0.075,
              1e-15);
  // A point without an estimate is counted as excluded, not as an error.
  f.est[1].H = NAN;
  const ErrorValue e = compute_error(Quantity::H, Norm::rectified, f.est, f.exact, f.all);
  EXPECT_EQ(e.excluded, 1);
  EXPECT_NEAR(e.value, 0.3 / 3, 1e-15);
}

TEST(Metrics, PointCloudNormsParseAndApplyToTheirQuantities) {
  for (Norm n : {Norm::L2, Norm::Linf, Norm::angle_rms, Norm::rectified})
    EXPECT_EQ(parse_norm(to_string(n)), n);
  EXPECT_THROW(parse_norm("angle"), UsageError);
  EXPECT_NO_THROW(check_norm_applies(Quantity::normal, Norm::angle_rms));
  EXPECT_THROW(check_norm_applies(Quantity::H, Norm::angle_rms), UsageError);
  for (Quantity q : {Quantity::H, Quantity::K, Quantity::k1, Quantity::k2})
    EXPECT_NO_THROW(check_norm_applies(q, Norm::rectified));
  EXPECT_THROW(check_norm_applies(Quantity::normal, Norm::rectified), UsageError);
  EXPECT_THROW(check_norm_applies(Quantity::d1, Norm::rectified), UsageError);
  Fixture f = make(2);
  EXPECT_THROW(compute_error(Quantity::d1, Norm::angle_rms, f.est, f.exact, f.all), UsageError);
}

}  // namespace
}  // namespace curvbench
