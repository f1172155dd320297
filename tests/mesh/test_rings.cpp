// k-ring and half-ring neighbourhoods against the paper's Table 2 and docs/algorithms.md §1.1.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <set>
#include <vector>

#include "core/errors.h"
#include "mesh/rings.h"

namespace curvbench {
namespace {

// Regular valence-6 lattice on an (n+1) x (n+1) grid: every square (i,j) split along the same
// diagonal, so every interior vertex has valence 6.
Mesh regular_lattice(int n) {
  VertexMatrix V((n + 1) * (n + 1), 3);
  for (int j = 0; j <= n; ++j)
    for (int i = 0; i <= n; ++i) V.row(j * (n + 1) + i) << i + 0.5 * j, 0.866 * j, 0.0;
  FaceMatrix F(2 * n * n, 3);
  int f = 0;
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i) {
      const int a = j * (n + 1) + i, b = a + 1, c = a + n + 1, d = c + 1;
      F.row(f++) << a, b, c;
      F.row(f++) << b, d, c;
    }
  return Mesh(V, F);
}

// 4-8 ("union jack") mesh on an N x N grid: square (i,j) split along (i,j)-(i+1,j+1) when i+j
// is even, else along (i+1,j)-(i,j+1) (docs/algorithms.md §10.2).
Mesh four_eight(int n) {
  VertexMatrix V((n + 1) * (n + 1), 3);
  for (int j = 0; j <= n; ++j)
    for (int i = 0; i <= n; ++i) V.row(j * (n + 1) + i) << i, j, 0.0;
  FaceMatrix F(2 * n * n, 3);
  int f = 0;
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i) {
      const int a = j * (n + 1) + i, b = a + 1, c = a + n + 1, d = c + 1;
      if ((i + j) % 2 == 0) {
        F.row(f++) << a, b, d;
        F.row(f++) << a, d, c;
      } else {
        F.row(f++) << a, b, c;
        F.row(f++) << b, d, c;
      }
    }
  return Mesh(V, F);
}

// Closed regular valence-6 torus-topology mesh (periodic lattice), n x n.
Mesh periodic_lattice(int n) {
  VertexMatrix V(n * n, 3);
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i) V.row(j * n + i) << i, j, 0.0;
  FaceMatrix F(2 * n * n, 3);
  int f = 0;
  auto id = [n](int i, int j) { return ((j + n) % n) * n + (i + n) % n; };
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i) {
      F.row(f++) << id(i, j), id(i + 1, j), id(i, j + 1);
      F.row(f++) << id(i + 1, j), id(i + 1, j + 1), id(i, j + 1);
    }
  return Mesh(V, F);
}

std::vector<int> ring_counts_with_centre(const Mesh& mesh, int v) {
  RingCollector rc(mesh);
  std::vector<int> counts;
  for (double r : {1.0, 1.5, 2.0, 2.5, 3.0, 3.5}) {
    rc.collect(v, r);
    counts.push_back(static_cast<int>(rc.neighbours().size()) + 1);
  }
  return counts;
}

TEST(Rings, PaperTable2RegularValence6) {
  const Mesh mesh = regular_lattice(14);
  const int centre = 7 * 15 + 7;
  EXPECT_EQ(ring_counts_with_centre(mesh, centre), (std::vector<int>{7, 13, 19, 31, 37, 55}));
  // Table 2: about twice the number of coefficients 3, 6, 10, 15, 21, 28 of degrees 1..6.
  EXPECT_EQ(num_coefficients(1), 3);
  EXPECT_EQ(num_coefficients(6), 28);
  for (int d = 1; d <= 6; ++d) EXPECT_DOUBLE_EQ(default_ring(d), 0.5 * (d + 1));
}

TEST(Rings, FourEightValence8And4) {
  const Mesh mesh = four_eight(16);
  const int v8 = 8 * 17 + 8;  // i+j even
  const int v4 = 8 * 17 + 7;  // i+j odd
  EXPECT_EQ(mesh.vertex_faces(v8).size(), 8u);
  EXPECT_EQ(mesh.vertex_faces(v4).size(), 4u);
  EXPECT_EQ(ring_counts_with_centre(mesh, v8), (std::vector<int>{9, 13, 25, 33, 49, 61}));
  EXPECT_EQ(ring_counts_with_centre(mesh, v4), (std::vector<int>{5, 9, 21, 25, 45, 53}));
}

TEST(Rings, BoundaryVertices) {
  const Mesh lattice = regular_lattice(14);
  const int mid_edge = 7;  // (7, 0) on the bottom row
  ASSERT_TRUE(lattice.is_boundary_vertex(mid_edge));
  EXPECT_EQ(ring_counts_with_centre(lattice, mid_edge), (std::vector<int>{5, 8, 12, 18, 22, 31}));

  const Mesh fe = four_eight(16);
  EXPECT_EQ(ring_counts_with_centre(fe, 8), (std::vector<int>{6, 9, 15, 19, 28, 35}));  // even
  EXPECT_EQ(ring_counts_with_centre(fe, 7), (std::vector<int>{4, 6, 13, 16, 26, 30}));  // odd
}

