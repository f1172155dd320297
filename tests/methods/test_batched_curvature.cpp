// The lane-wise frames and height-function curvature (methods/kernels/batched_curvature.h) against
// the scalar functions they mirror: bit for bit on every regular lane, and the scalar functions'
// special cases (zero or non-finite input, zero gradient, exact umbilic, huge values) flagged as
// not regular so that the caller takes the scalar path.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <random>

#include "method_test_util.h"
#include "methods/kernels/batched_curvature.h"

namespace curvbench {
namespace {

constexpr int kLanes = kBatchLanes;
constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

using testing::same_bits;

TEST(BatchedCurvature, FramesHaveTheBitsOfMakeLocalFrame) {
  std::mt19937 rng(7);
  std::normal_distribution<double> gauss;
  int regular = 0;
  for (int batch = 0; batch < 500; ++batch) {
    alignas(64) double normals[3 * kLanes];
    Vec3 n[kLanes];
    for (int l = 0; l < kLanes; ++l) {
      n[l] = Vec3(gauss(rng), gauss(rng), gauss(rng));
      if (batch % 3 == 0) n[l].normalize();  // unit (the usual input) and not
      if (batch == 1 && l < 6) n[l] = 1e-3 * Vec3::Unit(l % 3) * (l < 3 ? 1.0 : -1.0);  // axes
      if (batch == 2) n[l] = Vec3(1.0, 1.0, (l % 2) ? 1.0 : -0.0);  // ties in |x| > |y|
      for (int c = 0; c < 3; ++c) normals[c * kLanes + l] = n[l](c);
    }
    BatchedFrames frames;
    batched_local_frames(normals, frames);
    for (int l = 0; l < kLanes; ++l) {
      ASSERT_TRUE(frames.regular[static_cast<size_t>(l)]) << batch << " " << l;
      const LocalFrame a = make_local_frame(n[l]), b = frames.frame(l);
      EXPECT_TRUE(same_bits(a.t1, b.t1) && same_bits(a.t2, b.t2) && same_bits(a.m, b.m))
          << "batch " << batch << " lane " << l << ": " << n[l].transpose();
      ++regular;
    }
  }
  EXPECT_EQ(regular, 500 * kLanes);
}

TEST(BatchedCurvature, ZeroOrNonFiniteNormalsAreLeftToTheScalarFrame) {
  alignas(64) double normals[3 * kLanes] = {};
  const Vec3 bad[4] = {Vec3::Zero(), Vec3(kNaN, 0, 1), Vec3(0, INFINITY, 0), Vec3(1e200, 1e200, 0)};
  for (int l = 0; l < kLanes; ++l) {
    const Vec3 n = l < 4 ? bad[l] : Vec3(0.0, 0.0, 1.0);
    for (int c = 0; c < 3; ++c) normals[c * kLanes + l] = n(c);
  }
  BatchedFrames frames;
  batched_local_frames(normals, frames);
  for (int l = 0; l < kLanes; ++l) EXPECT_EQ(frames.regular[static_cast<size_t>(l)], l >= 4) << l;
}

// Random frames and Taylor derivatives; lane l of batch b gets case (b + l) % 8 of special
// inputs or a random one.
TEST(BatchedCurvature, CurvatureHasTheBitsOfCurvatureFromHeight) {
  std::mt19937 rng(11);
  std::normal_distribution<double> gauss;
  constexpr int stride = kMaxRhs * kLanes;
  int regular = 0, irregular = 0;
  for (int batch = 0; batch < 400; ++batch) {
    alignas(64) double normals[3 * kLanes];
    alignas(64) double taylor[6 * stride] = {};
    double t[kLanes][5];
    for (int l = 0; l < kLanes; ++l) {
      const Vec3 n = Vec3(gauss(rng), gauss(rng), gauss(rng)).normalized();
      for (int c = 0; c < 3; ++c) normals[c * kLanes + l] = n(c);
      const double scale = std::pow(10.0, static_cast<int>(rng() % 7) - 3);
      for (int e = 0; e < 5; ++e) t[l][e] = scale * gauss(rng);
      switch ((batch + l) % 8) {
        case 0:  // zero gradient (the scalar chooses cs = 1, sn = 0)
          t[l][0] = t[l][1] = 0.0;
          break;
        case 1:  // exact umbilic of the tensor
          t[l][0] = t[l][1] = 0.0;
          t[l][2] = t[l][4];
          t[l][3] = 0.0;
          break;
        case 2:  // non-finite
          t[l][3] = kNaN;
          break;
        case 3:  // a gradient too large for the plain square root
          t[l][0] = 1e200;
          break;
        default:
          break;
      }
      for (int e = 0; e < 5; ++e) taylor[(1 + e) * stride + l] = t[l][e];
    }
    BatchedFrames frames;
    batched_local_frames(normals, frames);
    BatchedCurvature out;
    batched_curvature_from_height(frames, taylor, stride, out);
    for (int l = 0; l < kLanes; ++l) {
      const LocalFrame f = frames.frame(l);
      const Curvature a =
          curvature_from_height(f.t1, f.t2, f.m, t[l][0], t[l][1], t[l][2], t[l][3], t[l][4]);
      const int kind = (batch + l) % 8;
      if (kind <= 3) {
        EXPECT_FALSE(out.regular[static_cast<size_t>(l)]) << "case " << kind;
        ++irregular;
        continue;
      }
      ASSERT_TRUE(out.regular[static_cast<size_t>(l)]) << batch << " " << l;
      ++regular;
      const Curvature b = out.curvature(l);
      EXPECT_TRUE(same_bits(a.normal, b.normal) && same_bits(a.k1, b.k1) && same_bits(a.k2, b.k2) &&
                  same_bits(a.H, b.H) && same_bits(a.K, b.K) && same_bits(a.d1, b.d1) &&
                  same_bits(a.d2, b.d2))
          << "batch " << batch << " lane " << l << ": k1 " << a.k1 << " vs " << b.k1 << ", d1 "
          << a.d1.transpose() << " vs " << b.d1.transpose();
    }
  }
  EXPECT_EQ(regular + irregular, 400 * kLanes);
  EXPECT_EQ(regular, 400 * kLanes / 2);  // cases 4-7 of every 8
}

}  // namespace
}  // namespace curvbench
