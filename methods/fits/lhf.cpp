// LHF-d: local height function fitting (paper §2.2, §4.2.2; docs/algorithms.md §3, §5.5, §6.1).
// The ring is projected orthogonally onto the plane of the approximate normal m0 (frame of §3),
// the heights f_i = (p_i - p0) . m0 are fitted by a degree-d weighted polynomial (eq. 15 weights
// with the normal safeguard, safeguarded QR), and the normal and curvatures come from the height
// column of Table 1. All the work is in the shared driver (ring_fit_estimator.h).
#include <memory>

#include "methods/fits/ring_fit_estimator.h"

namespace curvbench {

namespace {

class LhfEstimator final : public RingFitEstimator {
 public:
  explicit LhfEstimator(EstimatorOptions options) : RingFitEstimator(options, FitRoute::height) {}
  bool batchable() const override { return true; }  // the default projection hook
  std::string name() const override { return "lhf"; }
  NeighbourhoodUse neighbourhood_use() const override { return NeighbourhoodUse::neighbours; }
};

}  // namespace

std::unique_ptr<Estimator> make_lhf_estimator(EstimatorOptions options) {
  return std::make_unique<LhfEstimator>(options);
}

}  // namespace curvbench
