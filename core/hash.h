// 64-bit FNV-1a: the project's one non-cryptographic hash (case-store stamps, the plot styles'
// fallback slot). Stable across platforms and runs, so hashes may be written to files.
#pragma once

#include <cstdint>
#include <string_view>

namespace curvbench {

inline constexpr std::uint64_t kFnv1a64Offset = 0xcbf29ce484222325ULL;

/// FNV-1a of `bytes`, continuing from `h` (chain calls to hash several pieces).
constexpr std::uint64_t fnv1a64(std::string_view bytes, std::uint64_t h = kFnv1a64Offset) {
  for (unsigned char ch : bytes) {
    h ^= ch;
    h *= 0x100000001b3ULL;  // the FNV 64-bit prime
  }
  return h;
}

}  // namespace curvbench
