// write_report (harness/report.h): the figure section of REPORT.md from an experiment's CSV:
// the panel caption, the family's caption from the family table, one row per method with its
// errors per level and the rate between the first and last level; a missing CSV is said.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <string>
#include <vector>

#include "harness/experiment.h"
#include "harness/report.h"
#include "harness/results_table.h"
#include "meshgen/generate.h"
#include "tests/cli/cli_runner.h"
#include "tests/harness/synthetic_rows.h"

// GCC 12 reports a false -Wrestrict for short string assignments inlined at -O3 (GCC bug
// 105329), as in bench/bench_estimators.cpp.
#pragma GCC diagnostic ignored "-Wrestrict"

namespace curvbench {
namespace {

// H L2 errors e0 (h / 0.4)^rate on levels 1-3 of torus-unstructured (h = 0.4, 0.2, 0.1).
std::vector<ErrorRow> rows_of(const std::string& method, double e0, double rate) {
  return testing::synthetic_series("report-test", "torus-unstructured", method, e0, rate);
}

Experiment experiment(const std::string& section = "5.2") {
  return parse_experiment_text(
      "name report-test\ntitle \"A report test\"\nsection " + section +
          "\n"
          "mesh torus-unstructured levels=1,2,3\nmethod lhf-2\nmethod lhf-4\n"
          "panel rt-h \"Report test. L2 errors in H.\" H L2\n",
      "report-test.exp");
}

TEST(WriteReport, FigureSectionHasCaptionsErrorsAndRates) {
  const auto dir = testing::fresh_dir("report_figures");
  std::vector<ErrorRow> rows = rows_of("LHF-2", 1e-2, 2.0);
  for (const ErrorRow& r : rows_of("LHF-4", 1e-4, 4.0)) rows.push_back(r);
  write_error_csv((dir / "report-test.csv").string(), rows);
  ReportOptions o;
  o.results_dir = dir.string();
  o.plots = false;
  const std::string path = write_report({experiment()}, o);
  ASSERT_EQ(path, (dir / "REPORT.md").string());
  const std::string md = testing::slurp(path);
  EXPECT_NE(md.find("## report-test: A report test (paper §5.2)"), std::string::npos);
  EXPECT_NE(md.find("### Report test. L2 errors in H."), std::string::npos);
  EXPECT_NE(md.find("**" + mesh_family("torus-unstructured").caption + "** (`torus-unstructured`"),
            std::string::npos)
      << "the caption comes from the family table";
  // Rates from the first and the last level: exactly 2 and 4 (printed with two decimals).
  const auto row = [&](const std::string& method) {
    const auto at = md.find("| " + method + " |");
    EXPECT_NE(at, std::string::npos) << method;
    return at == std::string::npos ? std::string() : md.substr(at, md.find('\n', at) - at);
  };
  EXPECT_NE(row("LHF-2").find("**2.00**"), std::string::npos) << row("LHF-2");
  EXPECT_NE(row("LHF-4").find("**4.00**"), std::string::npos) << row("LHF-4");
  EXPECT_NE(row("LHF-4").find("1.00e-04"), std::string::npos) << row("LHF-4");
  EXPECT_NE(row("LHF-4").find("6.25e-06"), std::string::npos) << row("LHF-4");  // 1e-4 / 16

  // A study beyond the paper says so, not "paper §beyond".
  const std::string md_beyond = testing::slurp(write_report({experiment("beyond")}, o));
  EXPECT_NE(md_beyond.find("## report-test: A report test (beyond the paper)\n"),
            std::string::npos);
  EXPECT_EQ(md_beyond.find("§beyond"), std::string::npos);
}

TEST(WriteReport, MissingCsvIsSaidAndStopLeavesNoReport) {
  const auto dir = testing::fresh_dir("report_missing");
  ReportOptions o;
  o.results_dir = dir.string();
  o.plots = false;
  const std::string md = testing::slurp(write_report({experiment()}, o));
  EXPECT_NE(md.find("Not run yet: " + (dir / "report-test.csv").string() + " is missing."),
            std::string::npos);
  // A stop request before the first plot: no REPORT.md is written (the previous one stays).
  std::filesystem::remove(dir / "REPORT.md");
  write_error_csv((dir / "report-test.csv").string(), rows_of("LHF-2", 1e-2, 2.0));
  o.plots = true;
  o.stop = [] { return true; };
  EXPECT_EQ(write_report({experiment()}, o), "");
  EXPECT_FALSE(std::filesystem::exists(dir / "REPORT.md"));
}

}  // namespace
}  // namespace curvbench
