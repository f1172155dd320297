// The CSV's number text: the shortest decimal that reads back to exactly the double, laid out as
// std::to_chars(first, last, x) lays it out (plain format: fixed or scientific, whichever is
// shorter, fixed on a tie), byte for byte, about three times faster than libstdc++'s to_chars:
// the digits come from the Dragonbox algorithm ({fmt}'s, header-only), the layout is
// std::to_chars's rule. tests/harness/test_shortest_double.cpp checks the bytes against
// std::to_chars on millions of doubles over the whole range.
#pragma once

namespace curvbench {

/// Bytes write_shortest needs at p: it copies whole words past the number's end.
inline constexpr int kShortestRoom = 48;

/// Writes x at p (at most 24 characters; non-finite values as std::to_chars writes them) and
/// returns the end.
char* write_shortest(char* p, double x);

}  // namespace curvbench
