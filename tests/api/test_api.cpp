// The public C++ API (include/curvbench/curvbench.h): exactness on a quadric, the sign
// convention, result shapes, error types and messages; the status enum, test meshes, scoring,
// options by name and the advice's error path.
#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <string>
#include <vector>

#include "curvbench/curvbench.h"

namespace curvbench {
namespace {

// z = (a x^2 + b y^2) / 2 on a (2k+1) x (2k+1) grid over [-1, 1]^2, triangulated
// counter-clockwise seen from +z; the centre vertex is index k (2k + 1) + k.
void quadric_grid(double a, double b, int k, Eigen::MatrixXd& V, Eigen::MatrixXi& F) {
  const int s = 2 * k + 1;
  V.resize(s * s, 3);
  for (int i = 0; i < s; ++i)
    for (int j = 0; j < s; ++j) {
      const double x = -1.0 + 2.0 * j / (s - 1), y = -1.0 + 2.0 * i / (s - 1);
      V.row(i * s + j) << x, y, 0.5 * (a * x * x + b * y * y);
    }
  F.resize(2 * (s - 1) * (s - 1), 3);
  int f = 0;
  for (int i = 0; i + 1 < s; ++i)
    for (int j = 0; j + 1 < s; ++j) {
      const int v = i * s + j;
      F.row(f++) << v, v + 1, v + s + 1;
      F.row(f++) << v, v + s + 1, v + s;
    }
}

TEST(Api, QuadricIsExactAtTheCentreWithUpwardNormals) {
  Eigen::MatrixXd V;
  Eigen::MatrixXi F;
  quadric_grid(0.8, -0.3, 5, V, F);
  EstimateOptions o;
  o.method = "lhf";
  o.degree = 2;
  const EstimateResult r = estimate(V, F, o);
  const int c = 5 * 11 + 5;
  ASSERT_EQ(r.k1.size(), V.rows());
  ASSERT_EQ(r.normal.rows(), V.rows());
  ASSERT_EQ(r.status.size(), static_cast<size_t>(V.rows()));
  EXPECT_EQ(r.method, "LHF-2");
  // B = n . x_uu with the upward normal: k1 = 0.8, k2 = -0.3 at the apex (paper §2).
  EXPECT_NEAR(r.k1(c), 0.8, 1e-10);
  EXPECT_NEAR(r.k2(c), -0.3, 1e-10);
  EXPECT_NEAR(r.H(c), 0.25, 1e-10);
  EXPECT_NEAR(r.K(c), -0.24, 1e-10);
  EXPECT_NEAR(r.normal(c, 2), 1.0, 1e-12);
  EXPECT_NEAR(std::abs(r.d1(c, 0)), 1.0, 1e-10);
  EXPECT_EQ(r.status[c], Status::ok);
  EXPECT_STREQ(status_name(Status::degree_reduced), "degree_reduced");
}

// A point set (no faces): the same grid's points, the default k-NN neighbourhood. At the apex
// the neighbourhood is symmetric, so the PCA normal is the z axis, turned upward on an open set,
// and the quadratic fit is exact; estimate(V, options) is estimate(V, empty F, options); a method
// that needs faces is a UsageError naming it.
TEST(Api, PointSetEstimateIsExactAtTheApexOfAQuadric) {
  Eigen::MatrixXd V;
  Eigen::MatrixXi F;
  quadric_grid(0.8, -0.3, 5, V, F);
  EstimateOptions o;
  o.method = "lhf-2";
  const EstimateResult r = estimate(V, o);
  const int c = 5 * 11 + 5;
  ASSERT_EQ(r.H.size(), V.rows());
  EXPECT_EQ(r.method, "LHF-2");
  EXPECT_NEAR(r.normal(c, 2), 1.0, 1e-12);
  EXPECT_NEAR(r.k1(c), 0.8, 1e-10);
  EXPECT_NEAR(r.k2(c), -0.3, 1e-10);
  EXPECT_NEAR(r.H(c), 0.25, 1e-10);
  EXPECT_EQ(r.status[c], Status::ok);
  // Every normal of the open grid points up (the orientation rule of docs/point_sets.md).
  EXPECT_GT(r.normal.col(2).minCoeff(), 0.0);
  const EstimateResult same = estimate(V, Eigen::MatrixXi(0, 3), o);
  EXPECT_TRUE(same.H.cwiseEqual(r.H).all());
  EXPECT_TRUE(same.normal.cwiseEqual(r.normal).all());
  o.method = "meyer";
  try {
    estimate(V, o);
    ADD_FAILURE() << "meyer on a point set";
  } catch (const UsageError& e) {
    const std::string what = e.what();
    EXPECT_NE(what.find("Meyer"), std::string::npos) << what;
    EXPECT_NE(what.find("a point set has no faces"), std::string::npos) << what;
  }
}

TEST(Api, ThreadCountDoesNotChangeTheBits) {
  Eigen::MatrixXd V;
  Eigen::MatrixXi F;
  quadric_grid(0.5, 0.2, 8, V, F);
  EstimateOptions o;
  o.method = "LHF-3";
  o.threads = 1;
  const EstimateResult one = estimate(V, F, o);
  o.threads = 2;
  const EstimateResult two = estimate(V, F, o);
  EXPECT_EQ(one.method, "LHF-3");
  for (Eigen::Index i = 0; i < V.rows(); ++i) {
    EXPECT_EQ(std::memcmp(&one.k1(i), &two.k1(i), sizeof(double)), 0);
    EXPECT_EQ(std::memcmp(&one.H(i), &two.H(i), sizeof(double)), 0);
  }
}

TEST(Api, ErrorsAreTypedWithOneLineMessages) {
  Eigen::MatrixXd V;
  Eigen::MatrixXi F;
  quadric_grid(0.5, 0.2, 2, V, F);
  Eigen::MatrixXi bad = F;
  bad(3, 1) = 99;
  // Named, not the default argument's temporary: GCC 12 warns (maybe-uninitialized) inside the
  // temporary's std::string member at -O3.
  const EstimateOptions defaults;
  try {
    estimate(V, bad, defaults);
    FAIL() << "no exception";
  } catch (const InputError& e) {
    EXPECT_EQ(std::string(e.what()), "mesh: face 3 references vertex 99, out of range [0, 25)");
  }
  Eigen::MatrixXd nan = V;
  nan(2, 1) = std::nan("");
  EXPECT_THROW(estimate(nan, F, defaults), InputError);
  Eigen::MatrixXd two_columns = V.leftCols(2);
  EXPECT_THROW(estimate(two_columns, F, defaults), InputError);
  EstimateOptions o;
  o.method = "nosuch";
  EXPECT_THROW(estimate(V, F, o), UsageError);
  o.method = "lhf-4";
  o.degree = 2;
  try {
    estimate(V, F, o);
    FAIL() << "no exception";
  } catch (const UsageError& e) {
    EXPECT_EQ(std::string(e.what()), "method lhf-4 names degree 4 but degree is 2");
  }
  Eigen::MatrixXd V2;
  Eigen::MatrixXi F2;
  EXPECT_THROW(read_mesh("/nonexistent/mesh.off", V2, F2), InputError);
}

TEST(Api, ReadMeshMethodsAndVersion) {
  Eigen::MatrixXd V;
  Eigen::MatrixXi F;
  read_mesh(std::string(CURVBENCH_SOURCE_DIR) + "/tests/corpus/off/tetra.off", V, F);
  EXPECT_EQ(V.rows(), 4);
  EXPECT_EQ(F.rows(), 4);
  bool has_lhf = false;
  for (const auto& m : methods()) has_lhf |= m == "lhf";
  EXPECT_TRUE(has_lhf);
  EXPECT_EQ(version().find("0."), 0u);
}

// One status enum: the numbers written to PLY files, each with its own name.
TEST(Api, StatusCodesAndNames) {
  static_assert(static_cast<int>(Status::ok) == 0 && static_cast<int>(Status::failed) == 2 &&
                static_cast<int>(Status::sign_undetermined) == 5 &&
                static_cast<int>(Status::reprojected) == 7 &&
                static_cast<int>(Status::normal_fallback) == kStatusCount - 1);
  std::vector<std::string> names;
  for (int i = 0; i < kStatusCount; ++i) names.push_back(status_name(static_cast<Status>(i)));
  EXPECT_EQ(names.front(), "ok");
  EXPECT_EQ(names.back(), "normal_fallback");
  for (size_t i = 0; i < names.size(); ++i)
    for (size_t j = i + 1; j < names.size(); ++j) EXPECT_NE(names[i], names[j]);
}

// The exact quantities scored as an estimate have no error, on every vertex.
TEST(Api, ScoreOfTheExactAnswerIsZero) {
  TestMeshOptions m;
  m.family = "bump-48";
  m.level = 2;
  const TestMesh t = generate_mesh(m);
  ASSERT_EQ(t.exact.H.size(), t.V.rows());
  EstimateResult exact;
  exact.normal = t.exact.normal;
  exact.k1 = t.exact.k1;
  exact.k2 = t.exact.k2;
  exact.H = t.exact.H;
  exact.K = t.exact.K;
  exact.d1 = t.exact.d1;
  exact.d2 = t.exact.d2;
  exact.degree = Eigen::VectorXi::Zero(t.V.rows());
  exact.points = Eigen::VectorXi::Zero(t.V.rows());
  exact.ring = Eigen::VectorXd::Zero(t.V.rows());
  exact.status.assign(static_cast<size_t>(t.V.rows()), Status::ok);
  const std::vector<QuantityError> s = score(t.V, t.F, t.exact, exact);
  ASSERT_EQ(s.size(), 6u);
  EXPECT_EQ(s[0].quantity, "normal");
  EXPECT_EQ(s[5].quantity, "d1");
  for (const QuantityError& q : s) {
    EXPECT_EQ(q.L2, 0.0) << q.quantity;
    EXPECT_EQ(q.Linf, 0.0) << q.quantity;
    EXPECT_EQ(q.excluded, 0) << q.quantity;
  }
  EXPECT_EQ(s[1].counted, t.V.rows());  // H over every vertex
  EXPECT_THROW(score(t.V, t.F, t.exact, exact, "inner"), UsageError);
  m.level = 1;
  const TestMesh coarse = generate_mesh(m);
  EXPECT_THROW(score(coarse.V, coarse.F, t.exact, exact), InputError);
}

// generate_mesh, estimate and score together: LHF-2's normals converge at about second order on
// the structured torus (paper §5.1: order d for the normals of a degree-d fit).
TEST(Api, TestMeshEstimateAndScoreShowTheNormalsConvergence) {
  double error[2] = {0, 0};
  for (int level : {2, 3}) {
    TestMeshOptions m;
    m.family = "torus-structured";
    m.level = level;
    const TestMesh t = generate_mesh(m);
    EstimateOptions o;
    o.method = "lhf-2";
    o.threads = 1;
    error[level - 2] = score(t.V, t.F, t.exact, estimate(t.V, t.F, o)).front().L2;
  }
  EXPECT_GT(error[0] / error[1], 3.0);  // h halves: 4x at order 2
  TestMeshOptions bad;
  bad.family = "torus-structured";
  bad.shape = {{"aspect", 16.0}};  // not taken by this family
  EXPECT_THROW(generate_mesh(bad), UsageError);
  bool aspect = false;
  for (const MeshOptionDescription& d : mesh_options()) aspect |= d.name == "aspect";
  EXPECT_TRUE(aspect);
}

TEST(Api, OptionsByName) {
  EstimatorOptions o;
  set_estimator_option(o, "ball_factor", 2.5);
  set_estimator_option(o, "rings", 3.0);
  set_estimator_option(o, "noisy", true);
  EXPECT_EQ(o.ball_factor, 2.5);
  EXPECT_EQ(o.rings, 3.0);
  EXPECT_TRUE(o.noisy);
  EXPECT_THROW(set_estimator_option(o, "rings", std::string("two")), UsageError);
  EXPECT_THROW(set_estimator_option(o, "nosuch", 1.0), UsageError);
  const std::vector<OptionDescription> table = estimator_options();
  ASSERT_FALSE(table.empty());
  EXPECT_EQ(table.front().name, "degree");
  EXPECT_EQ(table.front().type, "int");
}

TEST(Api, RecommendNamesAMissingTable) {
  Eigen::MatrixXd V;
  Eigen::MatrixXi F;
  quadric_grid(0.5, 0.2, 5, V, F);
  RecommendOptions o;
  o.results = "/nonexistent";
  try {
    recommend(V, F, o);
    FAIL() << "no exception";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("recommendations.csv: not found"), std::string::npos)
        << e.what();
  }
}

}  // namespace
}  // namespace curvbench
