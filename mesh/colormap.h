// Per-vertex colours for curvature pictures (`estimate --color`).
//
//   values  n doubles (e.g. H per vertex), NaN allowed
//   ->      n RGB triples in 0..255 and the range limit L
//
// Diverging map on the symmetric range [-L, L]: -L blue (59, 76, 192), 0 light grey-white
// (221, 221, 221), +L red (180, 4, 38) (the end and middle colours of Moreland's cool-warm map),
// linear in RGB in between; values beyond +-L take the end colours; NaN is mid grey
// (128, 128, 128). L is the `percentile`-th percentile of |value| over the finite values, so a
// few spikes (needles, folds) do not wash the picture out; L = 0 (all zero) paints every finite
// value white. Symmetric so that white is zero curvature and the sign convention stays visible.
#pragma once

#include <array>
#include <cstdint>
#include <span>
#include <vector>

namespace curvbench {

struct VertexColors {
  std::vector<std::array<std::uint8_t, 3>> rgb;  ///< one per value
  double limit = 0.0;                            ///< L
};

/// Colours of `values` (see the file comment). percentile in (0, 100]; throws UsageError else.
VertexColors diverging_colors(std::span<const double> values, double percentile = 98.0);

}  // namespace curvbench
