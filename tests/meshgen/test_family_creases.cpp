// The generated families are smooth surfaces: at level 2 none has a sharp edge at the default
// crease angle (mesh/creases.h), but the squeezed lantern, whose slices meet at 64 degrees at
// every level by construction (its face normals do not converge, docs/mesh_families.md).
#include <gtest/gtest.h>

#include "mesh/creases.h"
#include "meshgen/generate.h"

namespace curvbench {
namespace {

TEST(FamilyCreases, SmoothFamiliesHaveNoneAtLevel2) {
  for (const std::string& family : mesh_families()) {
    MeshSpec spec;
    spec.family = family;
    spec.level = 2;
    const Mesh mesh = generate_mesh(spec).mesh;
    const Creases c = detect_creases(mesh);
    if (family == "lantern-squeezed") {
      EXPECT_EQ(c.num_edges(), mesh.num_edges() - mesh.num_boundary_edges()) << family;
    } else {
      EXPECT_EQ(c.num_edges(), 0) << family;
      EXPECT_EQ(c.num_vertices(), 0) << family;
    }
  }
}

}  // namespace
}  // namespace curvbench
