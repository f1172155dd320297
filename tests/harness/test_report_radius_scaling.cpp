// The REPORT.md section "Neighbourhoods that shrink more slowly than h"
// (harness/report/radius_scaling.h): the bounds of docs/algorithms.md §15, the rates per alpha
// from the errors CSVs, and the table that sets them side by side.
#include "harness/report/model.h"
#include "harness/report/radius_scaling.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <sstream>
#include <string>
#include <variant>
#include <vector>

#include "tests/cli/cli_runner.h"
#include "tests/harness/synthetic_rows.h"

namespace curvbench {
namespace {

namespace fs = std::filesystem;

TEST(ReportRadiusScaling, BoundsAreTheWorseOfTruncationAndInputTerms) {
  // Degree 2, O(h^2) input errors, radius c h^alpha (docs/algorithms.md §15's table).
  const RadiusScalingBounds third = radius_scaling_bounds(1.0 / 3.0);
  EXPECT_NEAR(third.curvature, 1.0 / 3.0, 1e-15);
  EXPECT_NEAR(third.curvature_symmetric, 2.0 / 3.0, 1e-15);
  EXPECT_NEAR(third.normals, 2.0 / 3.0, 1e-15);
  const RadiusScalingBounds half = radius_scaling_bounds(0.5);
  EXPECT_DOUBLE_EQ(half.curvature, 0.5);
  EXPECT_DOUBLE_EQ(half.curvature_symmetric, 1.0);
  EXPECT_DOUBLE_EQ(half.normals, 1.0);
  const RadiusScalingBounds two_thirds = radius_scaling_bounds(2.0 / 3.0);
  EXPECT_NEAR(two_thirds.curvature, 2.0 / 3.0, 1e-15);
  EXPECT_NEAR(two_thirds.curvature_symmetric, 2.0 / 3.0, 1e-15);
  EXPECT_NEAR(two_thirds.normals, 4.0 / 3.0, 1e-15);
  const RadiusScalingBounds fixed_rings = radius_scaling_bounds(1.0);
  EXPECT_DOUBLE_EQ(fixed_rings.curvature, 0.0);  // a fixed number of rings: no convergence
  EXPECT_DOUBLE_EQ(fixed_rings.curvature_symmetric, 0.0);
  EXPECT_DOUBLE_EQ(fixed_rings.normals, 1.0);
}

TEST(ReportRadiusScaling, RatesPerAlphaSideBySide) {
  // Two experiments (alpha 1/2 and 1): LHF-2's H converges at rate 1.1 and 0.3, Meyer's (scored
  // on the interior) at -0.5 in both; levels 1-3, h = 0.4, 0.2, 0.1.
  const fs::path dir = testing::fresh_dir("report_radius_scaling");
  std::vector<Experiment> experiments(2);
  const double alphas[2] = {0.5, 1.0}, lhf_rates[2] = {1.1, 0.3};
  for (int i = 0; i < 2; ++i) {
    Experiment& e = experiments[static_cast<size_t>(i)];
    e.name = i == 0 ? "rs-half" : "rs-one";
    e.radius_alpha = alphas[i];
    e.radius_c = i == 0 ? 0.447 : 2.0;
    std::vector<ErrorRow> rows =
        testing::synthetic_series(e.name, "torus-iso", "LHF-2", 0.1, lhf_rates[i]);
    for (ErrorRow r : testing::synthetic_series(e.name, "torus-iso", "Meyer", 0.2, -0.5)) {
      r.vertex_set = "interior";
      rows.push_back(r);
    }
    write_error_csv((dir / std::string(e.name).append(".csv")).string(), rows);
    const std::vector<RadiusScalingRate> rates = radius_scaling_rates(rows, alphas[i]);
    ASSERT_EQ(rates.size(), 2u);
    EXPECT_EQ(rates[0].method, "LHF-2");
    EXPECT_NEAR(rates[0].rate, lhf_rates[i], 1e-12);
    EXPECT_EQ(rates[0].first_level, 1);
    EXPECT_EQ(rates[0].last_level, 3);
    EXPECT_EQ(rates[1].method, "Meyer (interior)");
    EXPECT_NEAR(rates[1].rate, -0.5, 1e-12);
  }
  // A diagnostic at alpha 1/2 over levels 2-3 only: its row names its levels.
  Experiment diag;
  diag.name = "rs-diag";
  diag.radius_alpha = 0.5;
  diag.radius_c = 0.44;
  std::vector<ErrorRow> diag_rows;
  for (const ErrorRow& r :
       testing::synthetic_series(diag.name, "torus-iso", "LHF-2 diag", 0.1, 1.5))
    if (r.level >= 2) diag_rows.push_back(r);
  write_error_csv((dir / "rs-diag.csv").string(), diag_rows);
  experiments.push_back(diag);
  Experiment plain;  // no radius-scaling: not in the section
  plain.name = "fig03-05";
  experiments.push_back(plain);

  ReportOptions options;
  options.results_dir = dir.string();
  const report::Section section = radius_scaling_section(experiments, options);
  const std::string text = report::to_markdown(section);
  EXPECT_NE(text.find("## Neighbourhoods that shrink more slowly than h"), std::string::npos);
  EXPECT_NE(text.find("`rs-half` (alpha 0.5, c 0.447), `rs-one` (alpha 1, c 2)"), std::string::npos)
      << text;
  EXPECT_NE(text.find("### `torus-iso`, mean curvature H (levels 1-3)\n\n"
                      "| rate | alpha = 0.5 | alpha = 1 |\n"
                      "|---|---:|---:|\n"
                      "| *bound, general stencil* | *0.50* | *0.00* |\n"
                      "| *bound, odd terms cancel* | *1.00* | *0.00* |\n"
                      "| LHF-2 | 1.10 | 0.30 |\n"
                      "| Meyer (interior) | -0.50 | -0.50 |\n"
                      "| LHF-2 diag (levels 2-3) | 1.50 | - |\n"),
            std::string::npos)
      << text;
  EXPECT_EQ(text.find("### `torus-iso`, normals"), std::string::npos);  // only H rows given
  // The cells carry the rates: LHF-2 at alpha 1/2, the bound at alpha 1/2.
  const report::Table* h_table = nullptr;
  for (const report::Block& b : section.blocks)
    if (const auto* t = std::get_if<report::Table>(&b)) h_table = t;
  ASSERT_NE(h_table, nullptr);
  ASSERT_EQ(h_table->rows.size(), 5u);
  EXPECT_NEAR(h_table->rows[2][1].value, 1.1, 1e-12);
  EXPECT_DOUBLE_EQ(h_table->rows[0][1].value, 0.5);
  EXPECT_TRUE(std::isnan(h_table->rows[4][2].value));  // "-"

  // No radius-scaling experiment with a CSV: nothing.
  const report::Section none = radius_scaling_section({plain}, options);
  EXPECT_TRUE(none.title.empty());
  EXPECT_TRUE(none.blocks.empty());
}

}  // namespace
}  // namespace curvbench
