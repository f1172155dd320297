// The mesh dispatcher (meshgen/generate.h): families, levels, options and error paths.
#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <iterator>
#include <string>
#include <vector>

#include "core/errors.h"
#include "meshgen/bump_grid.h"
#include "meshgen/bump_irregular.h"
#include "meshgen/generate.h"
#include "meshgen/noise.h"
#include "meshgen/torus_structured.h"
#include "tests/meshgen/identical_matrices.h"

namespace curvbench {
namespace {

// The UsageError message thrown by generate_mesh(spec), or "" if none.
std::string usage_error(const MeshSpec& spec) {
  try {
    generate_mesh(spec);
  } catch (const UsageError& e) {
    return e.what();
  }
  return "";
}

TEST(Generate, Families) {
  std::vector<std::string> expected = {"torus-structured",
                                       "torus-jittered",
                                       "torus-iso",
                                       "torus-iso-projected",
                                       "bump-48",
                                       "bump-irregular",
                                       "bump-unstructured",
                                       "torus-unstructured",
                                       "torus-unstructured-minval5",
                                       "torus-anisotropic",
                                       "bump-anisotropic",
                                       "bump-density",
                                       "lantern",
                                       "lantern-squeezed",
                                       "ellipsoid"};
  for (const char* surface : {"torus", "sphere", "ellipsoid", "bump"})
    for (const char* sampling : {"uniform", "blue", "anisotropic", "stripes"})
      expected.push_back(std::string("points-") + surface + "-" + sampling);
  EXPECT_EQ(mesh_families(), expected);
  EXPECT_EQ(max_mesh_level("torus-structured"), 6);  // 5-6: beyond the paper, for scaling
  EXPECT_EQ(max_mesh_level("torus-jittered"), 6);
  EXPECT_EQ(max_mesh_level("torus-iso"), 5);
  EXPECT_EQ(max_mesh_level("torus-iso-projected"), 5);
  EXPECT_EQ(max_mesh_level("bump-48"), 6);
  EXPECT_EQ(max_mesh_level("bump-irregular"), 6);
  EXPECT_EQ(max_mesh_level("bump-unstructured"), 6);
  EXPECT_EQ(max_mesh_level("torus-unstructured"), 4);  // the paper's four well-shaped meshes
  EXPECT_EQ(max_mesh_level("torus-unstructured-minval5"), 4);
  EXPECT_EQ(max_mesh_level("torus-anisotropic"), 4);
  EXPECT_EQ(max_mesh_level("bump-anisotropic"), 4);
  EXPECT_EQ(max_mesh_level("bump-density"), 4);
  for (const std::string& family : expected) {
    MeshSpec spec;
    spec.family = family;
    const GeneratedMesh gm = generate_mesh(spec);
    EXPECT_EQ(gm.family, family);
    EXPECT_EQ(gm.level, 1);
    ASSERT_TRUE(gm.surface);
    EXPECT_EQ(gm.exact_points.rows(), gm.mesh.num_vertices());
    EXPECT_EQ(gm.mesh.num_faces() > 0, !mesh_family(family).point_set) << family;
    EXPECT_TRUE(gm.mesh.is_consistently_oriented());
    EXPECT_FALSE(gm.description.empty());
  }
}

TEST(Generate, DispatchesToTheGenerators) {
  MeshSpec spec;
  spec.family = "torus-structured";
  spec.level = 2;
  spec.jitter = true;
  spec.seed = 17;
  EXPECT_TRUE(test::identical(generate_mesh(spec).mesh.vertices(),
                              torus_structured(2, true, 17).mesh.vertices()));
  // torus-jittered is the jittered structured mesh under its own family name.
  MeshSpec jittered{"torus-jittered", 2, 0, 17};
  const GeneratedMesh gj = generate_mesh(jittered);
  EXPECT_EQ(gj.family, "torus-jittered");
  EXPECT_TRUE(test::identical(gj.mesh.vertices(), torus_structured(2, true, 17).mesh.vertices()));
  EXPECT_TRUE(test::identical(gj.mesh.faces(), torus_structured(2, false, 17).mesh.faces()));
  EXPECT_FALSE(test::identical(gj.mesh.vertices(), torus_structured(2, false, 17).mesh.vertices()));
  spec = MeshSpec{"bump-48", 3};
  EXPECT_TRUE(test::identical(generate_mesh(spec).mesh.faces(), bump_48(3).mesh.faces()));
  spec = MeshSpec{"bump-irregular", 2, 0, 23};
  EXPECT_TRUE(
      test::identical(generate_mesh(spec).mesh.vertices(), bump_irregular(2, 23).mesh.vertices()));
  // Noise with the spec's seed, on top of the clean mesh.
  spec = MeshSpec{"bump-irregular", 2, 3, 23};
  EXPECT_TRUE(test::identical(generate_mesh(spec).mesh.vertices(),
                              add_noise(bump_irregular(2, 23), 3, 23).mesh.vertices()));
  // The isosurface levels are n = 16 * 2^(L-1); level 1 has the paper's 320 vertices.
  spec = MeshSpec{"torus-iso", 1};
  const GeneratedMesh iso = generate_mesh(spec);
  EXPECT_EQ(iso.mesh.num_vertices(), 320);
  spec.family = "torus-iso-projected";
  const GeneratedMesh proj = generate_mesh(spec);
  EXPECT_TRUE(test::identical(proj.mesh.faces(), iso.mesh.faces()));
  for (int i = 0; i < proj.mesh.num_vertices(); ++i) {
    const Vec3 p = proj.mesh.position(i);
    ASSERT_NEAR(std::hypot(std::hypot(p.x(), p.y()) - 1.0, p.z()), 0.3, 1e-12);
  }
  EXPECT_GT((iso.mesh.vertices() - proj.mesh.vertices()).norm(), 1e-3);  // raw is off the torus
}

TEST(Generate, ErrorsNameTheValidValues) {
  const std::string unknown = usage_error(MeshSpec{"sphere"});
  for (const std::string& f : mesh_families()) EXPECT_NE(unknown.find(f), std::string::npos);
  EXPECT_NE(unknown.find("sphere"), std::string::npos);
  EXPECT_NE(usage_error(MeshSpec{""}), "");

  EXPECT_NE(usage_error(MeshSpec{"torus-structured", 0}).find("1..6"), std::string::npos);
  EXPECT_NE(usage_error(MeshSpec{"torus-structured", 7}).find("1..6"), std::string::npos);
  EXPECT_NE(usage_error(MeshSpec{"torus-iso", 6}).find("1..5"), std::string::npos);
  EXPECT_NE(usage_error(MeshSpec{"bump-48", -1}).find("1..6"), std::string::npos);
  EXPECT_NE(usage_error(MeshSpec{"bump-irregular", 7}).find("1..6"), std::string::npos);
  EXPECT_NE(usage_error(MeshSpec{"bump-48", 1, -1}).find("noise order"), std::string::npos);
  EXPECT_NE(usage_error(MeshSpec{"bump-48", 1, 5}).find("noise order"), std::string::npos);
  MeshSpec jitter{"bump-48"};
  jitter.jitter = true;
  EXPECT_NE(usage_error(jitter).find("torus-structured"), std::string::npos);
  EXPECT_THROW(max_mesh_level("nope"), UsageError);
}

TEST(Generate, MeshQuality) {
  // The 4-8 mesh flattened to z = 0: right isosceles triangles; interior valences 4 and 8,
  // boundary 3 and 5.
  const Mesh lifted = bump_48(1).mesh;
  VertexMatrix flat = lifted.vertices();
  flat.col(2).setZero();
  const MeshQuality q48 = mesh_quality(Mesh(flat, lifted.faces()));
  EXPECT_NEAR(q48.min_angle_deg, 45.0, 1e-12);
  EXPECT_NEAR(q48.max_angle_deg, 90.0, 1e-12);
  EXPECT_EQ(q48.min_valence, 4);
  EXPECT_EQ(q48.max_valence, 8);
  EXPECT_EQ(q48.min_boundary_valence, 3);
  EXPECT_EQ(q48.max_boundary_valence, 5);
  const MeshQuality qt = mesh_quality(torus_structured(1).mesh);
  EXPECT_EQ(qt.min_valence, 6);
  EXPECT_EQ(qt.max_valence, 6);
  EXPECT_EQ(qt.min_boundary_valence, 0);
  EXPECT_EQ(qt.max_boundary_valence, 0);
  EXPECT_GT(qt.min_angle_deg, 40.0);  // near-equilateral at the mean radius
  EXPECT_LT(qt.max_angle_deg, 90.0);
}

}  // namespace
}  // namespace curvbench

