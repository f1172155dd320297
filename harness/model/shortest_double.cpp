#include "harness/model/shortest_double.h"

#include <charconv>
#include <cmath>
#include <cstdint>
#include <cstring>

// {fmt} 9 header-only: only its Dragonbox shortest-digits routine is used (fmt::detail, pinned by
// tools/deps.sh's libfmt-dev and checked against std::to_chars by the tests).
#ifndef FMT_HEADER_ONLY
#define FMT_HEADER_ONLY
#endif
#include <fmt/format.h>

namespace curvbench {

namespace {

constexpr char kDigitPairs[] =
    "00010203040506070809101112131415161718192021222324252627282930313233343536373839"
    "40414243444546474849505152535455565758596061626364656667686970717273747576777879"
    "8081828384858687888990919293949596979899";

void put2(char* p, unsigned r) {
  std::memcpy(p, kDigitPairs + 2 * r, 2);
}

/// Exactly 8 digits of v < 10^8.
void put8(char* p, std::uint32_t v) {
  const std::uint32_t hi = v / 10000, lo = v % 10000;
  put2(p, hi / 100);
  put2(p + 2, hi % 100);
  put2(p + 4, lo / 100);
  put2(p + 6, lo % 100);
}

}  // namespace

char* write_shortest(char* p, double x) {
  if (!std::isfinite(x) || x == 0.0) return std::to_chars(p, p + 32, x).ptr;
  if (std::signbit(x)) {
    *p++ = '-';
    x = -x;
  }
  const auto dec = fmt::detail::dragonbox::to_decimal(x);
  const int exponent = dec.exponent;  // x = significand * 10^exponent, at most 17 digits
  // The digits end at buf + 32 and are followed by zeros, so that fixed-size copies (no library
  // call for a variable length) carry whatever trailing zeros a layout needs.
  char buf[64];
  std::memset(buf + 32, '0', 32);
  char* const end = buf + 32;
  char* d = end;
  std::uint64_t v = dec.significand;
  while (v >= 100000000) {
    const std::uint64_t q = v / 100000000;
    d -= 8;
    put8(d, static_cast<std::uint32_t>(v - q * 100000000));
    v = q;
  }
  auto w = static_cast<std::uint32_t>(v);
  while (w >= 100) {
    d -= 2;
    put2(d, w % 100);
    w /= 100;
  }
  if (w >= 10) {
    d -= 2;
    put2(d, w);
  } else {
    *--d = static_cast<char>('0' + w);
  }
  const int length = static_cast<int>(end - d);
  // std::to_chars's choice (the shorter of %f and %e, %f on a tie), as the exponent range in
  // which fixed is not longer: one digit "0.001" .. "10000"; more, "0.0001234" .. "123400000".
  const int lower = length == 1 ? -3 : -(length + 3);
  const int upper = length == 1 ? 4 : 5;
  if (lower <= exponent && exponent <= upper) {
    if (exponent >= 0) {  // the digits, then the zeros after them in buf (<= 22 in all)
      // At and beyond 2^53 an integer's shortest digits and zeros need not be its value, and
      // std::to_chars then prints the exact integer in full (below, the rounding interval holds
      // no other integer): its bytes for those few.
      if (exponent > 0 && x >= 9007199254740992.0) return std::to_chars(p, p + 32, x).ptr;
      std::memcpy(p, d, 24);
      return p + length + exponent;
    }
    const int whole = length + exponent;  // digits before the point, <= 16
    if (whole > 0) {
      std::memcpy(p, d, 16);
      p[whole] = '.';
      std::memcpy(p + whole + 1, d + whole, 16);  // the <= 16 digits after the point
      return p + length + 1;
    }
    std::memcpy(p, "0.000", 5);  // "0." and the -whole <= 3 zeros
    std::memcpy(p + 2 - whole, d, 24);
    return p + 2 - whole + length;
  }
  // d.ddde+XX
  p[0] = d[0];
  if (length > 1) {
    p[1] = '.';
    std::memcpy(p + 2, d + 1, 16);
    p += length + 1;
  } else {
    p += 1;
  }
  int e = exponent + length - 1;
  *p++ = 'e';
  *p++ = e < 0 ? '-' : '+';
  if (e < 0) e = -e;
  if (e >= 100) {
    *p++ = static_cast<char>('0' + e / 100);
    e %= 100;
  }
  put2(p, static_cast<unsigned>(e));
  return p + 2;
}

}  // namespace curvbench
