// "lscm-fast": LSCM-d on the in-house dense LSCM map; the estimator itself is shared with "lscm"
// (lscm.cpp, lscm.h), only the map differs.
//
// The issue requires lscm-fast to give the same parameterization as CGAL's LSCM_parameterizer_3
// up to a similarity, so by default it copies CGAL's choices: the two pins are the extremes along
// the longest axis of the bounding box (Two_vertices_parameterizer_3) and the conformal energy is
// not divided by triangle area. docs/algorithms.md §8's variant (farthest pair, Levy's 1/A_T
// energy) is LscmMapOptions{LscmPins::farthest_pair, true}; it differs from CGAL's map by more than
// a similarity on curved patches (tests/methods/test_lscm.cpp measures by how much).
#include "methods/fits/lscm.h"

namespace curvbench {

std::unique_ptr<Estimator> make_lscm_fast_estimator(EstimatorOptions options) {
  LscmSettings settings;
  settings.fast_map = LscmMapOptions{LscmPins::bounding_box, false};
  return make_lscm_estimator_with(options, false, settings);
}

}  // namespace curvbench