namespace curvbench {
namespace {

// docs/mesh_families.md carries the family table as mesh_family_markdown() writes it, between
// its two marker lines, so that the doc cannot drift from the table in generate.cpp.
TEST(Generate, TheDocsTableIsTheFamilyTable) {
  std::ifstream in(std::string(CURVBENCH_SOURCE_DIR) + "/docs/mesh_families.md");
  ASSERT_TRUE(in) << "docs/mesh_families.md";
  const std::string doc((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  const std::string begin = "<!-- family table: begin -->\n", end = "<!-- family table: end -->";
  const auto a = doc.find(begin), b = doc.find(end);
  ASSERT_NE(a, std::string::npos);
  ASSERT_NE(b, std::string::npos);
  EXPECT_EQ(doc.substr(a + begin.size(), b - a - begin.size()), mesh_family_markdown());
}

// Every family of the table generates its first level, carries its name, and has a caption and
// a role (the report's captions and the docs table come from them).
TEST(Generate, EveryFamilyOfTheTableGeneratesWithItsName) {
  for (const MeshFamilyInfo& f : mesh_family_table()) {
    EXPECT_FALSE(f.caption.empty()) << f.name;
    EXPECT_FALSE(f.paper_role.empty()) << f.name;
    EXPECT_EQ(mesh_family(f.name).caption, f.caption);
    if (f.name == "torus-unstructured") continue;  // meshing takes seconds; test_torus_unstructured
    MeshSpec spec;
    spec.family = f.name;
    const GeneratedMesh g = generate_mesh(spec);
    EXPECT_EQ(g.family, f.name);
    EXPECT_EQ(g.level, 1) << f.name;
    EXPECT_GT(g.mesh.num_vertices(), 100) << f.name;
  }
}

}  // namespace
}  // namespace curvbench
