// The neighbourhood size as a declared trait (methods/estimator.h NeighbourhoodSize, one column of
// the registry line): radius scaling (harness/run/runner.h scale_radius) sizes each method through
// its declaration, n = c h^(alpha - 1) edge lengths as half rings, whole rings or a ball factor.
#include <gtest/gtest.h>

#include <cmath>

#include "core/errors.h"
#include "harness/model/experiment.h"
#include "harness/model/results_table.h"
#include "harness/run/runner.h"
#include "methods/estimator.h"

namespace curvbench {
namespace {

TEST(RadiusTrait, EveryMethodDeclaresItsNeighbourhoodSize) {
  EXPECT_EQ(method_info("LHF-2").radius, NeighbourhoodSize::half_rings);
  EXPECT_EQ(method_info("jet").radius, NeighbourhoodSize::half_rings);
  EXPECT_EQ(method_info("Xu-2").radius, NeighbourhoodSize::fixed);
  EXPECT_EQ(method_info("quadric").radius, NeighbourhoodSize::whole_rings);
  EXPECT_EQ(method_info("ICC").radius, NeighbourhoodSize::ball_factor);
  EXPECT_EQ(method_info("normal-cycle").radius, NeighbourhoodSize::ball_factor);
  EXPECT_EQ(method_info("meyer").radius, NeighbourhoodSize::fixed);
  EXPECT_THROW(method_info("no-such-method"), UsageError);
}

TEST(MethodGroup, VariantsBelongToTheirMethodsGroup) {
  EXPECT_EQ(method_group("LHF-2"), MethodGroup::paper_fit);
  EXPECT_EQ(method_group("LSCM-fast-4"), MethodGroup::paper_fit);
  EXPECT_EQ(method_group("LHF-2 (1.5-ring)"), MethodGroup::paper_fit);
  EXPECT_EQ(method_group("LHF-2 rings=3"), MethodGroup::paper_fit);
  EXPECT_EQ(method_group("Jet-4"), MethodGroup::jet);
  EXPECT_EQ(method_group("ICC-ball2"), MethodGroup::discrete);
  EXPECT_EQ(method_group("Normal-cycle ball-factor=4"), MethodGroup::discrete);
  EXPECT_EQ(method_group("vtk-curvatures"), MethodGroup::outside);
  EXPECT_EQ(method_group("lhfx"), MethodGroup::outside);
}

TEST(RadiusTrait, RadiusScalingSizesEachMethodByItsDeclaration) {
  Experiment e;
  e.radius_alpha = 0.5;
  e.radius_c = 0.44;
  const double h = 0.01;  // n = 0.44 * 0.01^(-1/2) = 4.4 edge lengths
  const auto scaled = [&](const std::string& method) {
    EstimatorOptions opt;
    scale_radius(e, method, h, opt);
    return opt;
  };
  EXPECT_DOUBLE_EQ(scaled("lhf-2").rings, 4.5);    // half rings: round(8.8) / 2
  EXPECT_DOUBLE_EQ(scaled("quadric").rings, 4.0);  // whole rings: round(4.4)
  EXPECT_NEAR(scaled("icc").ball_factor, 4.4, 1e-12);
  const EstimatorOptions defaults;
  EXPECT_EQ(scaled("xu-2").rings, defaults.rings);  // fixed: its 1-ring stays
  EXPECT_EQ(scaled("meyer").ball_factor, defaults.ball_factor);
}

// A sweep's rows carry the radius and the noise typed: the runner sets them from the experiment,
// and reading the CSV back gives the same values, so the report and the advice never parse a
// label.
TEST(RadiusTrait, SweepRowsCarryTheRadiusAndNoiseTyped) {
  const Experiment e = parse_experiment_text(
      "title t\nsection beyond\nreport sweeps\nsweep radius\n"
      "mesh torus-unstructured levels=1 noise-sigma=0,0.03\n"
      "method lhf-2 rings=1.5,2\nmethod icc ball-factor=2,3\nmethod meyer\n"
      "method lhf-2 qr-tol=1e-8,1e-12\npanel p c H L2\n",
      "typed.exp");
  MeshCache cache;
  std::vector<ErrorRow> rows;
  const std::vector<Experiment> experiments{e};  // the cases point into it
  for (const RunCase& c : expand_cases(experiments))
    for (ErrorRow& r : run_case(c, cache, 1)) rows.push_back(std::move(r));
  ASSERT_EQ(rows.size(), 2u * 7u);  // two meshes, seven methods, one panel
  int swept = 0;
  for (const ErrorRow& r : rows) {
    ErrorRow read = r;  // what read_error_csv makes of the row's text
    type_columns(read);
    EXPECT_EQ(r.method_base, read.method_base) << r.method;
    EXPECT_EQ(r.radius_parameter, read.radius_parameter) << r.method;
    EXPECT_TRUE(r.radius == read.radius || (std::isnan(r.radius) && std::isnan(read.radius)))
        << r.method;
    EXPECT_TRUE(r.noise_level == read.noise_level) << r.noise;
    swept += !r.radius_parameter.empty();
  }
  EXPECT_EQ(swept, 2 * 4);
  const auto find = [&](const std::string& label, const std::string& noise) {
    for (const ErrorRow& r : rows)
      if (r.method == label && r.noise == noise) return r;
    ADD_FAILURE() << label << " " << noise;
    return ErrorRow{};
  };
  const ErrorRow icc = find("ICC ball-factor=3", "normal gauss 0.03h");
  EXPECT_EQ(icc.method_base, "ICC");
  EXPECT_EQ(icc.radius_parameter, "ball-factor");
  EXPECT_EQ(icc.radius, 3.0);
  EXPECT_EQ(icc.noise_level.model, "normal gauss");
  EXPECT_EQ(icc.noise_level.sigma_over_h, 0.03);
  const ErrorRow lhf = find("LHF-2 rings=1.5", "none");
  EXPECT_EQ(lhf.method_base, "LHF-2");
  EXPECT_EQ(lhf.radius, 1.5);
  EXPECT_EQ(lhf.noise_level.sigma_over_h, 0.0);
  // A listed option that is not a radius is part of the method, not a radius.
  const ErrorRow qr = find("LHF-2 qr-tol=1e-8", "none");
  EXPECT_EQ(qr.method_base, "LHF-2 qr-tol=1e-8");
  EXPECT_EQ(qr.radius_parameter, "");
}

}  // namespace
}  // namespace curvbench
