// The neighbourhood size as a declared trait (methods/estimator.h NeighbourhoodSize, one column of
// the registry line): radius scaling (harness/run/runner.h scale_radius) sizes each method through
// its declaration, n = c h^(alpha - 1) edge lengths as half rings, whole rings or a ball factor.
#include <gtest/gtest.h>

#include <cmath>

#include "core/errors.h"
#include "harness/model/experiment.h"
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

}  // namespace
}  // namespace curvbench
