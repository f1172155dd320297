// Mesh options in experiments (experiment.h `mesh ... aspect=A`): parsed and checked with the
// line, kept apart in the case key, the case id and the results' family column.
#include <gtest/gtest.h>

#include <set>
#include <string>

#include "core/errors.h"
#include "harness/model/experiment.h"
#include "harness/run/case_store.h"
#include "harness/run/runner.h"

namespace curvbench {
namespace {

const std::string kHead = "title \"Anisotropy\"\nsection x\nmethod lhf-2\npanel p \"H.\" H L2\n";

std::string parse_error(const std::string& mesh_line) {
  try {
    parse_experiment_text(kHead + mesh_line + "\n", "bad.exp");
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

TEST(MeshOptionsRun, ParsedAndCheckedOnTheMeshLine) {
  const Experiment e = parse_experiment_text(
      kHead +
          "mesh torus-anisotropic levels=1\nmesh torus-anisotropic levels=1 aspect=16\n"
          "mesh bump-density levels=1 density=2\nmesh bump-48 levels=1\n",
      "aniso.exp");
  ASSERT_EQ(e.meshes.size(), 4u);
  EXPECT_FALSE(e.meshes[0].shape.aspect.has_value());
  EXPECT_EQ(e.meshes[1].shape.aspect, 16.0);
  EXPECT_EQ(e.meshes[2].shape.density, 2.0);
  EXPECT_EQ(e.meshes[0].label(), "torus-anisotropic-A4");
  EXPECT_EQ(e.meshes[1].label(), "torus-anisotropic-A16");
  EXPECT_EQ(e.meshes[2].label(), "bump-density-D2");
  EXPECT_EQ(e.meshes[3].label(), "bump-48");

  EXPECT_EQ(parse_error("mesh torus-anisotropic levels=1 aspect=1"),
            "bad.exp:5: aspect 1 out of range: must be > 1");
  EXPECT_EQ(parse_error("mesh bump-density levels=1 density=0.5"),
            "bad.exp:5: density 0.5 out of range: must be >= 1");
  EXPECT_EQ(parse_error("mesh torus-structured levels=1 aspect=4"),
            "bad.exp:5: aspect 4 does not apply to torus-structured (only to torus-anisotropic, "
            "bump-anisotropic)");
  EXPECT_EQ(parse_error("mesh bump-anisotropic levels=1 aspect=wide"),
            "bad.exp:5: 'wide' is not a number");
  EXPECT_EQ(
      parse_error("mesh bump-anisotropic levels=1 stretch=2"),
      "bad.exp:5: expected levels=1,2,3,4 [noise-order=K] [noise-sigma=S,...] [noise-model=M] "
      "[noise-alpha=A] [outliers=P,...] [aspect=A] [density=D]");
}

TEST(MeshOptionsRun, TwoAspectsStayApartInKeysIdsAndRows) {
  const std::vector<Experiment> experiments = {parse_experiment_text(
      kHead + "mesh torus-anisotropic levels=1 aspect=4\nmesh torus-anisotropic levels=1 "
              "aspect=16\nmesh torus-anisotropic levels=1\n",
      "aniso.exp")};
  const std::vector<RunCase> cases = expand_cases(experiments);  // points into `experiments`
  ASSERT_EQ(cases.size(), 3u);
  EXPECT_NE(case_inputs(cases[0]), case_inputs(cases[1]));
  EXPECT_NE(case_id(cases[0]), case_id(cases[1]));
  EXPECT_NE(case_inputs(cases[0]).find(";aspect=4;"), std::string::npos);
  EXPECT_NE(case_inputs(cases[1]).find(";aspect=16;"), std::string::npos);
  // The default given or not: the same mesh, the same case.
  EXPECT_EQ(case_inputs(cases[0]), case_inputs(cases[2]));
  EXPECT_EQ(case_id(cases[0]), "aniso/torus-anisotropic-A4_L1_lhf-2_" +
                                   case_id(cases[0]).substr(case_id(cases[0]).size() - 8));

  MeshCache cache;
  const auto a4 = run_case(cases[0], cache, 1), a16 = run_case(cases[1], cache, 1);
  ASSERT_EQ(a4.size(), 1u);
  ASSERT_EQ(a16.size(), 1u);
  EXPECT_EQ(a4[0].family, "torus-anisotropic-A4");
  EXPECT_EQ(a16[0].family, "torus-anisotropic-A16");
  EXPECT_NE(a4[0].error, a16[0].error);  // two meshes
}

}  // namespace
}  // namespace curvbench
