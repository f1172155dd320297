// build_report (harness/report/report.h): an experiment's section from its CSV, rendered to
// markdown: the panel caption, the family's caption from the family table, one row per method with
// its errors per level and the rate between the first and last level; one table per vertex set; a
// missing CSV is said; a stop request gives nothing.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <string>
#include <vector>

#include "core/errors.h"
#include "harness/model/experiment.h"
#include "harness/model/results_table.h"
#include "harness/report/point_clouds.h"
#include "harness/report/report.h"
#include "meshgen/generate.h"
#include "tests/cli/cli_runner.h"
#include "tests/harness/synthetic_rows.h"

// GCC 12 reports a false -Wrestrict for short string assignments inlined at -O3 (GCC bug
// 105329), as in bench/bench_estimators.cpp.
#pragma GCC diagnostic ignored "-Wrestrict"

namespace curvbench {
namespace {

// H L2 errors e0 (h / 0.4)^rate on levels 1-3 of torus-unstructured (h = 0.4, 0.2, 0.1).
std::vector<ErrorRow> rows_of(const std::string& method, double e0, double rate,
                              const std::string& set = "all") {
  auto rows = testing::synthetic_series("report-test", "torus-unstructured", method, e0, rate);
  for (ErrorRow& r : rows) r.vertex_set = set;
  return rows;
}

Experiment experiment(const std::string& section = "5.2") {
  return parse_experiment_text(
      "title \"A report test\"\nsection " + section +
          "\n"
          "mesh torus-unstructured levels=1,2,3\nmethod lhf-2\nmethod lhf-4\n"
          "panel rt-h \"Report test. L2 errors in H.\" H L2\n",
      "report-test.exp");
}

// The markdown of the experiment's section.
std::string experiment_markdown(const std::filesystem::path& dir, const std::string& section) {
  ReportOptions o;
  o.results_dir = dir.string();
  o.plots = false;
  const auto content = build_report({experiment(section)}, o);
  EXPECT_TRUE(content.has_value());
  if (!content || content->experiments.empty()) return "";
  return report::to_markdown(content->experiments.front());
}

// The table line of a method: "| LHF-2 | ... |" (the first one from `from`).
std::string method_line(const std::string& md, const std::string& method, size_t from = 0) {
  const auto at = md.find("| " + method + " |", from);
  return at == std::string::npos ? std::string() : md.substr(at, md.find('\n', at) - at);
}

TEST(BuildReport, ExperimentSectionHasCaptionsErrorsAndRates) {
  const auto dir = testing::fresh_dir("report_figures");
  std::vector<ErrorRow> rows = rows_of("LHF-2", 1e-2, 2.0);
  for (const ErrorRow& r : rows_of("LHF-4", 1e-4, 4.0)) rows.push_back(r);
  write_error_csv((dir / "report-test.csv").string(), rows);
  const std::string md = experiment_markdown(dir, "5.2");
  EXPECT_NE(md.find("## report-test: A report test (paper §5.2)"), std::string::npos);
  EXPECT_NE(md.find("### Report test. L2 errors in H."), std::string::npos);
  EXPECT_NE(md.find("**" + mesh_family("torus-unstructured").caption + "** (`torus-unstructured`"),
            std::string::npos)
      << "the caption comes from the family table";
  // Rates from the first and the last level: exactly 2 and 4 (printed with two decimals).
  EXPECT_NE(method_line(md, "LHF-2").find("**2.00**"), std::string::npos)
      << method_line(md, "LHF-2");
  EXPECT_NE(method_line(md, "LHF-4").find("**4.00**"), std::string::npos)
      << method_line(md, "LHF-4");
  EXPECT_NE(method_line(md, "LHF-4").find("1.00e-04"), std::string::npos);
  EXPECT_NE(method_line(md, "LHF-4").find("6.25e-06"), std::string::npos);  // 1e-4 / 16

  // A study beyond the paper says so, not "paper §beyond".
  const std::string md_beyond = experiment_markdown(dir, "beyond");
  EXPECT_NE(md_beyond.find("## report-test: A report test (beyond the paper)\n"),
            std::string::npos);
  EXPECT_EQ(md_beyond.find("§beyond"), std::string::npos);
}

// Rows of two vertex sets of one method never share a table: each caption names its set and
// holds that set's errors (the diag-b4 tables once printed the valence-5 rows under the
// valence-4 caption).
TEST(BuildReport, EachVertexSetHasItsOwnTable) {
  const auto dir = testing::fresh_dir("report_sets");
  std::vector<ErrorRow> rows = rows_of("LHF-2", 1e-2, 2.0, "valence-4-or-less");
  for (const ErrorRow& r : rows_of("LHF-2", 3e-2, 1.0, "valence-5-or-more")) rows.push_back(r);
  write_error_csv((dir / "report-test.csv").string(), rows);
  const std::string md = experiment_markdown(dir, "5.1");
  const size_t four = md.find("vertex set valence-4-or-less");
  const size_t five = md.find("vertex set valence-5-or-more");
  ASSERT_NE(four, std::string::npos);
  ASSERT_NE(five, std::string::npos);
  ASSERT_LT(four, five);
  EXPECT_NE(method_line(md, "LHF-2", four).find("1.00e-02"), std::string::npos);
  EXPECT_NE(method_line(md, "LHF-2", four).find("**2.00**"), std::string::npos);
  EXPECT_NE(method_line(md, "LHF-2", five).find("3.00e-02"), std::string::npos);
  EXPECT_NE(method_line(md, "LHF-2", five).find("**1.00**"), std::string::npos);
}

TEST(BuildReport, PlotsHoldTheSeriesWithRatesAndReferenceSlopes) {
  const auto dir = testing::fresh_dir("report_plot_series");
  std::vector<ErrorRow> rows = rows_of("LHF-2", 1e-2, 2.0);
  write_error_csv((dir / "report-test.csv").string(), rows);
  ReportOptions o;
  o.results_dir = dir.string();
  o.plots = false;
  const auto content = build_report({experiment()}, o);
  ASSERT_TRUE(content);
  const report::Plot* plot = nullptr;
  for (const auto& b : content->experiments.front().blocks)
    if (const auto* p = std::get_if<report::Plot>(&b)) plot = p;
  ASSERT_NE(plot, nullptr);
  ASSERT_EQ(plot->series.size(), 2u);  // LHF-2 and the O(h^2) slope
  EXPECT_EQ(plot->series[0].label, "LHF-2 (rate 2.00)");
  ASSERT_EQ(plot->series[0].points.size(), 3u);
  EXPECT_DOUBLE_EQ(plot->series[0].points[2].x, 0.1);
  EXPECT_DOUBLE_EQ(plot->series[0].points[2].y, 1e-2 / 16);
  EXPECT_EQ(plot->series[1].label, "O(h^2)");
  // The slope: half the coarsest error at h = 0.4, falling as h^2 to h = 0.1.
  EXPECT_DOUBLE_EQ(plot->series[1].points[0].y, 0.5e-2);
  EXPECT_DOUBLE_EQ(plot->series[1].points[1].y, 0.5e-2 / 16);
  EXPECT_TRUE(plot->image.empty()) << "no PNG without plots";
}

TEST(BuildReport, MissingCsvIsSaidAndStopGivesNothing) {
  const auto dir = testing::fresh_dir("report_missing");
  const std::string md = experiment_markdown(dir, "5.2");
  EXPECT_NE(md.find("Not run yet: " + (dir / "report-test.csv").string() + " is missing."),
            std::string::npos);
  write_error_csv((dir / "report-test.csv").string(), rows_of("LHF-2", 1e-2, 2.0));
  ReportOptions o;
  o.results_dir = dir.string();
  o.plots = true;
  o.stop = [] { return true; };
  EXPECT_FALSE(build_report({experiment()}, o).has_value());
}

// The point-cloud study's section: per estimator and point-set series the finest error with its
// rate, the least error of a column marked; the torus as a mesh and as points side by side with
// the ratio of their finest H errors. LHF-2: mesh 1e-2 at rate 2 (finest 6.25e-4), points 2e-2 at
// rate 1.5 (finest 2e-2 / 8 = 2.5e-3): ratio 4.00. Jet-2 on the blue-noise points only, 2e-2 at
// rate 2 (finest 1.25e-3, the column's least).
TEST(PointCloudStudy, RateTableAndSideBySide) {
  const auto dir = testing::fresh_dir("point_cloud_study");
  std::vector<ErrorRow> rows;
  const auto add = [&](const char* family, const char* method, double e0, double rate) {
    for (ErrorRow r : testing::synthetic_series("pc-test", family, method, e0, rate)) {
      r.surface = "torus";
      rows.push_back(r);
    }
  };
  add("torus-unstructured", "LHF-2", 1e-2, 2.0);
  add("points-torus-uniform", "LHF-2", 2e-2, 1.5);
  add("points-torus-blue", "LHF-2", 1e-2, 1.0);
  add("points-torus-blue", "Jet-2", 2e-2, 2.0);
  write_error_csv((dir / "pc-test.csv").string(), rows);
  const Experiment e = parse_experiment_text(
      "title \"Point test\"\nsection beyond\nreport points\n"
      "mesh points-torus-uniform levels=1,2,3\nmesh points-torus-blue levels=1,2,3\n"
      "mesh torus-unstructured levels=1,2,3\nmethod lhf-2\nmethod jet-2\n"
      "panel p \"P.\" H L2\n",
      "pc-test.exp");
  const std::string md = report::to_markdown(point_cloud_section({e}, dir.string()));
  EXPECT_NE(md.find("| estimator | torus-uniform | torus-blue |"), std::string::npos) << md;
  EXPECT_NE(md.find("| LHF-2 | **2.50e-03 (1.50)** | 2.50e-03 (1.00) |"), std::string::npos) << md;
  EXPECT_NE(md.find("| Jet-2 | - | **1.25e-03 (2.00)** |"), std::string::npos) << md;
  EXPECT_NE(md.find("| `torus-unstructured` / `points-torus-uniform` | LHF-2 | - | - | "
                    "6.25e-04 (2.00) | 2.50e-03 (1.50) | 4.00 |"),
            std::string::npos)
      << md;
  // Without results, one line says so.
  const auto empty = testing::fresh_dir("point_cloud_study_empty");
  EXPECT_NE(report::to_markdown(point_cloud_section({e}, empty.string())).find("No point-cloud"),
            std::string::npos);
  EXPECT_TRUE(point_cloud_summary({e}, empty.string()).blocks.empty());
}

// CSV fields in double quotes keep their commas and read "" as one quote (make bench's
// limits.csv quotes its notes: its report step used to fail, "expected 6 fields, got 9").
TEST(CsvTable, QuotedFieldsKeepTheirCommas) {
  const CsvTable t = parse_csv_table(
      "# provenance\nstage,bound_kind,notes\n"
      "read,\"plain copy (read(2), 1 MiB buffer)\",\"110 MB, \"\"fast\"\"\"\r\n",
      "limits.csv");
  ASSERT_EQ(t.rows.size(), 1u);
  EXPECT_EQ(t.text(0, t.col("bound_kind")), "plain copy (read(2), 1 MiB buffer)");
  EXPECT_EQ(t.text(0, t.col("notes")), "110 MB, \"fast\"");
  EXPECT_THROW(parse_csv_table("a,b\n1,2,3\n", "x.csv"), InputError);
}

}  // namespace
}  // namespace curvbench
