// `curvbench estimate --vertex-normals W --quadric-constant --ball-factor C`: the options of
// single methods reach the estimator, and bad values or the wrong method exit 2 with a message.
#include <gtest/gtest.h>

#include <filesystem>
#include <string>

#include "mesh/io.h"
#include "meshgen/torus_structured.h"
#include "tests/cli/cli_runner.h"

namespace curvbench {
namespace {

namespace fs = std::filesystem;
using testing::fresh_dir;
using testing::run_cli;
using testing::slurp;

TEST(CliEstimateOptions, ReachTheMethodAndBadUseExitsTwo) {
  const fs::path dir = fresh_dir("cli_estimate_options");
  const std::string mesh = (dir / "t.off").string();
  write_mesh(mesh, torus_structured(1).mesh, {}, {});
  // Each option changes the numbers of its method (the CSV bytes differ from the default run).
  const auto estimate = [&](const std::string& args, const std::string& out) {
    const auto r = run_cli("estimate " + mesh + " " + args + " --output " + (dir / out).string());
    EXPECT_EQ(r.exit_code, 0) << args << "\n" << r.output;
    return slurp(dir / out);
  };
  EXPECT_NE(estimate("--method quadric", "q.csv"),
            estimate("--method quadric --quadric-constant", "qc.csv"));
  EXPECT_NE(estimate("--method normal-cycle", "n.csv"),
            estimate("--method normal-cycle --ball-factor 2", "nb.csv"));
  EXPECT_NE(estimate("--method meyer", "m.csv"),
            estimate("--method meyer --vertex-normals angle", "ma.csv"));
  EXPECT_EQ(estimate("--method rusinkiewicz", "r.csv"),
            estimate("--method rusinkiewicz --vertex-normals max", "rm.csv"));  // its default

  const auto expect_usage_error = [&](const std::string& args, const std::string& needle) {
    const auto r =
        run_cli("estimate " + mesh + " " + args + " --output " + (dir / "bad.csv").string());
    EXPECT_EQ(r.exit_code, 2) << args << "\n" << r.output;
    EXPECT_NE(r.output.find(needle), std::string::npos) << args << "\n" << r.output;
    EXPECT_FALSE(fs::exists(dir / "bad.csv")) << args;
  };
  expect_usage_error("--method lhf-2 --vertex-normals area",
                     "vertex-normals applies to the discrete operators only");
  expect_usage_error("--method meyer --vertex-normals cotan", "valid: default, area, angle, max");
  expect_usage_error("--method meyer --quadric-constant", "applies to method 'quadric' only");
  expect_usage_error("--method quadric --ball-factor 2",
                     "only (the methods sized by a ball), not to 'quadric'");
  expect_usage_error("--method normal-cycle --ball-factor -1", "ball-factor -1: out of range");

  const auto help = run_cli("estimate --help");
  EXPECT_EQ(help.exit_code, 0);
  for (const char* s : {"--vertex-normals", "--quadric-constant", "--ball-factor"})
    EXPECT_NE(help.output.find(s), std::string::npos) << s;
  fs::remove_all(dir);
}

}  // namespace
}  // namespace curvbench
