// bump-density (meshgen/bump_density.h): a Delaunay mesh of the square on the bump whose edge
// length grows linearly by the density option D from x = 0 to x = 1.
#include <gtest/gtest.h>

#include <Eigen/Dense>
#include <cmath>
#include <vector>

#include "bump_test_util.h"
#include "meshgen/bump_density.h"
#include "meshgen/generate.h"
#include "tests/meshgen/identical_matrices.h"

namespace curvbench {
namespace {

GeneratedMesh bump_density_mesh(int level, double density, std::uint64_t seed = 1) {
  MeshSpec spec;
  spec.family = "bump-density";
  spec.level = level;
  spec.seed = seed;
  spec.shape.density = density;
  return generate_mesh(spec);
}

double mean_length_in(const std::vector<double>& length, const std::vector<double>& x, double lo,
                      double hi) {
  double sum = 0.0;
  int n = 0;
  for (size_t i = 0; i < x.size(); ++i)
    if (x[i] >= lo && x[i] < hi) {
      sum += length[i];
      ++n;
    }
  return sum / n;
}

TEST(BumpDensity, SquareDomainDelaunayOnTheBump) {
  for (double density : {1.0, 8.0, 20.0})
    for (int level = 1; level <= 3; ++level) {
      SCOPED_TRACE("D=" + std::to_string(density) + " level " + std::to_string(level));
      const GeneratedMesh g = bump_density_mesh(level, density);
      EXPECT_EQ(g.family, "bump-density");
      EXPECT_EQ(g.level, level);
      testing::expect_square_bump_mesh(g);
      EXPECT_EQ(testing::delaunay_violations(g.mesh), 0);
      // Well shaped in the plane: smallest angles 18.0-25.1 degrees measured for seeds 1-3,
      // levels 1-4, D in {1, 2, 4, 8, 16, 20}. A bound of what the generator gives, not a
      // guarantee of the construction (a quarter-spacing jitter alone allows less).
      VertexMatrix flat = g.mesh.vertices();
      flat.col(2).setZero();
      EXPECT_GT(mesh_quality(Mesh(flat, g.mesh.faces())).min_angle_deg, 15.0);
    }
}

TEST(BumpDensity, ExactQuantitiesMatchFiniteDifferences) {
  EXPECT_GT(testing::expect_bump_exact_matches_fd(bump_density_mesh(2, 8.0), 5), 100);
}

TEST(BumpDensity, EdgeLengthGrowsByTheDensityFactor) {
  // h(x) = h0 (1 + (D - 1) x): a least-squares line through the planar edge lengths against
  // their midpoints' x gives h(1)/h(0) = D (measured within 1.5% for D = 1-16, levels 2-4). The
  // mean edge length over a tenth [a, b] counts edges at the density 1/h^2, so it is
  // int h^-1 / int h^-2 = ln(h(b)/h(a)) / (1/h(a) - 1/h(b)) (h0 = 1): the sparsest over the
  // densest tenth is 5.93 for D = 8 (measured 5.96), not D.
  for (double density : {1.0, 4.0, 8.0, 16.0}) {
    SCOPED_TRACE("D=" + std::to_string(density));
    std::vector<double> length, x;
    testing::planar_edges(bump_density_mesh(3, density).mesh, length, x);
    Eigen::MatrixXd A(static_cast<Eigen::Index>(x.size()), 2);
    Eigen::VectorXd b(static_cast<Eigen::Index>(x.size()));
    for (size_t i = 0; i < x.size(); ++i) {
      A.row(static_cast<Eigen::Index>(i)) << 1.0, x[i];
      b(static_cast<Eigen::Index>(i)) = length[i];
    }
    const Eigen::Vector2d fit = A.colPivHouseholderQr().solve(b);
    EXPECT_NEAR((fit(0) + fit(1)) / fit(0) / density, 1.0, 0.03);
    const double tenths = mean_length_in(length, x, 0.9, 1.0) / mean_length_in(length, x, 0.0, 0.1);
    const auto mean_h = [density](double lo, double hi) {
      const double ha = 1.0 + (density - 1.0) * lo, hb = 1.0 + (density - 1.0) * hi;
      return density == 1.0 ? 1.0 : std::log(hb / ha) / (1.0 / ha - 1.0 / hb);
    };
    EXPECT_NEAR(tenths / (mean_h(0.9, 1.0) / mean_h(0.0, 0.1)), 1.0, 0.03);
  }
}

TEST(BumpDensity, LevelsHalveHAndStayCheap) {
  for (double density : {1.0, 8.0, 16.0}) {
    double previous_h = 0.0;
    for (int level = 1; level <= 4; ++level) {
      const Mesh m = bump_density_mesh(level, density).mesh;
      if (level > 1) {
        EXPECT_NEAR(previous_h / m.mean_edge_length(), 2.0, 0.1);
      }
      previous_h = m.mean_edge_length();
      if (level == 1) {
        EXPECT_NEAR(m.num_vertices(), 289, 40);
      }
      if (level == 4) {
        EXPECT_LT(m.num_vertices(), 20000);
      }
    }
  }
}

TEST(BumpDensity, DeterministicPerSeed) {
  const GeneratedMesh a = bump_density_mesh(2, 8.0, 5), b = bump_density_mesh(2, 8.0, 5),
                      c = bump_density_mesh(2, 8.0, 6);
  EXPECT_TRUE(test::identical(a.mesh.vertices(), b.mesh.vertices()));
  EXPECT_TRUE(test::identical(a.mesh.faces(), b.mesh.faces()));
  ASSERT_EQ(a.mesh.num_vertices(), c.mesh.num_vertices());  // the seed moves points only
  EXPECT_FALSE(test::identical(a.mesh.vertices(), c.mesh.vertices()));
  // The default D is kDefaultDensity, given or not.
  MeshSpec spec{"bump-density", 2, 0, 5};
  EXPECT_TRUE(test::identical(generate_mesh(spec).mesh.vertices(), a.mesh.vertices()));
  EXPECT_EQ(bump_density_points(2, 8.0, 5), a.mesh.vertices().leftCols(2));
}

}  // namespace
}  // namespace curvbench
