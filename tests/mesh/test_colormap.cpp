// Diverging per-vertex colours (mesh/colormap.h).
#include <gtest/gtest.h>

#include <array>
#include <limits>
#include <vector>

#include "core/errors.h"
#include "mesh/colormap.h"

namespace curvbench {
namespace {

using Rgb = std::array<std::uint8_t, 3>;

TEST(Colormap, SymmetricRangeEndsMiddleAndNan) {
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const std::vector<double> x = {-2, -1, 0, 1, 2, nan, 0.5};
  const VertexColors c = diverging_colors(x, 100.0);
  EXPECT_EQ(c.limit, 2.0);
  EXPECT_EQ(c.rgb[0], (Rgb{59, 76, 192}));
  EXPECT_EQ(c.rgb[2], (Rgb{221, 221, 221}));
  EXPECT_EQ(c.rgb[4], (Rgb{180, 4, 38}));
  EXPECT_EQ(c.rgb[3], (Rgb{201, 113, 130}));  // halfway between white and red (rounded)
  EXPECT_EQ(c.rgb[1], (Rgb{140, 149, 207}));
  EXPECT_EQ(c.rgb[5], (Rgb{128, 128, 128}));
}

TEST(Colormap, RobustRangeIgnoresASpike) {
  std::vector<double> x(99, -1.0);
  x.push_back(1000.0);  // one spike among 100 values: above the 98th percentile
  const VertexColors c = diverging_colors(x);
  EXPECT_EQ(c.limit, 1.0);
  EXPECT_EQ(c.rgb[0], (Rgb{59, 76, 192}));
  EXPECT_EQ(c.rgb[99], (Rgb{180, 4, 38}));  // clipped to the end colour
  const VertexColors zero = diverging_colors(std::vector<double>(3, 0.0));
  EXPECT_EQ(zero.limit, 0.0);
  EXPECT_EQ(zero.rgb[1], (Rgb{221, 221, 221}));
  EXPECT_THROW(diverging_colors(x, 0.0), UsageError);
}

}  // namespace
}  // namespace curvbench
