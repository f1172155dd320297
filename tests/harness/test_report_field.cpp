// The REPORT.md section "The estimators in common use" (harness/report/field.h): finest-level
// errors with rates, the time per vertex from the timings CSV, and the generated words about
// convergence follow the numbers and the stated thresholds.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <string>
#include <tuple>
#include <variant>
#include <vector>

#include "harness/model/results_table.h"
#include "harness/report/field.h"
#include "harness/report/model.h"
#include "tests/cli/cli_runner.h"
#include "tests/harness/synthetic_rows.h"

namespace curvbench {
namespace {

namespace fs = std::filesystem;

// Three levels with h = 0.4, 0.2, 0.1 and errors e0 * (h/0.4)^rate, H L2 only.
std::vector<ErrorRow> series(const std::string& method, double e0, double rate) {
  return testing::synthetic_series("field-estimators-test", "bump-irregular", method, e0, rate);
}

// The field sections (harness/report/field.h) of `experiments` from the CSVs in `dir`, no plots.
report::Section field_section(const fs::path& dir, const std::vector<Experiment>& experiments) {
  ReportOptions options;
  options.results_dir = dir.string();
  options.plots = false;
  report::Section s{"field-studies", "", {}};
  int missing = 0;
  EXPECT_TRUE(field_sections(experiments, options, missing, s));
  EXPECT_EQ(missing, 0);
  return s;
}

// Its markdown.
std::string field_markdown(const fs::path& dir, const std::vector<Experiment>& experiments) {
  return report::to_markdown(field_section(dir, experiments));
}

// The blocks of type T of a section, in order.
template <class T>
std::vector<const T*> blocks_of(const report::Section& s) {
  std::vector<const T*> out;
  for (const report::Block& b : s.blocks)
    if (const auto* t = std::get_if<T>(&b)) out.push_back(t);
  return out;
}

TEST(ReportField, TablesRatesTimesAndWordsFollowTheNumbers) {
  const fs::path dir = testing::fresh_dir("report_field");
  Experiment e;
  e.name = "field-estimators-test";
  e.report = ReportSection::field;
  e.meshes = {{"bump-irregular", {1, 2, 3}}};
  std::vector<ErrorRow> rows;
  for (const auto& [method, e0, rate] : std::vector<std::tuple<std::string, double, double>>{
           {"Second", 1e-2, 2.0}, {"Stalls", 1e-1, 0.2}, {"Exact", 1e-14, -1.0}}) {
    const auto s = series(method, e0, rate);
    rows.insert(rows.end(), s.begin(), s.end());
  }
  write_error_csv((dir / "field-estimators-test.csv").string(), rows);
  write_timing_csv((dir / "timings" / "field-estimators-test.csv").string(), rows);

  const report::Section section = field_section(dir, {e});
  const std::string text = report::to_markdown(section);
  EXPECT_NE(text.find("## The estimators in common use"), std::string::npos) << text;
  // Finest level: 1e-2 * (1/4)^2 = 6.25e-4, rate 2, 5 us per vertex; the cells carry the
  // numbers.
  EXPECT_NE(text.find("| Second | - | - | 6.25e-04 (2.00) | - |"), std::string::npos) << text;
  const auto tables = blocks_of<report::Table>(section);
  ASSERT_GE(tables.size(), 1u);
  const report::Table& errors = *tables.front();
  ASSERT_EQ(errors.columns.size(), 10u);
  EXPECT_EQ(errors.columns[3], "H L2");
  EXPECT_EQ(errors.columns[9], "us/vertex");
  ASSERT_EQ(errors.rows.size(), 3u);
  EXPECT_EQ(errors.rows[0][0].text, "Second");
  EXPECT_DOUBLE_EQ(errors.rows[0][3].value, 6.25e-4);
  EXPECT_NEAR(errors.rows[0][9].value, 5.0, 1e-9);
  EXPECT_TRUE(std::isnan(errors.rows[0][1].value));  // "-": no normal errors
  // The two cost plots: one series per method, the time on the x axis, not reversed.
  const auto plots = blocks_of<report::Plot>(section);
  ASSERT_EQ(plots.size(), 2u);
  EXPECT_EQ(plots[0]->id, "field-frontier_field-estimators-test_bump-irregular");
  EXPECT_EQ(plots[0]->x_label, "time per vertex (microseconds)");
  EXPECT_EQ(plots[1]->id, "field-time_field-estimators-test_bump-irregular");
  EXPECT_FALSE(plots[1]->reverse_x);
  EXPECT_TRUE(plots[1]->log_x && plots[1]->log_y);
  ASSERT_EQ(plots[0]->series.size(), 3u);
  EXPECT_EQ(plots[0]->series[0].label, "Second");
  ASSERT_EQ(plots[0]->series[0].points.size(), 3u);
  EXPECT_NEAR(plots[0]->series[0].points[2].x, 5.0, 1e-9);
  EXPECT_DOUBLE_EQ(plots[0]->series[0].points[2].y, 6.25e-4);
  EXPECT_TRUE(plots[0]->image.empty());  // not rendered without plots
  // The cheapest to reach 1e-2 .. 1e-8 (1e-1: every method at once): Exact at level 1 (2 ms),
  // then Second at the same time.
  ASSERT_EQ(tables.size(), 2u);
  const report::Table& cheapest = *tables[1];
  EXPECT_EQ(cheapest.columns[0], "target");
  ASSERT_EQ(cheapest.rows.size(), 7u);
  EXPECT_DOUBLE_EQ(cheapest.rows[0][0].value, 1e-2);
  EXPECT_EQ(cheapest.rows[0][1].text, "Exact (1, 0.002 s, 1.00e-14)");
  EXPECT_DOUBLE_EQ(cheapest.rows[0][1].value, 2e-3);
  EXPECT_EQ(cheapest.rows[0][2].text, "Second (1, 0.002 s, 1.00e-02)");
  EXPECT_NE(text.find("| 5.00 |"), std::string::npos) << text;
  EXPECT_NE(text.find("- mean curvature H: converge: Second (2.00); do not converge (average "
                      "rate, last rate): Stalls (0.20, last 0.20); exact up to round-off "
                      "(error <= 1.00e-10): Exact."),
            std::string::npos)
      << text;
  EXPECT_NE(text.find("Smallest L2 error in H at level 3: Exact"), std::string::npos) << text;

  // No field-estimators experiment: nothing.
  Experiment other = e;
  other.name = "fig03-05";
  EXPECT_TRUE(field_section(dir, {other}).blocks.empty());
}

TEST(ReportField, TheCheapestEstimatorToATargetErrorFollowsTheRows) {
  // Errors e0 (h/0.4)^rate at h = 0.4, 0.2, 0.1; times 5 us per vertex (400, 1600, 6400
  // vertices: 2, 8, 32 ms), Fourth ten times that.
  std::vector<ErrorRow> rows;
  const std::string methods[] = {"Second", "Fourth", "Stalls"};
  const double e0[] = {2e-2, 2e-2, 5e-2}, rate[] = {2.0, 4.0, 0.2}, slow[] = {1.0, 10.0, 1.0};
  for (size_t i = 0; i < std::size(methods); ++i)
    for (int level = 1; level <= 3; ++level) {
      ErrorRow r;
      r.method = methods[i];
      r.level = level;
      r.vertices = 100 << (2 * level);
      r.h = 0.4 / (1 << (level - 1));
      r.error = e0[i] * std::pow(r.h / 0.4, rate[i]);
      r.seconds = slow[i] * 1e-6 * 5.0 * r.vertices;
      rows.push_back(r);
    }
  // 1e-2: Second at level 2 (5e-3, 8 ms); Fourth reaches it at level 2 (1.25e-3, 80 ms).
  CheapestToReach c = cheapest_to_reach(rows, 1e-2);
  ASSERT_NE(c.best, nullptr);
  EXPECT_EQ(c.best->method, "Second");
  EXPECT_EQ(c.best->level, 2);
  EXPECT_DOUBLE_EQ(c.best->seconds, 1e-6 * 5.0 * 1600);
  ASSERT_NE(c.runner_up, nullptr);
  EXPECT_EQ(c.runner_up->method, "Fourth");
  EXPECT_EQ(c.runner_up->level, 2);
  // 1e-3: Second reaches only 1.25e-3; Fourth at level 3 (7.8e-5); no runner-up.
  c = cheapest_to_reach(rows, 1e-3);
  ASSERT_NE(c.best, nullptr);
  EXPECT_EQ(c.best->method, "Fourth");
  EXPECT_EQ(c.best->level, 3);
  EXPECT_EQ(c.runner_up, nullptr);
  EXPECT_EQ(cheapest_to_reach(rows, 1e-5).best, nullptr);
  // 1e-1 is reached by every method at once; 1e-2, 1e-3 and 1e-4 by some; 1e-5 by none.
  EXPECT_EQ(time_targets(rows), (std::vector<double>{1e-2, 1e-3, 1e-4, 1e-5}));
  // Rows without a time count for nothing.
  for (ErrorRow& r : rows) r.seconds = std::nan("");
  EXPECT_EQ(cheapest_to_reach(rows, 1e-2).best, nullptr);
  EXPECT_TRUE(time_targets(rows).empty());
}

TEST(ReportField, TwoSettingsOfAFamilyCompareAtTheirFinestLevels) {
  // torus-anisotropic at A = 4 (levels 1-3, finest h = 0.1) and A = 16 (levels 1-2, finest
  // h = 0.2): the sentence names each finest level and h, and the ratios A16 / A4 there.
  const fs::path dir = testing::fresh_dir("report_field_settings");
  Experiment e;
  e.name = "hard-meshes-test";
  e.report = ReportSection::hard;
  MeshShape a4, a16;
  a4.aspect = 4.0;
  a16.aspect = 16.0;
  e.meshes = {{"torus-anisotropic", {1, 2, 3}, -1, a4}, {"torus-anisotropic", {1, 2}, -1, a16}};
  std::vector<ErrorRow> rows;
  for (const auto& [label, method, e0] : std::vector<std::tuple<std::string, std::string, double>>{
           {"torus-anisotropic-A4", "Second", 1e-2},
           {"torus-anisotropic-A4", "Other", 1e-3},
           {"torus-anisotropic-A16", "Second", 4e-2},
           {"torus-anisotropic-A16", "Other", 1e-1}}) {
    for (const ErrorRow& r : series(method, e0, 2.0))
      if (label.ends_with("A4") || r.level <= 2) {
        rows.push_back(r);
        rows.back().experiment = e.name;
        rows.back().family = label;
      }
  }
  write_error_csv((dir / "hard-meshes-test.csv").string(), rows);
  const std::string text = field_markdown(dir, {e});
  // A4 level 3: 1e-2 / 16, 1e-3 / 16; A16 level 2: 4e-2 / 4, 1e-1 / 4: ratios 16 and 400.
  EXPECT_NE(text.find("- `torus-anisotropic-A16` (level 2, h = 2.00e-01) against "
                      "`torus-anisotropic-A4` (level 3, h = 1.00e-01), finest-level L2 error "
                      "in H, ratio per method (smallest first): Second 16.00, Other 400.00."),
            std::string::npos)
      << text;
}

}  // namespace
}  // namespace curvbench
