// The `ellipsoid` family (meshgen/ellipsoid_mesh.h): vertices on the ellipsoid, a closed outward
// well-shaped mesh, exact quantities against finite differences of the parameterization, the
// sign convention, determinism and level sizes. Levels 1 and 2 here (3 and 4 take seconds).
#include "meshgen/ellipsoid_mesh.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <string>

#include "core/errors.h"
#include "meshgen/generate.h"
#include "surfaces/ellipsoid.h"
#include "tests/meshgen/identical_matrices.h"
#include "tests/meshgen/inward_faces.h"
#include "tests/surfaces/surface_test_util.h"

namespace curvbench {
namespace {

constexpr double kA = 1.0, kB = 0.8, kC = 0.6;

double implicit(const Vec3& p) {
  const double x = p.x() / kA, y = p.y() / kB, z = p.z() / kC;
  return x * x + y * y + z * z - 1.0;
}

Vec3 ellipsoid_outward(const Vec3& p) {  // the gradient direction of the implicit function
  return Vec3(p.x() / (kA * kA), p.y() / (kB * kB), p.z() / (kC * kC)).normalized();
}

class EllipsoidMesh : public ::testing::TestWithParam<int> {};

TEST_P(EllipsoidMesh, OnTheEllipsoidClosedOutwardWellShaped) {
  const int level = GetParam();
  const GeneratedMesh g = generate_mesh(MeshSpec{"ellipsoid", level});
  const Mesh& m = g.mesh;
  EXPECT_EQ(g.family, "ellipsoid");
  EXPECT_EQ(g.level, level);
  ASSERT_EQ(g.surface->name(), "ellipsoid");
  EXPECT_EQ(g.exact_points, m.vertices());
  double worst = 0.0;
  for (int v = 0; v < m.num_vertices(); ++v)
    worst = std::max(worst, std::abs(implicit(m.position(v))));
  EXPECT_LT(worst, 1e-14);
  // A closed sphere-like surface: every directed edge once, its reverse once; F = 2V - 4.
  EXPECT_EQ(m.num_faces(), 2 * m.num_vertices() - 4);
  std::map<std::pair<int, int>, int> edge_use;
  for (int f = 0; f < m.num_faces(); ++f)
    for (int k = 0; k < 3; ++k) ++edge_use[{m.face_vertex(f, k), m.face_vertex(f, (k + 1) % 3)}];
  for (const auto& [e, n] : edge_use) {
    ASSERT_EQ(n, 1);
    ASSERT_EQ(edge_use.count({e.second, e.first}), 1u);
  }
  EXPECT_EQ(testing::inward_faces(m, ellipsoid_outward), 0);
  const MeshQuality q = mesh_quality(m);
  EXPECT_GE(q.min_angle_deg, 25.0);
  EXPECT_LT(q.min_valence, 6);
  EXPECT_GT(q.max_valence, 6);
}

// The exact quantities at the vertices against finite differences of (a cos v cos u,
// b cos v sin u, c sin v) at the vertex's (u, v); the sign convention: outward normal, k1 >= k2
// (both negative), d1 orthogonal to n. d1 is compared away from the four umbilics.
TEST_P(EllipsoidMesh, ExactQuantitiesAndSignConvention) {
  const GeneratedMesh g = generate_mesh(MeshSpec{"ellipsoid", GetParam()});
  int compared = 0, directions = 0;
  for (int v = 0; v < g.mesh.num_vertices(); v += 5) {
    const Vec3 p = g.exact_points.row(v).transpose();
    const SurfacePoint e = g.surface->evaluate(p);
    const std::string where = "vertex " + std::to_string(v);
    test::expect_frame_conventions(e, where.c_str());
    EXPECT_LE((e.point - p).norm(), 1e-15);
    EXPECT_LE((e.normal - ellipsoid_outward(p)).norm(), 1e-14);
    EXPECT_LT(e.k1, 0.0);
    const double lat = std::asin(std::clamp(p.z() / kC, -1.0, 1.0));
    if (std::abs(lat) > 1.3) continue;  // the parameterization degenerates at the poles
    const double lon = std::atan2(p.y() / kB, p.x() / kA);
    const test::Reference ref = test::fd_reference(*g.surface, lon, lat);
    directions += test::expect_matches_reference(e, ref, 1e-6, 1e-2, where.c_str());
    ++compared;
  }
  EXPECT_GT(compared, g.mesh.num_vertices() / 5 - g.mesh.num_vertices() / 20);
  EXPECT_GT(directions, compared * 9 / 10);
}

INSTANTIATE_TEST_SUITE_P(Levels, EllipsoidMesh, ::testing::Values(1, 2));

TEST(EllipsoidFamily, DeterministicLevelsGrowAndLevelChecks) {
  const GeneratedMesh a = ellipsoid_mesh(1, 1), b = ellipsoid_mesh(1, 1);
  EXPECT_TRUE(test::identical(a.mesh.vertices(), b.mesh.vertices()));
  EXPECT_TRUE(test::identical(a.mesh.faces(), b.mesh.faces()));
  const GeneratedMesh c = ellipsoid_mesh(1, 2);
  EXPECT_FALSE(
      test::identical(a.mesh.vertices(), c.mesh.vertices()));  // the seed reaches the mesher
  const GeneratedMesh cached = generate_mesh(MeshSpec{"ellipsoid", 1});
  EXPECT_TRUE(test::identical(cached.mesh.vertices(), a.mesh.vertices()));
  const int v1 = a.mesh.num_vertices(),
            v2 = generate_mesh(MeshSpec{"ellipsoid", 2}).mesh.num_vertices();
  EXPECT_GT(v1, 200);
  EXPECT_GT(v2, 3 * v1);
  EXPECT_LT(v2, 5 * v1);
  EXPECT_EQ(max_mesh_level("ellipsoid"), 4);
  EXPECT_THROW(ellipsoid_mesh(0), UsageError);
  EXPECT_THROW(ellipsoid_mesh(5), UsageError);
}

}  // namespace
}  // namespace curvbench
