// The leaderboard (harness/report/leaderboard.h) and the report's pages (harness/report/pages.h): a
// class with several meshes shows each estimator's worst; the CSV round-trips; the site is written
// whole or not at all; the summary names the winners.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "core/errors.h"
#include "harness/model/experiment.h"
#include "harness/report/leaderboard.h"
#include "harness/report/pages.h"
#include "harness/run_pipeline.h"
#include "tests/cli/cli_runner.h"
#include "tests/harness/synthetic_rows.h"

namespace curvbench {
namespace {

namespace fs = std::filesystem;

Experiment field_experiment() {
  return parse_experiment_text(
      "title \"Field test\"\nsection beyond\nreport field\n"
      "mesh torus-unstructured levels=1,2,3\nmesh torus-structured levels=1,2,3\n"
      "mesh torus-iso-projected levels=1,2,3\nmethod lhf-2\nmethod meyer\n"
      "panel ft-h \"Field test. L2 errors in H.\" H L2\n",
      "field-test.exp");
}

// LHF-2: 1e-2 at rate 2 on the unstructured torus, 4e-2 at rate 1 on the structured one, 1e-3 at
// rate 3 on the isosurface; Meyer 1e-1 at rate 0 on the unstructured torus only.
fs::path write_field_results(const std::string& name) {
  const auto dir = testing::fresh_dir(name);
  std::vector<ErrorRow> rows;
  const auto add = [&](const std::string& family, const std::string& method, double e0,
                       double rate) {
    for (ErrorRow r : testing::synthetic_series("field-test", family, method, e0, rate))
      rows.push_back(r);
  };
  add("torus-unstructured", "LHF-2", 1e-2, 2.0);
  add("torus-structured", "LHF-2", 4e-2, 1.0);
  add("torus-iso-projected", "LHF-2", 1e-3, 3.0);
  add("torus-unstructured", "Meyer", 1e-1, 0.0);
  write_error_csv((dir / "field-test.csv").string(), rows);
  write_timing_csv((dir / "timings" / "field-test.csv").string(), rows);
  return dir;
}

const LeaderRow* find(const std::vector<LeaderRow>& rows, const std::string& method,
                      const std::string& cls) {
  for (const LeaderRow& r : rows)
    if (r.method == method && r.mesh_class == cls && r.quantity == "H" && r.norm == "L2") return &r;
  return nullptr;
}

TEST(Leaderboard, AClassShowsTheWorstOfItsMeshes) {
  const auto dir = write_field_results("leaderboard_worst");
  const auto rows = leaderboard_rows({field_experiment()}, dir.string());
  const LeaderRow* lhf = find(rows, "LHF-2", "well-shaped");
  ASSERT_NE(lhf, nullptr);
  EXPECT_DOUBLE_EQ(lhf->error, 4e-2 / 4);  // the structured torus's finest error, rate 1
  EXPECT_NEAR(lhf->rate, 1.0, 1e-12);      // the smaller rate
  EXPECT_EQ(lhf->meshes, "torus-structured torus-unstructured");
  EXPECT_EQ(lhf->group, "paper fits");
  EXPECT_NEAR(lhf->us_per_vertex, 5.0, 1e-9);
  const LeaderRow* iso = find(rows, "LHF-2", "isosurface");
  ASSERT_NE(iso, nullptr);
  EXPECT_NEAR(iso->rate, 3.0, 1e-12);
  const LeaderRow* meyer = find(rows, "Meyer", "well-shaped");
  ASSERT_NE(meyer, nullptr);
  EXPECT_EQ(meyer->group, "discrete operators");
  EXPECT_EQ(find(rows, "Meyer", "isosurface"), nullptr);

  write_leaderboard_csv((dir / "leaderboard.csv").string(), rows);
  const auto back = read_leaderboard_csv((dir / "leaderboard.csv").string());
  ASSERT_EQ(back.size(), rows.size());
  EXPECT_EQ(back[0].method, rows[0].method);
  EXPECT_EQ(back[0].error, rows[0].error) << "shortest round-trip";
}

TEST(Leaderboard, TheSummaryNamesEachClassWinner) {
  const auto dir = write_field_results("leaderboard_summary");
  const auto rows = leaderboard_rows({field_experiment()}, dir.string());
  ClaimView miss;
  miss.id = "B1";
  miss.statement = "LHF-2 converges at rate 2.";
  miss.verdict = "not reproduced";
  miss.why =
      "No cause found. Localised (where the miss is, not why): the structured torus "
      "(experiment fig03-05): 1.0. Tried: more.";
  const std::string md = summary_markdown({}, rows, {"**Summary:** counts.", {miss}}, dir.string());
  EXPECT_NE(md.find("| well-shaped | - | [LHF-2 1.00e-02 (1.00)](report/field-test.md) | - | - |"),
            std::string::npos)
      << md;
  EXPECT_NE(md.find("**Summary:** counts."), std::string::npos);
  EXPECT_NE(
      md.find("- **B1** LHF-2 converges at rate 2. localised, no cause: the structured torus.\n"),
      std::string::npos)
      << "one line per miss, its Why line's verdict on the cause";
  EXPECT_LT(std::count(md.begin(), md.end(), '\n'), 150);
}

TEST(ReportPages, SiteIsWrittenWholeOrNotAtAll) {
  const auto dir = write_field_results("site_whole");
  fs::create_directories(dir / "site");
  { std::ofstream(dir / "site" / "index.html") << "old"; }
  ReportFiles files;
  files.results_dir = dir.string();
  files.chart_js = (dir / "no-such-chart.js").string();
  ReportContent content;
  EXPECT_THROW(write_site({field_experiment()}, content, {}, {}, files), InputError);
  EXPECT_EQ(testing::slurp(dir / "site" / "index.html"), "old") << "the old site stays";
  for (const auto& f : fs::directory_iterator(dir))
    EXPECT_EQ(f.path().filename().string().find(".tmp."), std::string::npos) << f.path();
}

TEST(RenderResults, BadCsvsStopNamingTheFile) {
  const auto dir = write_field_results("render_bad");
  RenderOptions o;
  o.experiments = {field_experiment()};
  o.output = dir.string();
  o.plots = false;
  o.site = false;
  o.require_all = true;
  // Missing.
  fs::rename(dir / "field-test.csv", dir / "kept.csv");
  try {
    render_results(o);
    ADD_FAILURE() << "a missing CSV must throw";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("field-test.csv: not found"), std::string::npos);
  }
  // Truncated: the last row cut in half.
  std::string text = testing::slurp(dir / "kept.csv");
  { std::ofstream(dir / "field-test.csv") << text.substr(0, text.size() - 40); }
  try {
    render_results(o);
    ADD_FAILURE() << "a truncated CSV must throw";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("field-test.csv"), std::string::npos) << e.what();
  }
  // Another version: a column missing.
  std::string other;  // every line without its last field ("failed")
  for (size_t at = 0; at < text.size();) {
    const size_t end = text.find('\n', at);
    const std::string line = text.substr(at, end - at);
    other += (line.rfind('#', 0) == 0 ? line : line.substr(0, line.rfind(','))) + "\n";
    at = end == std::string::npos ? text.size() : end + 1;
  }
  { std::ofstream(dir / "field-test.csv") << other; }
  EXPECT_THROW(render_results(o), InputError);
}

}  // namespace
}  // namespace curvbench
