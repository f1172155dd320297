// `curvbench estimate`: the command-line contract other tools depend on (columns, one row per
// vertex, full precision, PLY output, degree-in-name, thread independence, exit code 2).
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <vector>

#include "mesh/io.h"
#include "tests/cli/cli_runner.h"

namespace curvbench {
namespace {

using testing::fresh_dir;
using testing::run_cli;
using testing::slurp;
namespace fs = std::filesystem;

std::vector<std::vector<std::string>> read_csv(const fs::path& p) {
  std::vector<std::vector<std::string>> rows;
  std::ifstream in(p);
  std::string line;
  while (std::getline(in, line)) {
    std::vector<std::string> f;
    std::stringstream ss(line);
    std::string cell;
    while (std::getline(ss, cell, ',')) f.push_back(cell);
    rows.push_back(f);
  }
  return rows;
}

class CliEstimate : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = fresh_dir("cli_estimate");
    torus_ = dir_ / "torus.off";
    ASSERT_EQ(
        run_cli("mesh --family torus-jittered --level 2 --output " + torus_.string()).exit_code, 0);
    bump_ = dir_ / "bump.ply";
    ASSERT_EQ(run_cli("mesh --family bump-48 --level 1 --output " + bump_.string()).exit_code, 0);
  }
  fs::path dir_, torus_, bump_;
};

TEST_F(CliEstimate, CsvContract) {
  const auto out = dir_ / "lhf.csv";
  const auto r =
      run_cli("estimate " + torus_.string() + " --method lhf --degree 2 --output " + out.string());
  ASSERT_EQ(r.exit_code, 0) << r.output;
  const auto rows = read_csv(out);
  ASSERT_EQ(rows.size(), 5633u);  // header + 5632 vertices
  const std::vector<std::string> header = {"vertex", "nx",  "ny",     "nz",     "k1",    "k2",
                                           "H",      "K",   "d1x",    "d1y",    "d1z",   "d2x",
                                           "d2y",    "d2z", "degree", "points", "status"};
  EXPECT_EQ(rows[0], header);
  // Torus R=1, r=0.3: k2 = -1/r everywhere and H in [-2.051, -0.952] (docs/algorithms.md §11.1).
  // At level 2 the Linf error of LHF-2 in H is about 0.04 (results/fig03-05.csv: 2.0e-2 relative
  // to max|H| = 2.05) and in k2 about 0.07 (0.26 at level 1, quadratic convergence), so 0.1 and
  // 0.15 are safe bounds for this contract check.
  for (size_t i = 1; i < rows.size(); ++i) {
    ASSERT_EQ(rows[i].size(), header.size());
    EXPECT_EQ(rows[i][0], std::to_string(i - 1));
    const double nx = std::stod(rows[i][1]), ny = std::stod(rows[i][2]), nz = std::stod(rows[i][3]);
    EXPECT_NEAR(nx * nx + ny * ny + nz * nz, 1.0, 1e-12);
    EXPECT_NEAR(std::stod(rows[i][5]), -1.0 / 0.3, 0.15);
    const double H = std::stod(rows[i][6]);
    EXPECT_LT(H, -0.952 + 0.1);
    EXPECT_GT(H, -2.051 - 0.1);
    EXPECT_EQ(rows[i][14], "2");
    EXPECT_EQ(rows[i][16], "ok");
  }
  // Full double precision: 17 significant digits are written.
  EXPECT_GE(rows[1][4].size(), 17u) << rows[1][4];
}

TEST_F(CliEstimate, DegreeInNameThreadsAndPly) {
  const auto a = dir_ / "a.csv", b = dir_ / "b.csv", c = dir_ / "c.csv";
  ASSERT_EQ(
      run_cli("estimate " + torus_.string() + " --method LHF-3 --threads 1 --output " + a.string())
          .exit_code,
      0);
  ASSERT_EQ(run_cli("estimate " + torus_.string() +
                    " --method lhf --degree 3 --threads 2 "
                    "--output " +
                    b.string())
                .exit_code,
            0);
  EXPECT_EQ(slurp(a), slurp(b));  // same bytes for any thread count
  const auto rows = read_csv(a);
  EXPECT_EQ(rows[1][14], "3");

  // Xu-2 on an open mesh: boundary vertices excluded (NaN), interior ones computed.
  ASSERT_EQ(run_cli("estimate " + bump_.string() + " --method xu --output " + c.string()).exit_code,
            0);
  const auto xu = read_csv(c);
  int excluded = 0;
  for (size_t i = 1; i < xu.size(); ++i)
    if (xu[i][16] == "excluded") {
      ++excluded;
      EXPECT_EQ(xu[i][6], "nan");
    }
  EXPECT_EQ(excluded, 4 * 16);  // the boundary of the 17 x 17 grid

  const auto ply = dir_ / "out.ply";
  ASSERT_EQ(
      run_cli("estimate " + torus_.string() + " --method lop-2 --output " + ply.string()).exit_code,
      0);
  const std::string text = slurp(ply);
  for (const char* p :
       {"property double nx", "property double k1", "property double H", "property double d2z"})
    EXPECT_NE(text.find(p), std::string::npos) << p;
  EXPECT_EQ(read_mesh(ply.string()).num_vertices(), 5632);
}

TEST(CliEstimateHelp, DocumentsSkipInvalid) {
  const auto r = run_cli("estimate --help");
  EXPECT_EQ(r.exit_code, 0);
  EXPECT_NE(r.output.find("--skip-invalid"), std::string::npos) << r.output;
  EXPECT_NE(r.output.find("only the remaining vertices"), std::string::npos) << r.output;
}

TEST_F(CliEstimate, BadUsageExits2AndWritesNothing) {
  const auto out = dir_ / "never.csv";
  const std::string tail = " --output " + out.string();
  struct Case {
    std::string args, message;
  } cases[] = {
      {"estimate " + torus_.string() + " --method magic" + tail, "unknown method 'magic'"},
      {"estimate " + torus_.string() + " --method lhf --degree 9" + tail, "degree 9"},
      {"estimate " + torus_.string() + " --method xu --degree 3" + tail, "degree 3"},
      {"estimate " + torus_.string() + " --method lhf --rings 1.25" + tail, "1.25"},
      {"estimate " + (dir_ / "missing.off").string() + " --method lhf" + tail, "missing.off"},
      {"estimate " + torus_.string() + " --method lhf --output " + (dir_ / "x.txt").string(),
       "x.txt"},
  };
  for (const auto& c : cases) {
    const auto r = run_cli(c.args);
    EXPECT_EQ(r.exit_code, 2) << c.args << "\n" << r.output;
    EXPECT_NE(r.output.find(c.message), std::string::npos) << c.args << "\n" << r.output;
  }
  EXPECT_FALSE(fs::exists(out));
  EXPECT_FALSE(fs::exists(dir_ / "x.txt"));
}

}  // namespace
}  // namespace curvbench
