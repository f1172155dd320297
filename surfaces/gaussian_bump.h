// The open test surface of paper §5.2 (docs/algorithms.md §10.2, §11.2): the Gaussian bump
//   z = g(r) = exp(-a r^2),  r^2 = (x - 1/2)^2 + (y - 1/2)^2,  a = 81/16,  on [0, 1]^2,
// a HeightField named "bump" with the analytic derivatives of §11.2 (dx = x - 1/2, dy = y - 1/2):
//   f_x = -2a dx g, f_y = -2a dy g, f_xx = (4a^2 dx^2 - 2a) g, f_yy = (4a^2 dy^2 - 2a) g,
//   f_xy = 4a^2 dx dy g.
// Its only umbilic is the peak (1/2, 1/2), where k1 = k2 = -2a = -81/8.
#pragma once

#include "surfaces/height_field.h"

namespace curvbench {

/// a = 81/16 of the bump's exponent.
inline constexpr double kBumpExponent = 81.0 / 16.0;

/// z = exp(-81/16 ((x - 1/2)^2 + (y - 1/2)^2)) on [0, 1]^2, name "bump".
SurfacePtr make_gaussian_bump();

}  // namespace curvbench
