// Torus isosurface meshes (meshgen/torus_isosurface.h): paper Table 4 reproduced exactly
// (docs/claims.md A2-A4), topology, orientation, projection, determinism, errors.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <numbers>
#include <vector>

#include "core/errors.h"
#include "meshgen/marching_cubes.h"
#include "meshgen/torus_isosurface.h"
#include "tests/meshgen/identical_matrices.h"
#include "tests/meshgen/isosurface_test_util.h"

namespace curvbench {
namespace {

using testing::count_sign_changing_edges;
using testing::expect_closed_oriented_manifold;
using testing::num_components;

// n = 256 takes about a second per mesh in Release; optimised builds only.
#ifdef NDEBUG
constexpr int kMaxGridPoints = 256;
#else
constexpr int kMaxGridPoints = 128;
#endif

// Paper Table 4 as printed: vertices, "average edge length" (half the true mean, A4), L2, Linf,
// each with the unit of its last printed digit, and the printed convergence rates.
struct PaperRow {
  int n, vertices;
  double half_edge, half_edge_unit;
  double l2, l2_unit, linf, linf_unit;
  double rate_l2, rate_linf;  // vs the previous row; 0 for the first
};
constexpr PaperRow kTable4[] = {
    {16, 320, 0.11, 0.01, 3.60e-3, 1e-5, 9.30e-3, 1e-5, 0.0, 0.0},
    {32, 1760, 0.048, 0.001, 1.12e-3, 1e-5, 3.47e-3, 1e-5, 1.69, 1.42},
    {64, 7320, 0.023, 0.001, 2.59e-4, 1e-6, 9.03e-4, 1e-6, 2.11, 1.94},
    {128, 31136, 0.011, 0.001, 6.71e-5, 1e-7, 2.25e-4, 1e-6, 1.95, 2.00},
    {256, 122464, 0.0057, 0.0001, 1.65e-5, 1e-7, 5.70e-5, 1e-7, 2.03, 1.98},
};

// x printed to the paper's digits gives `printed`: |x - printed| <= half a unit of the last digit.
void expect_prints_as(double x, double printed, double unit, const char* what) {
  EXPECT_LE(std::abs(x - printed), 0.5 * unit * (1.0 + 1e-9))
      << what << " = " << x << ", paper prints " << printed;
}

const GeneratedMesh& cached(int n, bool project) {
  static std::map<std::pair<int, bool>, GeneratedMesh> cache;
  auto it = cache.find({n, project});
  if (it == cache.end())
    it = cache.emplace(std::pair{n, project}, torus_isosurface(n, project)).first;
  return it->second;
}

TEST(TorusIsosurface, GridPointsPerLevel) {
  EXPECT_EQ(isosurface_grid_points(1), 16);
  EXPECT_EQ(isosurface_grid_points(2), 32);
  EXPECT_EQ(isosurface_grid_points(3), 64);
  EXPECT_EQ(isosurface_grid_points(4), 128);
  EXPECT_EQ(isosurface_grid_points(5), 256);
  EXPECT_THROW(isosurface_grid_points(0), UsageError);
  EXPECT_THROW(isosurface_grid_points(9), UsageError);
}

TEST(TorusIsosurface, SignedDistance) {
  EXPECT_DOUBLE_EQ(torus_signed_distance(0.0, 0.0, 0.0), 0.7);
  EXPECT_DOUBLE_EQ(torus_signed_distance(1.0, 0.0, 0.0), -0.3);
  EXPECT_DOUBLE_EQ(torus_signed_distance(0.0, -1.0, 0.5), 0.2);
  EXPECT_DOUBLE_EQ(torus_signed_distance(2.0, 0.0, 0.0), 0.7);
  EXPECT_NEAR(torus_signed_distance(0.6, 0.8, -0.3), 0.0, 1e-15);
}

// A2, A3, A4 and the printed convergence rates.
TEST(TorusIsosurface, Table4MatchesPaper) {
  const std::vector<Table4Row> rows = table4(kMaxGridPoints);
  ASSERT_EQ(rows.size(), kMaxGridPoints == 256 ? 5u : 4u);
  for (size_t i = 0; i < rows.size(); ++i) {
    const PaperRow& p = kTable4[i];
    const Table4Row& r = rows[i];
    SCOPED_TRACE(p.n);
    EXPECT_EQ(r.grid_points, p.n);
    EXPECT_EQ(r.vertices, p.vertices);                                       // A2
    expect_prints_as(r.rms_error, p.l2, p.l2_unit, "L2");                    // A3
    expect_prints_as(r.max_error, p.linf, p.linf_unit, "Linf");              // A3
    expect_prints_as(r.mean_edge_length / 2, p.half_edge, p.half_edge_unit,  // A4
                     "mean edge length / 2");
    if (i > 0) {
      const double rate_l2 = std::log2(rows[i - 1].rms_error / r.rms_error);
      const double rate_linf = std::log2(rows[i - 1].max_error / r.max_error);
      expect_prints_as(rate_l2, p.rate_l2, 0.01, "L2 rate");
      expect_prints_as(rate_linf, p.rate_linf, 0.01, "Linf rate");
    }
  }
}

TEST(TorusIsosurface, ClosedGenusOneOutwardManifold) {
  const double exact_volume = 2.0 * std::numbers::pi * std::numbers::pi * 1.0 * 0.09;
  double prev_deficit = 0.0;
  for (int n = 16; n <= kMaxGridPoints; n *= 2) {
    SCOPED_TRACE(n);
    const Mesh& m = cached(n, false).mesh;
    expect_closed_oriented_manifold(m);
    EXPECT_EQ(m.euler_characteristic(), 0);
    EXPECT_EQ(num_components(m), 1);  // one closed surface with V - E + F = 0: genus 1
    EXPECT_EQ(m.num_faces(), 2 * m.num_vertices());
    // Outward: positive volume, with a second-order deficit (11% at n = 16, where the tube is
    // only three grid cells across; 2% at n = 32; then /4 per level).
    const double deficit = (exact_volume - m.signed_volume()) / exact_volume;
    EXPECT_GT(deficit, 0.0);
    EXPECT_LT(deficit, n == 16 ? 0.12 : 0.025);
    if (n > 16) {
      EXPECT_GT(prev_deficit / deficit, 3.5);
      EXPECT_LT(prev_deficit / deficit, 6.0);
    }
    prev_deficit = deficit;
  }
}

TEST(TorusIsosurface, OneVertexPerSignChangingEdgeAndNoAmbiguousFace) {
  for (int n = 16; n <= 128; n *= 2) {
    SCOPED_TRACE(n);
    const std::vector<double> ax = matlab_linspace(-1.5, 1.5, n);
    const IsosurfaceMesh iso = marching_cubes(ax, ax, ax, torus_signed_distance);
    EXPECT_EQ(iso.ambiguous_faces, 0);
    EXPECT_EQ(iso.center_vertices, 0);
    EXPECT_EQ(iso.vertices.rows(), count_sign_changing_edges(ax, torus_signed_distance));
    EXPECT_TRUE(test::identical(cached(n, false).mesh.vertices(), iso.vertices));
    EXPECT_TRUE(test::identical(cached(n, false).mesh.faces(), iso.faces));
  }
}

// Outward orientation vertex by vertex: every area-weighted normal within 30 degrees of the exact
// outward normal, and the worst angle (0.47, 0.23, 0.13, 0.065 rad) about halving per level, O(h).
TEST(TorusIsosurface, NormalsPointOutward) {
  double prev_angle = 0.0;
  for (int n = 16; n <= 128; n *= 2) {
    SCOPED_TRACE(n);
    const GeneratedMesh& g = cached(n, false);
    const VertexMatrix N = g.mesh.area_weighted_normals();
    double min_dot = 1.0;
    for (int v = 0; v < g.mesh.num_vertices(); ++v)
      min_dot = std::min(min_dot, N.row(v).dot(g.surface->evaluate(g.exact_points.row(v)).normal));
    EXPECT_GT(min_dot, std::cos(std::numbers::pi / 6));
    const double angle = std::acos(min_dot);
    if (n > 16) {
      EXPECT_GT(prev_angle / angle, 1.5);
    }
    prev_angle = angle;
  }
}

TEST(TorusIsosurface, RawAndProjectedVariants) {
  for (int n = 16; n <= 128; n *= 2) {
    SCOPED_TRACE(n);
    const GeneratedMesh& raw = cached(n, false);
    const GeneratedMesh& proj = cached(n, true);
    const int level = n == 16 ? 1 : n == 32 ? 2 : n == 64 ? 3 : 4;
    EXPECT_EQ(raw.family, "torus-iso");
    EXPECT_EQ(proj.family, "torus-iso-projected");
    EXPECT_EQ(raw.level, level);
    EXPECT_EQ(proj.level, level);
    ASSERT_NE(raw.surface, nullptr);
    ASSERT_NE(proj.surface, nullptr);
    EXPECT_EQ(raw.surface->name(), "torus");
    EXPECT_FALSE(raw.description.empty());
    // Same connectivity; projected vertices on the torus and equal to their exact points.
    EXPECT_TRUE(test::identical(proj.mesh.faces(), raw.mesh.faces()));
    EXPECT_EQ(proj.exact_points, proj.mesh.vertices());
    expect_closed_oriented_manifold(proj.mesh);
    EXPECT_EQ(proj.mesh.euler_characteristic(), 0);
    EXPECT_GT(proj.mesh.signed_volume(), 0.0);
    const VertexMatrix& V = raw.mesh.vertices();
    for (int v = 0; v < raw.mesh.num_vertices(); ++v) {
      const Vec3 p = proj.mesh.position(v);
      EXPECT_LE(std::abs(torus_signed_distance(p.x(), p.y(), p.z())), 1e-12);
      // Raw exact points are the closest torus points: the same points, at distance |f|.
      EXPECT_EQ(raw.exact_points.row(v), proj.mesh.vertices().row(v));
      const double d = std::abs(torus_signed_distance(V(v, 0), V(v, 1), V(v, 2)));
      EXPECT_NEAR((raw.exact_points.row(v) - V.row(v)).norm(), d, 1e-12);
    }
  }
}

TEST(TorusIsosurface, Deterministic) {
  const GeneratedMesh a = torus_isosurface(64, false), b = torus_isosurface(64, false);
  EXPECT_TRUE(test::identical(a.mesh.vertices(), b.mesh.vertices()));
  EXPECT_TRUE(test::identical(a.mesh.faces(), b.mesh.faces()));
  EXPECT_EQ(a.exact_points, b.exact_points);
  EXPECT_TRUE(test::identical(a.mesh.vertices(), cached(64, false).mesh.vertices()));
}

TEST(TorusIsosurface, OtherSizesAndErrors) {
  const GeneratedMesh g = torus_isosurface(20, false);
  EXPECT_EQ(g.level, 0);
  EXPECT_EQ(g.family, "torus-iso");
  expect_closed_oriented_manifold(g.mesh);
  EXPECT_EQ(g.mesh.euler_characteristic(), 0);
  EXPECT_THROW(torus_isosurface(1, false), UsageError);
  EXPECT_THROW(torus_isosurface(4096, true), UsageError);
  EXPECT_THROW(table4(8), UsageError);
  EXPECT_EQ(table4(40).size(), 2u);  // n = 16, 32
}

}  // namespace
}  // namespace curvbench
