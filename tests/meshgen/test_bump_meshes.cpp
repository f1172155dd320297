// Gaussian-bump meshes: the 4-8 mesh and the seeded irregular Delaunay mesh (docs/algorithms.md
// §10.2, paper §5.2).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <set>
#include <vector>

#include "bump_test_util.h"
#include "core/errors.h"
#include "meshgen/bump_grid.h"
#include "meshgen/bump_irregular.h"
#include "meshgen/generate.h"
#include "tests/meshgen/identical_matrices.h"

namespace curvbench {
namespace {

double bump_height(double x, double y) {
  return std::exp(-81.0 / 16.0 * ((x - 0.5) * (x - 0.5) + (y - 0.5) * (y - 0.5)));
}

// Number of distinct edge neighbours of every vertex.
std::vector<int> valences(const Mesh& m) {
  std::vector<std::set<int>> nb(m.num_vertices());
  for (int f = 0; f < m.num_faces(); ++f)
    for (int k = 0; k < 3; ++k) {
      nb[m.face_vertex(f, k)].insert(m.face_vertex(f, (k + 1) % 3));
      nb[m.face_vertex(f, k)].insert(m.face_vertex(f, (k + 2) % 3));
    }
  std::vector<int> val(m.num_vertices());
  for (int v = 0; v < m.num_vertices(); ++v) val[v] = static_cast<int>(nb[v].size());
  return val;
}

// Signed area in xy of face f.
double xy_area(const Mesh& m, int f) {
  const Vec3 a = m.position(m.face_vertex(f, 0)), b = m.position(m.face_vertex(f, 1)),
             c = m.position(m.face_vertex(f, 2));
  return 0.5 * ((b.x() - a.x()) * (c.y() - a.y()) - (b.y() - a.y()) * (c.x() - a.x()));
}

// Checks shared by both bump families: counts, topology, +z orientation, vertices on the bump,
// domain exactly [0,1]^2 with the 4N boundary vertices on its perimeter.
void check_bump_mesh(const GeneratedMesh& gm, int N) {
  const Mesh& m = gm.mesh;
  EXPECT_EQ(m.num_vertices(), (N + 1) * (N + 1));
  EXPECT_EQ(m.num_faces(), 2 * N * N);
  EXPECT_EQ(m.euler_characteristic(), 1);
  EXPECT_EQ(m.num_nonmanifold_edges(), 0);
  EXPECT_EQ(m.num_isolated_vertices(), 0);
  EXPECT_TRUE(m.is_consistently_oriented());
  EXPECT_EQ(m.num_boundary_edges(), 4 * N);
  EXPECT_EQ(m.num_boundary_vertices(), 4 * N);
  double area = 0, min_area = 1;
  for (int f = 0; f < m.num_faces(); ++f) {
    const double a = xy_area(m, f);
    area += a;
    min_area = std::min(min_area, a);
  }
  EXPECT_GT(min_area, 0.0);  // every face ccw in xy: normals +z
  // Positive faces with total area 1 inside [0,1]^2 tile the square exactly.
  EXPECT_NEAR(area, 1.0, 1e-12);
  double perimeter = 0;
  for (int f = 0; f < m.num_faces(); ++f)
    for (int k = 0; k < 3; ++k)
      if (m.face_neighbor(f, k) < 0) {
        const Vec3 a = m.position(m.face_vertex(f, k)),
                   b = m.position(m.face_vertex(f, (k + 1) % 3));
        perimeter += std::hypot(b.x() - a.x(), b.y() - a.y());
      }
  EXPECT_NEAR(perimeter, 4.0, 1e-12);
  for (int v = 0; v < m.num_vertices(); ++v) {
    const Vec3 p = m.position(v);
    ASSERT_GE(p.x(), 0.0);
    ASSERT_LE(p.x(), 1.0);
    ASSERT_GE(p.y(), 0.0);
    ASSERT_LE(p.y(), 1.0);
    const bool on_square = p.x() == 0.0 || p.x() == 1.0 || p.y() == 0.0 || p.y() == 1.0;
    ASSERT_EQ(on_square, m.is_boundary_vertex(v)) << "vertex " << v;
    ASSERT_NEAR(p.z(), bump_height(p.x(), p.y()), 1e-15);
  }
  EXPECT_EQ(gm.exact_points, m.vertices());
  ASSERT_TRUE(gm.surface);
  EXPECT_EQ(gm.surface->name(), "bump");
  EXPECT_FALSE(gm.description.empty());
}

TEST(Bump48, CountsValencesAndOrientation) {
  for (int level = 1; level <= 4; ++level) {
    const GeneratedMesh gm = bump_48(level);
    const int N = 16 << (level - 1);
    ASSERT_EQ(bump_grid_size(level), N);
    EXPECT_EQ(gm.family, "bump-48");
    EXPECT_EQ(gm.level, level);
    check_bump_mesh(gm, N);
    const std::vector<int> val = valences(gm.mesh);
    int n8 = 0, n4 = 0;
    for (int j = 0; j <= N; ++j)
      for (int i = 0; i <= N; ++i) {
        const int v = j * (N + 1) + i;
        const Vec3 p = gm.mesh.position(v);
        ASSERT_EQ(p.x(), static_cast<double>(i) / N);
        ASSERT_EQ(p.y(), static_cast<double>(j) / N);
        const bool bi = i == 0 || i == N, bj = j == 0 || j == N;
        const bool even = (i + j) % 2 == 0;
        int expected;
        if (bi && bj)
          expected = 3;  // corner
        else if (bi || bj)
          expected = even ? 5 : 3;  // edge
        else
          expected = even ? 8 : 4;  // interior
        ASSERT_EQ(val[v], expected) << "vertex (" << i << ", " << j << ")";
        if (!bi && !bj) (val[v] == 8 ? n8 : n4)++;
      }
    EXPECT_EQ(n8, ((N - 1) * (N - 1) + 1) / 2);
    EXPECT_EQ(n4, ((N - 1) * (N - 1) - 1) / 2);
    EXPECT_EQ(val[(N / 2) * (N + 1) + N / 2], 8);  // the peak (1/2, 1/2) is a valence-8 vertex
  }
}

TEST(BumpIrregular, TopologyDomainAndDelaunay) {
  for (int level = 1; level <= 4; ++level) {
    const GeneratedMesh gm = bump_irregular(level, 1);
    const int N = 16 << (level - 1);
    const double h = 1.0 / N;
    EXPECT_EQ(gm.family, "bump-irregular");
    EXPECT_EQ(gm.level, level);
    check_bump_mesh(gm, N);
    const Mesh& m = gm.mesh;
    // Jitter bounds: interior +-h/4 in x and y, boundary along the edge only, corners fixed.
    for (int j = 0; j <= N; ++j)
      for (int i = 0; i <= N; ++i) {
        const Vec3 p = m.position(j * (N + 1) + i);
        ASSERT_LE(std::abs(p.x() - i * h), 0.25 * h + 1e-15);
        ASSERT_LE(std::abs(p.y() - j * h), 0.25 * h + 1e-15);
        if (i == 0 || i == N) {
          ASSERT_EQ(p.x(), i == 0 ? 0.0 : 1.0);
        }
        if (j == 0 || j == N) {
          ASSERT_EQ(p.y(), j == 0 ? 0.0 : 1.0);
        }
      }
    // Delaunay in xy: across every interior edge the two opposite angles sum to at most pi.
    EXPECT_EQ(testing::delaunay_violations(m), 0);
    // Varying valences; well-shaped in the plane. For interior triangles the shortest edge is
    // >= h/2 and an empty circumcircle has radius < 1.5h/sqrt(2), so the smallest angle is
    // >= asin(0.5 / 2.12) = 13.6 degrees (measured: 24.9, 22.7, 20.5, 19.1 for seed 1).
    VertexMatrix flat = m.vertices();
    flat.col(2).setZero();
    const MeshQuality q = mesh_quality(Mesh(flat, m.faces()));
    EXPECT_LT(q.min_valence, 6);
    EXPECT_GT(q.max_valence, 6);
    EXPECT_GE(q.min_valence, 3);
    EXPECT_LE(q.max_valence, 10);
    EXPECT_GT(q.min_angle_deg, 13.0);
  }
}

TEST(BumpIrregular, DeterministicPerSeed) {
  const GeneratedMesh a = bump_irregular(2, 5), b = bump_irregular(2, 5), c = bump_irregular(2, 6);
  EXPECT_TRUE(test::identical(a.mesh.vertices(), b.mesh.vertices()));
  EXPECT_TRUE(test::identical(a.mesh.faces(), b.mesh.faces()));
  EXPECT_FALSE(test::identical(a.mesh.vertices(), c.mesh.vertices()));
  EXPECT_FALSE(test::identical(a.mesh.faces(), c.mesh.faces()));
  // Levels use independent streams: level 1 is not a subsample of level 2's jitter sequence.
  EXPECT_NE(bump_irregular_points(1, 5)(18, 0), bump_irregular_points(2, 5)(34, 0));
}

TEST(BumpMeshes, MeanEdgeLengthHalves) {
  for (auto gen : {+[](int l) { return bump_48(l); }, +[](int l) { return bump_irregular(l); }}) {
    double prev = 0;
    for (int level = 1; level <= 4; ++level) {
      const double h = gen(level).mesh.mean_edge_length();
      if (level > 1) {
        EXPECT_NEAR(prev / h, 2.0, 0.2);
      }
      prev = h;
    }
  }
}

TEST(BumpMeshes, BadInputThrows) {
  EXPECT_THROW(bump_48(0), UsageError);
  EXPECT_THROW(bump_48(max_bump_level() + 1), UsageError);
  EXPECT_THROW(bump_irregular(0), UsageError);
  PlanarPoints dup(4, 2);
  dup << 0, 0, 1, 0, 0, 1, 1, 0;
  EXPECT_THROW(delaunay_triangulation(dup), InputError);
}

}  // namespace
}  // namespace curvbench
