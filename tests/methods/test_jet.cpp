// Jet-d (methods/fits/jet.cpp): CGAL's Monge_via_jet_fitting in the project's conventions.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <vector>

#include "core/errors.h"
#include "mesh/rings.h"
#include "meshgen/bump_grid.h"
#include "meshgen/torus_structured.h"
#include "method_test_util.h"
#include "methods/estimator.h"

namespace curvbench {
namespace {

using testing::direction_error;
using testing::grid_mesh;
using testing::icosphere;
using testing::monge_exact;
using testing::rotation;

EstimatorOptions with_degree(int d) {
  EstimatorOptions o;
  o.degree = d;
  return o;
}

// Sign convention (docs/algorithms.md §0): a sphere of radius 2 with outward faces has
// k1 = k2 = H = -0.5, K = 0.25 and outward normals; the error shrinks under refinement.
TEST(Jet, SphereOfRadiusTwo) {
  for (int d : {2, 3, 4}) {
    const auto est = make_estimator("jet", with_degree(d));
    double prev = 0.0;
    for (int level = 2; level <= 4; ++level) {
      const Mesh mesh = icosphere(level, 2.0);
      const auto r = estimate_mesh(mesh, *est);
      double ek = 0.0, eK = 0.0, en = 0.0;
      for (int v = 0; v < mesh.num_vertices(); ++v) {
        const VertexEstimate& q = r[static_cast<size_t>(v)];
        ASSERT_EQ(q.status, VertexStatus::ok);
        EXPECT_EQ(q.degree, d);
        EXPECT_GE(q.points, num_coefficients(d));
        ek = std::max({ek, std::abs(q.k1 + 0.5), std::abs(q.k2 + 0.5), std::abs(q.H + 0.5)});
        eK = std::max(eK, std::abs(q.K - 0.25));
        en = std::max(en, (q.normal - mesh.position(v).normalized()).norm());
        EXPECT_GE(q.k1, q.k2);
      }
      std::printf("jet-%d sphere level %d: max |k+0.5| %.3e, |K-0.25| %.3e, |n-n*| %.3e\n", d,
                  level, ek, eK, en);
      EXPECT_LT(ek, 0.1);  // the wrong sign would give 1
      EXPECT_LT(en, 0.01);
      if (level > 2) {
        EXPECT_LT(ek, 0.75 * prev);
      }
      if (level == 4) {
        EXPECT_LT(ek, 0.01);
      }
      prev = ek;
    }
  }
}

// Reversed faces: the area-weighted normals point inward, and so must the jet normal, with
// k = +1/a (CGAL's Monge normal is made to agree with the given normal).
TEST(Jet, InwardOrientationFlipsNormalAndCurvatures) {
  const Mesh outward = icosphere(3, 2.0);
  FaceMatrix F = outward.faces();
  F.col(1).swap(F.col(2));
  const Mesh inward(outward.vertices(), F);
  const auto est = make_estimator("jet-2", EstimatorOptions{});
  const auto a = estimate_mesh(outward, *est);
  const auto b = estimate_mesh(inward, *est);
  for (size_t v = 0; v < a.size(); ++v) {
    EXPECT_NEAR((a[v].normal + b[v].normal).norm(), 0.0, 1e-12);
    EXPECT_NEAR(a[v].k1, -b[v].k2, 1e-12);
    EXPECT_NEAR(a[v].k2, -b[v].k1, 1e-12);
    EXPECT_NEAR(b[v].H, 0.5, 0.02);
  }
}

// On a centrally symmetric grid of z = (a x^2 + 2b xy + c y^2)/2 (rotated and translated), the
// PCA axis at the centre is the height axis and the height is a quadratic in the fitting frame,
// so every degree d >= 2 is exact there: values and directions.
TEST(Jet, ExactAtTheCentreOfAQuadraticHeightField) {
  const Mat3 R = rotation(0.4, 0.9, -1.3);
  const Vec3 o(1.0, -2.0, 0.5);
  const Mat2 Hs = (Mat2() << 1.3, 0.4, 0.4, -0.7).finished();
  const Mesh mesh = grid_mesh(12, 0.1, false, 0.0, 1, [&](double x, double y) {
    const Vec2 p(x - 0.6, y - 0.6);
    return Vec3(o + R * Vec3(p.x(), p.y(), 0.5 * p.dot(Hs * p)));
  });
  const int centre = 6 * 13 + 6;
  const auto exact = monge_exact(R, Vec2::Zero(), Hs);
  const VertexMatrix normals = mesh.area_weighted_normals();
  const MeshContext ctx{mesh, normals};
  for (int d : {2, 3, 4}) {
    const auto est = make_estimator("jet", with_degree(d));
    const auto ws = est->make_workspace(mesh);
    VertexEstimate q;
    est->estimate(ctx, centre, *ws, q);
    ASSERT_EQ(q.status, VertexStatus::ok);
    EXPECT_NEAR((q.normal - exact.normal).norm(), 0.0, 1e-10) << d;
    EXPECT_NEAR(q.k1, exact.k1, 1e-9) << d;
    EXPECT_NEAR(q.k2, exact.k2, 1e-9) << d;
    EXPECT_NEAR(q.H, exact.H, 1e-9) << d;
    EXPECT_NEAR(q.K, exact.K, 1e-9) << d;
    EXPECT_LT(direction_error(q.d1, exact.d1), 1e-8) << d;
    EXPECT_LT(direction_error(q.d2, exact.d2), 1e-8) << d;
    EXPECT_NEAR(q.d1.norm(), 1.0, 1e-12);
    EXPECT_NEAR(q.d2.norm(), 1.0, 1e-12);
    EXPECT_NEAR(q.d1.dot(q.normal), 0.0, 1e-12);
    EXPECT_NEAR(q.d2.dot(q.normal), 0.0, 1e-12);
    EXPECT_NEAR((q.d1.cross(q.d2) - q.normal).norm(), 0.0, 1e-12);  // right-handed
    EXPECT_EQ(q.points, 1 + (d == 2 ? 12 : d == 3 ? 18 : 30));      // rings 1.5, 2, 2.5
    EXPECT_EQ(q.ring, 0.5 * (d + 1));
  }
}

// Torus (R = 1, r = 0.3), jittered well-shaped meshes: the mean-curvature error shrinks under
// refinement for every degree, and directions stay unit, tangent and right-handed.
TEST(Jet, TorusConverges) {
  const GeneratedMesh coarse = torus_structured(1, true, 7);
  const GeneratedMesh fine = torus_structured(2, true, 7);
  for (int d : {2, 3, 4}) {
    const auto est = make_estimator("jet", with_degree(d));
    double err[2] = {0.0, 0.0};
    int i = 0;
    for (const GeneratedMesh* g : {&coarse, &fine}) {
      const auto r = estimate_mesh(g->mesh, *est);
      for (int v = 0; v < g->mesh.num_vertices(); ++v) {
        const VertexEstimate& q = r[static_cast<size_t>(v)];
        ASSERT_EQ(q.status, VertexStatus::ok);
        const SurfacePoint x = g->surface->evaluate(g->exact_points.row(v).transpose());
        err[i] = std::max(err[i], std::abs(q.H - x.H));
        EXPECT_GT(q.normal.dot(x.normal), 0.99);
        EXPECT_NEAR(q.d1.dot(q.normal), 0.0, 1e-12);
        EXPECT_NEAR((q.d1.cross(q.d2) - q.normal).norm(), 0.0, 1e-12);
      }
      ++i;
    }
    std::printf("jet-%d torus max |H error|: level 1 %.3e, level 2 %.3e\n", d, err[0], err[1]);
    EXPECT_LT(err[1], 0.75 * err[0]);
  }
}

TEST(Jet, NoNanOnAMeshWithBoundaryAndThreadIndependent) {
  const GeneratedMesh bump = bump_48(1);
  for (int d : {2, 3, 4}) {
    EstimatorOptions o1 = with_degree(d), o2 = with_degree(d);
    o1.threads = 1;
    o2.threads = 2;
    const auto r1 = estimate_mesh(bump.mesh, *make_estimator("jet", o1));
    const auto r2 = estimate_mesh(bump.mesh, *make_estimator("jet", o2));
    for (size_t i = 0; i < r1.size(); ++i) {
      const VertexEstimate& q = r1[i];
      EXPECT_EQ(q.status, VertexStatus::ok) << i;
      EXPECT_TRUE(q.normal.allFinite() && std::isfinite(q.k1) && std::isfinite(q.k2) &&
                  q.d1.allFinite() && q.d2.allFinite());
      EXPECT_GT(q.normal.z(), 0.0);  // upward
      EXPECT_EQ(q.k1, r2[i].k1);
      EXPECT_EQ(q.normal, r2[i].normal);
    }
  }
}

// Too few points for CGAL ((d+1)(d+2)/2 = 6 for d = 2) in the whole component: the plane through
// them (degree 1, degree_reduced: the normal, k1 = k2 = 0, as the ring fits' safeguard). Every
// vertex of this two-triangle patch lies within 0.2 of the plane z = 0.05 x + 0.05 y... so the
// normal points up, within 15 degrees of z.
TEST(Jet, TooFewPointsGiveThePlane) {
  VertexMatrix V(4, 3);
  V << 0, 0, 0, 1, 0, 0, 1, 1, 0.2, 0, 1, 0;
  FaceMatrix F(2, 3);
  F << 0, 1, 2, 0, 2, 3;
  const Mesh mesh(V, F);
  const auto r = estimate_mesh(mesh, *make_estimator("jet-2", EstimatorOptions{}));
  for (int v = 0; v < 4; ++v) {
    const VertexEstimate& q = r[static_cast<size_t>(v)];
    EXPECT_EQ(q.status, VertexStatus::degree_reduced);
    EXPECT_EQ(q.degree, 1);
    EXPECT_EQ(q.k1, 0.0);
    EXPECT_EQ(q.K, 0.0);
    EXPECT_GT(q.normal.z(), std::cos(15.0 * M_PI / 180.0)) << v;
    EXPECT_NEAR(q.d1.dot(q.normal), 0.0, 1e-12);
  }
}

TEST(Jet, Registry) {
  EstimatorOptions o;
  EXPECT_EQ(make_estimator("JET-3", o)->label(), "Jet-3");
  EXPECT_EQ(make_estimator("jet", o)->default_ring(), 1.5);
  EXPECT_THROW(make_estimator("jet-1", o), UsageError);
  EXPECT_THROW(make_estimator("jet-5", o), UsageError);
  o.rings = 1.25;
  EXPECT_THROW(make_estimator("jet-2", o), UsageError);
  o.rings = 2.0;
  EXPECT_EQ(make_estimator("jet-2", o)->options().rings, 2.0);
}

}  // namespace
}  // namespace curvbench
