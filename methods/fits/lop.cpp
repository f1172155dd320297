// LOP-d: local orthogonal projection parameterization (paper §4.2.2; docs/algorithms.md §3, §6.2).
// The same projection, neighbourhood, weights and safeguard as LHF-d, but the three global
// coordinates x - p0 are fitted (3 right-hand sides, one QR) and the quantities come from the
// parametric formulas, eqs. (1)-(8). Mathematically identical to LHF-d (docs/algorithms.md §3 [D]);
// only the cost differs.
#include <memory>

#include "methods/fits/ring_fit_estimator.h"

namespace curvbench {

namespace {

class LopEstimator final : public RingFitEstimator {
 public:
  explicit LopEstimator(EstimatorOptions options)
      : RingFitEstimator(options, FitRoute::parametric) {}
  bool batchable() const override { return true; }  // the default projection hook
  std::string name() const override { return "lop"; }
  NeighbourhoodUse neighbourhood_use() const override { return NeighbourhoodUse::neighbours; }
};

}  // namespace

std::unique_ptr<Estimator> make_lop_estimator(EstimatorOptions options) {
  return std::make_unique<LopEstimator>(options);
}

}  // namespace curvbench
