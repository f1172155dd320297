// LSCM-d estimators "lscm" (CGAL map) and "lscm-fast" (in-house map); see lscm.h.
#include "methods/fits/lscm.h"

#include <memory>
#include <string>
#include <vector>

#include "methods/fits/ring_fit_estimator.h"

namespace curvbench {

namespace {

struct LscmScratch final : ParamScratch {
  std::unique_ptr<CgalLscmMap> cgal;
  std::unique_ptr<LscmMap> fast;
};

class LscmEstimator final : public RingFitEstimator {
 public:
  LscmEstimator(EstimatorOptions options, bool cgal, const LscmSettings& settings)
      : RingFitEstimator(options, FitRoute::parametric), cgal_(cgal), settings_(settings) {}

  std::string name() const override {
    if (!cgal_) return "lscm-fast";
    return settings_.cgal_solver == CgalLscmSolver::opennl_cg ? "lscm-cg" : "lscm";
  }
  std::string display_name() const override {
    if (!cgal_) return "LSCM-fast";
    return settings_.cgal_solver == CgalLscmSolver::opennl_cg ? "LSCM-CG" : "LSCM";
  }

 protected:
  bool parameterize(const RingView& ring, std::vector<Vec2>& uv,
                    ParamScratch* scratch) const override {
    auto* s = static_cast<LscmScratch*>(scratch);
    if (s == nullptr) return false;
    try {
      return cgal_ ? s->cgal->map(ring.centre, ring.neighbours, ring.faces, uv)
                   : s->fast->map(ring.centre, ring.neighbours, ring.faces, uv);
    } catch (...) {
      return false;
    }
  }

  std::unique_ptr<ParamScratch> make_param_scratch(const Mesh& mesh) const override {
    auto s = std::make_unique<LscmScratch>();
    if (cgal_) {
      s->cgal = std::make_unique<CgalLscmMap>(mesh, settings_.cgal_solver);
    } else {
      s->fast = std::make_unique<LscmMap>(mesh, settings_.fast_map);
    }
    return s;
  }

  bool use_normal_safeguard() const override { return settings_.normal_safeguard; }
  bool rejects_turned_normal() const override { return true; }

 private:
  bool cgal_;
  LscmSettings settings_;
};

}  // namespace

std::unique_ptr<Estimator> make_lscm_estimator_with(EstimatorOptions options, bool cgal,
                                                    const LscmSettings& settings) {
  return std::make_unique<LscmEstimator>(options, cgal, settings);
}

std::unique_ptr<Estimator> make_lscm_estimator(EstimatorOptions options) {
  return make_lscm_estimator_with(options, true, LscmSettings{});
}

}  // namespace curvbench
