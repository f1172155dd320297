// Seeded, deterministic random numbers for the mesh generators (docs/algorithms.md §10.1(b) jitter,
// §10.2 irregular point set, §10.3 controlled noise).
//
// The engine is std::mt19937_64, whose output sequence is fixed by the C++ standard. The
// distributions are written here instead of using std::uniform_real_distribution /
// std::normal_distribution, whose outputs differ between standard libraries, so a given seed
// gives the same meshes on every platform:
//   uniform01()  53-bit uniform in [0, 1): (engine() >> 11) * 2^-53
//   normal()     standard normal by the Box-Muller transform of two 53-bit uniforms; both
//                values of a pair are used (the second one is cached).
#pragma once

#include <cstdint>
#include <random>

namespace curvbench {

/// SplitMix64 finaliser: a bijective 64-bit mix, used to derive independent stream seeds.
std::uint64_t splitmix64(std::uint64_t x);

/// Seed of sub-stream `stream` of the user seed `seed` (e.g. one stream per level), so that
/// different levels or generators never share a random sequence.
std::uint64_t derive_seed(std::uint64_t seed, std::uint64_t stream);

class Rng {
 public:
  explicit Rng(std::uint64_t seed) : engine_(seed) {}

  /// Uniform in [0, 1) with 53 random bits.
  double uniform01();
  /// Uniform in [a, b).
  double uniform(double a, double b) { return a + (b - a) * uniform01(); }
  /// Standard normal N(0, 1) (Box-Muller).
  double normal();

 private:
  std::mt19937_64 engine_;
  bool has_spare_ = false;
  double spare_ = 0.0;
};

}  // namespace curvbench
