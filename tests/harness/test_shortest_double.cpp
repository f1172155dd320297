// harness/model/shortest_double.h: the estimate CSV's numbers are std::to_chars's bytes, exactly.
#include <gtest/gtest.h>

#include <charconv>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <limits>
#include <random>
#include <string>

#include "harness/model/shortest_double.h"

namespace curvbench {
namespace {

std::string reference(double x) {
  char b[64];
  return std::string(b, std::to_chars(b, b + sizeof b, x).ptr);
}

std::string ours(double x) {
  char b[64];
  return std::string(b, write_shortest(b, x));
}

double from_bits(std::uint64_t u) {
  double x;
  std::memcpy(&x, &u, sizeof x);
  return x;
}

TEST(ShortestDouble, SpecialValues) {
  for (const double x : {0.0,
                         -0.0,
                         1.0,
                         -1.0,
                         0.1,
                         0.5,
                         1e-3,
                         1e-4,
                         1e4,
                         1e5,
                         1234e-7,
                         1234e-8,
                         1234e5,
                         1234e6,
                         123456789012345678.0,
                         1e22,
                         1e23,
                         5e-324,
                         -5e-324,
                         2.2250738585072014e-308,
                         std::numeric_limits<double>::max(),
                         std::numeric_limits<double>::lowest(),
                         std::numeric_limits<double>::min(),
                         std::numeric_limits<double>::denorm_min(),
                         std::numeric_limits<double>::infinity(),
                         -std::numeric_limits<double>::infinity(),
                         std::numeric_limits<double>::quiet_NaN(),
                         9007199254740993.0,
                         0.30000000000000004})
    EXPECT_EQ(ours(x), reference(x)) << reference(x);
}

// Every binary exponent and sign through random bit patterns, and the neighbourhoods of the
// layout's switch points: d * 10^k for short d and every k, and their neighbouring doubles.
TEST(ShortestDouble, SameBytesAsToCharsOverTheWholeRange) {
  std::mt19937_64 rng(12345);
  int checked = 0;
  const auto check = [&](double x) {
    if (std::isnan(x)) return;
    const std::string a = ours(x), b = reference(x);
    ASSERT_EQ(a, b) << "bits " << std::hex << [&] {
      std::uint64_t u;
      std::memcpy(&u, &x, sizeof u);
      return u;
    }();
    ++checked;
  };
  for (int i = 0; i < 3'000'000; ++i) check(from_bits(rng()));
  std::uniform_real_distribution<double> unit(-1.0, 1.0);
  for (int i = 0; i < 1'000'000; ++i) {
    const double u = unit(rng);
    check(u);
    check(u * 1e5);
    check(std::ldexp(u, static_cast<int>(rng() % 200) - 100));
  }
  for (int k = -325; k <= 309; ++k)
    for (const double d : {1.0, 2.0, 5.0, 9.0, 12.0, 99.0, 123.0, 1234.0, 98765.0, 123456789.0}) {
      const double x = d * std::pow(10.0, k);
      if (!std::isfinite(x) || x == 0) continue;
      check(x);
      check(-x);
      check(std::nextafter(x, 0.0));
      check(std::nextafter(x, std::numeric_limits<double>::infinity()));
    }
  for (int v = 1; v <= 200000; ++v) {
    check(v);
    check(v / 1000.0);
  }
  EXPECT_GT(checked, 6'000'000);
}

}  // namespace
}  // namespace curvbench
