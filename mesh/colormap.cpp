// Diverging per-vertex colours; see colormap.h.
#include "mesh/colormap.h"

#include <algorithm>
#include <cmath>

#include "core/errors.h"

namespace curvbench {

VertexColors diverging_colors(std::span<const double> values, double percentile) {
  if (!(percentile > 0.0 && percentile <= 100.0))
    throw UsageError("colour range percentile must be in (0, 100]");
  std::vector<double> mags;
  mags.reserve(values.size());
  for (double x : values)
    if (std::isfinite(x)) mags.push_back(std::abs(x));
  VertexColors out;
  if (!mags.empty()) {
    const size_t k =
        static_cast<size_t>(std::ceil(percentile / 100.0 * static_cast<double>(mags.size())) - 1.0);
    const size_t i = std::min(k, mags.size() - 1);
    std::nth_element(mags.begin(), mags.begin() + static_cast<std::ptrdiff_t>(i), mags.end());
    out.limit = mags[i];
  }
  constexpr double kLow[3] = {59, 76, 192}, kMid[3] = {221, 221, 221}, kHigh[3] = {180, 4, 38};
  out.rgb.resize(values.size());
  for (size_t v = 0; v < values.size(); ++v) {
    const double x = values[v];
    auto& c = out.rgb[v];
    if (!std::isfinite(x)) {
      c = {128, 128, 128};
      continue;
    }
    const double t = out.limit > 0.0 ? std::clamp(x / out.limit, -1.0, 1.0) : 0.0;
    const double* end = t < 0.0 ? kLow : kHigh;
    const double s = std::abs(t);
    for (int j = 0; j < 3; ++j)
      c[static_cast<size_t>(j)] =
          static_cast<std::uint8_t>(std::lround(kMid[j] + s * (end[j] - kMid[j])));
  }
  return out;
}

}  // namespace curvbench
