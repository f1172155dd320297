// Mesh features (harness/model/mesh_features.h) on generated meshes whose values are known from
// their construction (meshgen/anisotropic.h, bump_density.h, lantern.h).
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "core/errors.h"
#include "harness/model/mesh_features.h"
#include "meshgen/generate.h"

namespace curvbench {
namespace {

Mesh family_mesh_of(const std::string& family, int level, MeshShape shape = {}) {
  MeshSpec spec;
  spec.family = family;
  spec.level = level;
  spec.shape = shape;
  return generate_mesh(spec).mesh;
}

// The anisotropic families stretch equilateral triangles A times along one direction: the ratio
// of the principal edge directions is A (measured at level 2: torus 2.03, 3.81, 7.20, bump 2.41,
// 4.16, 8.40 for A = 2, 4, 8; the torus's triangles sag sideways, the bump's boundary half
// triangles count too). Well-shaped isotropic meshes read near 1.
TEST(MeshFeatures, AnisotropyIsTheAspectRatio) {
  for (const char* family : {"torus-anisotropic", "bump-anisotropic"})
    for (double aspect : {2.0, 4.0, 8.0}) {
      MeshShape shape;
      shape.aspect = aspect;
      const MeshFeatures m = measure_mesh_features(family_mesh_of(family, 2, shape));
      EXPECT_NEAR(m.anisotropy / aspect, 1.0, 0.22) << family << " A = " << aspect;
      EXPECT_EQ(m.irregular_valence_share, 0.0) << family;  // a staggered grid: valence 6
    }
  EXPECT_LT(measure_mesh_features(family_mesh_of("torus-unstructured", 2)).anisotropy, 1.25);
  EXPECT_LT(measure_mesh_features(family_mesh_of("ellipsoid", 2)).anisotropy, 1.25);
}

// bump-density's edge length varies by the factor D across the square: the density ratio
// (90th over 10th percentile of the local edge length) grows with D; at D = 1 only the jitter
// spreads it.
TEST(MeshFeatures, DensityRatioFollowsTheContrast) {
  double previous = 0.0;
  for (double d : {1.0, 8.0, 32.0}) {
    MeshShape shape;
    shape.density = d;
    const double ratio =
        measure_mesh_features(family_mesh_of("bump-density", 2, shape)).density_ratio;
    EXPECT_GT(ratio, previous) << "D = " << d;
    previous = ratio;
    if (d == 1.0) {
      EXPECT_LT(ratio, 1.6);
    }
    if (d == 8.0) {
      EXPECT_GT(ratio, 4.0);
    }
  }
  EXPECT_LT(measure_mesh_features(family_mesh_of("torus-unstructured", 2)).density_ratio, 1.5);
}

// Closed meshes have no boundary; the bump's square has one; the torus-structured grid has
// valence 6 everywhere and near-equilateral angles; the squeezed lantern's triangles have two
// angles below 20 degrees and one above 100 (2/3 and 1/3 of the angles).
TEST(MeshFeatures, SharesOfKnownMeshes) {
  const MeshFeatures torus = measure_mesh_features(family_mesh_of("torus-structured", 2));
  EXPECT_EQ(torus.boundary_share, 0.0);
  EXPECT_EQ(torus.irregular_valence_share, 0.0);
  EXPECT_EQ(torus.small_angle_share, 0.0);
  EXPECT_EQ(torus.obtuse_angle_share, 0.0);
  const Mesh bump = family_mesh_of("bump-irregular", 2);
  EXPECT_DOUBLE_EQ(measure_mesh_features(bump).boundary_share,
                   static_cast<double>(bump.num_boundary_vertices()) / bump.num_vertices());
  EXPECT_GT(measure_mesh_features(bump).boundary_share, 0.05);
  const MeshFeatures squeezed = measure_mesh_features(family_mesh_of("lantern-squeezed", 2));
  EXPECT_NEAR(squeezed.small_angle_share, 2.0 / 3.0, 1e-12);
  EXPECT_NEAR(squeezed.obtuse_angle_share, 1.0 / 3.0, 1e-12);
}

// Every feature is a shape property: scaling the mesh leaves them all (size_over_h included).
TEST(MeshFeatures, ScaleInvariant) {
  const Mesh mesh = family_mesh_of("bump-density", 2);
  const Mesh scaled(mesh.vertices() * 3.0, mesh.faces());
  const MeshFeatures a = measure_mesh_features(mesh), b = measure_mesh_features(scaled);
  for (const FeatureInfo& f : advice_features())
    EXPECT_NEAR(a.*(f.field), b.*(f.field), 1e-9 * std::fabs(a.*(f.field))) << f.name;
  EXPECT_NEAR(a.size_over_h, b.size_over_h, 1e-9 * a.size_over_h);
}

TEST(MeshFeatures, MeshWithoutFacesIsAnInputError) {
  VertexMatrix v(3, 3);
  v << 0, 0, 0, 1, 0, 0, 0, 1, 0;
  EXPECT_THROW((void)measure_mesh_features(Mesh(v, FaceMatrix(0, 3))), InputError);
}

}  // namespace
}  // namespace curvbench
