// Structured "well-shaped" torus meshes (docs/algorithms.md §10.1(b), paper Table 5).
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "core/errors.h"
#include "meshgen/torus_structured.h"
#include "tests/meshgen/identical_matrices.h"
#include "tests/meshgen/inward_faces.h"
#include "tests/meshgen/torus_test_util.h"

namespace curvbench {
namespace {

using testing::kTorusR;
using testing::kTorusr;
using testing::torus_distance;
using testing::torus_outward;

TEST(TorusStructured, CountsTopologyAndOrientation) {
  const int paper_v[4] = {1338, 5246, 21156, 85208};  // paper Table 5 (GAMBIT meshes)
  for (int level = 1; level <= 4; ++level) {
    const GeneratedMesh gm = torus_structured(level);
    const Mesh& m = gm.mesh;
    const int nv = 22 << (level - 1), nu = 64 << (level - 1);
    EXPECT_EQ(torus_structured_rows(level), nv);
    EXPECT_EQ(torus_structured_columns(level), nu);
    EXPECT_EQ(m.num_vertices(), nu * nv);
    EXPECT_NEAR(m.num_vertices(), paper_v[level - 1], 0.10 * paper_v[level - 1]);
    EXPECT_EQ(m.num_faces(), 2 * m.num_vertices());
    EXPECT_FALSE(m.has_boundary());
    EXPECT_EQ(m.num_nonmanifold_edges(), 0);
    EXPECT_EQ(m.num_isolated_vertices(), 0);
    EXPECT_TRUE(m.is_consistently_oriented());
    EXPECT_EQ(m.euler_characteristic(), 0);
    // Outward: positive volume close to 2 pi^2 R r^2 (an inscribed polyhedron: slightly less).
    const double exact_volume =
        2.0 * std::numbers::pi * std::numbers::pi * kTorusR * kTorusr * kTorusr;
    EXPECT_GT(m.signed_volume(), 0.97 * exact_volume);
    EXPECT_LT(m.signed_volume(), exact_volume);
    EXPECT_EQ(testing::inward_faces(m, torus_outward), 0);
    // Valence 6 everywhere (each vertex in 6 faces on a closed mesh).
    for (int v = 0; v < m.num_vertices(); ++v) ASSERT_EQ(m.vertex_faces(v).size(), 6u);
    // On the torus, exact points are the vertices.
    double dmax = 0;
    for (int v = 0; v < m.num_vertices(); ++v) dmax = std::max(dmax, torus_distance(m.position(v)));
    EXPECT_LT(dmax, 1e-12);
    EXPECT_EQ(gm.exact_points, m.vertices());
    ASSERT_TRUE(gm.surface);
    EXPECT_EQ(gm.surface->name(), "torus");
    EXPECT_EQ(gm.family, "torus-structured");
    EXPECT_EQ(gm.level, level);
    EXPECT_FALSE(gm.description.empty());
  }
}

TEST(TorusStructured, MeanEdgeLengthHalves) {
  double h_prev = 0;
  for (int level = 1; level <= 4; ++level) {
    const double h = torus_structured(level).mesh.mean_edge_length();
    if (level == 1) {
      EXPECT_NEAR(h, 0.10, 0.01);  // docs/algorithms.md §10.1(b): ~0.10 at level 1
    } else {
      EXPECT_NEAR(h_prev / h, 2.0, 0.2);
    }
    h_prev = h;
  }
}

TEST(TorusStructured, JitterKeepsConnectivityAndSurface) {
  const int level = 2;
  const GeneratedMesh plain = torus_structured(level);
  const GeneratedMesh a = torus_structured(level, true, 7);
  const GeneratedMesh b = torus_structured(level, true, 7);
  const GeneratedMesh c = torus_structured(level, true, 8);
  const Mesh& m = a.mesh;
  EXPECT_TRUE(test::identical(m.faces(), plain.mesh.faces()));
  EXPECT_EQ(m.num_vertices(), plain.mesh.num_vertices());
  EXPECT_EQ(m.euler_characteristic(), 0);
  EXPECT_TRUE(m.is_consistently_oriented());
  EXPECT_EQ(testing::inward_faces(m, torus_outward), 0);
  EXPECT_EQ(a.exact_points, m.vertices());
  // Deterministic per seed; another seed gives other points.
  EXPECT_TRUE(test::identical(a.mesh.vertices(), b.mesh.vertices()));
  EXPECT_FALSE(test::identical(a.mesh.vertices(), c.mesh.vertices()));

  const int nu = torus_structured_columns(level), nv = torus_structured_rows(level);
  const double du = 2 * std::numbers::pi / nu, dv = 2 * std::numbers::pi / nv;
  int moved = 0;
  double max_u = 0, max_v = 0;
  for (int i = 0; i < m.num_vertices(); ++i) {
    const Vec3 p = m.position(i), q = plain.mesh.position(i);
    EXPECT_LT(torus_distance(p), 1e-12);
    if ((p - q).norm() > 1e-9) ++moved;
    // Angular displacement in u and v, in cells: at most 0.15.
    const auto angle = [](double x) { return std::remainder(x, 2 * std::numbers::pi); };
    const double u_p = std::atan2(p.y(), p.x()), u_q = std::atan2(q.y(), q.x());
    const double v_p = std::atan2(p.z(), std::hypot(p.x(), p.y()) - kTorusR);
    const double v_q = std::atan2(q.z(), std::hypot(q.x(), q.y()) - kTorusR);
    max_u = std::max(max_u, std::abs(angle(u_p - u_q)) / du);
    max_v = std::max(max_v, std::abs(angle(v_p - v_q)) / dv);
  }
  EXPECT_EQ(moved, m.num_vertices());
  EXPECT_LE(max_u, 0.15 + 1e-9);
  EXPECT_LE(max_v, 0.15 + 1e-9);
  EXPECT_GT(max_u, 0.14);  // the full jitter range is used (5632 draws)
  EXPECT_GT(max_v, 0.14);
}

TEST(TorusStructured, BadLevelThrows) {
  EXPECT_THROW(torus_structured(0), UsageError);
  EXPECT_THROW(torus_structured(7), UsageError);
}

}  // namespace
}  // namespace curvbench
