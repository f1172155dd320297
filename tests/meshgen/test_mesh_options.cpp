// The mesh options (MeshShape: aspect, density; meshgen/generate.h): the families that take
// them, range checks and errors naming option and value, the results' labels and case-key text.
#include <gtest/gtest.h>

#include <string>

#include "core/errors.h"
#include "meshgen/generate.h"

namespace curvbench {
namespace {

// The message of the UsageError that generate_mesh throws (empty if none).
std::string error_of(const std::string& family, std::optional<double> aspect,
                     std::optional<double> density) {
  MeshSpec spec;
  spec.family = family;
  spec.shape.aspect = aspect;
  spec.shape.density = density;
  try {
    generate_mesh(spec);
  } catch (const UsageError& e) {
    return e.what();
  }
  return "";
}

TEST(MeshOptions, TheFamiliesThatTakeThem) {
  EXPECT_EQ(mesh_family("torus-anisotropic").options, std::vector<std::string>{"aspect"});
  EXPECT_EQ(mesh_family("bump-anisotropic").options, std::vector<std::string>{"aspect"});
  EXPECT_EQ(mesh_family("bump-density").options, std::vector<std::string>{"density"});
  EXPECT_TRUE(mesh_family("torus-structured").options.empty());
  EXPECT_EQ(mesh_option_table().size(), 2u);
  EXPECT_EQ(mesh_option_table()[0].default_value, 4.0);
  EXPECT_EQ(mesh_option_table()[1].default_value, 8.0);
}

TEST(MeshOptions, RangeAndFamilyErrorsNameOptionAndValue) {
  EXPECT_EQ(error_of("torus-anisotropic", 1.0, {}), "aspect 1 out of range: must be > 1");
  EXPECT_EQ(error_of("bump-anisotropic", 0.5, {}), "aspect 0.5 out of range: must be > 1");
  EXPECT_EQ(error_of("bump-anisotropic", -3.0, {}), "aspect -3 out of range: must be > 1");
  EXPECT_EQ(error_of("torus-anisotropic", std::nan(""), {}),
            "aspect nan out of range: must be > 1");
  EXPECT_EQ(error_of("bump-density", {}, 0.99), "density 0.99 out of range: must be >= 1");
  EXPECT_EQ(error_of("bump-density", {}, 1.0), "");  // uniform sampling is allowed
  EXPECT_EQ(error_of("torus-anisotropic", 1.01, {}), "");
  EXPECT_EQ(error_of("torus-unstructured", 16.0, {}),
            "aspect 16 does not apply to torus-unstructured (only to torus-anisotropic, "
            "bump-anisotropic)");
  EXPECT_EQ(error_of("torus-anisotropic", {}, 4.0),
            "density 4 does not apply to torus-anisotropic (only to bump-density)");
  EXPECT_EQ(error_of("bump-density", 4.0, {}),
            "aspect 4 does not apply to bump-density (only to torus-anisotropic, "
            "bump-anisotropic)");
  MeshShape shape;
  EXPECT_THROW(set_mesh_option(shape, "stretch", 2.0), UsageError);
  try {
    set_mesh_option(shape, "stretch", 2.0);
  } catch (const UsageError& e) {
    EXPECT_STREQ(e.what(), "unknown mesh option 'stretch' (valid: aspect, density)");
  }
  set_mesh_option(shape, "density", 3.0);
  EXPECT_EQ(shape.density, 3.0);
  EXPECT_FALSE(shape.aspect.has_value());
}

TEST(MeshOptions, LabelsAndCaseKeys) {
  MeshShape none, a16, d2;
  a16.aspect = 16.0;
  d2.density = 2.5;
  EXPECT_EQ(mesh_label("torus-anisotropic", none), "torus-anisotropic-A4");
  EXPECT_EQ(mesh_label("torus-anisotropic", a16), "torus-anisotropic-A16");
  EXPECT_EQ(mesh_label("bump-anisotropic", a16), "bump-anisotropic-A16");
  EXPECT_EQ(mesh_label("bump-density", none), "bump-density-D8");
  EXPECT_EQ(mesh_label("bump-density", d2), "bump-density-D2.5");
  EXPECT_EQ(mesh_label("torus-structured", none), "torus-structured");
  EXPECT_EQ(mesh_label("not-a-family", none), "not-a-family");
  EXPECT_EQ(mesh_shape_key("torus-anisotropic", none), ";aspect=4");
  EXPECT_EQ(mesh_shape_key("torus-anisotropic", a16), ";aspect=16");
  EXPECT_EQ(mesh_shape_key("bump-density", d2), ";density=2.5");
  EXPECT_EQ(mesh_shape_key("bump-48", none), "");
  MeshShape a16b;
  a16b.aspect = 16.0;
  EXPECT_EQ(a16, a16b);
  EXPECT_NE(a16, none);
}

GeneratedMesh no_mesh(const MeshSpec&) {
  return {};
}

TEST(MeshOptions, RegisteredFamiliesNameKnownOptions) {
  EXPECT_THROW(register_mesh_family({"toy-stretch", 1, "", "", "none", {"stretch"}}, &no_mesh),
               UsageError);
}

}  // namespace
}  // namespace curvbench
