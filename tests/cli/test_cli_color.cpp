// `curvbench estimate --color H|K|k1|k2`: per-vertex RGB in the PLY (mesh/colormap.h).
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

TEST(CliColor, PlyGetsRgbAndTheRange) {
  const fs::path dir = fresh_dir("cli_color");
  write_mesh((dir / "t.off").string(), torus_structured(1).mesh, {}, {});
  const auto r = run_cli("estimate " + (dir / "t.off").string() +
                         " --method lhf-2 --color H --output " + (dir / "t.ply").string());
  ASSERT_EQ(r.exit_code, 0) << r.output;
  const std::string ply = slurp(dir / "t.ply");
  const std::string header = ply.substr(0, ply.find("end_header"));
  for (const char* line : {"property int red", "property int green", "property int blue",
                           "comment color: H, blue -L .. white 0 .. red +L, L = "})
    EXPECT_NE(header.find(line), std::string::npos) << line << "\n" << header;
  // On the torus (R = 1, r = 0.3) H ranges over [-2.05, -0.95] (outer to inner equator),
  // and the range limit is close to max |H| = 2.05 (98th percentile).
  const size_t at = header.find("L = ") + 4;
  const double limit = std::stod(header.substr(at));
  EXPECT_GT(limit, 1.8);
  EXPECT_LT(limit, 2.2);
  const auto bad = run_cli("estimate " + (dir / "t.off").string() +
                           " --method lhf-2 --color H --output " + (dir / "t.csv").string());
  EXPECT_EQ(bad.exit_code, 2);
  EXPECT_NE(bad.output.find("--color needs a .ply"), std::string::npos) << bad.output;
  EXPECT_FALSE(fs::exists(dir / "t.csv"));
  fs::remove_all(dir);
}

}  // namespace
}  // namespace curvbench
