// LSCM-d: ring fitting on a local least-squares conformal map (paper §4.2.3; docs/algorithms.md
// §8).
//
// Per vertex the shared driver (ring_fit_estimator.h) collects the ring of the degree (default
// (d+1)/2, adaptive half-ring growth), and this estimator maps the ring faces F_r to the plane
// with an LSCM (lscm_parameterization.h); the driver then fits x - p0 (3 RHS) against (u, v)
// with the distance part of the eq. (15) weights and the safeguarded QR, and evaluates the
// parametric formulas (§6.2). The map is normalised (centre at the origin, counter-clockwise),
// so x_u x x_v points to the side the faces are counter-clockwise from (outward / upward).
// A ring that is not a topological disk is cut to a disk around the vertex
// (lscm_parameterization.h) and the fit uses the vertices of that disk: status disk_cut if the
// cut left ring vertices out (degree_reduced if the degree still drops after the adaptive growth;
// ok if it dropped faces only, e.g. where two faces of a half ring pinch at one outer vertex, as
// the fit then has every point of the ring). A map failure makes that
// fit attempt fail: the vertex is reported as failed unless an earlier ring of the adaptive loop
// fitted.
//
//   "lscm"       CgalLscmMap: CGAL's LSCM_parameterizer_3 + Two_vertices_parameterizer_3, as in
//                the paper (Eigen SimplicialLDLT on the normal equations by default).
//   "lscm-fast"  LscmMap: the in-house dense LSCM with CGAL's choices by default (the two pins are
//                the extremes along the longest bounding-box axis, the energy is not divided by
//                triangle area), so it matches "lscm" up to a similarity (lscm_fast.cpp).
//
// gamma of eq. (15) is 1 by default (docs/algorithms.md §4 [CH]: the paper applies the normal-angle
// safeguard to LOP only); LscmSettings::normal_safeguard = true applies gamma = max(0, m_i . m0).
#pragma once

#include <memory>

#include "methods/estimator.h"
#include "methods/fits/lscm_parameterization.h"

namespace curvbench {

struct LscmSettings {
  bool normal_safeguard = false;                            ///< apply gamma of eq. (15)
  CgalLscmSolver cgal_solver = CgalLscmSolver::eigen_ldlt;  ///< "lscm" only
  LscmMapOptions fast_map{};                                ///< "lscm-fast" only
};

/// "lscm" (registry factory; default settings).
std::unique_ptr<Estimator> make_lscm_estimator(EstimatorOptions options);
/// "lscm-fast" (registry factory; default settings).
std::unique_ptr<Estimator> make_lscm_fast_estimator(EstimatorOptions options);

/// Either LSCM estimator with explicit settings (ablations and tests). cgal = true: "lscm".
/// Throws UsageError like the registry factories for bad options.
std::unique_ptr<Estimator> make_lscm_estimator_with(EstimatorOptions options, bool cgal,
                                                    const LscmSettings& settings);

}  // namespace curvbench
