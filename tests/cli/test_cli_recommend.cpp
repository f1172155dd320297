// `curvbench recommend`: the three families' level-2 meshes classify as their quality classes, a
// given --noise picks the nearest level's row, and the one-line errors (exit 2).
#include <gtest/gtest.h>

#include <algorithm>
#include <fstream>
#include <string>

#include "tests/cli/cli_runner.h"

namespace curvbench {
namespace {

using testing::fresh_dir;
using testing::run_cli;

// A recommendations.csv whose best label names its cell: "M-<quality>-<sigma>"; sigma/h = 0.01
// not swept.
void write_table(const std::filesystem::path& dir) {
  std::ofstream out(dir / "recommendations.csv");
  out << "# test\nquality,sigma_over_h,status,best_label\n";
  for (const char* q : {"well-shaped", "isosurface", "irregular"})
    for (const char* s : {"0", "0.01", "0.03", "0.1"})
      out << q << ',' << s << (std::string(s) == "0.01" ? ",not swept," : ",swept,M-") << q << '-'
          << s << "\n";
}

std::string off_of(const std::filesystem::path& dir, const std::string& family) {
  const std::string path = (dir / (family + ".off")).string();
  const auto r = run_cli("mesh --family " + family + " --level 2 --output " + path);
  EXPECT_EQ(r.exit_code, 0) << r.output;
  return path;
}

TEST(CliRecommend, FamiliesClassifyAndNoiseGivenPicksTheNearestLevel) {
  const auto dir = fresh_dir("recommend");
  write_table(dir);
  const std::string results = " --results " + dir.string();
  for (const auto& [family, quality] :
       {std::pair<std::string, std::string>{"torus-unstructured", "well-shaped"},
        {"torus-iso-projected", "isosurface"},
        {"bump-irregular", "irregular"}}) {
    const std::string mesh = off_of(dir, family);
    auto r = run_cli("recommend " + mesh + results);  // estimated: noise-free meshes
    ASSERT_EQ(r.exit_code, 0) << r.output;
    EXPECT_NE(r.output.find("quality:       " + quality + " ("), std::string::npos) << r.output;
    EXPECT_NE(r.output.find("(estimated"), std::string::npos) << r.output;
    EXPECT_NE(r.output.find("M-" + quality + "-0\n"), std::string::npos) << r.output;
    r = run_cli("recommend " + mesh + " --noise 0.05" + results);
    ASSERT_EQ(r.exit_code, 0) << r.output;
    EXPECT_NE(r.output.find("given by --noise"), std::string::npos) << r.output;
    EXPECT_NE(r.output.find("M-" + quality + "-0.03\n"), std::string::npos) << r.output;
  }
  const std::string mesh = (dir / "torus-unstructured.off").string();
  for (const auto& [noise, level] :
       {std::pair<std::string, std::string>{"0.004", "0"}, {"0.025", "0.03"}, {"0.5", "0.1"}}) {
    const auto r = run_cli("recommend " + mesh + " --noise " + noise + results);
    ASSERT_EQ(r.exit_code, 0) << r.output;
    EXPECT_NE(r.output.find("M-well-shaped-" + level + "\n"), std::string::npos) << r.output;
    EXPECT_EQ(r.output.find("no sweep ran"), std::string::npos) << r.output;
  }
  const auto r = run_cli("recommend " + mesh + " --noise 0.008" + results);
  ASSERT_EQ(r.exit_code, 0) << r.output;
  EXPECT_NE(r.output.find("not swept\n  best_label          well-shaped-0.01\n"), std::string::npos)
      << r.output;
  EXPECT_NE(r.output.find("no sweep ran at this noise level"), std::string::npos) << r.output;
  std::filesystem::remove_all(dir);
}

// One line on stderr, exit 2.
void expect_error(const std::string& args, const std::string& words) {
  const auto r = run_cli(args);
  EXPECT_EQ(r.exit_code, 2) << args << ": " << r.output;
  EXPECT_NE(r.output.find(words), std::string::npos) << r.output;
  EXPECT_EQ(std::count(r.output.begin(), r.output.end(), '\n'), 1) << r.output;
}

TEST(CliRecommend, Errors) {
  const auto dir = fresh_dir("recommend_errors");
  write_table(dir);
  const std::string results = " --results " + dir.string();
  const std::string mesh = off_of(dir, "bump-irregular");
  expect_error("recommend " + mesh + " --noise -0.1" + results, "--noise -0.1");
  expect_error("recommend " + mesh + " --results " + (dir / "none").string(), "make experiments");
  expect_error("recommend " + (dir / "missing.off").string() + results, "missing.off");
  std::ofstream(dir / "tri.off") << "OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n";
  expect_error("recommend " + (dir / "tri.off").string() + results, "cannot classify");
  // An 8 x 8 grid with a third triangle on one interior edge: non-manifold.
  std::ofstream nm(dir / "nm.off");
  nm << "OFF\n65 99 0\n";
  for (int j = 0; j < 8; ++j)
    for (int i = 0; i < 8; ++i) nm << i << ' ' << j << " 0\n";
  nm << "0.5 0.5 1\n";
  for (int j = 0; j < 7; ++j)
    for (int i = 0; i < 7; ++i) {
      const int a = 8 * j + i;
      nm << "3 " << a << ' ' << a + 1 << ' ' << a + 9 << "\n3 " << a << ' ' << a + 9 << ' ' << a + 8
         << "\n";
    }
  nm << "3 9 18 64\n";
  nm.close();
  expect_error("recommend " + (dir / "nm.off").string() + results, "non-manifold");
  std::filesystem::remove_all(dir);
}

}  // namespace
}  // namespace curvbench
