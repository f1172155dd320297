// Convergence smoke tests on the generated meshes (meshgen/generate.h): Proposition 2 of the
// paper, normals O(h^d) and mean curvature O(h^{d-1}) for degree-d fitting.
// rate = log(e_first / e_last) / log(h_first / h_last) over the levels used, h = mean edge length.
#include <gtest/gtest.h>

#include <string>

#include "tests/methods/convergence_rates.h"

namespace curvbench {
namespace {

using testing::convergence_rates;
using testing::ConvergenceRates;

TEST(Convergence, TorusStructured) {
  const ConvergenceRates r2 = convergence_rates("torus-structured", "lhf-2", {1, 3});
  EXPECT_GE(r2.normal, 1.7);
  EXPECT_GE(r2.H, 0.9);
  const ConvergenceRates r4 = convergence_rates("torus-structured", "lhf-4", {1, 3});
  EXPECT_GE(r4.normal, 3.5);
}

// The bump's coarsest level (N = 16) is pre-asymptotic for degree 4 (its level 1 -> 2 normal
// rate is 3.0, then 3.9), so the bump uses levels 2..4 (1089 .. 16641 vertices).
TEST(Convergence, Bump48) {
  const ConvergenceRates r2 = convergence_rates("bump-48", "lhf-2", {2, 4});
  EXPECT_GE(r2.normal, 1.7);
  EXPECT_GE(r2.H, 0.9);
  const ConvergenceRates r4 = convergence_rates("bump-48", "lhf-4", {2, 4});
  EXPECT_GE(r4.normal, 3.5);
}

TEST(Convergence, BumpIrregular) {
  const ConvergenceRates r2 = convergence_rates("bump-irregular", "lhf-2", {2, 4});
  EXPECT_GE(r2.normal, 1.7);
  EXPECT_GE(r2.H, 0.9);
  const ConvergenceRates r4 = convergence_rates("bump-irregular", "lhf-4", {2, 4});
  EXPECT_GE(r4.normal, 3.5);
}

}  // namespace
}  // namespace curvbench
