// Shared helpers of the benchmark suites (bench_estimators, bench_solvers) for the paper's
// Table 5 (§5.4): timing samples recorded by the benchmark bodies, the rows of
// results/table5_timing.csv, atomic file writes and the process's memory policy.
//
// CSV columns: mesh,level,verts,tris,method,degree,threads,seconds,tris_per_second
//   seconds          median over every timed whole-mesh pass (all iterations of all repetitions)
//   tris_per_second  tris / seconds
// Header-only: each bench/*.cpp is its own executable.
#pragma once

#include <unistd.h>

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

#include <benchmark/benchmark.h>

#include "bench/timing.h"
#include "core/build_info.h"
#include "harness/model/results_table.h"

namespace curvbench::bench {

/// The settings every per-level sweep shares: mesh levels 1..levels as the argument, wall time,
/// 9 repetitions (the median resists the bursts of load of a shared machine) of at least 0.1 s,
/// milliseconds, and an O(N) complexity fit.
inline benchmark::internal::Benchmark* level_sweep(benchmark::internal::Benchmark* b, int levels) {
  return b->DenseRange(1, levels)
      ->ArgName("level")
      ->UseRealTime()
      ->MinTime(0.1)
      ->Repetitions(9)
      ->Unit(benchmark::kMillisecond)
      ->Complexity(benchmark::oN);
}

inline constexpr const char* kTable5Header =
    "mesh,level,verts,tris,method,degree,threads,seconds,tris_per_second";

/// One (mesh level, method, threads) case and the wall times of its whole-mesh passes.
struct Sample {
  std::string mesh;
  int level = 0;
  long verts = 0;
  long tris = 0;
  std::string method;  ///< label, e.g. "LHF-2", "LHF-2 QR"
  int degree = 0;
  int threads = 1;
  std::vector<double> seconds;
};

/// Registry of samples in registration order (benchmarks run in that order).
class SampleLog {
 public:
  Sample& get(const Sample& key) {
    const std::string id = key.mesh + "|" + std::to_string(key.level) + "|" + key.method + "|" +
                           std::to_string(key.threads);
    auto it = index_.find(id);
    if (it != index_.end()) return samples_[it->second];
    index_[id] = samples_.size();
    samples_.push_back(key);
    return samples_.back();
  }
  const std::vector<Sample>& samples() const { return samples_; }

 private:
  std::map<std::string, size_t> index_;
  std::vector<Sample> samples_;
};

inline double median(std::vector<double> x) {
  if (x.empty()) return 0.0;
  std::sort(x.begin(), x.end());
  const size_t n = x.size();
  return n % 2 == 1 ? x[n / 2] : 0.5 * (x[n / 2 - 1] + x[n / 2]);
}

/// A row of table5_timing.csv (seconds already the median).
struct Table5Row {
  std::string mesh;
  int level = 0;
  long verts = 0;
  long tris = 0;
  std::string method;
  int degree = 0;
  int threads = 1;
  double seconds = 0.0;
};

inline std::vector<Table5Row> rows_from_samples(const SampleLog& log) {
  std::vector<Table5Row> rows;
  for (const Sample& s : log.samples()) {
    if (s.seconds.empty()) continue;  // filtered out
    rows.push_back(
        {s.mesh, s.level, s.verts, s.tris, s.method, s.degree, s.threads, median(s.seconds)});
  }
  return rows;
}

/// The CSV text: the provenance comment, `comment` (a further '#' line, none if empty), the
/// header, the rows.
inline std::string format_rows(const std::vector<Table5Row>& rows,
                               const std::string& comment = "") {
  std::string out = provenance_comment() + "\n" + (comment.empty() ? "" : comment + "\n") +
                    std::string(kTable5Header) + "\n";
  char buf[512];
  for (const Table5Row& r : rows) {
    std::snprintf(buf, sizeof buf, "%s,%d,%ld,%ld,%s,%d,%d,%.6g,%.6g\n", r.mesh.c_str(), r.level,
                  r.verts, r.tris, r.method.c_str(), r.degree, r.threads, r.seconds,
                  r.seconds > 0.0 ? static_cast<double>(r.tris) / r.seconds : 0.0);
    out += buf;
  }
  return out;
}

/// Reads a file written by format_rows (throws std::runtime_error naming the file).
inline std::vector<Table5Row> read_rows(const std::string& path) {
  const CsvTable t = read_csv_table(path);
  std::string header;
  for (const auto& h : t.header) header += (header.empty() ? "" : ",") + h;
  if (header != kTable5Header) throw std::runtime_error(path + ": not a table5 timing file");
  std::vector<Table5Row> rows;
  for (size_t i = 0; i < t.rows.size(); ++i)
    rows.push_back({t.text(i, 0), t.integer(i, 1), t.integer(i, 2), t.integer(i, 3), t.text(i, 4),
                    t.integer(i, 5), t.integer(i, 6), t.number(i, 7)});
  return rows;
}

/// Removes the flag --name=VALUE from argv (before benchmark::Initialize) and returns VALUE.
inline std::string take_flag(int& argc, char** argv, const std::string& name) {
  const std::string prefix = "--" + name + "=";
  std::string value;
  int out = 1;
  for (int i = 1; i < argc; ++i) {
    const std::string a = argv[i];
    if (a.rfind(prefix, 0) == 0) {
      value = a.substr(prefix.size());
    } else {
      argv[out++] = argv[i];
    }
  }
  argc = out;
  return value;
}

}  // namespace curvbench::bench
