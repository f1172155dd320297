// The REPORT.md section "Sweeps at a fixed mesh" (harness/report/sweeps.h): labels read back into
// method and radius, the best radius per (family, noise, quantity) and best_radius.csv follow the
// rows.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <sstream>
#include <string>
#include <variant>
#include <vector>

#include "harness/model/results_table.h"
#include "harness/report/model.h"
#include "harness/report/sweeps.h"
#include "tests/cli/cli_runner.h"
#include "tests/harness/synthetic_rows.h"

namespace curvbench {
namespace {

namespace fs = std::filesystem;

using testing::sweep_row;

// The typed columns of a row read back from its text: the swept radius from the label, sigma/h
// and the noise model from the noise column.
TEST(ReportSweeps, LabelsAndNoiseLabelsReadBack) {
  const RadiusLabel a = split_radius_label("LHF-2 rings=1.5");
  EXPECT_EQ(a.method, "LHF-2");
  EXPECT_EQ(a.parameter, "rings");
  EXPECT_EQ(a.radius, 1.5);
  const RadiusLabel b = split_radius_label("My ICC ball-factor=4");
  EXPECT_EQ(b.method, "My ICC");
  EXPECT_EQ(b.parameter, "ball-factor");
  EXPECT_EQ(b.radius, 4.0);
  const RadiusLabel c = split_radius_label("Meyer");
  EXPECT_EQ(c.method, "Meyer");
  EXPECT_EQ(c.parameter, "");
  EXPECT_TRUE(std::isnan(c.radius));
  EXPECT_EQ(split_radius_label("X rings=wide").parameter, "");
  // A listed option that is not a radius stays in the method's label.
  EXPECT_EQ(split_radius_label("LHF-2 qr-tol=1e-8").method, "LHF-2 qr-tol=1e-8");
  EXPECT_EQ(parse_noise_label("none").sigma_over_h, 0.0);
  EXPECT_EQ(parse_noise_label("normal gauss 0.03h").sigma_over_h, 0.03);
  EXPECT_EQ(parse_noise_label("normal gauss 0.03h").model, "normal gauss");
  EXPECT_EQ(parse_noise_label("tangential uniform 0.1h").sigma_over_h, 0.1);
  for (const char* other : {"h^2", "outliers 1%", "isotropic gauss 0.1h^2", "isosurface", "x 0.1h"})
    EXPECT_TRUE(std::isnan(parse_noise_label(other).sigma_over_h)) << other;
  EXPECT_EQ(parse_noise_label("isotropic uniform 0.003h").model, "isotropic uniform");
  EXPECT_EQ(parse_noise_label("none").model, "");
}

// The smallest error wins, per (noise, quantity); a tie goes to the smaller radius; a NaN error
// never wins; a fixed method keeps its one row.
TEST(ReportSweeps, BestRadiusIsTheSmallestError) {
  std::vector<ErrorRow> rows = {
      sweep_row("torus-unstructured", "LHF-2 rings=1", "none", 0.3, "H"),
      sweep_row("torus-unstructured", "LHF-2 rings=2", "none", 0.1, "H"),
      sweep_row("torus-unstructured", "LHF-2 rings=3", "none", 0.2, "H"),
      sweep_row("torus-unstructured", "LHF-2 rings=4", "none", std::nan(""), "H"),
      sweep_row("torus-unstructured", "LHF-2 rings=1", "none", 0.5, "K"),
      sweep_row("torus-unstructured", "LHF-2 rings=2", "none", 0.5, "K"),
      sweep_row("torus-unstructured", "LHF-2 rings=1", "normal gauss 0.03h", 0.9, "H"),
      sweep_row("torus-unstructured", "LHF-2 rings=4", "normal gauss 0.03h", 0.4, "H"),
      sweep_row("torus-unstructured", "Meyer", "none", 0.7, "H")};
  const std::vector<BestRadius> best = best_radii(rows);
  ASSERT_EQ(best.size(), 4u);
  EXPECT_EQ(best[0].method, "LHF-2");
  EXPECT_EQ(best[0].quantity, "H");
  EXPECT_EQ(best[0].radius, 2.0);
  EXPECT_EQ(best[0].error, 0.1);
  EXPECT_EQ(best[0].label, "LHF-2 rings=2");
  EXPECT_EQ(best[0].radii, 4);
  EXPECT_EQ(best[0].lowest, 1.0);
  EXPECT_EQ(best[0].highest, 4.0);
  EXPECT_EQ(best[1].quantity, "K");
  EXPECT_EQ(best[1].radius, 1.0);  // the tie
  EXPECT_EQ(best[2].noise, "normal gauss 0.03h");
  EXPECT_EQ(best[2].radius, 4.0);
  EXPECT_EQ(best[3].method, "Meyer");
  EXPECT_EQ(best[3].parameter, "");
  EXPECT_EQ(best[3].error, 0.7);

  const fs::path dir = testing::fresh_dir("report_sweeps");
  write_best_radius_csv((dir / "best.csv").string(), best);
  const CsvTable t = read_csv_table((dir / "best.csv").string());
  ASSERT_EQ(t.rows.size(), 4u);
  EXPECT_EQ(t.text(2, t.col("noise")), "normal gauss 0.03h");
  EXPECT_EQ(t.number(2, t.col("sigma_over_h")), 0.03);
  EXPECT_EQ(t.number(2, t.col("best_radius")), 4.0);
  EXPECT_EQ(t.text(3, t.col("parameter")), "fixed");
  EXPECT_EQ(t.number(0, t.col("error")), 0.1);
  EXPECT_EQ(t.number(2, t.col("lowest_radius")), 1.0);
  EXPECT_TRUE(std::isnan(t.number(3, t.col("highest_radius"))));
}

// The section: a table per (family, noise) with each method's best radius and error, and
// best_radius.csv in the results folder; the sweeps are not in the generic per-experiment part.
// After them, the recommendations and recommendations.csv.
TEST(ReportSweeps, SectionAndCsvFromTheResults) {
  const fs::path dir = testing::fresh_dir("report_sweeps_section");
  Experiment e;
  e.name = "sweep-test";
  e.title = "A sweep";
  e.sweep = "radius";
  e.report = ReportSection::sweeps;
  e.source = "experiments/sweep_test.exp";
  std::vector<ErrorRow> rows;
  for (const char* q : {"normal", "H", "K"}) {
    rows.push_back(sweep_row("torus-unstructured", "ICC ball-factor=1", "none", 0.2, q));
    rows.push_back(sweep_row("torus-unstructured", "ICC ball-factor=2", "none", 0.05, q));
    rows.push_back(sweep_row("torus-unstructured", "Meyer", "none", 0.3, q));
    rows[rows.size() - 3].seconds = 0.01;
    rows[rows.size() - 2].seconds = 0.02;
    rows[rows.size() - 1].seconds = 0.005;
  }
  write_error_csv((dir / "sweep-test.csv").string(), rows);
  fs::create_directories(dir / "timings");
  write_timing_csv((dir / "timings" / "sweep-test.csv").string(), rows);
  ReportOptions o;
  o.results_dir = dir.string();
  o.plots = false;
  int missing = 0;
  report::Section section{"sweeps", "", {}};
  ASSERT_TRUE(sweeps_section({e}, o, missing, section));
  const std::string text = report::to_markdown(section);
  EXPECT_NE(text.find("## Sweeps at a fixed mesh"), std::string::npos);
  EXPECT_NE(text.find("| ICC | ball-factor (2 values) | C = 2 (largest) | 5.00e-02 | C = 2 "
                      "(largest) | 5.00e-02 | C = 2 (largest) | 5.00e-02 |"),
            std::string::npos)
      << text;
  EXPECT_NE(text.find("| Meyer | - | 1-ring | 3.00e-01 |"), std::string::npos) << text;
  const CsvTable t = read_csv_table((dir / "best_radius.csv").string());
  EXPECT_EQ(t.rows.size(), 6u);
  EXPECT_EQ(missing, 0);
  // Then the recommendations (harness/report/recommend.h) from the same rows and the timings CSV.
  const auto choosing = text.find("## Choosing an estimator and a radius");
  ASSERT_NE(choosing, std::string::npos) << text;
  EXPECT_GT(choosing, text.find("## Sweeps at a fixed mesh"));
  EXPECT_NE(text.find("| well-shaped | 0 | `ICC ball-factor=2` (largest) | 5.00e-02 | 0.02 s | "
                      "`ICC ball-factor=2` | 5.00e-02 | 0.02 s |"),
            std::string::npos)
      << text;
  // The tables carry their numbers, the plots their series (one per quantity, not rendered).
  std::vector<const report::Table*> tables;
  std::vector<const report::Plot*> plots;
  for (const report::Block& b : section.blocks) {
    if (const auto* tab = std::get_if<report::Table>(&b)) tables.push_back(tab);
    if (const auto* p = std::get_if<report::Plot>(&b)) plots.push_back(p);
  }
  // The sweep's, the recommendations', the cross-validation's summary and its table.
  ASSERT_EQ(tables.size(), 4u);
  EXPECT_EQ(tables[2]->id, "advice-regret-summary");
  // One family only: held out, nothing is left to learn from; no regret is measured.
  EXPECT_TRUE(tables[2]->rows.empty());
  ASSERT_EQ(tables[3]->rows.size(), 1u);
  EXPECT_EQ(tables[3]->rows[0][2].text, "none");
  EXPECT_EQ(read_csv_table((dir / "advice_cases.csv").string()).rows.size(), 6u);  // normal, H
  EXPECT_EQ(read_csv_table((dir / "advice_cross_validation.csv").string()).rows.size(), 2u);
  const report::Table& sweep = *tables[0];
  ASSERT_EQ(sweep.rows.size(), 2u);
  EXPECT_EQ(sweep.rows[0][0].text, "ICC");
  EXPECT_DOUBLE_EQ(sweep.rows[0][2].value, 2.0);
  EXPECT_DOUBLE_EQ(sweep.rows[0][3].value, 5e-2);
  EXPECT_DOUBLE_EQ(sweep.rows[1][3].value, 0.3);
  ASSERT_EQ(plots.size(), 3u);
  EXPECT_EQ(plots[1]->id, "sweep-test_torus-unstructured_none_H");
  EXPECT_FALSE(plots[1]->log_x);
  EXPECT_TRUE(plots[1]->log_y);
  EXPECT_TRUE(plots[1]->image.empty());
  // ICC's curve over its two radii, Meyer's dotted line, the circled best radius.
  ASSERT_EQ(plots[1]->series.size(), 3u);
  EXPECT_EQ(plots[1]->series[0].label, "ICC");
  ASSERT_EQ(plots[1]->series[0].points.size(), 2u);
  EXPECT_EQ(plots[1]->series[1].label, "Meyer (1-ring)");
  EXPECT_EQ(plots[1]->series[1].dash, 3);
  EXPECT_DOUBLE_EQ(plots[1]->series[1].points[0].y, 0.3);
  EXPECT_EQ(plots[1]->series[2].label, "best radius");
  ASSERT_EQ(plots[1]->series[2].points.size(), 1u);
  EXPECT_DOUBLE_EQ(plots[1]->series[2].points[0].x, 2.0);
  EXPECT_DOUBLE_EQ(plots[1]->series[2].points[0].y, 5e-2);
  EXPECT_DOUBLE_EQ(tables[1]->rows[0][3].value, 5e-2);  // the recommendation's error
  const CsvTable rec = read_csv_table((dir / "recommendations.csv").string());
  EXPECT_EQ(rec.rows.size(), 12u);
}

}  // namespace
}  // namespace curvbench
