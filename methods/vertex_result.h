// Filling a VertexEstimate (estimator.h) from fitted quantities, or as failed / excluded.
// Shared by every estimator so that the status conventions live in one place.
#pragma once

#include "core/shape_operator.h"
#include "methods/estimator.h"
#include "methods/local_frame.h"

namespace curvbench {

/// Failure (degree 0, ALGORITHM_NOTES §5.4 "consider the surface as flat"): normal = m0 (the
/// approximate normal as given), k1 = k2 = H = K = 0, d1 = frame.t1, d2 = frame.t2,
/// status failed.
void set_failed(const Vec3& m0, const LocalFrame& frame, double ring, int points,
                VertexEstimate& out);

/// Not computed by design (e.g. Xu at a boundary vertex): every value NaN, degree 0,
/// status excluded.
void set_excluded(double ring, int points, VertexEstimate& out);

/// Copies c into out with status ok (degree == requested) or degree_reduced (1 <= degree <
/// requested). Returns false, leaving out untouched, if degree < 1 or any value of c is not
/// finite.
bool set_quantities(const Curvature& c, int degree, int requested, int points, double ring,
                    VertexEstimate& out);

}  // namespace curvbench
