// Helpers that build a SurfacePoint (surface.h) from the shared curvature formulas.
#pragma once

#include "core/shape_operator.h"
#include "surfaces/surface.h"

namespace curvbench {

/// SurfacePoint at `point` with the quantities of `c`; umbilic = is_umbilic(c.k1, c.k2)
/// (|k1 - k2| <= 1e-8 max(|k1|, |k2|)).
SurfacePoint to_surface_point(const Vec3& point, const Curvature& c);

/// A unit tangent pair (t1, t2) of the unit normal n with t1 x t2 = n, defined for every n
/// (Duff, Burgess, Christensen, Hery, Kensler, Liani, Villemin, "Building an orthonormal basis,
/// revisited", JCGT 6(1), 2017).
void orthonormal_tangents(const Vec3& n, Vec3& t1, Vec3& t2);

/// Every field NaN (umbilic false): the answer to a non-finite query point.
SurfacePoint nan_surface_point();

}  // namespace curvbench
