// A study sharded over processes (the cluster recipe of docs/cluster.md): three concurrent
// `curvbench run --shard K/3` processes into one case store (--cache), then `--report-only`, give
// the same bytes (CSVs, rates, REPORT.md, CLAIMS.md, plots) as one single-process run, checked by
// tools/cluster/same_outputs.sh (also the Slurm test's check). Also: the case ids and the
// partition (--list-cases), and the report of an incomplete store naming what is missing.
#include <gtest/gtest.h>
#include <sys/wait.h>

#include <algorithm>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <map>
#include <set>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

#include "tests/cli/cli_runner.h"

namespace curvbench {
namespace {

using testing::fresh_dir;
using testing::run_cli;
using testing::slurp;
namespace fs = std::filesystem;

// 2 meshes x 2 levels x 3 methods = 12 small cases.
void write_shard_experiment(const fs::path& dir) {
  fs::create_directories(dir);
  std::ofstream(dir / "shard.exp")
      << "title   \"Shard check\"\n"
         "section 5.2\n"
         "mesh    bump-48 levels=1,2\n"
         "mesh    torus-structured levels=1,2\n"
         "method  lhf-2\n"
         "method  lop-2\n"
         "method  lhf-4\n"
         "panel   shard-n \"Fig. 0. L2 errors in normals.\" normal L2\n"
         "panel   shard-h \"Fig. 0. L2 errors in H.\" H L2\n";
}

std::vector<std::string> lines(const std::string& text) {
  std::vector<std::string> out;
  std::istringstream in(text);
  for (std::string l; std::getline(in, l);)
    if (!l.empty()) out.push_back(l);
  return out;
}

// Every file under `dir` (relative path -> bytes), skipping the case store.
std::map<std::string, std::string> outputs_without_cache(const fs::path& dir) {
  return testing::files_under(dir, {".cache"});
}

class CliShard : public ::testing::Test {
 protected:
  void SetUp() override {
    ::setenv("SOURCE_DATE_EPOCH", "1790000000", 1);
    root_ = fresh_dir("cli_shard");
    write_shard_experiment(root_ / "experiments");
    common_ =
        " --experiments-dir " + (root_ / "experiments").string() + " --table4-max 16 --threads 1";
  }
  void TearDown() override { fs::remove_all(root_); }
  fs::path root_;
  std::string common_;
};

TEST_F(CliShard, ListCasesIsAStablePartitionBalancedByCost) {
  const auto all = run_cli("run shard --list-cases" + common_);
  ASSERT_EQ(all.exit_code, 0) << all.output;
  const auto ids = lines(all.output);
  ASSERT_EQ(ids.size(), 12u) << all.output;
  EXPECT_EQ(ids.front().rfind("shard/bump-48_L1_lhf-2_", 0), 0u) << ids.front();
  EXPECT_EQ(std::set<std::string>(ids.begin(), ids.end()).size(), ids.size());
  std::multiset<std::string> union_of_shards;
  for (int k = 1; k <= 3; ++k) {
    const auto r = run_cli("run shard --list-cases --shard " + std::to_string(k) + "/3" + common_);
    ASSERT_EQ(r.exit_code, 0) << r.output;
    const auto mine = lines(r.output);
    // The level-2 LHF-4 cases are the costliest (4^2 x 3.7): one per shard before the rest.
    EXPECT_GE(mine.size(), 2u) << r.output;
    union_of_shards.insert(mine.begin(), mine.end());
    EXPECT_EQ(
        lines(
            run_cli("run shard --list-cases --shard " + std::to_string(k) + "/3" + common_).output),
        mine);
  }
  EXPECT_EQ(union_of_shards, std::multiset<std::string>(ids.begin(), ids.end()));
  for (const char* bad : {"0/3", "4/3", "3", "a/b", "1/0"}) {
    const auto r = run_cli(std::string("run shard --list-cases --shard ") + bad + common_);
    EXPECT_EQ(r.exit_code, 2) << bad << ": " << r.output;
    EXPECT_NE(r.output.find("expected K/N"), std::string::npos) << r.output;
  }
}

TEST_F(CliShard, ThreeShardProcessesThenTheReportEqualOneRun) {
  const fs::path single = root_ / "single", sharded = root_ / "sharded", store = root_ / "store";
  const auto one = run_cli("run shard --output " + single.string() + common_);
  ASSERT_EQ(one.exit_code, 0) << one.output;

  // An empty store: the report names the missing cases.
  const std::string report =
      "run shard --report-only --output " + sharded.string() + " --cache " + store.string();
  auto r = run_cli(report + common_);
  EXPECT_EQ(r.exit_code, 2) << r.output;
  EXPECT_NE(r.output.find("12 of 12 cases missing"), std::string::npos) << r.output;

  // docs/cluster.md's recipe: three shard processes at once into one store, then the report.
  const std::string exe = std::string(CURVBENCH_BINARY_DIR) + "/curvbench";
  const std::string shards = "for k in 1 2 3; do " + exe + " run shard --cache " + store.string() +
                             " --output " + sharded.string() + " --shard $k/3" + common_ +
                             " & done; wait";
  ASSERT_EQ(
      std::system(("(" + shards + ") > " + (root_ / "shards.log").string() + " 2>&1").c_str()), 0)
      << slurp(root_ / "shards.log");
  const std::string log = slurp(root_ / "shards.log");
  for (const char* k : {"shard 1/3 done", "shard 2/3 done", "shard 3/3 done"})
    EXPECT_NE(log.find(k), std::string::npos) << log;
  // Shards write only the store.
  EXPECT_FALSE(fs::exists(sharded / "shard.csv"));
  EXPECT_FALSE(fs::exists(sharded / "REPORT.md"));

  r = run_cli(report + common_);
  ASSERT_EQ(r.exit_code, 0) << r.output;
  const auto want = outputs_without_cache(single), got = outputs_without_cache(sharded);
  ASSERT_TRUE(want.count("REPORT.md") && want.count("shard.csv") && want.count("CLAIMS.md"));
  ASSERT_TRUE(want.count("plots/shard-h_torus-structured.svg"));
  ASSERT_TRUE(want.count("errors_by_cause/shard.csv"));  // from the store's finest-level cases
  ASSERT_TRUE(want.count("timings/shard.csv"));
  // The comparison is tools/cluster/same_outputs.sh's, which the Slurm test uses too: same files
  // and bytes, except timings/ (each case's measured seconds: same rows, not the same seconds).
  const auto same = [&](const fs::path& a, const fs::path& b) {
    const fs::path out = root_ / "same.log";
    const std::string cmd = std::string("bash ") + CURVBENCH_SOURCE_DIR +
                            "/tools/cluster/same_outputs.sh " + a.string() + " " + b.string() +
                            " > " + out.string() + " 2>&1";
    const int status = std::system(cmd.c_str());
    return std::make_pair(WIFEXITED(status) ? WEXITSTATUS(status) : -1, slurp(out));
  };
  const auto [code, text] = same(single, sharded);
  EXPECT_EQ(code, 0) << text;
  EXPECT_NE(text.find("same outputs: " + std::to_string(want.size()) + " files"), std::string::npos)
      << text;
  // The comparison can fail: one changed byte, one timings row more.
  const fs::path copy = root_ / "copy";
  fs::copy(sharded, copy, fs::copy_options::recursive);
  std::ofstream(copy / "REPORT.md", std::ios::app) << ' ';
  std::ofstream(copy / "timings" / "shard.csv", std::ios::app) << "row\n";
  const auto [bad_code, bad_text] = same(single, copy);
  EXPECT_EQ(bad_code, 1) << bad_text;
  EXPECT_NE(bad_text.find("differs: REPORT.md"), std::string::npos) << bad_text;
  EXPECT_NE(bad_text.find("differs (row count): timings/shard.csv"), std::string::npos) << bad_text;
  EXPECT_EQ(got.size(), want.size());

  // The parts chosen by measured times: recommendations.csv from its column best_seconds (18)
  // on, report/sweeps.md's section "Choosing an estimator and a radius" (same line count) and the
  // cells of the site's pages may differ; an error may not, nor a page's number of charts.
  const fs::path timed_a = root_ / "timed_a", timed_b = root_ / "timed_b";
  const std::string head = "# provenance\nquality,s,status,e,f,1,9,0.1,none,H,L2,3,";
  const auto write_timed = [&](const fs::path& d, const std::string& error,
                               const std::string& seconds) {
    fs::create_directories(d);
    std::ofstream(d / "recommendations.csv")
        << head << "LHF-2,rings,2,LHF-2 rings=2," << error << "," << seconds << ",ICC\n";
    fs::create_directories(d / "report");
    std::ofstream(d / "report" / "sweeps.md")
        << "# r\n\n## Choosing an estimator and a radius\n\n| " << seconds << " |\n";
    fs::create_directories(d / "site");
    std::ofstream(d / "site" / "cost.html") << "<section><canvas></canvas><table><tr><td>"
                                            << seconds << "</td></tr></table></section>\n";
  };
  write_timed(timed_a, "0.001", "0.0046");
  write_timed(timed_b, "0.001", "0.0099");
  EXPECT_EQ(same(timed_a, timed_b).first, 0) << same(timed_a, timed_b).second;
  write_timed(timed_b, "0.002", "0.0046");
  const auto [timed_code, timed_text] = same(timed_a, timed_b);
  EXPECT_EQ(timed_code, 1) << timed_text;
  EXPECT_NE(timed_text.find("differs (before best_seconds): recommendations.csv"),
            std::string::npos)
      << timed_text;
  std::ofstream(timed_b / "site" / "cost.html", std::ios::app) << "<canvas></canvas>\n";
  EXPECT_NE(same(timed_a, timed_b).second.find("differs (number of <canvas): site/cost.html"),
            std::string::npos);

  // A store missing one case: the report fails and names it.
  const auto ids = lines(run_cli("run shard --list-cases --shard 2/3" + common_).output);
  ASSERT_FALSE(ids.empty());
  ASSERT_TRUE(fs::remove(store / (ids.front() + ".csv")));
  r = run_cli(report + common_);
  EXPECT_EQ(r.exit_code, 2) << r.output;
  EXPECT_NE(r.output.find("1 of 12 cases missing"), std::string::npos) << r.output;
  EXPECT_NE(r.output.find(ids.front()), std::string::npos) << r.output;
}

// The alternative readings (harness/readings/readings.h) are cases too: each shard computes its
// part of them into the store's readings/ folder, and the report writes their CSVs as one run does.
TEST_F(CliShard, ShardsComputeTheReadingsToo) {
  const fs::path dir = root_ / "reading-experiments";
  fs::create_directories(dir);
  // The safeguard readings re-run LHF-2 (a ring fit) on any mesh; bump-irregular, not the
  // well-shaped torus, whose table of levels 1-4 every unsharded run would write (25 s).
  std::ofstream(dir / "well.exp") << "title   \"Reading check\"\n"
                                     "section 5.1\n"
                                     "mesh    bump-irregular levels=1\n"
                                     "method  lhf-2\n"
                                     "method  xu-2\n"
                                     "panel   well-n \"Fig. 0. L2 errors in normals.\" normal L2\n";
  const std::string common =
      " --experiments-dir " + dir.string() + " --table4-max 16 --threads 1 --no-plots";
  const fs::path single = root_ / "single", sharded = root_ / "sharded", store = root_ / "store";
  const auto one = run_cli("run well --output " + single.string() + common);
  ASSERT_EQ(one.exit_code, 0) << one.output;
  const std::string reading_csv = "readings/safeguard=rjj-only/well.csv";
  ASSERT_TRUE(fs::exists(single / reading_csv)) << one.output;
  for (int k = 1; k <= 2; ++k) {
    const auto r = run_cli("run well --cache " + store.string() + " --output " + sharded.string() +
                           " --shard " + std::to_string(k) + "/2" + common);
    ASSERT_EQ(r.exit_code, 0) << r.output;
    EXPECT_FALSE(fs::exists(sharded / reading_csv)) << "a shard writes only the store";
  }
  const auto r = run_cli("run well --report-only --cache " + store.string() + " --output " +
                         sharded.string() + common);
  ASSERT_EQ(r.exit_code, 0) << r.output;
  const auto want = outputs_without_cache(single), got = outputs_without_cache(sharded);
  for (const char* name : {"well.csv", "CLAIMS.md", "REPORT.md"}) {
    ASSERT_TRUE(want.count(name) && got.count(name)) << name;
    EXPECT_TRUE(got.at(name) == want.at(name)) << name << " differs from the single-process run";
  }
  ASSERT_TRUE(got.count(reading_csv)) << r.output;
  EXPECT_TRUE(got.at(reading_csv) == want.at(reading_csv));
}

}  // namespace
}  // namespace curvbench
