// Surface variation (methods/operators/surface_variation.cpp): 0 on a plane, positive and
// unsigned on a sphere, shrinking like (h/r)^2 under refinement (it is not a curvature), the
// PCA normal turned to the input normal's side.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "methods/estimator.h"
#include "tests/methods/method_test_util.h"

namespace curvbench {
namespace {

using testing::bitwise_equal;
using testing::grid_mesh;
using testing::icosphere;
using testing::rotation;

TEST(SurfaceVariation, RegistryAndComputes) {
  const auto est = make_estimator("surface-variation", {});
  EXPECT_EQ(est->label(), "SurfVar");
  const ComputedQuantities c = est->computes();
  EXPECT_TRUE(c.normal);
  EXPECT_TRUE(c.mean);
  EXPECT_FALSE(c.principal);
  EXPECT_FALSE(c.gaussian);
  EXPECT_FALSE(c.directions);
  EXPECT_EQ(method_info("surface-variation").radius, NeighbourhoodSize::half_rings);
}

TEST(SurfaceVariation, ZeroOnAPlaneWithItsNormal) {
  const Mat3 R = rotation(1.1, 0.7, 0.2);
  const Mesh m =
      grid_mesh(10, 0.1, true, 0.3, 9, [&](double x, double y) { return Vec3(R * Vec3(x, y, 0)); });
  const auto res = estimate_mesh(m, *make_estimator("surface-variation", {}));
  for (int v = 0; v < m.num_vertices(); ++v) {
    const VertexEstimate& e = res[static_cast<size_t>(v)];
    ASSERT_EQ(e.status, VertexStatus::ok) << v;
    EXPECT_LT(std::abs(e.H), 1e-15) << v;
    EXPECT_LT((e.normal - R * Vec3::UnitZ()).norm(), 1e-12) << v;
    EXPECT_TRUE(std::isnan(e.k1) && std::isnan(e.K) && std::isnan(e.d1.x())) << v;
  }
}

// On a sphere it is positive at every vertex, the same with the orientation reversed (unsigned;
// only the normal turns), and its mean over the vertices falls like h^2 (the ring's extent
// squared over r^2): the rate from icosphere level 2 to 5 is 2 (measured 2.00).
TEST(SurfaceVariation, SphereIsPositiveUnsignedAndFallsLikeHSquared) {
  const double r = 1.5;
  double mean[2] = {}, h[2] = {};
  for (int level : {2, 5}) {
    const Mesh m = icosphere(level, r);
    FaceMatrix flipped = m.faces();
    flipped.col(1).swap(flipped.col(2));
    const Mesh inward(m.vertices(), flipped);
    const auto out = estimate_mesh(m, *make_estimator("surface-variation", {}));
    const auto in = estimate_mesh(inward, *make_estimator("surface-variation", {}));
    double sum = 0;
    for (int v = 0; v < m.num_vertices(); ++v) {
      const VertexEstimate& e = out[static_cast<size_t>(v)];
      ASSERT_EQ(e.status, VertexStatus::ok);
      EXPECT_GT(e.H, 0.0);
      EXPECT_GT(e.normal.dot(m.position(v).normalized()), 0.99);
      // (the reversed faces list the ring in another order: equal up to rounding)
      EXPECT_NEAR(in[static_cast<size_t>(v)].H, e.H, 1e-12 * e.H);
      EXPECT_LT((in[static_cast<size_t>(v)].normal + e.normal).norm(), 1e-12);
      sum += e.H;
    }
    const int i = level == 2 ? 0 : 1;
    mean[i] = sum / m.num_vertices();
    h[i] = m.mean_edge_length() / r;
    std::printf("icosphere level %d: h/r %.4g  mean surface variation %.4e  / (h/r)^2 = %.4f\n",
                level, h[i], mean[i], mean[i] / (h[i] * h[i]));
  }
  const double rate = std::log(mean[0] / mean[1]) / std::log(h[0] / h[1]);
  EXPECT_NEAR(rate, 2.0, 0.05);
}

// Without an input normal (zero, as a vertex without faces has) the PCA normal's sign is
// arbitrary: status sign_undetermined, the value still there.
TEST(SurfaceVariation, NoInputNormalIsSignUndetermined) {
  const Mesh m = icosphere(2, 1.0);
  const VertexMatrix zero = VertexMatrix::Zero(m.num_vertices(), 3);
  const auto est = make_estimator("surface-variation", {});
  const auto data = est->prepare(m, zero, 1);
  auto ws = est->make_workspace(m);
  VertexEstimate e;
  est->estimate(MeshContext{m, zero, data.get()}, 0, *ws, e);
  EXPECT_EQ(e.status, VertexStatus::sign_undetermined);
  EXPECT_GT(e.H, 0.0);
}

TEST(SurfaceVariation, ThreadCountDoesNotChangeTheBits) {
  const Mesh m = icosphere(3, 1.0);
  EstimatorOptions one, two;
  one.threads = 1;
  two.threads = 2;
  const auto a = estimate_mesh(m, *make_estimator("surface-variation", one));
  const auto b = estimate_mesh(m, *make_estimator("surface-variation", two));
  for (size_t i = 0; i < a.size(); ++i) EXPECT_TRUE(bitwise_equal(a[i], b[i])) << i;
}

}  // namespace
}  // namespace curvbench
