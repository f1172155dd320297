// Marching cubes (meshgen/marching_cubes.h): case tables, closed manifold output on sphere and
// random fields, the asymptotic decider, orientation, degenerate samples, determinism, errors.
#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <bit>
#include <cmath>
#include <cstdint>
#include <limits>
#include <map>
#include <numbers>
#include <random>
#include <utility>
#include <vector>

#include "core/errors.h"
#include "mesh/mesh.h"
#include "meshgen/marching_cubes.h"
#include "meshgen/marching_cubes_tables.h"
#include "tests/meshgen/isosurface_test_util.h"

namespace curvbench {
namespace {

using testing::count_sign_changing_edges;
using testing::expect_closed_oriented_manifold;
using testing::num_components;

Vec3 corner_point(int c) {
  return Vec3(mc::kCornerOffset[c][0], mc::kCornerOffset[c][1], mc::kCornerOffset[c][2]);
}
Vec3 edge_midpoint(int e) {
  return 0.5 * (corner_point(mc::kEdgeCorner[e][0]) + corner_point(mc::kEdgeCorner[e][1]));
}
bool edges_share_face(int a, int b) {
  for (const auto& fc : mc::kFaceCorner) {
    auto on = [&fc](int e) {
      int hits = 0;
      for (int c : fc) hits += (c == mc::kEdgeCorner[e][0] || c == mc::kEdgeCorner[e][1]) ? 1 : 0;
      return hits == 2;
    };
    if (on(a) && on(b)) return true;
  }
  return false;
}

TEST(MatlabLinspace, ValuesAndEndpoints) {
  const std::vector<double> v = matlab_linspace(-1.5, 1.5, 5);
  ASSERT_EQ(v.size(), 5u);
  EXPECT_EQ(v[0], -1.5);
  EXPECT_EQ(v[1], -0.75);
  EXPECT_EQ(v[2], 0.0);
  EXPECT_EQ(v[3], 0.75);
  EXPECT_EQ(v[4], 1.5);
  const std::vector<double> w = matlab_linspace(-1.5, 1.5, 256);
  EXPECT_EQ(w.front(), -1.5);
  EXPECT_EQ(w.back(), 1.5);
  for (int i = 0; i + 1 < 256; ++i) {
    EXPECT_EQ(w[i], -1.5 + (i * 3.0) / 255);
    EXPECT_LT(w[i], w[i + 1]);
  }
  EXPECT_THROW(matlab_linspace(0.0, 1.0, 1), UsageError);
}

// Per-cell invariant that makes neighbouring cells glue into a closed oriented manifold: a pair
// of cut edges on one cube face is joined once (the face segment, shared with the neighbour);
// any other pair is joined in both directions (an interior chord) or not at all.
TEST(MarchingCubesTables, EveryCaseGluesAndCoversItsCutEdges) {
  const mc::CaseTables& t = mc::case_tables();
  int entries = 0, centered_entries = 0;
  for (int c = 0; c < 256; ++c) {
    const int amb = t.ambiguous_faces(c);
    for (int d = 0; d < 64; ++d) {
      if ((d & ~amb) != 0) continue;
      ++entries;
      std::map<std::pair<int, int>, int> directed;  // edge 12 = the polygon's extra vertex
      std::vector<int> used(13, 0);
      const auto tris = t.triangles(c, d);
      ASSERT_EQ(tris.size() % 3, 0u);
      for (size_t i = 0; i < tris.size(); i += 3) {
        for (int k = 0; k < 3; ++k) {
          ++directed[{tris[i + k], tris[i + (k + 1) % 3]}];
          ++used[tris[i + k]];
        }
      }
      const auto cen = t.centered_polygons(c, d);
      if (!cen.empty()) {
        ++centered_entries;
        EXPECT_GE(std::popcount(static_cast<unsigned>(amb)), 2) << "case " << c;
      }
      int extra = 0;
      for (size_t r = 0; r < cen.size(); r += cen[r] + 1) {
        const int len = cen[r];
        for (int m = 1; m <= len; ++m) {
          const int a = cen[r + m], b = cen[r + 1 + m % len];
          ++directed[{a, b}];
          ++directed[{b, 12 + extra}];
          ++directed[{12 + extra, a}];
          ++used[a];
        }
        ++extra;
      }
      for (int e = 0; e < 12; ++e) {
        const bool cut = ((c >> mc::kEdgeCorner[e][0]) & 1) != ((c >> mc::kEdgeCorner[e][1]) & 1);
        EXPECT_EQ(used[e] > 0, cut) << "case " << c << " edge " << e;
      }
      for (const auto& [ab, count] : directed) {
        const auto [a, b] = ab;
        const auto it = directed.find({b, a});
        const int back = it == directed.end() ? 0 : it->second;
        if (a < 12 && b < 12 && edges_share_face(a, b)) {
          EXPECT_EQ(count + back, 1)
              << "case " << c << " decisions " << d << " face pair " << a << "-" << b;
        } else {
          EXPECT_EQ(count, 1) << "case " << c << " chord " << a << "-" << b;
          EXPECT_EQ(back, 1) << "case " << c << " chord " << a << "-" << b;
        }
      }
    }
  }
  EXPECT_EQ(entries, 656);  // sum over the 256 cases of 2^(number of ambiguous faces)
  EXPECT_GT(centered_entries, 0);
}

TEST(MarchingCubesTables, AmbiguousFacesAndOrientation) {
  const mc::CaseTables& t = mc::case_tables();
  EXPECT_EQ(t.ambiguous_faces(0), 0);
  EXPECT_EQ(t.ambiguous_faces(255), 0);
  EXPECT_EQ(t.ambiguous_faces((1 << 0) | (1 << 2)), 1);  // corners 0, 2 diagonal on face -z
  EXPECT_EQ(t.ambiguous_faces((1 << 0) | (1 << 6)), 0);  // body diagonal: no face ambiguous
  EXPECT_EQ(t.ambiguous_faces(0b10100101), 63);          // checkerboard: all six faces
  EXPECT_TRUE(t.triangles(0, 0).empty());
  EXPECT_TRUE(t.triangles(255, 0).empty());
  // One inside corner: one triangle facing away from it; one outside corner: facing it.
  const Vec3 center(0.5, 0.5, 0.5);
  for (int c = 0; c < 8; ++c) {
    for (const bool inside_corner : {true, false}) {
      const int cube_case = inside_corner ? (1 << c) : (255 ^ (1 << c));
      const auto tri = t.triangles(cube_case, 0);
      ASSERT_EQ(tri.size(), 3u);
      const Vec3 n = (edge_midpoint(tri[1]) - edge_midpoint(tri[0]))
                         .cross(edge_midpoint(tri[2]) - edge_midpoint(tri[0]));
      const Vec3 away = center - corner_point(c);
      EXPECT_GT(inside_corner ? n.dot(away) : -n.dot(away), 0.0) << "corner " << c;
    }
  }
}

double sphere_sdf(double x, double y, double z) {
  return std::sqrt(x * x + y * y + z * z) - 0.7;
}

TEST(MarchingCubes, SphereIsClosedGenusZeroAndOutward) {
  for (const int n : {9, 17, 24, 40}) {
    SCOPED_TRACE(n);
    const std::vector<double> ax = matlab_linspace(-1.0, 1.0, n);
    const IsosurfaceMesh iso = marching_cubes(ax, ax, ax, sphere_sdf);
    EXPECT_EQ(iso.center_vertices, 0);
    EXPECT_EQ(iso.vertices.rows(), count_sign_changing_edges(ax, sphere_sdf));
    const Mesh m(iso.vertices, iso.faces);
    expect_closed_oriented_manifold(m);
    EXPECT_EQ(m.euler_characteristic(), 2);
    EXPECT_EQ(num_components(m), 1);
    EXPECT_EQ(m.num_faces(), 2 * m.num_vertices() - 4);
    // Outward: positive volume close to 4/3 pi r^3 (second-order deficit), outward normals.
    const double h = 2.0 / (n - 1);
    const double exact = 4.0 / 3.0 * std::numbers::pi * 0.343;
    EXPECT_GT(m.signed_volume(), 0.0);
    EXPECT_LT(std::abs(m.signed_volume() - exact) / exact, 2.0 * h * h);
    const VertexMatrix N = m.area_weighted_normals();
    for (int v = 0; v < m.num_vertices(); ++v) {
      const Vec3 p = m.position(v);
      EXPECT_GT(N.row(v).dot(p.normalized()), 0.9);
      // Linear interpolation of the distance function (second derivative <= 1/|p| along an edge,
      // |p| >= 0.7 - h): |f(vertex)| <= h^2 / (8 (0.7 - h)).
      EXPECT_LT(std::abs(p.norm() - 0.7), h * h / (8.0 * (0.7 - h)));
    }
  }
}

TEST(MarchingCubes, FacesFaceIncreasingF) {
  const std::vector<double> ax = matlab_linspace(-1.0, 1.0, 17);
  const IsosurfaceMesh out = marching_cubes(ax, ax, ax, sphere_sdf);
  const IsosurfaceMesh in =
      marching_cubes(ax, ax, ax, [](double x, double y, double z) { return -sphere_sdf(x, y, z); });
  // Same sign-changing edges (no sample is exactly 0), same vertices; orientation reversed.
  EXPECT_EQ(in.vertices, out.vertices);
  const Mesh mi(in.vertices, in.faces), mo(out.vertices, out.faces);
  expect_closed_oriented_manifold(mi);
  EXPECT_NEAR(mi.signed_volume(), -mo.signed_volume(), 1e-12);
  EXPECT_LT(mi.signed_volume(), 0.0);
}

// One ambiguous face (z = 1, i, j in {1, 2}) with inside samples a at (1,1,1), (2,2,1) and outside
// samples b at (2,1,1), (1,2,1); everything else +1. The bilinear saddle value decides whether
// the two inside samples are joined by a tube (one sphere) or separate (two spheres).
IsosurfaceMesh ambiguous_face_grid(double inside_value, double outside_value) {
  const std::vector<double> ax = matlab_linspace(0.0, 3.0, 4);
  auto f = [=](double x, double y, double z) {
    const int i = static_cast<int>(std::lround(x)), j = static_cast<int>(std::lround(y)),
              k = static_cast<int>(std::lround(z));
    if (k != 1 || i < 1 || i > 2 || j < 1 || j > 2) return 1.0;
    return i == j ? inside_value : outside_value;
  };
  return marching_cubes(ax, ax, ax, f);
}

TEST(MarchingCubes, AsymptoticDeciderOnAmbiguousFace) {
  struct Case {
    double a, b;
    int components;
  };
  // saddle value (b^2 - a^2)/(2b + 2a) with a, b the magnitudes: < 0 joins the inside samples.
  for (const Case& c : {Case{-1.0, 0.1, 1}, Case{-0.1, 1.0, 2}, Case{-0.5, 0.5, 2}}) {
    SCOPED_TRACE(c.a);
    const IsosurfaceMesh iso = ambiguous_face_grid(c.a, c.b);
    EXPECT_EQ(iso.ambiguous_faces, 1);
    EXPECT_EQ(iso.center_vertices, 0);
    const Mesh m(iso.vertices, iso.faces);
    expect_closed_oriented_manifold(m);
    EXPECT_EQ(num_components(m), c.components);
    EXPECT_EQ(m.euler_characteristic(), 2 * c.components);
    EXPECT_GT(m.signed_volume(), 0.0);
  }
}

// Random samples on an n^3 grid with spacing 1, +1 on the grid boundary (so the level set is
// closed): continuous U(-1/2, 1/2) or bimodal values. Cell corners get independent signs, so all
// cases, many ambiguous faces and the extra-vertex polygons occur.
struct RandomField {
  int n;
  std::vector<double> values;
  RandomField(std::mt19937_64& engine, int n_, bool continuous) : n(n_), values(n_ * n_ * n_) {
    for (int k = 0; k < n; ++k) {
      for (int j = 0; j < n; ++j) {
        for (int i = 0; i < n; ++i) {
          const bool boundary =
              i == 0 || j == 0 || k == 0 || i == n - 1 || j == n - 1 || k == n - 1;
          const double u = static_cast<double>(engine() >> 11) * 0x1p-53;
          values[(static_cast<size_t>(k) * n + j) * n + i] =
              boundary ? 1.0 : (continuous ? u - 0.5 : (u < 0.5 ? -1.0 - u : u));
        }
      }
    }
  }
  std::vector<double> axis() const { return matlab_linspace(0.0, n - 1.0, n); }
  double operator()(double x, double y, double z) const {
    return values[(static_cast<size_t>(std::lround(z)) * n + std::lround(y)) * n + std::lround(x)];
  }
};

// The result must always be a closed oriented 2-manifold.
TEST(MarchingCubes, RandomFieldsGiveClosedManifolds) {
  std::mt19937_64 engine(20090101);
  int ambiguous = 0, centers = 0;
  for (int trial = 0; trial < 60; ++trial) {
    SCOPED_TRACE(trial);
    const RandomField field(engine, 6 + trial % 4, trial % 2 == 1);
    const std::vector<double> ax = field.axis();
    const IsosurfaceMesh iso = marching_cubes(ax, ax, ax, field);
    ambiguous += iso.ambiguous_faces;
    centers += iso.center_vertices;
    EXPECT_EQ(iso.vertices.rows(), count_sign_changing_edges(ax, field) + iso.center_vertices);
    const Mesh m(iso.vertices, iso.faces);
    expect_closed_oriented_manifold(m);
    EXPECT_EQ(m.euler_characteristic() % 2, 0);
  }
  EXPECT_GT(ambiguous, 1000);
  EXPECT_GT(centers, 0);
}

// Samples exactly on the level set (f = 0 counts as outside) with two inside neighbours put two
// vertices on one grid point: zero-length edges and zero-area faces, but the mesh stays a closed
// manifold and nothing divides by a zero length.
TEST(MarchingCubes, ExactZeroSamplesGiveCoincidentVerticesButClosedMesh) {
  const std::vector<double> ax = matlab_linspace(-1.0, 1.0, 9);  // spacing 0.25, exact
  auto f = [](double x, double y, double z) {
    return std::abs(x) + std::abs(y) + std::abs(z) - 0.5;  // octahedron |x|_1 = 0.5
  };
  EXPECT_EQ(f(0.25, 0.25, 0.0), 0.0);
  const IsosurfaceMesh iso = marching_cubes(ax, ax, ax, f);
  const Mesh m(iso.vertices, iso.faces);
  expect_closed_oriented_manifold(m);
  EXPECT_EQ(m.euler_characteristic(), 2);
  int zero_edges = 0;
  for (int g = 0; g < m.num_faces(); ++g)
    for (int k = 0; k < 3; ++k)
      if (m.position(m.face_vertex(g, k)) == m.position(m.face_vertex(g, (k + 1) % 3)))
        ++zero_edges;
  EXPECT_GT(zero_edges, 0);
  EXPECT_TRUE(std::isfinite(m.mean_edge_length()));
  EXPECT_TRUE(m.area_weighted_normals().allFinite());
  EXPECT_NEAR(m.signed_volume(), 4.0 / 3.0 * 0.125, 1e-12);  // exact: the octahedron itself
}

TEST(MarchingCubes, Deterministic) {
  std::mt19937_64 engine(7);
  const RandomField field(engine, 12, true);
  const std::vector<double> ax = field.axis();
  const IsosurfaceMesh a = marching_cubes(ax, ax, ax, field), b = marching_cubes(ax, ax, ax, field);
  EXPECT_GT(a.ambiguous_faces, 0);
  EXPECT_EQ(a.vertices, b.vertices);
  EXPECT_EQ(a.faces, b.faces);
  EXPECT_EQ(a.ambiguous_faces, b.ambiguous_faces);
  EXPECT_EQ(a.center_vertices, b.center_vertices);
}

TEST(MarchingCubes, ErrorPaths) {
  const std::vector<double> ax = matlab_linspace(-1.0, 1.0, 5);
  const std::vector<double> one = {0.0};
  const std::vector<double> flat = {0.0, 1.0, 1.0};
  EXPECT_THROW(marching_cubes(one, ax, ax, sphere_sdf), UsageError);
  EXPECT_THROW(marching_cubes(ax, flat, ax, sphere_sdf), UsageError);
  auto nan_field = [](double x, double, double) {
    return x > 0.4 ? std::numeric_limits<double>::quiet_NaN() : 1.0;
  };
  EXPECT_THROW(marching_cubes(ax, ax, ax, nan_field), InputError);
  // No sign change: empty output, not an error.
  const IsosurfaceMesh empty =
      marching_cubes(ax, ax, ax, [](double, double, double) { return 1.0; });
  EXPECT_EQ(empty.vertices.rows(), 0);
  EXPECT_EQ(empty.faces.rows(), 0);
}

}  // namespace
}  // namespace curvbench
