// The noise estimate (harness/model/noise_estimate.h): against known noise on every generated
// family (harness/model/noise_validation.h, the table of docs/robustness.md), creases left out on
// CAD-like meshes (tests/mesh/crease_test_meshes.h), and its two units.
#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

#include "harness/model/noise_estimate.h"
#include "harness/model/noise_validation.h"
#include "meshgen/generate.h"
#include "tests/mesh/crease_test_meshes.h"

namespace curvbench {
namespace {

// The built-in families, taken before any test runs: tests/harness/test_extending.cpp registers
// a test-only one in this process.
// The noise estimate reads faces: the point-cloud families are left out.
const std::vector<std::string> kBuiltInFamilies = [] {
  std::vector<std::string> out;
  for (const MeshFamilyInfo& f : mesh_family_table())
    if (!f.point_set) out.push_back(f.name);
  return out;
}();

// Every built-in family, levels 1 and 2, sigma/h = 0 ... 0.1 (about 3 s in Release).
TEST(NoiseEstimate, WithinToleranceOnEveryFamily) {
  NoiseCheckSpec spec;
  spec.families = kBuiltInFamilies;
  ASSERT_GE(spec.families.size(), 15u);
  const auto rows = noise_check(spec);
  ASSERT_EQ(rows.size(), spec.families.size() * 2 * spec.sigmas.size());
  for (const NoiseCheckRow& r : rows) {
    const double rel = r.level >= 2 ? kNoiseEstimateRelTol : kNoiseEstimateCoarseRelTol;
    EXPECT_LE(std::fabs(r.estimated - r.expected), rel * r.expected + kNoiseEstimateAbsTol)
        << r.family << " level " << r.level << " sigma/h " << r.true_sigma << ": estimated "
        << r.estimated << ", floor " << r.floor;
    EXPECT_TRUE(r.within);
  }
}

// The floor is the discretisation's: far below 0.001 on the well-shaped torus at level 2, and
// the isosurface's O(h^2) vertex offsets at its level 2.
TEST(NoiseEstimate, FloorWithoutNoise) {
  NoiseCheckSpec spec;
  spec.families = {"torus-unstructured", "torus-iso"};
  spec.levels = {2};
  spec.sigmas = {0.0};
  const auto rows = noise_check(spec);
  ASSERT_EQ(rows.size(), 2u);
  EXPECT_LT(rows[0].estimated, 3e-4);
  EXPECT_GT(rows[1].estimated, 0.005);
  EXPECT_LT(rows[1].estimated, 0.012);
}

// Noise-free CAD-like meshes: near zero with the creases left out; the fits across them alone
// read as noise (a crease angle of 179 degrees finds none).
TEST(NoiseEstimate, CreasesAreNotNoise) {
  for (const auto& [name, m] : {std::pair{"cube", crease_test::meshed_cube(16)},
                                std::pair{"part", crease_test::fandisk_like_part()}}) {
    const NoiseEstimate e = estimate_noise(m.mesh);
    EXPECT_TRUE(e.creases_left_out) << name;
    EXPECT_EQ(e.crease_vertices, static_cast<int>(m.crease_vertices.size())) << name;
    EXPECT_EQ(e.sharp_edges, static_cast<int>(m.sharp_edges.size())) << name;
    EXPECT_GT(e.vertices_used, 50) << name;
    EXPECT_LT(e.sigma_over_h, 1e-4) << name;
    const NoiseEstimate across = estimate_noise(m.mesh, 179.0);
    EXPECT_EQ(across.crease_vertices, 0) << name;
    EXPECT_GT(across.sigma_over_h, 100 * std::fmax(e.sigma_over_h, 1e-6)) << name;
  }
}

// With noise (isotropic, sigma per axis, so sigma along the normal too) the estimate finds sigma.
// Up to 0.03 h every crease is left out; at 0.1 h (median dihedral angle about 16 degrees) the
// 68-degree ramp of the part no longer stands out 5 times above the median, the 90-degree edges
// still do.
TEST(NoiseEstimate, NoisyCreasedMeshes) {
  for (const auto& [name, m] : {std::pair{"cube", crease_test::meshed_cube(16)},
                                std::pair{"part", crease_test::fandisk_like_part()}})
    for (double sigma : {0.01, 0.03, 0.1}) {
      const NoiseEstimate e = estimate_noise(crease_test::with_isotropic_noise(m.mesh, sigma, 5));
      const int creases = static_cast<int>(m.crease_vertices.size());
      if (sigma < 0.1) {
        EXPECT_EQ(e.crease_vertices, creases) << name << " " << sigma;
      } else {
        EXPECT_GT(e.crease_vertices, creases * 3 / 4) << name;
      }
      EXPECT_TRUE(e.creases_left_out) << name << " " << sigma;
      EXPECT_NEAR(e.sigma_over_h / sigma, 1.0, kNoiseEstimateRelTol) << name << " " << sigma;
    }
}

// sigma/h does not depend on the mesh's scale; sigma/h^2 = (sigma/h) / h, in 1/length.
TEST(NoiseEstimate, Units) {
  MeshSpec spec;
  spec.family = "torus-unstructured";
  spec.level = 2;
  NoiseModel model;
  model.scale = 0.03;
  const Mesh m = add_noise(generate_mesh(spec), 1, 3, model).mesh;
  const Mesh twice(2.0 * m.vertices(), m.faces());
  const NoiseEstimate a = estimate_noise(m), b = estimate_noise(twice);
  EXPECT_DOUBLE_EQ(a.sigma_over_h2, a.sigma_over_h / m.mean_edge_length());
  EXPECT_NEAR(b.sigma_over_h, a.sigma_over_h, 1e-12 * a.sigma_over_h);
  EXPECT_NEAR(b.sigma_over_h2, 0.5 * a.sigma_over_h2, 1e-12 * a.sigma_over_h2);
  EXPECT_EQ(estimate_sigma_over_h(m), a.sigma_over_h);
}

// A cube too coarse for any fit off its creases: the vertices next to them count after all.
TEST(NoiseEstimate, CoarseCubeFallsBackToTheVerticesNextToCreases) {
  const auto cube = crease_test::meshed_cube(4);
  const NoiseEstimate e = estimate_noise(cube.mesh);
  EXPECT_FALSE(e.creases_left_out);
  EXPECT_EQ(e.vertices_used, e.near_crease_vertices);
  EXPECT_GT(e.vertices_used, 0);
}

}  // namespace
}  // namespace curvbench
