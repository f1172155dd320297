// The noise of a mesh estimated from the mesh alone (`curvbench recommend`, harness/report/
// recommend_table.h): the spread of the vertices about a local polynomial fit to their
// neighbours, in units of the mean edge length h.
#pragma once

#include "mesh/mesh.h"

namespace curvbench {

/// sigma/h estimated from the mesh: per interior vertex, the height of the vertex above the
/// degree-4 polynomial fitted (unweighted least squares with a constant term, the fitting
/// routine of LHF-4) to its neighbours' heights, ring 2 grown to at least 23 neighbours, in the
/// frame of its area-weighted normal; sigma = 1.4826 x median |height| / kNoiseResidualGain
/// (a robust deviation; the gain, the ratio of that deviation to the true sigma measured on the
/// well-shaped torus, level 2, at sigma/h = 0.01, 0.03 and 0.1, accounts for the noise of the
/// fitted surface itself), divided by the mean edge length. Throws
/// InputError when no vertex has enough neighbours.
inline constexpr double kNoiseResidualGain = 1.22;
double estimate_sigma_over_h(const Mesh& mesh);

}  // namespace curvbench
