// `curvbench estimate --timing`: prints one line per stage (read, neighbourhoods+fit, write)
// with a non-negative time, and writes exactly the same CSV bytes as without --timing.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <regex>
#include <sstream>
#include <string>

#include "tests/cli/cli_runner.h"

namespace curvbench {
namespace {

using testing::fresh_dir;
using testing::run_cli;
using testing::slurp;
namespace fs = std::filesystem;

TEST(CliTiming, PrintsStagesAndKeepsOutput) {
  const fs::path dir = fresh_dir("cli_timing");
  const fs::path mesh = dir / "torus.off";
  ASSERT_EQ(run_cli("mesh --family torus-structured --level 1 --output " + mesh.string()).exit_code,
            0);
  const fs::path plain = dir / "plain.csv";
  const fs::path timed = dir / "timed.csv";
  const std::string base = "estimate " + mesh.string() + " --method LHF-2 --threads 1 --output ";
  const auto r0 = run_cli(base + plain.string());
  ASSERT_EQ(r0.exit_code, 0) << r0.output;
  EXPECT_EQ(r0.output.find("timing:"), std::string::npos) << r0.output;

  const auto r1 = run_cli(base + timed.string() + " --timing");
  ASSERT_EQ(r1.exit_code, 0) << r1.output;
  for (const char* stage : {"read", "neighbourhoods\\+fit", "write"}) {
    const std::regex line(std::string("(^|\n)timing: ") + stage + " [0-9]+\\.[0-9]+ s\n");
    EXPECT_TRUE(std::regex_search(r1.output, line)) << stage << " missing in:\n" << r1.output;
  }
  const std::string a = slurp(plain);
  ASSERT_FALSE(a.empty());
  EXPECT_EQ(a, slurp(timed));
  fs::remove_all(dir);
}

}  // namespace
}  // namespace curvbench
