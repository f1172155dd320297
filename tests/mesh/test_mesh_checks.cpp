// Mesh defect counts (mesh/mesh_checks.h) on small hostile meshes whose counts are known by
// construction: bow tie, book of three pages, disjoint pieces, duplicates, slivers, annulus.
#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <numbers>
#include <vector>

#include "mesh/mesh.h"
#include "mesh/mesh_checks.h"

namespace curvbench {
namespace {

Mesh make(const std::vector<Vec3>& points, const std::vector<std::array<int, 3>>& faces) {
  VertexMatrix V(static_cast<Eigen::Index>(points.size()), 3);
  for (size_t i = 0; i < points.size(); ++i) V.row(static_cast<Eigen::Index>(i)) = points[i];
  FaceMatrix F(static_cast<Eigen::Index>(faces.size()), 3);
  for (size_t f = 0; f < faces.size(); ++f)
    F.row(static_cast<Eigen::Index>(f)) << faces[f][0], faces[f][1], faces[f][2];
  return Mesh(V, F);
}

// Regular octahedron, outward faces (vertices 0..5 shifted by `offset`, moved by `shift`).
void add_octahedron(std::vector<Vec3>& points, std::vector<std::array<int, 3>>& faces,
                    const Vec3& shift) {
  const int o = static_cast<int>(points.size());
  for (const Vec3& p : {Vec3(1, 0, 0), Vec3(-1, 0, 0), Vec3(0, 1, 0), Vec3(0, -1, 0), Vec3(0, 0, 1),
                        Vec3(0, 0, -1)})
    points.push_back(p + shift);
  const int f[8][3] = {{0, 2, 4}, {2, 1, 4}, {1, 3, 4}, {3, 0, 4},
                       {2, 0, 5}, {1, 2, 5}, {3, 1, 5}, {0, 3, 5}};
  for (const auto& t : f) faces.push_back({o + t[0], o + t[1], o + t[2]});
}

TEST(MeshChecks, CleanClosedMeshHasNoDefects) {
  std::vector<Vec3> p;
  std::vector<std::array<int, 3>> f;
  add_octahedron(p, f, Vec3::Zero());
  const MeshChecks c = check_mesh(make(p, f));
  EXPECT_EQ(c.zero_area_faces, 0);
  EXPECT_EQ(c.duplicate_vertices, 0);
  EXPECT_EQ(c.duplicate_faces, 0);
  EXPECT_EQ(c.isolated_vertices, 0);
  EXPECT_EQ(c.nonmanifold_edges, 0);
  EXPECT_EQ(c.nonmanifold_vertices, 0);
  EXPECT_EQ(c.components, 1);
  EXPECT_EQ(c.inconsistent_edges, 0);
  EXPECT_EQ(c.boundary_edges, 0);
  EXPECT_EQ(c.boundary_loops, 0);
}

TEST(MeshChecks, BowTieIsOneNonManifoldVertex) {
  // Two triangles touching only at vertex 0.
  const Mesh m =
      make({Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(1, 1, 0), Vec3(-1, 0, 0), Vec3(-1, -1, 0)},
           {{0, 1, 2}, {0, 3, 4}});
  const MeshChecks c = check_mesh(m);
  EXPECT_EQ(c.nonmanifold_vertices, 1);
  EXPECT_EQ(c.nonmanifold_edges, 0);
  EXPECT_EQ(c.components, 1);  // connected through vertex 0
  EXPECT_EQ(c.boundary_edges, 6);
  EXPECT_EQ(c.boundary_loops, 1);  // the two loops touch at vertex 0
  EXPECT_EQ(c.zero_area_faces, 0);
}

TEST(MeshChecks, BookOfThreePagesHasANonManifoldEdgeAndTwoVertices) {
  // Edge 0-1 shared by three faces; its endpoints are non-manifold, the page tips are not.
  const Mesh m =
      make({Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(0.5, 1, 0), Vec3(0.5, -1, 0), Vec3(0.5, 0, 1)},
           {{0, 1, 2}, {1, 0, 3}, {0, 1, 4}});
  EXPECT_TRUE(m.is_nonmanifold_edge(0, 0));
  EXPECT_FALSE(m.is_boundary_edge(0, 0));
  EXPECT_EQ(m.face_neighbor(0, 0), -1);  // unchanged meaning
  EXPECT_TRUE(m.is_boundary_edge(0, 1));
  const MeshChecks c = check_mesh(m);
  EXPECT_EQ(c.nonmanifold_edges, 1);
  EXPECT_EQ(c.nonmanifold_vertices, 2);
  EXPECT_EQ(c.boundary_edges, 6);
  EXPECT_EQ(c.boundary_loops, 1);
  EXPECT_EQ(c.components, 1);
}

TEST(MeshChecks, ComponentsIsolatedVerticesAndDuplicates) {
  std::vector<Vec3> p;
  std::vector<std::array<int, 3>> f;
  add_octahedron(p, f, Vec3::Zero());
  add_octahedron(p, f, Vec3(5, 0, 0));
  p.push_back(Vec3(9, 9, 9));     // 12: isolated
  p.push_back(Vec3(1, 0, 0));     // 13: duplicate of vertex 0 (and isolated)
  p.push_back(Vec3(1, 0, -0.0));  // 14: duplicate of vertex 0 too (-0 == 0)
  f.push_back({4, 2, 0});         // same vertex set as face 0, other orientation
  f.push_back({2, 4, 0});         // same vertex set and orientation as face 0
  const Mesh m = make(p, f);
  const MeshChecks c = check_mesh(m);
  EXPECT_EQ(c.components, 2);  // isolated vertices are not components
  EXPECT_EQ(c.isolated_vertices, 3);
  EXPECT_EQ(c.duplicate_vertices, 2);
  EXPECT_EQ(c.duplicate_faces, 2);
  // Edge 0-2 now has four faces: non-manifold, as are its endpoints (vertex 4 too: edges 2-4,
  // 0-4 have four faces each).
  EXPECT_EQ(c.nonmanifold_edges, 3);
  EXPECT_EQ(c.nonmanifold_vertices, 3);
  EXPECT_EQ(c.boundary_edges, 0);
}

TEST(MeshChecks, ZeroAreaFacesUpToRounding) {
  const Mesh m = make({Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(2, 0, 0), Vec3(0.5, 1e-13, 0),
                       Vec3(0.5, 1e-6, 0), Vec3(0.1, 0.1, 0.1), Vec3(0.3, 0.3, 0.3)},
                      {{0, 1, 2},  // exactly collinear
                       {0, 1, 3},  // height 1e-13: zero area up to the tolerance
                       {0, 1, 4},  // height 1e-6: a sliver, but a real triangle
                       {0, 5, 6},  // collinear in floating point (0.1 and 0.3 inexact)
                       {1, 4, 5}});
  EXPECT_EQ(count_zero_area_faces(m), 3);
}

TEST(MeshChecks, AnnulusHasTwoBoundaryLoopsAndFlippedFacesAreCounted) {
  // A square band: outer square z = 0 (vertices 0..3) and inner square z = 1 (4..7).
  std::vector<Vec3> p = {Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(1, 1, 0), Vec3(0, 1, 0),
                         Vec3(0, 0, 1), Vec3(1, 0, 1), Vec3(1, 1, 1), Vec3(0, 1, 1)};
  std::vector<std::array<int, 3>> f;
  for (int i = 0; i < 4; ++i) {
    const int j = (i + 1) % 4;
    f.push_back({i, j, 4 + j});
    f.push_back({i, 4 + j, 4 + i});
  }
  MeshChecks c = check_mesh(make(p, f));
  EXPECT_EQ(c.boundary_edges, 8);
  EXPECT_EQ(c.boundary_loops, 2);
  EXPECT_EQ(c.inconsistent_edges, 0);
  EXPECT_EQ(c.nonmanifold_vertices, 0);
  EXPECT_EQ(c.components, 1);
  // Flip one face: its three edges, two interior, become inconsistent (one is a boundary edge).
  std::swap(f[0][1], f[0][2]);
  c = check_mesh(make(p, f));
  EXPECT_EQ(c.inconsistent_edges, 2);
  EXPECT_EQ(c.boundary_loops, 2);
}

// valence_histogram: entry k counts the vertices with k distinct edge neighbours.
TEST(MeshChecks, ValenceHistogram) {
  std::vector<Vec3> p;
  std::vector<std::array<int, 3>> f;
  add_octahedron(p, f, Vec3::Zero());
  EXPECT_EQ(valence_histogram(make(p, f)), (std::vector<int>{0, 0, 0, 0, 6}));
  // An isolated vertex counts at valence 0.
  p.push_back(Vec3(5, 5, 5));
  EXPECT_EQ(valence_histogram(make(p, f)), (std::vector<int>{1, 0, 0, 0, 6}));
  // An open hexagonal fan: the centre has six neighbours, each rim vertex three (the centre and
  // its two rim neighbours), boundary or not.
  std::vector<Vec3> q = {Vec3(0, 0, 0)};
  std::vector<std::array<int, 3>> g;
  for (int i = 0; i < 6; ++i) {
    const double a = i * std::numbers::pi / 3.0;
    q.push_back(Vec3(std::cos(a), std::sin(a), 0));
    g.push_back({0, 1 + i, 1 + (i + 1) % 6});
  }
  EXPECT_EQ(valence_histogram(make(q, g)), (std::vector<int>{0, 0, 0, 6, 0, 0, 1}));
  EXPECT_TRUE(valence_histogram(Mesh()).empty());
}

}  // namespace
}  // namespace curvbench
