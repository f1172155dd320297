// Mesh core: adjacency, boundary, edges, orientation, Euler characteristic, validation.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <string>

#include "core/errors.h"
#include "mesh/mesh.h"

namespace curvbench {
namespace {

// Regular octahedron with outward-oriented faces.
Mesh octahedron() {
  VertexMatrix V(6, 3);
  V << 1, 0, 0, -1, 0, 0, 0, 1, 0, 0, -1, 0, 0, 0, 1, 0, 0, -1;
  FaceMatrix F(8, 3);
  F << 0, 2, 4, 2, 1, 4, 1, 3, 4, 3, 0, 4, 2, 0, 5, 1, 2, 5, 3, 1, 5, 0, 3, 5;
  return Mesh(V, F);
}

// Unit square split into two triangles (ccw seen from +z).
Mesh square() {
  VertexMatrix V(4, 3);
  V << 0, 0, 0, 1, 0, 0, 1, 1, 0, 0, 1, 0;
  FaceMatrix F(2, 3);
  F << 0, 1, 2, 0, 2, 3;
  return Mesh(V, F);
}

TEST(MeshCore, ClosedOctahedron) {
  const Mesh m = octahedron();
  EXPECT_EQ(m.num_vertices(), 6);
  EXPECT_EQ(m.num_faces(), 8);
  EXPECT_EQ(m.num_edges(), 12);
  EXPECT_EQ(m.euler_characteristic(), 2);
  EXPECT_FALSE(m.has_boundary());
  EXPECT_EQ(m.num_boundary_vertices(), 0);
  EXPECT_EQ(m.num_nonmanifold_edges(), 0);
  EXPECT_TRUE(m.is_consistently_oriented());
  EXPECT_NEAR(m.signed_volume(), 4.0 / 3.0, 1e-14);  // two pyramids of volume 2/3
  EXPECT_NEAR(m.mean_edge_length(), std::sqrt(2.0), 1e-14);
  for (int v = 0; v < 6; ++v) EXPECT_EQ(m.vertex_faces(v).size(), 4u);
  // Face adjacency is symmetric and every edge has a neighbour.
  for (int f = 0; f < 8; ++f)
    for (int k = 0; k < 3; ++k) {
      const int g = m.face_neighbor(f, k);
      ASSERT_GE(g, 0);
      bool back = false;
      for (int l = 0; l < 3; ++l) back |= m.face_neighbor(g, l) == f;
      EXPECT_TRUE(back);
    }
  // Area-weighted normals of a symmetric closed mesh point along the vertex position.
  const VertexMatrix N = m.area_weighted_normals();
  for (int v = 0; v < 6; ++v) EXPECT_NEAR((N.row(v) - m.vertices().row(v)).norm(), 0.0, 1e-14);
}

TEST(MeshCore, OpenSquareBoundary) {
  const Mesh m = square();
  EXPECT_EQ(m.num_edges(), 5);
  EXPECT_EQ(m.num_boundary_edges(), 4);
  EXPECT_EQ(m.num_boundary_vertices(), 4);
  EXPECT_EQ(m.euler_characteristic(), 1);
  EXPECT_TRUE(m.is_consistently_oriented());
  EXPECT_EQ(m.face_neighbor(0, 2), 1);  // edge 2->0 of face 0 is the diagonal
  EXPECT_EQ(m.face_neighbor(0, 0), -1);
  EXPECT_FALSE(m.is_boundary_edge(0, 2));
  EXPECT_TRUE(m.is_boundary_edge(0, 0));
  EXPECT_FALSE(m.is_nonmanifold_edge(0, 0));
  EXPECT_NEAR(m.mean_edge_length(), (4.0 + std::sqrt(2.0)) / 5.0, 1e-15);
  const VertexMatrix N = m.area_weighted_normals();
  for (int v = 0; v < 4; ++v) EXPECT_NEAR(N(v, 2), 1.0, 1e-15);
}

TEST(MeshCore, DetectsInconsistentOrientation) {
  VertexMatrix V(4, 3);
  V << 0, 0, 0, 1, 0, 0, 1, 1, 0, 0, 1, 0;
  FaceMatrix F(2, 3);
  F << 0, 1, 2, 0, 3, 2;  // second face flipped: both traverse the diagonal as 2 -> 0
  const Mesh m(V, F);
  EXPECT_FALSE(m.is_consistently_oriented());
  EXPECT_EQ(m.num_inconsistent_edges(), 1);
}

TEST(MeshCore, CountsNonManifoldEdgesAndIsolatedVertices) {
  VertexMatrix V(6, 3);
  V << 0, 0, 0, 1, 0, 0, 0, 1, 0, 0, -1, 0, 0, 0, 1, 5, 5, 5;
  FaceMatrix F(3, 3);
  F << 0, 1, 2, 1, 0, 3, 0, 1, 4;  // edge 0-1 shared by three faces; vertex 5 unused
  const Mesh m(V, F);
  EXPECT_EQ(m.num_nonmanifold_edges(), 1);
  EXPECT_EQ(m.num_isolated_vertices(), 1);
  EXPECT_EQ(m.face_neighbor(0, 0), -1);
  EXPECT_TRUE(m.is_nonmanifold_edge(0, 0));
  EXPECT_FALSE(m.is_boundary_edge(0, 0));
  EXPECT_TRUE(m.is_boundary_edge(0, 1));
}

TEST(MeshCore, ValidationErrorsNameTheProblem) {
  VertexMatrix V(3, 3);
  V << 0, 0, 0, 1, 0, 0, 0, 1, 0;
  FaceMatrix F(1, 3);
  F << 0, 1, 3;
  try {
    Mesh m(V, F, "bad.off");
    FAIL() << "expected InputError";
  } catch (const InputError& e) {
    const std::string msg = e.what();
    EXPECT_NE(msg.find("bad.off"), std::string::npos);
    EXPECT_NE(msg.find("out of range"), std::string::npos);
  }
  F << 0, -1, 2;
  EXPECT_THROW(Mesh(V, F), InputError);
  F << 0, 1, 1;
  EXPECT_THROW(Mesh(V, F), InputError);
  F << 0, 1, 2;
  V(1, 2) = std::numeric_limits<double>::quiet_NaN();
  try {
    Mesh m(V, F, "nan.off");
    FAIL() << "expected InputError";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("vertex 1"), std::string::npos);
  }
  V(1, 2) = std::numeric_limits<double>::infinity();
  EXPECT_THROW(Mesh(V, F), InputError);
}

// Given normals: one row per vertex or none; the mismatch names the source.
TEST(MeshCore, GivenNormalsNeedOneRowPerVertex) {
  VertexMatrix V(3, 3);
  V << 0, 0, 0, 1, 0, 0, 0, 1, 0;
  Mesh m(V, FaceMatrix(0, 3), "pts.xyz");
  EXPECT_EQ(m.source(), "pts.xyz");
  EXPECT_FALSE(m.has_given_normals());
  try {
    m.set_given_normals(VertexMatrix::Zero(2, 3));
    FAIL() << "expected InputError";
  } catch (const InputError& e) {
    EXPECT_EQ(std::string(e.what()), "pts.xyz: 2 normals for 3 points");
  }
  m.set_given_normals(VertexMatrix::Ones(3, 3));
  EXPECT_TRUE(m.has_given_normals());
  m.set_given_normals(VertexMatrix());
  EXPECT_FALSE(m.has_given_normals());
}

TEST(MeshCore, EmptyMeshIsHarmless) {
  const Mesh m;
  EXPECT_EQ(m.num_vertices(), 0);
  EXPECT_EQ(m.num_edges(), 0);
  EXPECT_EQ(m.mean_edge_length(), 0.0);
}

}  // namespace
}  // namespace curvbench
