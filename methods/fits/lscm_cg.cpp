// "lscm-cg": LSCM-d on CGAL's LSCM_parameterizer_3 solved by OpenNL's Jacobi-preconditioned
// conjugate gradients (CGAL's solver when Eigen is not enabled; relative tolerance 1e-6).
//
// Not a method of the paper, but most likely the map the paper's CGAL 3.x produced: its LSCM
// had no Eigen back end. "lscm" solves the same system exactly (sparse LDLT). Running both shows
// how much of the paper's LSCM-4 behaviour (§5.1: "failed to converge on poor-shaped meshes")
// comes from an inexact parameterization rather than from conformal maps as such.
#include "methods/fits/lscm.h"

namespace curvbench {

std::unique_ptr<Estimator> make_lscm_cg_estimator(EstimatorOptions options) {
  LscmSettings settings;
  settings.cgal_solver = CgalLscmSolver::opennl_cg;
  return make_lscm_estimator_with(options, true, settings);
}

}  // namespace curvbench
