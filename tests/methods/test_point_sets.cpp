// Estimators on point sets (meshes without faces; docs/point_sets.md): the default k-NN
// neighbourhood converges, signs are outward, face methods refuse, bad inputs get a status.
#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

#include "core/errors.h"
#include "mesh/mesh.h"
#include "mesh/neighbourhood_table.h"
#include "meshgen/generate.h"
#include "meshgen/point_samples.h"
#include "methods/estimator.h"
#include "methods/option_schema.h"
#include "surfaces/sphere.h"
#include "surfaces/torus.h"

namespace curvbench {
namespace {

Mesh point_set(VertexMatrix V) {
  return Mesh(std::move(V), FaceMatrix(0, 3), "points");
}

struct HError {
  double l2 = 0.0;       // ||H - H*|| / ||H*|| over the estimated points
  int estimated = 0;     // points with status ok
  int wrong_side = 0;    // estimated normals with n . n* <= 0
  double spacing = 0.0;  // sqrt(area / n)
};

HError torus_h_error(const std::string& method, int n, EstimatorOptions options = {}) {
  const double R = 1.0, r = 0.4;
  const Torus torus(R, r);
  const Mesh mesh = point_set(sample_torus_points(n, R, r, 20261127));
  const auto est = estimate_mesh(mesh, *make_estimator(method, options));
  HError e;
  double num = 0.0, den = 0.0;
  for (int i = 0; i < n; ++i) {
    const VertexEstimate& o = est[static_cast<size_t>(i)];
    if (o.status != VertexStatus::ok) continue;
    const SurfacePoint s = torus.evaluate(mesh.position(i));
    num += (o.H - s.H) * (o.H - s.H);
    den += s.H * s.H;
    ++e.estimated;
    if (!(o.normal.dot(s.normal) > 0.0)) ++e.wrong_side;
  }
  e.l2 = std::sqrt(num / den);
  e.spacing = std::sqrt(4.0 * M_PI * M_PI * R * r / n);
  return e;
}

// The "done when" of the point-set work: LHF-4 and Jet-4 with the default neighbourhood
// (knn = 30) on area-uniform random torus samples of 4k, 16k and 64k points converge in H with
// an L2 rate of at least 2.5 against the spacing, every normal outward.
void expect_converges(const std::string& method) {
  std::vector<HError> levels;
  for (const int n : {4000, 16000, 64000}) {
    levels.push_back(torus_h_error(method, n));
    const HError& e = levels.back();
    EXPECT_GE(e.estimated, n * 99 / 100) << method << " n=" << n;
    EXPECT_EQ(e.wrong_side, 0) << method << " n=" << n;
  }
  const double rate = std::log(levels.front().l2 / levels.back().l2) /
                      std::log(levels.front().spacing / levels.back().spacing);
  for (const HError& e : levels)
    std::printf("%s h=%.4g H L2=%.3e\n", method.c_str(), e.spacing, e.l2);
  std::printf("%s H L2 rate %.2f\n", method.c_str(), rate);
  EXPECT_GE(rate, 2.5) << method;
}

TEST(PointSetConvergence, Lhf4DefaultNeighbourhoodConvergesInH) {
  expect_converges("lhf-4");
}

TEST(PointSetConvergence, Jet4DefaultNeighbourhoodConvergesInH) {
  expect_converges("jet-4");
}

TEST(PointSets, SphereSignsAreOutwardForEveryPointMethod) {
  // Points of a radius-2 sphere: k1 = k2 = H = -1/2 with outward normals.
  const double a = 2.0;
  const Sphere sphere(a);
  VertexMatrix V(2000, 3);
  const VertexMatrix T = sample_torus_points(2000, 1.0, 0.5, 7);  // directions only
  for (int i = 0; i < V.rows(); ++i) V.row(i) = a * T.row(i).normalized();
  const Mesh mesh = point_set(V);
  for (const std::string method : {"lhf-2", "lop-2", "jet-2"}) {
    const auto est = estimate_mesh(mesh, *make_estimator(method, {}));
    int ok = 0;
    for (int i = 0; i < V.rows(); ++i) {
      const VertexEstimate& o = est[static_cast<size_t>(i)];
      if (o.status != VertexStatus::ok) continue;
      ++ok;
      EXPECT_GT(o.normal.dot(mesh.position(i)), 0.0) << method << " point " << i;
      EXPECT_NEAR(o.H, -1.0 / a, 0.05) << method << " point " << i;
      EXPECT_GE(o.k1, o.k2);
    }
    EXPECT_EQ(ok, V.rows()) << method;
  }
}

TEST(PointSets, FaceMethodsRefuseAPointSetWithOneLine) {
  const Mesh mesh = point_set(sample_torus_points(500, 1.0, 0.4, 1));
  for (const std::string method : {"meyer", "lscm-2", "xu-2"}) {
    try {
      estimate_mesh(mesh, *make_estimator(method, {}));
      ADD_FAILURE() << method << " estimated a point set";
    } catch (const UsageError& e) {
      const std::string what = e.what();
      EXPECT_NE(what.find("a point set has no faces"), std::string::npos) << what;
      EXPECT_NE(what.find("lhf"), std::string::npos) << what;
      EXPECT_EQ(what.find('\n'), std::string::npos) << what;
    }
  }
}

TEST(PointSets, NeighbourhoodOptionRefusesFaceMethodsAndServesFitsOnAMesh) {
  const VertexMatrix V = sample_torus_points(50, 1.0, 0.4, 1);
  FaceMatrix F(1, 3);
  F << 0, 1, 2;
  const Mesh mesh(V, F);
  EstimatorOptions o;
  set_option(o, "neighbourhood", "knn=10");
  EXPECT_THROW(make_estimator("meyer", o), UsageError);
  EXPECT_THROW(make_estimator("lscm-2", o), UsageError);
  EXPECT_NO_THROW(estimate_mesh(mesh, *make_estimator("lhf-2", o)));
}

TEST(PointSets, NeighbourhoodOptionParsesAndPrints) {
  EstimatorOptions o;
  const OptionInfo& info = option_info("neighbourhood");
  EXPECT_EQ(option_text(o, info), "default");
  for (const std::string text : {"knn=20", "radius=0.25", "radius=2.5s", "default"}) {
    set_option(o, "neighbourhood", text);
    EXPECT_EQ(option_text(o, info), text);
  }
  for (const std::string bad : {"knn=0", "knn=2.5", "radius=-1", "radius=s", "ring=2", "knn="})
    EXPECT_THROW(set_option(o, "neighbourhood", bad), UsageError) << bad;
  EstimatorOptions both;
  both.rings = 2.0;
  set_option(both, "neighbourhood", "knn=20");
  EXPECT_THROW(make_estimator("lhf-2", both), UsageError);
}

// The three neighbourhood rules give the same estimate where they select the same points, and
// the thread count changes no bit.
TEST(PointSets, RulesAgreeAndThreadsChangeNothing) {
  const Mesh mesh = point_set(sample_torus_points(3000, 1.0, 0.4, 3));
  EstimatorOptions one, two;
  one.threads = 1;
  two.threads = 2;
  const auto a = estimate_mesh(mesh, *make_estimator("lhf-3", one));
  const auto b = estimate_mesh(mesh, *make_estimator("lhf-3", two));
  for (size_t i = 0; i < a.size(); ++i) {
    ASSERT_EQ(std::memcmp(&a[i].H, &b[i].H, sizeof(double)), 0) << i;
    ASSERT_EQ(a[i].status, b[i].status);
  }
  EstimatorOptions knn;
  set_option(knn, "neighbourhood", "knn=20");  // the default of degree 3
  const auto c = estimate_mesh(mesh, *make_estimator("lhf-3", knn));
  for (size_t i = 0; i < a.size(); ++i) ASSERT_EQ(std::memcmp(&a[i].H, &c[i].H, sizeof(double)), 0);
  // A ball of 6 mean spacings holds about pi 36 / 4 = 28 random points (the mean spacing of
  // uniform random points is about half the inverse root of the density): enough for degree 3.
  EstimatorOptions ball;
  set_option(ball, "neighbourhood", "radius=6s");
  const auto d = estimate_mesh(mesh, *make_estimator("lhf-3", ball));
  int ok = 0;
  for (const auto& e : d) ok += e.status == VertexStatus::ok;
  EXPECT_GT(ok, 2900);
}

TEST(PointSets, ACacheChangesNothingWhereNeighboursTie) {
  // The vertices of a structured torus as points: equal distances everywhere. Without a cache
  // the table's 12-NN rows are the first 12 of the normals' 16-NN rows; with one, a search of 12.
  const Mesh grid = generate_mesh({"torus-structured", 2, 0, 1, false}).mesh;
  const Mesh mesh = point_set(grid.vertices());
  const auto est = make_estimator("lhf-2", {});
  const auto a = estimate_mesh(mesh, *est);
  NeighbourhoodCache cache(mesh);
  const auto b = estimate_mesh(mesh, *est, &cache);
  ASSERT_EQ(a.size(), b.size());
  for (size_t i = 0; i < a.size(); ++i) {
    ASSERT_EQ(std::memcmp(&a[i].H, &b[i].H, sizeof(double)), 0) << i;
    ASSERT_EQ(a[i].points, b[i].points) << i;
  }
}

// ---- bad input -------------------------------------------------------------------------------

TEST(PointSetBadInput, DuplicatePointsGetTheSameFiniteEstimate) {
  VertexMatrix V = sample_torus_points(2000, 1.0, 0.4, 5);
  V.row(1) = V.row(0);
  V.row(2) = V.row(0);
  const Mesh mesh = point_set(V);
  const auto est = estimate_mesh(mesh, *make_estimator("lhf-2", {}));
  EXPECT_EQ(est[0].status, VertexStatus::ok);
  EXPECT_TRUE(std::isfinite(est[0].H));
  EXPECT_EQ(est[0].H, est[1].H);
  EXPECT_EQ(est[0].H, est[2].H);
  EXPECT_EQ(est[0].points, est[1].points);
}

TEST(PointSetBadInput, FewerPointsThanKLowersTheDegreeOrFails) {
  // Five points of a sphere, LHF-4 (K = 30, 15 coefficients): four neighbours hold a plane at
  // most, never degree 4.
  VertexMatrix V(5, 3);
  V << 0, 0, 1, 0.1, 0, 0.995, 0, 0.1, 0.995, -0.1, 0, 0.995, 0, -0.1, 0.995;
  const auto est = estimate_mesh(point_set(V), *make_estimator("lhf-4", {}));
  for (const auto& e : est) {
    EXPECT_NE(e.status, VertexStatus::ok);
    EXPECT_LT(e.degree, 4);
    EXPECT_LE(e.points, 5);
  }
}

TEST(PointSetBadInput, CollinearPointsAreUndeterminedOrFailed) {
  VertexMatrix V(40, 3);
  for (int i = 0; i < 40; ++i) V.row(i) << 0.1 * i, 0.2 * i, -0.05 * i;
  const auto est = estimate_mesh(point_set(V), *make_estimator("lhf-2", {}));
  for (const auto& e : est)
    EXPECT_TRUE(e.status == VertexStatus::failed || e.status == VertexStatus::sign_undetermined)
        << to_string(e.status);
}

TEST(PointSetBadInput, NonFiniteCoordinatesAreRefused) {
  VertexMatrix V = sample_torus_points(10, 1.0, 0.4, 5);
  V(3, 1) = std::nan("");
  EXPECT_THROW(point_set(V), InputError);
  V(3, 1) = INFINITY;
  EXPECT_THROW(point_set(V), InputError);
}

// The default k of a point set: 2 n(d) for the fits (12, 20, 30 for degrees 2-4; 3 n(d) when
// noisy), and at least the default ring's size on a regular mesh: 18 points for APSS and the
// surface variation (the 2-ring), which 2 n(1) = 6 would starve.
TEST(PointSets, DefaultKMatchesTheDefaultRing) {
  const Mesh mesh = point_set(sample_torus_points(50, 1.0, 0.4, 1));
  const auto k_of = [&](const char* method, bool noisy = false) {
    EstimatorOptions o;
    o.noisy = noisy;
    const NeighbourhoodSpec s = make_estimator(method, o)->neighbourhood_spec(mesh);
    EXPECT_EQ(s.points, NeighbourhoodSpec::Points::knn) << method;
    return static_cast<int>(s.size);
  };
  EXPECT_EQ(k_of("lhf-2"), 12);
  EXPECT_EQ(k_of("jet-3"), 20);
  EXPECT_EQ(k_of("lhf-4"), 30);
  EXPECT_EQ(k_of("lhf-2", true), 18);
  EXPECT_EQ(k_of("apss"), 18);
  EXPECT_EQ(k_of("surface-variation"), 18);
  EXPECT_EQ(regular_ring_size(1.0), 6);
  EXPECT_EQ(regular_ring_size(1.5), 12);
  EXPECT_EQ(regular_ring_size(2.5), 30);
  EXPECT_EQ(regular_ring_size(3.0), 36);
}

}  // namespace
}  // namespace curvbench
