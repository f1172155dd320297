// The point-cloud families (meshgen/point_families.h): sizes, exact points on the surface, the
// four samplings' defining properties, noise in units of the nominal spacing, determinism.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <string>
#include <vector>

#include "core/errors.h"
#include "meshgen/generate.h"
#include "meshgen/point_families.h"

namespace curvbench {
namespace {

GeneratedMesh points(const std::string& family, int level, int noise_order = 0,
                     NoiseModel model = {}) {
  MeshSpec spec;
  spec.family = family;
  spec.level = level;
  spec.noise_order = noise_order;
  spec.noise_model = model;
  return generate_mesh(spec);
}

// Brute-force nearest other point (the sets here have at most 4,000 points).
int nearest(const VertexMatrix& V, int i) {
  int best = -1;
  double d2 = INFINITY;
  for (int j = 0; j < V.rows(); ++j) {
    if (j == i) continue;
    const double e = (V.row(j) - V.row(i)).squaredNorm();
    if (e < d2) d2 = e, best = j;
  }
  return best;
}

// Every family: 1000 * 4^(L-1) points, no faces, each on the surface (its own exact point), the
// nominal spacing sqrt(A/n) halving from level to level.
TEST(PointFamilies, SizesSpacingAndPointsOnTheSurface) {
  for (const MeshFamilyInfo& f : mesh_family_table()) {
    if (!f.point_set) continue;
    EXPECT_EQ(f.max_level, kMaxPointLevel) << f.name;
    const GeneratedMesh a = points(f.name, 1), b = points(f.name, 2);
    EXPECT_EQ(a.mesh.num_vertices(), 1000) << f.name;
    EXPECT_EQ(b.mesh.num_vertices(), 4000) << f.name;
    EXPECT_EQ(a.mesh.num_faces(), 0) << f.name;
    EXPECT_NEAR(a.spacing, std::sqrt(point_family_area(f.name) / 1000), 1e-15) << f.name;
    EXPECT_NEAR(b.spacing / a.spacing, 0.5, 1e-14) << f.name;
    EXPECT_DOUBLE_EQ(mesh_size(a), a.spacing);
    double off = 0.0;
    for (int i = 0; i < b.mesh.num_vertices(); ++i) {
      const Vec3 p = b.mesh.position(i);
      off = std::max(off, (b.surface->project(p) - p).norm());
      EXPECT_EQ(p, Vec3(b.exact_points.row(i).transpose()));
    }
    EXPECT_LT(off, 1e-9) << f.name;
  }
  // The torus's and the sphere's areas are known: 4 pi^2 R r and 4 pi.
  const double pi = std::numbers::pi;
  EXPECT_NEAR(point_family_area("points-torus-uniform"), 4 * pi * pi * 0.3, 1e-7);
  EXPECT_NEAR(point_family_area("points-sphere-blue"), 4 * pi, 1e-4);
}

// Uniform by area: the torus's outer half (cos v > 0) holds 1/2 + r/(pi R) of the area, 0.5955;
// at 16,000 points the fraction is within 4 standard deviations (0.0039 each).
TEST(PointFamilies, UniformSamplesFollowTheArea) {
  const GeneratedMesh g = points("points-torus-uniform", 3);
  int outer = 0;
  for (int i = 0; i < g.mesh.num_vertices(); ++i) {
    const Vec3 p = g.mesh.position(i);
    outer += std::hypot(p.x(), p.y()) > 1.0;
  }
  const double expected = 0.5 + 0.3 / (std::numbers::pi * 1.0);
  const double sd = std::sqrt(expected * (1 - expected) / g.mesh.num_vertices());
  EXPECT_NEAR(static_cast<double>(outer) / g.mesh.num_vertices(), expected, 4 * sd);
}

// Blue noise keeps every pair at least 0.7 h apart; the uniform sample of the same size has
// pairs far closer.
TEST(PointFamilies, BlueNoiseKeepsItsDistance) {
  const GeneratedMesh blue = points("points-sphere-blue", 2);
  const GeneratedMesh uniform = points("points-sphere-uniform", 2);
  const auto min_distance = [](const VertexMatrix& V) {
    double d = INFINITY;
    for (int i = 0; i < V.rows(); ++i) d = std::min(d, (V.row(nearest(V, i)) - V.row(i)).norm());
    return d;
  };
  const double h = blue.spacing;
  EXPECT_GE(min_distance(blue.mesh.vertices()), 0.7 * h);
  EXPECT_LT(min_distance(uniform.mesh.vertices()), 0.1 * h);
}

// Anisotropic: every pair is at least 0.7 sqrt(A'/n) >= 0.7 h apart in the metric (4 dx, dy, dz)
// (A' >= A the area in that metric), while along x pairs come closer than 0.35 h, half the
// blue-noise distance, which no pair of the blue-noise sample does.
TEST(PointFamilies, AnisotropicSamplesAreDenserAlongX) {
  const GeneratedMesh g = points("points-sphere-anisotropic", 2);
  const VertexMatrix& V = g.mesh.vertices();
  double stretched = INFINITY, plain = INFINITY, plain_dx = 0.0;
  for (int i = 0; i < V.rows(); ++i)
    for (int j = i + 1; j < V.rows(); ++j) {
      const Vec3 d = (V.row(j) - V.row(i)).transpose();
      stretched = std::min(stretched, Vec3(4 * d.x(), d.y(), d.z()).norm());
      if (d.norm() < plain) plain = d.norm(), plain_dx = std::abs(d.x());
    }
  const double h = g.spacing;
  std::printf("anisotropic: min stretched distance %.3f h, min distance %.3f h (|dx| %.3f h)\n",
              stretched / h, plain / h, plain_dx / h);
  EXPECT_GE(stretched, 0.7 * h);
  EXPECT_LT(plain, 0.35 * h);
  EXPECT_GT(plain_dx, 0.5 * plain);  // the closest pair lies along x
}

// Stripes: every point within 0.02 h of a plane x = 2h j, and the nearest neighbour along its
// line (|dx| small) about h/2 away.
TEST(PointFamilies, StripesLieOnScanLines) {
  const GeneratedMesh g = points("points-torus-stripes", 2);
  const double h = g.spacing, gap = 2.0 * h;
  const VertexMatrix& V = g.mesh.vertices();
  int on_line = 0;
  for (int i = 0; i < V.rows(); ++i) {
    const double t = V(i, 0) / gap;
    EXPECT_LE(std::abs(t - std::round(t)) * gap, 0.02 * h + 1e-15) << i;
    on_line += std::abs(V(nearest(V, i), 0) - V(i, 0)) < 0.05 * h;
  }
  EXPECT_GT(on_line, V.rows() * 9 / 10);  // nearest neighbours are on the same scan line
}

// Noise is scaled by the nominal spacing: normal noise sigma = 0.05 h moves the points by
// |alpha| h along the normal, mean |alpha| = 0.05 sqrt(2/pi) (within 5% at 4,000 points); the
// exact points stay where the sample was.
TEST(PointFamilies, NoiseIsInUnitsOfTheSpacing) {
  NoiseModel model;
  model.scale = 0.05;
  const GeneratedMesh clean = points("points-ellipsoid-uniform", 2);
  const GeneratedMesh noisy = points("points-ellipsoid-uniform", 2, 1, model);
  double mean = 0.0;
  for (int i = 0; i < clean.mesh.num_vertices(); ++i) {
    EXPECT_EQ(Vec3(noisy.exact_points.row(i).transpose()), clean.mesh.position(i));
    mean += (noisy.mesh.position(i) - clean.mesh.position(i)).norm();
  }
  EXPECT_EQ(noisy.spacing, clean.spacing);  // the size stays the nominal spacing
  mean /= clean.mesh.num_vertices() * clean.spacing;
  EXPECT_NEAR(mean, 0.05 * std::sqrt(2 / std::numbers::pi),
              0.05 * 0.05 * std::sqrt(2 / std::numbers::pi));
}

// The same (family, level, seed) gives the same points; another seed other points.
TEST(PointFamilies, Deterministic) {
  EXPECT_EQ(points("points-bump-blue", 1).mesh.vertices(),
            points("points-bump-blue", 1).mesh.vertices());
  MeshSpec other;
  other.family = "points-bump-blue";
  other.seed = 2;
  EXPECT_NE(generate_mesh(other).mesh.vertices(), points("points-bump-blue", 1).mesh.vertices());
}

TEST(PointFamilies, UnknownNamesAreUsageErrors) {
  MeshSpec spec;
  spec.family = "points-torus-grid";
  EXPECT_THROW(generate_point_family(spec), UsageError);
  spec.family = "points-cube-uniform";
  EXPECT_THROW(generate_point_family(spec), UsageError);
  spec.family = "torus-unstructured";
  EXPECT_THROW(generate_point_family(spec), UsageError);
}

}  // namespace
}  // namespace curvbench