TEST(Rings, ClosedMeshRingsAreSymmetricAndSaturate) {
  const Mesh mesh = periodic_lattice(12);
  ASSERT_FALSE(mesh.has_boundary());
  EXPECT_EQ(mesh.euler_characteristic(), 0);
  // Every vertex of a periodic lattice sees the same counts.
  const auto c0 = ring_counts_with_centre(mesh, 0);
  EXPECT_EQ(c0, (std::vector<int>{7, 13, 19, 31, 37, 55}));
  EXPECT_EQ(ring_counts_with_centre(mesh, 77), c0);
  // Large rings saturate at the whole mesh and never list the centre or a duplicate.
  RingCollector rc(mesh);
  rc.collect(5, 20.0);
  std::set<int> unique(rc.neighbours().begin(), rc.neighbours().end());
  EXPECT_EQ(unique.size(), rc.neighbours().size());
  EXPECT_EQ(unique.count(5), 0u);
  EXPECT_EQ(static_cast<int>(rc.neighbours().size()), mesh.num_vertices() - 1);
  EXPECT_EQ(static_cast<int>(rc.faces().size()), mesh.num_faces());
}

TEST(Rings, MatchesSetDefinition) {
  // Brute-force the set definition of §1.1 and compare on every vertex of a 4-8 mesh.
  const Mesh mesh = four_eight(6);
  auto verts_of = [&](const std::set<int>& faces) {
    std::set<int> vs;
    for (int f : faces)
      for (int k = 0; k < 3; ++k) vs.insert(mesh.face_vertex(f, k));
    return vs;
  };
  auto shares_edge = [&](int f, int g) {
    int shared = 0;
    for (int a = 0; a < 3; ++a)
      for (int b = 0; b < 3; ++b) shared += mesh.face_vertex(f, a) == mesh.face_vertex(g, b);
    return shared == 2;
  };
  RingCollector rc(mesh);
  for (int v = 0; v < mesh.num_vertices(); ++v) {
    std::set<int> Vk{v}, Fk;
    for (int k = 1; k <= 3; ++k) {
      for (int w : Vk)
        for (int f : mesh.vertex_faces(w)) Fk.insert(f);
      Vk = verts_of(Fk);
      std::set<int> Fh = Fk;
      for (int g = 0; g < mesh.num_faces(); ++g)
        for (int f : Fk)
          if (shares_edge(f, g)) Fh.insert(g);
      for (const auto& [ring, faces] : {std::pair<double, std::set<int>>{k, Fk}, {k + 0.5, Fh}}) {
        rc.collect(v, ring);
        std::set<int> got_f(rc.faces().begin(), rc.faces().end());
        std::set<int> got_v(rc.neighbours().begin(), rc.neighbours().end());
        got_v.insert(v);
        EXPECT_EQ(got_f, faces) << "vertex " << v << " ring " << ring;
        EXPECT_EQ(got_v, verts_of(faces)) << "vertex " << v << " ring " << ring;
      }
    }
  }
}

TEST(Rings, IntegerCollectionMatchesCollect) {
  // collect_integer skips the half steps: the same V_k and F_k as collect(v, k) (4-8 mesh with
  // a boundary, valences 4 and 8), rings up to beyond the mesh; k < 1 is rejected.
  const Mesh mesh = four_eight(5);
  RingCollector a(mesh), b(mesh);
  for (int v = 0; v < mesh.num_vertices(); ++v)
    for (int k = 1; k <= 6; ++k) {
      a.collect(v, k);
      b.collect_integer(v, k);
      EXPECT_EQ(std::set<int>(a.faces().begin(), a.faces().end()),
                std::set<int>(b.faces().begin(), b.faces().end()))
          << "vertex " << v << " ring " << k;
      EXPECT_EQ(std::set<int>(a.neighbours().begin(), a.neighbours().end()),
                std::set<int>(b.neighbours().begin(), b.neighbours().end()))
          << "vertex " << v << " ring " << k;
      EXPECT_EQ(b.ring(), k);
    }
  EXPECT_THROW(b.collect_integer(0, 0), UsageError);
}

TEST(Rings, AdaptiveGrowthReachesMinimum) {
  const Mesh mesh = four_eight(16);
  const int v4 = 8 * 17 + 7;
  RingCollector rc(mesh);
  // d = 2 needs 9 neighbours: the valence-4 1.5-ring has 8, so it grows to the 2-ring (notes §1.2).
  EXPECT_EQ(min_neighbours(2), 9);
  EXPECT_DOUBLE_EQ(rc.collect_at_least(v4, 1.5, min_neighbours(2), 3.0), 2.0);
  EXPECT_EQ(rc.neighbours().size(), 20u);
  // min_neighbours(d) = round(1.5 n(d)) = 5, 9, 15, 23, 32, 42.
  const int expected[] = {5, 9, 15, 23, 32, 42};
  for (int d = 1; d <= 6; ++d) EXPECT_EQ(min_neighbours(d), expected[d - 1]);
  // Growth stops at the cap and when the mesh is exhausted.
  EXPECT_DOUBLE_EQ(rc.collect_at_least(v4, 1.0, 100000, 2.5), 2.5);
  const Mesh tiny = four_eight(2);
  RingCollector rt(tiny);
  rt.collect_at_least(0, 1.0, 1000, 50.0);
  EXPECT_EQ(static_cast<int>(rt.neighbours().size()), tiny.num_vertices() - 1);
  EXPECT_LT(rt.ring(), 50.0);
}

TEST(Rings, RejectsInvalidRingSizes) {
  const Mesh mesh = four_eight(2);
  RingCollector rc(mesh);
  EXPECT_THROW(rc.collect(0, 0.5), UsageError);
  EXPECT_THROW(rc.collect(0, 1.25), UsageError);
  EXPECT_THROW(rc.collect(0, -1.0), UsageError);
  EXPECT_THROW(rc.collect(0, std::nan("")), UsageError);
  EXPECT_THROW(rc.collect(0, 2e6), UsageError);  // above the largest ring, 1e6
  EXPECT_NO_THROW(rc.collect(0, 1e6));            // saturates at once on this small mesh
  EXPECT_EQ(rc.ring(), 1e6);
}

}  // namespace
}  // namespace curvbench
