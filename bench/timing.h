// Wall-clock timing for the benchmark programs that are not Google Benchmark suites
// (bench_limits, bench_neighbourhoods): the minimum over repetitions, since a shared machine only
// ever adds time; and keep_freed_memory, which every benchmark program calls first.
#pragma once

#include <algorithm>
#include <chrono>
#include <functional>
#include <limits>

#include <malloc.h>

namespace curvbench::bench {

/// Keeps the memory freed by one pass in the process for the next (glibc: no mmap for large
/// blocks, no trimming of the heap), so that every pass after the first reuses memory that is
/// already mapped. Called first thing in main(). Without it a pass paid for page faults that
/// depended on which benchmark ran before it: on the project's virtual machine, after CGAL's
/// LSCM had run, LHF-2 passes at 1.44 million vertices took 0.56-0.85 s instead of 0.36 s at
/// random (memory given back to the kernel is faulted in again through the hypervisor), which
/// random interleaving spread over the medians. The first pass of a run (and the end-to-end
/// row, a separate process) still pays for its first touches; the median does not see them.
inline void keep_freed_memory() {
  mallopt(M_MMAP_MAX, 0);
  mallopt(M_TRIM_THRESHOLD, -1);  // no trimming (the largest value)
}

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
