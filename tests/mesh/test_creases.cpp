// Crease detection (mesh/creases.h) on closed meshes whose sharp edges are known by construction
// (tests/mesh/crease_test_meshes.h): the detected sets equal the built ones exactly, with and
// without isotropic noise of 0.01 h per axis, which turns face normals by about a degree, far
// below the default 60-degree threshold.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <vector>

#include "core/errors.h"
#include "mesh/creases.h"
#include "tests/mesh/crease_test_meshes.h"

namespace curvbench {
namespace {

using crease_test::CreasedMesh;

constexpr double kNoise = 0.01;  // sigma/h per axis of with_isotropic_noise
constexpr std::uint64_t kSeed = 17;

void expect_creases(const CreasedMesh& m, const Mesh& mesh, const char* what) {
  const Creases c = detect_creases(mesh);
  EXPECT_EQ(c.threshold_deg, kDefaultCreaseAngle);
  EXPECT_EQ(c.edges, m.sharp_edges) << what;
  EXPECT_EQ(c.vertices, m.crease_vertices) << what;
  ASSERT_EQ(c.is_vertex.size(), size_t(mesh.num_vertices()));
  for (int v = 0; v < mesh.num_vertices(); ++v)
    EXPECT_EQ(c.is_vertex[size_t(v)] != 0,
              std::binary_search(m.crease_vertices.begin(), m.crease_vertices.end(), v))
        << what << " vertex " << v;
}

TEST(Creases, CubeEdgesAndOnlyThem) {
  constexpr int n = 8;
  const CreasedMesh cube = crease_test::meshed_cube(n);
  ASSERT_EQ(cube.sharp_edges.size(), size_t(12 * n));  // 12 edges of n segments
  ASSERT_EQ(cube.crease_vertices.size(), size_t(12 * (n - 1) + 8));
  expect_creases(cube, cube.mesh, "cube");
  expect_creases(cube, crease_test::with_isotropic_noise(cube.mesh, kNoise, kSeed), "noisy cube");
  // The corners are crease vertices; no vertex inside a face of the cube is.
  const Creases c = detect_creases(cube.mesh);
  int corners = 0, inside = 0;
  for (int v = 0; v < cube.mesh.num_vertices(); ++v) {
    int extreme = 0;
    for (int d = 0; d < 3; ++d) extreme += std::fabs(cube.mesh.position(v)[d]) == 1.0;
    if (extreme == 3) corners += c.is_vertex[size_t(v)];
    if (extreme == 1) inside += c.is_vertex[size_t(v)];
  }
  EXPECT_EQ(corners, 8);
  EXPECT_EQ(inside, 0);
}

TEST(Creases, CylinderRimsExactly) {
  constexpr int m = 32, k = 8, c = 4;
  const CreasedMesh cyl = crease_test::capped_cylinder(m, k, c);
  ASSERT_EQ(cyl.sharp_edges.size(), size_t(2 * m));
  ASSERT_EQ(cyl.crease_vertices.size(), size_t(2 * m));
  expect_creases(cyl, cyl.mesh, "cylinder");
  expect_creases(cyl, crease_test::with_isotropic_noise(cyl.mesh, kNoise, kSeed), "noisy cylinder");
  // Below the side's turn between sectors (360/m = 11.25 degrees) the m k side edges between
  // sectors are sharp too.
  EXPECT_EQ(detect_creases(cyl.mesh, 10.0).num_edges(), 2 * m + m * k);
  EXPECT_EQ(detect_creases(cyl.mesh, 12.0).num_edges(), 2 * m);
}

TEST(Creases, FandiskLikePart) {
  const CreasedMesh part = crease_test::fandisk_like_part();
  expect_creases(part, part.mesh, "part");
  expect_creases(part, crease_test::with_isotropic_noise(part.mesh, kNoise, kSeed), "noisy part");
}

// The angle across the edge a-b (seen from the first face of a's fan that holds it).
double edge_angle(const Mesh& mesh, int a, int b) {
  for (int f : mesh.vertex_faces(a))
    for (int k = 0; k < 3; ++k) {
      const int p = mesh.face_vertex(f, k), q = mesh.face_vertex(f, (k + 1) % 3);
      if ((p == a && q == b) || (p == b && q == a)) return dihedral_angle_deg(mesh, f, k);
    }
  return std::numeric_limits<double>::quiet_NaN();
}

// The threshold decides: the part's creases turn by 68.2 (the ramp's top), 90, 92.4 (the arc's
// end on the side) and 101.3 degrees (the ramp's foot), its arc by at most 4.8 between strips.
TEST(Creases, ThresholdSelectsByAngle) {
  const CreasedMesh part = crease_test::fandisk_like_part();
  const Mesh& mesh = part.mesh;
  std::map<long, int> by_angle;  // tenths of a degree -> sharp edges
  for (const auto& e : part.sharp_edges) ++by_angle[std::lround(10 * edge_angle(mesh, e[0], e[1]))];
  constexpr int ny = 20;  // edges along each line of the prism
  EXPECT_EQ(by_angle,
            (std::map<long, int>{{682, ny},
                                 {900, static_cast<int>(part.sharp_edges.size()) - 3 * ny},
                                 {924, ny},
                                 {1013, ny}}));
  const int all = static_cast<int>(part.sharp_edges.size());
  EXPECT_EQ(detect_creases(mesh, 70.0).num_edges(), all - ny);
  EXPECT_EQ(detect_creases(mesh, 95.0).num_edges(), ny);
  EXPECT_EQ(detect_creases(mesh, 5.0).num_edges(), all);
  EXPECT_GT(detect_creases(mesh, 4.5).num_edges(), all);
}

TEST(Creases, CubeEdgeIsNinetyDegreesWhateverTheOrientation) {
  const CreasedMesh cube = crease_test::meshed_cube(4);
  FaceMatrix F = cube.mesh.faces();
  for (Eigen::Index f = 0; f < F.rows(); f += 2) std::swap(F(f, 1), F(f, 2));
  const Mesh flipped(cube.mesh.vertices(), F);
  ASSERT_FALSE(flipped.is_consistently_oriented());
  EXPECT_EQ(detect_creases(flipped).edges, cube.sharp_edges);
  for (int f = 0; f < flipped.num_faces(); ++f)
    for (int k = 0; k < 3; ++k) {
      const double angle = dihedral_angle_deg(flipped, f, k);
      EXPECT_TRUE(std::fabs(angle) < 1e-12 || std::fabs(angle - 90.0) < 1e-12) << angle;
    }
}

TEST(Creases, BoundaryEdgesAreNeverSharp) {
  // The cube without the faces of its top (z = 1): the top's rim is a boundary loop.
  const CreasedMesh cube = crease_test::meshed_cube(4);
  std::vector<int> kept;
  for (int f = 0; f < cube.mesh.num_faces(); ++f) {
    bool top = true;
    for (int k = 0; k < 3; ++k)
      top = top && cube.mesh.position(cube.mesh.face_vertex(f, k)).z() == 1.0;
    if (!top) kept.push_back(f);
  }
  FaceMatrix F(static_cast<Eigen::Index>(kept.size()), 3);
  for (size_t i = 0; i < kept.size(); ++i) F.row(Eigen::Index(i)) = cube.mesh.faces().row(kept[i]);
  const Mesh open(cube.mesh.vertices(), F);
  ASSERT_EQ(open.num_boundary_edges(), 16);
  EXPECT_EQ(detect_creases(open).num_edges(), 8 * 4);  // 4 vertical edges and the bottom's 4
  int boundary = 0;
  for (int f = 0; f < open.num_faces(); ++f)
    for (int k = 0; k < 3; ++k)
      if (open.is_boundary_edge(f, k)) {
        ++boundary;
        EXPECT_TRUE(std::isnan(dihedral_angle_deg(open, f, k)));
      }
  EXPECT_EQ(boundary, 16);
}

TEST(Creases, SmoothSphereHasNone) {
  // An octahedron subdivided 4 times, projected onto the unit sphere (1026 vertices).
  std::vector<Vec3> p{{1, 0, 0}, {-1, 0, 0}, {0, 1, 0}, {0, -1, 0}, {0, 0, 1}, {0, 0, -1}};
  std::vector<std::array<int, 3>> f{{0, 2, 4}, {2, 1, 4}, {1, 3, 4}, {3, 0, 4},
                                    {2, 0, 5}, {1, 2, 5}, {3, 1, 5}, {0, 3, 5}};
  for (int level = 0; level < 4; ++level) {
    std::map<std::pair<int, int>, int> mid;
    auto midpoint = [&](int a, int b) {
      auto [it, added] = mid.try_emplace({std::min(a, b), std::max(a, b)}, 0);
      if (added) {
        p.push_back((p[size_t(a)] + p[size_t(b)]).normalized());
        it->second = static_cast<int>(p.size()) - 1;
      }
      return it->second;
    };
    std::vector<std::array<int, 3>> next;
    for (const auto& t : f) {
      const int ab = midpoint(t[0], t[1]), bc = midpoint(t[1], t[2]), ca = midpoint(t[2], t[0]);
      next.insert(next.end(), {{t[0], ab, ca}, {ab, t[1], bc}, {ca, bc, t[2]}, {ab, bc, ca}});
    }
    f = std::move(next);
  }
  VertexMatrix V(Eigen::Index(p.size()), 3);
  for (size_t i = 0; i < p.size(); ++i) V.row(Eigen::Index(i)) = p[i];
  FaceMatrix F(Eigen::Index(f.size()), 3);
  for (size_t i = 0; i < f.size(); ++i) F.row(Eigen::Index(i)) << f[i][0], f[i][1], f[i][2];
  const Mesh sphere(V, F);
  ASSERT_EQ(sphere.num_vertices(), 1026);
  EXPECT_EQ(detect_creases(sphere).num_edges(), 0);
  EXPECT_EQ(detect_creases(crease_test::with_isotropic_noise(sphere, kNoise, kSeed)).num_edges(),
            0);
}

TEST(Creases, ThresholdOutOfRangeIsAUsageError) {
  const Mesh mesh = crease_test::meshed_cube(2).mesh;
  for (double t : {0.0, -1.0, 180.0, 200.0, std::numeric_limits<double>::quiet_NaN()})
    EXPECT_THROW(detect_creases(mesh, t), UsageError) << t;
}

}  // namespace
}  // namespace curvbench
