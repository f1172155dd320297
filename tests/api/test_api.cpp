// The public C++ API (include/curvbench/curvbench.h): exactness on a quadric, the sign
// convention, result shapes, error types and messages.
#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <string>

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
  try {
    estimate(V, bad);
    FAIL() << "no exception";
  } catch (const InputError& e) {
    EXPECT_EQ(std::string(e.what()), "mesh: face 3 references vertex 99, out of range [0, 25)");
  }
  Eigen::MatrixXd nan = V;
  nan(2, 1) = std::nan("");
  EXPECT_THROW(estimate(nan, F), InputError);
  Eigen::MatrixXd two_columns = V.leftCols(2);
  EXPECT_THROW(estimate(two_columns, F), InputError);
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

}  // namespace
}  // namespace curvbench
