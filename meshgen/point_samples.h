// Point sets without connectivity sampled from the analytic surfaces (docs/point_sets.md).
#pragma once

#include <cstdint>

#include "core/types.h"

namespace curvbench {

/// n points uniform by area on the ring torus (R, r) about the z axis (surfaces/torus.h): u
/// uniform, v by rejection with acceptance (R + r cos v)/(R + r), the area element's ratio.
/// Deterministic: the same seed gives the same points (meshgen/random.h). Throws UsageError
/// unless n >= 1 and R > r > 0.
VertexMatrix sample_torus_points(int n, double R, double r, std::uint64_t seed);

}  // namespace curvbench
