// `curvbench mesh --aspect A / --density D` and the mesh options in `curvbench run`: bad values
// and options for a family that does not take them exit 2 with one line naming option and value;
// two aspects of one family give two families in the results CSV.
#include <gtest/gtest.h>

#include <fstream>
#include <string>

#include "tests/cli/cli_runner.h"

namespace curvbench {
namespace {

using testing::fresh_dir;
using testing::run_cli;
using testing::slurp;

TEST(CliMeshOptions, WritesTheStretchedMesh) {
  const auto dir = fresh_dir("cli_mesh_options");
  const auto r = run_cli("mesh --family torus-anisotropic --aspect 16 --level 1 --output " +
                         (dir / "t.ply").string());
  ASSERT_EQ(r.exit_code, 0) << r.output;
  EXPECT_NE(r.output.find("aspect A=16"), std::string::npos) << r.output;
  const auto d = run_cli("mesh --family bump-density --density 2 --level 1 --output " +
                         (dir / "b.off").string());
  ASSERT_EQ(d.exit_code, 0) << d.output;
  EXPECT_NE(d.output.find("density D=2 "), std::string::npos) << d.output;
}

TEST(CliMeshOptions, BadValuesExit2WithOneLine) {
  const auto dir = fresh_dir("cli_mesh_options_bad");
  const std::string out = " --level 1 --output " + (dir / "x.off").string();
  struct Case {
    std::string args, message;
  } cases[] = {
      {"--family torus-anisotropic --aspect 1", "aspect 1 out of range: must be > 1"},
      {"--family bump-anisotropic --aspect 0.25", "aspect 0.25 out of range: must be > 1"},
      {"--family bump-density --density 0.5", "density 0.5 out of range: must be >= 1"},
      {"--family torus-unstructured --aspect 4",
       "aspect 4 does not apply to torus-unstructured (only to torus-anisotropic, "
       "bump-anisotropic)"},
      {"--family bump-anisotropic --density 4",
       "density 4 does not apply to bump-anisotropic (only to bump-density)"},
  };
  for (const Case& c : cases) {
    const auto r = run_cli("mesh " + c.args + out);
    EXPECT_EQ(r.exit_code, 2) << c.args << ": " << r.output;
    EXPECT_NE(r.output.find(c.message), std::string::npos) << c.args << ": " << r.output;
    EXPECT_EQ(r.output.find('\n'), r.output.size() - 1) << "one line: " << r.output;
  }
  EXPECT_EQ(run_cli("mesh --family bump-anisotropic --aspect wide" + out).exit_code, 2);
  EXPECT_EQ(run_cli("mesh --table4 --aspect 4").exit_code, 2);
  EXPECT_FALSE(std::filesystem::exists(dir / "x.off"));
}

TEST(CliMeshOptions, TwoAspectsAreTwoFamiliesInTheResults) {
  const auto dir = fresh_dir("cli_mesh_options_run");
  std::ofstream(dir / "aniso.exp") << "title \"Anisotropy\"\nsection x\n"
                                      "mesh torus-anisotropic levels=1 aspect=4\n"
                                      "mesh torus-anisotropic levels=1 aspect=16\n"
                                      "method lhf-2\npanel p \"H.\" H L2\n";
  const auto r = run_cli("run aniso --experiments-dir " + dir.string() + " --output " +
                         (dir / "out").string() + " --no-readings --no-plots");
  ASSERT_EQ(r.exit_code, 0) << r.output;
  const std::string csv = slurp(dir / "out" / "aniso.csv");
  EXPECT_NE(csv.find(",torus-anisotropic-A4,1,"), std::string::npos) << csv;
  EXPECT_NE(csv.find(",torus-anisotropic-A16,1,"), std::string::npos) << csv;
}

}  // namespace
}  // namespace curvbench
