// APSS (methods/operators/apss.cpp): exact on spheres and planes sampled with exact normals, the
// sign convention, the normal constraint's weight, determinism, failures, and its convergence
// with the meshes' own (area-weighted) normals.
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "core/errors.h"
#include "meshgen/generate.h"
#include "methods/estimator.h"
#include "tests/methods/convergence_rates.h"
#include "tests/methods/method_test_util.h"

namespace curvbench {
namespace {

using testing::bitwise_equal;
using testing::grid_mesh;
using testing::icosphere;
using testing::rotation;

// The icosphere's vertices moved tangentially by up to `jitter` of their spacing and put back on
// the sphere: an irregular sample of it (the same connectivity).
Mesh jittered_sphere(int level, double r, double jitter, std::uint64_t seed) {
  const Mesh m = icosphere(level, r);
  const double h = m.mean_edge_length();
  Rng rng(seed);
  VertexMatrix V(m.num_vertices(), 3);
  for (int v = 0; v < m.num_vertices(); ++v) {
    const Vec3 p = m.position(v);
    const Vec3 d(rng.uniform(-1, 1), rng.uniform(-1, 1), rng.uniform(-1, 1));
    V.row(v) = (r * (p + jitter * h * d).normalized()).transpose();
  }
  return Mesh(V, m.faces());
}

// Radial (outward) unit normals of a sphere centred at the origin, times `side`.
VertexMatrix radial_normals(const Mesh& m, double side) {
  VertexMatrix n(m.num_vertices(), 3);
  for (int v = 0; v < m.num_vertices(); ++v)
    n.row(v) = side * m.position(v).normalized().transpose();
  return n;
}

std::vector<VertexEstimate> run_apss(const Mesh& m, const VertexMatrix& normals,
                                     const EstimatorOptions& o = {}) {
  const auto est = make_estimator("apss", o);
  auto ws = est->make_workspace(m);
  const auto data = est->prepare(m, normals, 1);
  std::vector<VertexEstimate> out(static_cast<size_t>(m.num_vertices()));
  const MeshContext ctx{m, normals, data.get()};
  for (int v = 0; v < m.num_vertices(); ++v)
    est->estimate(ctx, v, *ws, out[static_cast<size_t>(v)]);
  return out;
}

TEST(Apss, RegistryAndLabel) {
  const auto est = make_estimator("apss", {});
  EXPECT_EQ(est->label(), "APSS");
  EXPECT_FALSE(est->takes_degree());
  EXPECT_DOUBLE_EQ(est->default_ring(), 2.0);
  EXPECT_EQ(est->neighbourhood_use(), NeighbourhoodUse::neighbours);
  EXPECT_EQ(method_info("apss").radius, NeighbourhoodSize::half_rings);
  EXPECT_THROW(make_estimator("apss-2", {}), UsageError);
  EstimatorOptions o;
  o.rings = 1.25;
  EXPECT_THROW(make_estimator("apss", o), UsageError);
  o = {};
  o.apss_beta = 0.0;
  EXPECT_THROW(make_estimator("apss", o), UsageError);
  o.apss_beta = 2.0;
  EXPECT_THROW(make_estimator("lhf", o), UsageError);  // apss-beta is APSS's only
  EXPECT_NO_THROW(make_estimator("apss", o));
}

// On exact samples of a sphere with their exact normals every residual is zero: the fitted
// sphere is the sphere at every vertex, whatever the weights and beta (G&G 2007's reproduction
// of spheres), so H, k1, k2 = -1/r to rounding, the normal is radial.
TEST(Apss, ReproducesSpheresWithExactNormals) {
  const double r = 1.7;
  for (const double jitter : {0.0, 0.3}) {
    const Mesh m = jitter > 0 ? jittered_sphere(3, r, jitter, 7) : icosphere(3, r);
    for (const double beta : {1e-3, 1.0, 1e3}) {
      EstimatorOptions o;
      o.apss_beta = beta;
      const auto res = run_apss(m, radial_normals(m, 1.0), o);
      for (int v = 0; v < m.num_vertices(); ++v) {
        const VertexEstimate& e = res[static_cast<size_t>(v)];
        const std::string where = "jitter " + std::to_string(jitter) + " beta " +
                                  std::to_string(beta) + " v " + std::to_string(v);
        ASSERT_EQ(e.status, VertexStatus::ok) << where;
        EXPECT_NEAR(e.H, -1.0 / r, 1e-12) << where;
        EXPECT_NEAR(e.k1, -1.0 / r, 1e-10) << where;
        EXPECT_NEAR(e.k2, -1.0 / r, 1e-10) << where;
        EXPECT_NEAR(e.K, 1.0 / (r * r), 1e-10) << where;
        EXPECT_LT((e.normal - m.position(v).normalized()).norm(), 1e-12) << where;
      }
    }
  }
}

// The sign convention follows the normals: with inward normals the same sphere has k = +1/r.
TEST(Apss, InwardNormalsFlipTheSign) {
  const double r = 0.8;
  const Mesh m = icosphere(2, r);
  const auto res = run_apss(m, radial_normals(m, -1.0));
  for (int v = 0; v < m.num_vertices(); ++v) {
    const VertexEstimate& e = res[static_cast<size_t>(v)];
    EXPECT_NEAR(e.H, 1.0 / r, 1e-12);
    EXPECT_NEAR(e.k2, 1.0 / r, 1e-10);
    EXPECT_LT((e.normal + m.position(v).normalized()).norm(), 1e-12);
  }
}

// The sign with the mesh's own area-weighted normals (estimate_mesh): outward normals, k1, k2, H
// negative and near -1/r (icosphere level 4, h/r about 0.04; a sign test, the accuracy is
// measured below).
TEST(Apss, SphereSignWithMeshNormals) {
  const double r = 2.0;
  const Mesh m = icosphere(4, r);
  const auto res = estimate_mesh(m, *make_estimator("apss", {}));
  for (int v = 0; v < m.num_vertices(); ++v) {
    const VertexEstimate& e = res[static_cast<size_t>(v)];
    ASSERT_EQ(e.status, VertexStatus::ok);
    EXPECT_GT(e.normal.dot(m.position(v).normalized()), 0.999);
    EXPECT_NEAR(e.H * r, -1.0, 0.1);
    EXPECT_NEAR(e.k1 * r, -1.0, 0.1);
    EXPECT_NEAR(e.k2 * r, -1.0, 0.1);
  }
}

// A plane (rotated, jittered samples) with its exact normal: every curvature 0, the normal exact.
TEST(Apss, ReproducesPlanes) {
  const Mat3 R = rotation(0.4, 0.9, -1.3);
  const Vec3 offset(0.3, -2.0, 1.0);
  const Mesh m = grid_mesh(12, 0.1, true, 0.3, 5,
                           [&](double x, double y) { return Vec3(R * Vec3(x, y, 0) + offset); });
  VertexMatrix n(m.num_vertices(), 3);
  for (int v = 0; v < m.num_vertices(); ++v) n.row(v) = (R * Vec3::UnitZ()).transpose();
  const auto res = run_apss(m, n);
  for (int v = 0; v < m.num_vertices(); ++v) {
    const VertexEstimate& e = res[static_cast<size_t>(v)];
    ASSERT_EQ(e.status, VertexStatus::ok) << v;
    EXPECT_NEAR(e.H, 0.0, 1e-12) << v;
    EXPECT_NEAR(e.k1, 0.0, 1e-10) << v;
    EXPECT_NEAR(e.k2, 0.0, 1e-10) << v;
    EXPECT_LT((e.normal - R * Vec3::UnitZ()).norm(), 1e-12) << v;
  }
}

// The shape operator comes from the field's Hessian, not from the sphere (whose k1 = k2 = H):
// on a cylinder of radius 1 (exact normals, a regular grid, step 0.05) the principal curvatures
// separate, k1 = 0 along the axis and k2 = -1 around it, to 1e-3 (measured 1.2e-4: the ring is
// not a ball, so the field misses a few points inside the kernel's support). The weights'
// derivatives matter: with a support 1.5 times the farthest point instead, this vertex gave
// k1 = -0.047, k2 = -0.953 (points the support reaches but the ring lacks).
TEST(Apss, CylinderSeparatesThePrincipalCurvatures) {
  const double r = 1.0;
  const Mesh m = grid_mesh(40, 0.05, false, 0.0, 1, [&](double x, double y) {
    return Vec3(r * std::cos(x / r), r * std::sin(x / r), y);
  });
  VertexMatrix n(m.num_vertices(), 3);
  for (int v = 0; v < m.num_vertices(); ++v) {
    const Vec3 p = m.position(v);
    n.row(v) = Vec3(p.x(), p.y(), 0).normalized().transpose();
  }
  const auto res = run_apss(m, n);
  const int v = 20 * 41 + 20;
  const VertexEstimate& e = res[static_cast<size_t>(v)];
  ASSERT_EQ(e.status, VertexStatus::ok);
  EXPECT_NEAR(e.k1, 0.0, 1e-3);
  EXPECT_NEAR(e.k2, -1.0 / r, 1e-3);
  EXPECT_NEAR(e.H, -0.5 / r, 1e-3);
  EXPECT_GT(std::abs(e.d1.z()), 0.999);  // d1 along the axis
  EXPECT_LT(e.H, 0.0);
}

TEST(Apss, ThreadCountDoesNotChangeTheBits) {
  const Mesh m = jittered_sphere(3, 1.0, 0.3, 3);
  EstimatorOptions one, two;
  one.threads = 1;
  two.threads = 2;
  const auto a = estimate_mesh(m, *make_estimator("apss", one));
  const auto b = estimate_mesh(m, *make_estimator("apss", two));
  for (size_t i = 0; i < a.size(); ++i) EXPECT_TRUE(bitwise_equal(a[i], b[i])) << i;
}

// A vertex without faces has no neighbours (and no normal): failed, every value NaN.
TEST(Apss, IsolatedVertexFails) {
  VertexMatrix V(4, 3);
  V << 0, 0, 0, 1, 0, 0, 0, 1, 0, 5, 5, 5;
  FaceMatrix F(1, 3);
  F << 0, 1, 2;
  const Mesh m(V, F);
  const auto res = estimate_mesh(m, *make_estimator("apss", {}));
  EXPECT_EQ(res[3].status, VertexStatus::failed);
  EXPECT_TRUE(std::isnan(res[3].H));
}

// Convergence with the meshes' own area-weighted normals, levels 1-4 (rates from the first and
// last level). What a sphere fit can give: it is exact on spheres, but one algebraic sphere has
// one curvature, so where k1 != k2 the fitted u4 is an average of k1 and k2 weighted by the
// neighbourhood's second moments in the two principal directions, and its gradient at the vertex
// absorbs the part of the anisotropic residual that is odd about the vertex. On the paper's
// irregular meshes those moments do not become isotropic under refinement (each level has the
// same kinds of stencils), so the normal is first order and H from the sphere has an O(1)
// relative error that does not shrink. Measured (levels 1 -> 4, the same with the exact normals
// as input): torus-unstructured normal L2 2.0e-2 -> 1.8e-3 (rate 1.16), H L2 8.6e-2 -> 6.7e-2
// (rate 0.12); bump-irregular normal 5.1e-2 -> 2.2e-3 (1.51), H 0.19 -> 0.13 (0.19).
TEST(ApssConvergence, NormalsFirstOrderHStallsOnIrregularMeshes) {
  const testing::ConvergenceRates torus =
      testing::convergence_rates("torus-unstructured", "apss", {1, 2, 3, 4});
  EXPECT_GE(torus.normal, 1.0);
  EXPECT_LT(torus.H, 0.3);
  const testing::ConvergenceRates bump =
      testing::convergence_rates("bump-irregular", "apss", {1, 2, 3, 4});
  EXPECT_GE(bump.normal, 1.0);
  EXPECT_LT(bump.H, 0.3);
}

}  // namespace
}  // namespace curvbench
