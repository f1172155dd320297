// Consistent orientation before estimating (mesh/orientation.h).
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <numbers>
#include <random>
#include <utility>

#include "mesh/mesh.h"
#include "mesh/orientation.h"

namespace curvbench {
namespace {

// Closed torus (R = 1, r = 0.3), faces counter-clockwise seen from outside.
Mesh torus(int nu, int nv, Vec3 offset = Vec3::Zero()) {
  VertexMatrix V(nu * nv, 3);
  for (int j = 0; j < nv; ++j)
    for (int i = 0; i < nu; ++i) {
      const double u = 2 * std::numbers::pi * i / nu, v = 2 * std::numbers::pi * j / nv;
      V.row(j * nu + i) = (offset + Vec3((1 + 0.3 * std::cos(v)) * std::cos(u),
                                         (1 + 0.3 * std::cos(v)) * std::sin(u), 0.3 * std::sin(v)))
                              .transpose();
    }
  FaceMatrix F(2 * nu * nv, 3);
  const auto id = [&](int i, int j) { return (j % nv) * nu + (i % nu); };
  for (int j = 0, f = 0; j < nv; ++j)
    for (int i = 0; i < nu; ++i) {
      F.row(f++) << id(i, j), id(i + 1, j), id(i + 1, j + 1);
      F.row(f++) << id(i, j), id(i + 1, j + 1), id(i, j + 1);
    }
  return Mesh(V, F);
}

// The same triangle with the same orientation (any starting corner).
bool same_oriented_face(const FaceMatrix& a, const FaceMatrix& b, int f) {
  for (int s = 0; s < 3; ++s)
    if (a(f, 0) == b(f, s) && a(f, 1) == b(f, (s + 1) % 3) && a(f, 2) == b(f, (s + 2) % 3))
      return true;
  return false;
}

FaceMatrix flip_some(const FaceMatrix& F, double fraction, unsigned seed, int& flipped) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  FaceMatrix G = F;
  flipped = 0;
  for (int f = 0; f < G.rows(); ++f)
    if (u(rng) < fraction) {
      std::swap(G(f, 0), G(f, 2));
      ++flipped;
    }
  return G;
}

TEST(Orientation, RandomFlipsAreUndoneExactly) {
  const Mesh t = torus(24, 12);
  int flipped = 0;
  const Mesh soup(t.vertices(), flip_some(t.faces(), 0.3, 7, flipped));
  ASSERT_FALSE(soup.is_consistently_oriented());
  const OrientationResult a = orient_mesh(soup), b = orient_mesh(t);
  EXPECT_EQ(a.faces_flipped, flipped);
  EXPECT_EQ(b.faces_flipped, 0);
  EXPECT_TRUE(a.mesh.is_consistently_oriented());
  EXPECT_EQ(a.mesh.faces(), b.mesh.faces());  // identical rows: identical estimates
  for (int f = 0; f < t.num_faces(); ++f)
    EXPECT_TRUE(same_oriented_face(t.faces(), a.mesh.faces(), f));
  EXPECT_EQ(a.mesh.vertices(), t.vertices());
  EXPECT_EQ(a.patches, 1);
  EXPECT_EQ(a.closed_patches, 1);
  EXPECT_EQ(a.vertices_undetermined, 0);
  EXPECT_EQ(orientation_warnings(b).size(), 0u);
  ASSERT_EQ(orientation_warnings(a).size(), 1u);
  EXPECT_NE(
      orientation_warnings(a)[0].find("reoriented " + std::to_string(flipped) + " of 576 faces"),
      std::string::npos);
}

TEST(Orientation, InsideOutClosedMeshIsTurnedOutward) {
  const Mesh t = torus(16, 8);
  FaceMatrix G = t.faces();
  G.col(1).swap(G.col(2));
  const Mesh inside_out(t.vertices(), G);
  ASSERT_TRUE(inside_out.is_consistently_oriented());
  ASSERT_LT(inside_out.signed_volume(), 0.0);
  const OrientationResult r = orient_mesh(inside_out);
  EXPECT_EQ(r.faces_flipped, t.num_faces());
  EXPECT_GT(r.mesh.signed_volume(), 0.0);
  EXPECT_NEAR(r.mesh.signed_volume(), t.signed_volume(), 1e-12);
}

TEST(Orientation, TwoComponentsEachOutward) {
  // Two tori, the second inside out and with random flips: both end outward.
  const Mesh a = torus(12, 6), b = torus(12, 6, Vec3(5, 0, 0));
  VertexMatrix V(a.num_vertices() + b.num_vertices(), 3);
  V << a.vertices(), b.vertices();
  FaceMatrix Fb = b.faces().array() + a.num_vertices();
  Fb.col(1).swap(Fb.col(2));
  int flipped = 0;
  Fb = flip_some(Fb, 0.2, 3, flipped);
  FaceMatrix F(a.num_faces() + b.num_faces(), 3);
  F << a.faces(), Fb;
  const OrientationResult r = orient_mesh(Mesh(V, F));
  EXPECT_EQ(r.patches, 2);
  EXPECT_EQ(r.closed_patches, 2);
  EXPECT_NEAR(r.mesh.signed_volume(), a.signed_volume() + b.signed_volume(), 1e-12);
}

// A consistently oriented mesh takes the union-find path (no walk), a mesh with one inconsistent
// edge the walk: on the same patches they must agree on every face, patch count and flag. Three
// patches, interleaved in face order so that a patch's lowest face is not its first: an outward
// torus, an inside-out torus (reversed as a whole) and an open strip (kept) that touches the
// first torus at vertex 0 (a vertex of two patches: undetermined).
TEST(Orientation, ConsistentPathAgreesWithTheWalk) {
  const Mesh a = torus(10, 5), b = torus(8, 6, Vec3(5, 0, 0));
  const int na = a.num_vertices(), nb = b.num_vertices();
  VertexMatrix V(na + nb + 6, 3);
  V << a.vertices(), b.vertices(), VertexMatrix::Zero(6, 3);
  for (int i = 0; i < 3; ++i) {
    V.row(na + nb + 2 * i) << 10 + i, 0, 0;
    V.row(na + nb + 2 * i + 1) << 10 + i, 1, 0;
  }
  std::vector<std::array<int, 3>> faces;
  const int fa = a.num_faces(), fb = b.num_faces();
  for (int f = 0; f < std::max(fa, fb); ++f) {
    if (f < fb) faces.push_back({b.faces()(f, 0) + na, b.faces()(f, 2) + na, b.faces()(f, 1) + na});
    if (f < fa) faces.push_back({a.faces()(f, 0), a.faces()(f, 1), a.faces()(f, 2)});
  }
  const int s = na + nb;
  for (int i = 0; i < 2; ++i) {
    faces.push_back({s + 2 * i, s + 2 * i + 2, s + 2 * i + 3});
    faces.push_back({s + 2 * i, s + 2 * i + 3, s + 2 * i + 1});
  }
  faces.push_back({0, s + 5, s + 4});  // the strip's last face, at vertex 0 of the first torus
  FaceMatrix F(static_cast<Eigen::Index>(faces.size()), 3);
  for (size_t f = 0; f < faces.size(); ++f)
    F.row(static_cast<Eigen::Index>(f)) << faces[f][0], faces[f][1], faces[f][2];
  const Mesh consistent(V, F);
  ASSERT_TRUE(consistent.is_consistently_oriented());
  FaceMatrix G = F;
  std::swap(G(1, 1), G(1, 2));  // one face of the outward torus
  const Mesh walked(V, G);
  ASSERT_FALSE(walked.is_consistently_oriented());
  const OrientationResult x = orient_mesh(consistent), y = orient_mesh(walked);
  EXPECT_EQ(x.patches, 3);
  EXPECT_EQ(x.patches, y.patches);
  EXPECT_EQ(x.closed_patches, 2);
  EXPECT_EQ(x.closed_patches, y.closed_patches);
  EXPECT_EQ(x.faces_flipped, fb);
  EXPECT_EQ(y.faces_flipped, fb + 1);
  EXPECT_EQ(x.mesh.faces(), y.mesh.faces());
  EXPECT_EQ(x.sign_undetermined, y.sign_undetermined);
  EXPECT_EQ(x.vertices_undetermined, 1);
  EXPECT_EQ(x.sign_undetermined[0], 1);
  EXPECT_TRUE(x.mesh.is_consistently_oriented());
  EXPECT_NEAR(x.mesh.signed_volume(), a.signed_volume() + b.signed_volume(), 1e-12);
}

TEST(Orientation, OpenPatchKeepsTheMajorityOrientation) {
  // A strip (open): 1 of its faces flipped comes back; all but 1 flipped: the strip is reversed
  // to the majority, i.e. only the odd face changes.
  VertexMatrix V(8, 3);
  for (int i = 0; i < 4; ++i) {
    V.row(2 * i) << i, 0, 0;
    V.row(2 * i + 1) << i, 1, 0;
  }
  FaceMatrix F(6, 3);
  for (int i = 0; i < 3; ++i) {
    F.row(2 * i) << 2 * i, 2 * i + 2, 2 * i + 3;
    F.row(2 * i + 1) << 2 * i, 2 * i + 3, 2 * i + 1;
  }
  FaceMatrix G = F;
  std::swap(G(2, 1), G(2, 2));
  OrientationResult r = orient_mesh(Mesh(V, G));
  EXPECT_EQ(r.faces_flipped, 1);
  for (int f = 0; f < 6; ++f) EXPECT_TRUE(same_oriented_face(F, r.mesh.faces(), f));
  G.col(1).swap(G.col(2));
  r = orient_mesh(Mesh(V, G));
  EXPECT_EQ(r.faces_flipped, 1);
  for (int f = 0; f < 6; ++f) EXPECT_FALSE(same_oriented_face(F, r.mesh.faces(), f));
  EXPECT_EQ(r.closed_patches, 0);
  EXPECT_EQ(r.vertices_undetermined, 0);
}

TEST(Orientation, MoebiusStripSignIsUndetermined) {
  // A Moebius strip (3 rows across, 30 around) and, in the same file, a separate square.
  const int nu = 30;
  VertexMatrix V(3 * nu + 4, 3);
  for (int i = 0; i < nu; ++i)
    for (int j = 0; j < 3; ++j) {
      const double u = 2 * std::numbers::pi * i / nu, t = 0.3 * (j - 1);
      V.row(3 * i + j) << (1 + t * std::cos(u / 2)) * std::cos(u),
          (1 + t * std::cos(u / 2)) * std::sin(u), t * std::sin(u / 2);
    }
  V.row(3 * nu) << 5, 0, 0;
  V.row(3 * nu + 1) << 6, 0, 0;
  V.row(3 * nu + 2) << 6, 1, 0;
  V.row(3 * nu + 3) << 5, 1, 0;
  FaceMatrix F(4 * nu + 2, 3);
  int f = 0;
  for (int i = 0; i < nu; ++i)
    for (int j = 0; j < 2; ++j) {
      const int a = 3 * i + j, b = 3 * i + j + 1;
      // The next column; across the seam (i = nu - 1) the strip comes back upside down.
      const int c = i + 1 < nu ? 3 * (i + 1) + j : 2 - j;
      const int d = i + 1 < nu ? 3 * (i + 1) + j + 1 : 1 - j;
      F.row(f++) << a, c, d;
      F.row(f++) << a, d, b;
    }
  F.row(f++) << 3 * nu, 3 * nu + 1, 3 * nu + 2;
  F.row(f++) << 3 * nu, 3 * nu + 2, 3 * nu + 3;
  const Mesh mesh(V, F);
  const OrientationResult r = orient_mesh(mesh);
  EXPECT_EQ(r.patches, 2);
  EXPECT_EQ(r.nonorientable_patches, 1);
  EXPECT_EQ(r.vertices_undetermined, 3 * nu);
  for (int v = 0; v < 3 * nu; ++v) EXPECT_TRUE(r.sign_undetermined[static_cast<size_t>(v)]);
  for (int v = 3 * nu; v < 3 * nu + 4; ++v)
    EXPECT_FALSE(r.sign_undetermined[static_cast<size_t>(v)]);
  // Consistent everywhere but along one seam of the strip (one edge per row: 2 edges).
  EXPECT_EQ(r.mesh.num_inconsistent_edges(), 2);
  const auto w = orientation_warnings(r);
  ASSERT_FALSE(w.empty());
  EXPECT_NE(w.back().find("sign_undetermined"), std::string::npos);
}

TEST(Orientation, NonManifoldEdgeVerticesAreUndetermined) {
  // Three triangles on one edge (a fin).
  VertexMatrix V(5, 3);
  V << 0, 0, 0, 1, 0, 0, 0.5, 1, 0, 0.5, -1, 0, 0.5, 0, 1;
  FaceMatrix F(3, 3);
  F << 0, 1, 2, 1, 0, 3, 1, 0, 4;
  const OrientationResult r = orient_mesh(Mesh(V, F));
  EXPECT_EQ(r.patches, 3);
  EXPECT_TRUE(r.sign_undetermined[0] && r.sign_undetermined[1]);
  EXPECT_FALSE(r.sign_undetermined[2] || r.sign_undetermined[3] || r.sign_undetermined[4]);
}

// Mesh::reorient_faces updates the adjacency in place: the same mesh as one built from the
// reoriented faces, edge by edge.
void expect_same_mesh(const Mesh& a, const Mesh& b) {
  ASSERT_EQ(a.faces(), b.faces());
  EXPECT_EQ(a.vertices(), b.vertices());
  EXPECT_EQ(a.num_edges(), b.num_edges());
  EXPECT_EQ(a.num_boundary_edges(), b.num_boundary_edges());
  EXPECT_EQ(a.num_nonmanifold_edges(), b.num_nonmanifold_edges());
  EXPECT_EQ(a.num_inconsistent_edges(), b.num_inconsistent_edges());
  EXPECT_EQ(a.mean_edge_length(), b.mean_edge_length());
  for (int f = 0; f < a.num_faces(); ++f)
    for (int k = 0; k < 3; ++k) {
      EXPECT_EQ(a.face_neighbor(f, k), b.face_neighbor(f, k)) << f << " " << k;
      EXPECT_EQ(a.is_boundary_edge(f, k), b.is_boundary_edge(f, k));
      EXPECT_EQ(a.is_nonmanifold_edge(f, k), b.is_nonmanifold_edge(f, k));
    }
  for (int v = 0; v < a.num_vertices(); ++v) {
    const auto x = a.vertex_faces(v), y = b.vertex_faces(v);
    EXPECT_TRUE(std::equal(x.begin(), x.end(), y.begin(), y.end()));
  }
}

TEST(Orientation, InPlaceReorientationEqualsARebuiltMesh) {
  const Mesh t = torus(24, 12);
  int flipped = 0;
  // Flipped faces, rotated rows, and a cut (an open patch) so that boundary edges move too.
  FaceMatrix G = flip_some(t.faces(), 0.3, 11, flipped);
  for (int f = 0; f < G.rows(); f += 5) {
    const int a = G(f, 0), b = G(f, 1), c = G(f, 2);
    G.row(f) << b, c, a;
  }
  const FaceMatrix open = G.topRows(G.rows() - 40);
  for (const FaceMatrix& faces : {G, open}) {
    const OrientationResult r = orient_mesh(Mesh(t.vertices(), faces));
    expect_same_mesh(r.mesh, Mesh(r.mesh.vertices(), r.mesh.faces()));
    EXPECT_TRUE(r.mesh.is_consistently_oriented());
    const OrientationResult copy = orient_mesh(static_cast<const Mesh&>(Mesh(t.vertices(), faces)));
    expect_same_mesh(copy.mesh, r.mesh);
    EXPECT_EQ(copy.faces_flipped, r.faces_flipped);
    EXPECT_EQ(copy.sign_undetermined, r.sign_undetermined);
  }
  // A whole band of faces reversed (a closed loop of inconsistent edges either side of it).
  FaceMatrix seam = t.faces();
  for (int f = 0; f < 2 * 24; ++f) std::swap(seam(f, 1), seam(f, 2));
  Mesh twisted(t.vertices(), seam);
  const OrientationResult s = orient_mesh(std::move(twisted));
  expect_same_mesh(s.mesh, Mesh(s.mesh.vertices(), s.mesh.faces()));
}

// The usual input, already consistently oriented outward with every row starting at its smallest
// index: moved in, nothing copied (the same arrays), nothing changed, the same result as the copy.
TEST(Orientation, AlreadyOrientedMeshIsNotCopied) {
  const Mesh t = torus(24, 12);
  FaceMatrix rows = t.faces();
  for (int f = 0; f < rows.rows(); ++f) {  // smallest index first, same orientation
    int k = 0;
    for (int j = 1; j < 3; ++j)
      if (rows(f, j) < rows(f, k)) k = j;
    const int a = rows(f, k), b = rows(f, (k + 1) % 3), c = rows(f, (k + 2) % 3);
    rows.row(f) << a, b, c;
  }
  Mesh m(t.vertices(), rows);
  const double* vertices = m.vertices().data();
  const int* faces = m.faces().data();
  const OrientationResult copy = orient_mesh(static_cast<const Mesh&>(m));
  const OrientationResult r = orient_mesh(std::move(m));
  EXPECT_EQ(r.mesh.vertices().data(), vertices);
  EXPECT_EQ(r.mesh.faces().data(), faces);
  EXPECT_EQ(r.mesh.faces(), rows);
  EXPECT_EQ(r.faces_flipped, 0);
  EXPECT_EQ(r.vertices_undetermined, 0);
  EXPECT_TRUE(orientation_warnings(r).empty());
  expect_same_mesh(r.mesh, copy.mesh);
  EXPECT_EQ(r.sign_undetermined, copy.sign_undetermined);
}

}  // namespace
}  // namespace curvbench
