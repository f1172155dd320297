// Helpers that build a SurfacePoint (surface.h) from the shared curvature formulas.
#pragma once

#include "core/shape_operator.h"
#include "surfaces/surface.h"

namespace curvbench {

/// SurfacePoint at `point` with the quantities of `c`; umbilic = is_umbilic(c.k1, c.k2)
/// (|k1 - k2| <= 1e-8 max(|k1|, |k2|)).
SurfacePoint to_surface_point(const Vec3& point, const Curvature& c);

/// Every field NaN (umbilic false): the answer to a non-finite query point.
SurfacePoint nan_surface_point();

}  // namespace curvbench
