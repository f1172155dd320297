// `curvbench report`: the report and the site re-rendered from a results folder's CSVs, computing
// nothing; a CSV that is missing, truncated or written by another version exits 2 naming it and
// leaves the previous site in place.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <string>

#include "tests/cli/cli_runner.h"

namespace curvbench {
namespace {

using testing::fresh_dir;
using testing::run_cli;
using testing::slurp;
namespace fs = std::filesystem;

// A results folder from one small run (LHF-2 on the 4-8 bump, levels 1-2).
fs::path small_results(const fs::path& dir) {
  fs::create_directories(dir / "experiments");
  std::ofstream(dir / "experiments" / "small.exp")
      << "title   \"Small\"\nsection 5.2\nmesh    bump-48 levels=1,2\n"
         "method  lhf-2\npanel   small-h \"L2 errors in H.\" H L2\n";
  const auto r =
      run_cli("run small --experiments-dir " + (dir / "experiments").string() + " --output " +
              (dir / "results").string() + " --table4-max 16 --threads 1 --no-plots --no-readings");
  EXPECT_EQ(r.exit_code, 0) << r.output;
  return dir / "results";
}

TEST(CliReport, ReRendersTheSiteAndNamesABadCsv) {
  const auto dir = fresh_dir("cli_report");
  const fs::path results = small_results(dir);
  const std::string report = "report --results " + results.string() + " --experiments-dir " +
                             (dir / "experiments").string() + " --no-plots";
  fs::remove_all(results / "site");
  // --site-only writes the site and nothing else into the results folder.
  const auto stamp = [&] {
    std::string s;
    for (const auto& e : fs::directory_iterator(results))
      if (e.is_regular_file()) s += e.path().filename().string() + ":" + slurp(e.path()) + "\n";
    return s;
  };
  const std::string before = stamp();
  auto r = run_cli(report + " --site-only");
  ASSERT_EQ(r.exit_code, 0) << r.output;
  EXPECT_EQ(stamp(), before) << "a file of the results folder changed";
  ASSERT_TRUE(fs::exists(results / "site" / "exp-small.html"));
  const std::string site = slurp(results / "site" / "exp-small.html");
  EXPECT_NE(site.find("<canvas data-plot=\"small-h_bump-48\""), std::string::npos);

  const std::string csv = slurp(results / "small.csv");
  const auto expect_exit_2_naming = [&](const std::string& why) {
    const auto bad = run_cli(report);
    EXPECT_EQ(bad.exit_code, 2) << why << "\n" << bad.output;
    EXPECT_NE(bad.output.find("small.csv"), std::string::npos) << why << "\n" << bad.output;
    EXPECT_EQ(slurp(results / "site" / "exp-small.html"), site) << why << ": the site changed";
  };
  fs::remove(results / "small.csv");
  expect_exit_2_naming("missing");
  std::ofstream(results / "small.csv") << csv.substr(0, csv.size() - 30);
  expect_exit_2_naming("truncated");
  // Another version: the header without its column "failed" (and the rows without it).
  std::string other;
  for (size_t at = 0; at < csv.size();) {
    const size_t end = csv.find('\n', at);
    const std::string line = csv.substr(at, end - at);
    other += (line.rfind('#', 0) == 0 ? line : line.substr(0, line.rfind(','))) + "\n";
    at = end == std::string::npos ? csv.size() : end + 1;
  }
  std::ofstream(results / "small.csv") << other;
  expect_exit_2_naming("a missing column");
  for (const auto& e : fs::directory_iterator(results))
    EXPECT_EQ(e.path().filename().string().find(".tmp"), std::string::npos) << e.path();
}

}  // namespace
}  // namespace curvbench
