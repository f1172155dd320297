// Wall-clock timing for the benchmark programs that are not Google Benchmark suites
// (bench_limits, bench_neighbourhoods): the minimum over repetitions, since a shared machine only
// ever adds time.
#pragma once

#include <algorithm>
#include <chrono>
#include <functional>
#include <limits>

namespace curvbench::bench {

/// Seconds of wall time of one call of f.
inline double seconds_of(const std::function<void()>& f) {
  const auto t = std::chrono::steady_clock::now();
  f();
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t).count();
}

/// The minimum over `repeat` runs of f (a `prepare` before each, not timed).
inline double best_of(
    int repeat, const std::function<void()>& f, const std::function<void()>& prepare = [] {}) {
  double best = std::numeric_limits<double>::infinity();
  for (int r = 0; r < repeat; ++r) {
    prepare();
    best = std::min(best, seconds_of(f));
  }
  return best;
}

}  // namespace curvbench::bench
