#include "harness/report/table5.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <map>
#include <optional>
#include <tuple>
#include <vector>

#include "harness/model/paper_tables.h"
#include "harness/model/results_table.h"
#include "methods/estimator.h"

namespace curvbench {

namespace fs = std::filesystem;

namespace {

constexpr int kLevels = 4;  // Table 5's levels of the well-shaped torus

std::string fmt(const char* f, double x) {
  char buf[64];
  std::snprintf(buf, sizeof buf, f, x);
  return buf;
}

struct BenchRow {
  int level = 0;
  long verts = 0, tris = 0;
  std::string method;
  int threads = 1;
  double seconds = 0.0;
};

std::vector<BenchRow> read_timings(const std::string& path) {
  std::vector<BenchRow> out;
  if (!fs::exists(path)) return out;
  const CsvTable t = read_csv_table(path);
  const size_t cl = t.col("level"), cv = t.col("verts"), ct = t.col("tris"), cm = t.col("method"),
               cth = t.col("threads"), cs = t.col("seconds");
  for (size_t i = 0; i < t.rows.size(); ++i)
    out.push_back({t.integer(i, cl), static_cast<long>(t.number(i, cv)),
                   static_cast<long>(t.number(i, ct)), t.text(i, cm), t.integer(i, cth),
                   t.number(i, cs)});
  return out;
}

class Lookup {
 public:
  explicit Lookup(const std::vector<BenchRow>& rows) {
    for (const BenchRow& r : rows) map_[{r.method, r.level, r.threads}] = &r;
  }
  const BenchRow* get(const std::string& m, int level, int threads = 1) const {
    const auto it = map_.find({m, level, threads});
    return it == map_.end() ? nullptr : it->second;
  }
  /// t(a) / t(b), or nullopt.
  std::optional<double> ratio(const std::string& a, const std::string& b, int level, int ta = 1,
                              int tb = 1) const {
    const BenchRow* x = get(a, level, ta);
    const BenchRow* y = get(b, level, tb);
    if (!x || !y || y->seconds <= 0.0) return std::nullopt;
    return x->seconds / y->seconds;
  }

 private:
  std::map<std::tuple<std::string, int, int>, const BenchRow*> map_;
};

report::Cell ratio_cell(std::optional<double> x, const std::string& suffix = "") {
  return x ? report::Cell::number(*x, fmt("%.2f", *x) + suffix) : report::Cell("-");
}

// The text after "# machine: " in the CSV's comment lines, "" if none.
std::string machine_line(const std::string& path) {
  std::ifstream in(path);
  for (std::string line; std::getline(in, line);)
    if (line.rfind("# machine: ", 0) == 0) return line.substr(11);
  return "";
}

// A bench_solvers row (QR against SVD on identical systems): the solver table's, not a method's.
bool is_solver_row(const std::string& method) {
  return method.find("QR") != std::string::npos || method.find("SVD") != std::string::npos;
}

// The reference method of the ratios (paper::kTable5Reference) at a degree: "LHF-2".
std::string reference(int degree) {
  return std::string(paper::kTable5Reference) + "-" + std::to_string(degree);
}

// The columns of our tables: the paper's eight methods, then every other one-thread row of the
// timings (registry methods and bench variants such as "LHF-2 scalar"), in the file's order.
std::vector<std::string> our_methods(const std::vector<BenchRow>& rows) {
  std::vector<std::string> ours(paper::kTable5Methods.begin(), paper::kTable5Methods.end());
  for (const BenchRow& r : rows)
    if (r.threads == 1 && !is_solver_row(r.method) &&
        std::find(ours.begin(), ours.end(), r.method) == ours.end())
      ours.push_back(r.method);
  return ours;
}

// Our times with the paper's in parentheses, then the throughput.
void times_tables(report::Section& s, const std::vector<BenchRow>& rows, const Lookup& t) {
  const std::vector<std::string> ours = our_methods(rows);
  report::Table times;
  times.id = "table5-times";
  times.columns = {"mesh", "#V", "#T"};
  times.columns.insert(times.columns.end(), ours.begin(), ours.end());
  report::Table throughput;
  throughput.id = "table5-throughput";
  throughput.columns = {"mesh"};
  throughput.columns.insert(throughput.columns.end(), ours.begin(), ours.end());
  throughput.columns.push_back(reference(2) + " (2 threads)");
  // Thousand triangles per second of a row, as a cell.
  const auto rate = [](const BenchRow* r) {
    if (r == nullptr) return report::Cell("-");
    const double k = 1e-3 * static_cast<double>(r->tris) / r->seconds;
    return report::Cell::number(k, fmt("%.0f", k));
  };
  for (int level = 1; level <= kLevels; ++level) {
    const BenchRow* any = t.get(reference(2), level);
    const paper::Table5Row& p = paper::kTable5[static_cast<size_t>(level - 1)];
    std::vector<report::Cell> row{
        report::Cell::number(level, std::to_string(level)),
        report::Cell::number(
            any ? any->verts : std::nan(""),
            (any ? std::to_string(any->verts) : "-") + " (" + std::to_string(p.vertices) + ")"),
        report::Cell::number(
            any ? any->tris : std::nan(""),
            (any ? std::to_string(any->tris) : "-") + " (" + std::to_string(p.triangles) + ")")};
    std::vector<report::Cell> trow{report::Cell::number(level, std::to_string(level))};
    for (const std::string& m : ours) {
      const BenchRow* r = t.get(m, level);
      const double paper_s = paper::table5_seconds(m, level);
      const std::string paper_text = paper_s > 0.0 ? " (" + fmt("%.3g", paper_s) + ")" : "";
      row.push_back(r ? report::Cell::number(r->seconds, fmt("%.3g", r->seconds) + paper_text)
                      : report::Cell("-" + paper_text));
      trow.push_back(rate(r));
    }
    trow.push_back(rate(t.get(reference(2), level, 2)));
    times.add(std::move(row));
    throughput.add(std::move(trow));
  }
  s.heading("Our times (seconds, 1 thread), paper's in parentheses")
      .table(std::move(times))
      .heading("Throughput (thousand triangles/s, 1 thread)")
      .table(std::move(throughput));
}

// Time ratios, ours and (where the paper has both methods) the paper's: the paper's ratios
// (paper::kTable5Ratios), then each other method against the reference of its degree (a
// degree-free one against degree 2) and each bench variant ("LHF-2 scalar") against its method.
void ratio_table(report::Section& s, const std::vector<BenchRow>& rows, const Lookup& t) {
  struct RatioDef {
    std::string a, b;
    bool paper;
  };
  std::vector<RatioDef> ratios;
  for (const paper::Table5Ratio& r : paper::kTable5Ratios)
    ratios.push_back({std::string(r.a), std::string(r.b), true});
  const std::vector<std::string> ours = our_methods(rows);
  for (size_t i = paper::kTable5Methods.size(); i < ours.size(); ++i) {
    const std::string& m = ours[i];
    if (const size_t space = m.find(' '); space != std::string::npos) {
      ratios.push_back({m, m.substr(0, space), false});  // a bench variant of its method
      continue;
    }
    const size_t dash = m.rfind('-');
    const bool fit = dash != std::string::npos && dash + 2 == m.size() &&
                     std::isdigit(static_cast<unsigned char>(m.back()));
    const std::string ref = reference(fit ? m.back() - '0' : 2);
    if (m != ref) ratios.push_back({m, ref, false});
  }
  report::Table tab;
  tab.id = "table5-ratios";
  tab.columns = {"ratio"};
  for (int level = 1; level <= kLevels; ++level)
    tab.columns.push_back("level " + std::to_string(level));
  for (const RatioDef& r : ratios) {
    std::vector<report::Cell> row{r.a + " / " + r.b};
    for (int level = 1; level <= kLevels; ++level) {
      std::string paper_text;
      if (r.paper) {
        const double pa = paper::table5_seconds(r.a, level), pb = paper::table5_seconds(r.b, level);
        if (pa > 0.0 && pb > 0.0) paper_text = " (" + fmt("%.2f", pa / pb) + ")";
      }
      row.push_back(ratio_cell(t.ratio(r.a, r.b, level), paper_text));
    }
    tab.add(std::move(row));
  }
  s.heading("Time ratios, ours (paper)")
      .text(std::string(paper::kTable5JetNote))
      .table(std::move(tab));
}

// Safeguarded QR against SVD on identical LHF-2 systems (bench_solvers' rows).
void solver_table(report::Section& s, const std::vector<BenchRow>& rows, const Lookup& t) {
  std::vector<std::string> methods;
  std::string qr;
  for (const BenchRow& r : rows)
    if (is_solver_row(r.method) &&
        std::find(methods.begin(), methods.end(), r.method) == methods.end()) {
      methods.push_back(r.method);
      if (r.method.find("QR") != std::string::npos) qr = r.method;
    }
  if (methods.empty()) return;
  s.heading("Safeguarded QR vs SVD on identical " + reference(2) + " systems")
      .text("Measured by `bench/bench_solvers`: the weighted " + reference(2) +
            " systems of every vertex "
            "(1.5-ring grown to at least 9 neighbours, eq. 15 weights with the normal safeguard) "
            "are built once and stored; seconds = median wall time of fitting all of them "
            "(Vandermonde fill, row weighting, column scaling, solve, Taylor coefficients; only "
            "the solver differs), without neighbourhoods or frames. SVD: truncated at the absolute "
            "threshold 1e-8 after 2-norm column scaling (the `set_solver` defaults); the paper: "
            "\"roughly a factor of five\".");
  report::Table tab;
  tab.id = "table5-solvers";
  tab.columns = {"mesh"};
  for (const std::string& m : methods) tab.columns.push_back(m + " (s)");
  for (const std::string& m : methods)
    if (m.find("SVD") != std::string::npos) tab.columns.push_back(m + " / QR");
  for (int level = 1; level <= kLevels; ++level) {
    std::vector<report::Cell> row{report::Cell::number(level, std::to_string(level))};
    for (const std::string& m : methods) {
      const BenchRow* r = t.get(m, level);
      row.push_back(r ? report::Cell::number(r->seconds, fmt("%.3g", r->seconds))
                      : report::Cell("-"));
    }
    for (const std::string& m : methods)
      if (m.find("SVD") != std::string::npos)
        row.push_back(ratio_cell(qr.empty() ? std::nullopt : t.ratio(m, qr, level)));
    tab.add(std::move(row));
  }
  s.table(std::move(tab));
}

// Linear scaling: LHF-2's time per vertex on levels 1-6, 1 and 2 threads.
void scaling_table(report::Section& s, const std::vector<BenchRow>& table5,
                   const std::vector<BenchRow>& sweep) {
  std::vector<BenchRow> rows;
  for (const auto* part : {&table5, &sweep})
    for (const BenchRow& r : *part)
      if (r.method == reference(2)) rows.push_back(r);
  if (rows.empty()) return;
  const Lookup t(rows);
  int top = 0;
  for (const BenchRow& r : rows) top = std::max(top, r.level);
  report::Table tab;
  tab.id = "table5-scaling";
  tab.columns = {"level",         "#V",        "1 thread (s)", "ns/vertex",
                 "2 threads (s)", "ns/vertex", "speed-up"};
  double lo = 0.0, hi = 0.0;
  for (int level = 1; level <= top; ++level) {
    const BenchRow* a = t.get(reference(2), level, 1);
    const BenchRow* b = t.get(reference(2), level, 2);
    if (!a && !b) continue;
    const long verts = a ? a->verts : b->verts;
    std::vector<report::Cell> row{report::Cell::number(level, std::to_string(level)),
                                  report::Cell::number(verts, std::to_string(verts))};
    for (const BenchRow* r : {a, b}) {
      if (r == nullptr) {
        row.insert(row.end(), {"-", "-"});
        continue;
      }
      const double ns = 1e9 * r->seconds / static_cast<double>(verts);
      row.push_back(report::Cell::number(r->seconds, fmt("%.3g", r->seconds)));
      row.push_back(report::Cell::number(ns, fmt("%.0f", ns)));
    }
    row.push_back(ratio_cell(t.ratio(reference(2), reference(2), level, 1, 2)));
    tab.add(std::move(row));
    if (a) {
      const double ns = 1e9 * a->seconds / static_cast<double>(verts);
      lo = lo == 0.0 ? ns : std::min(lo, ns);
      hi = std::max(hi, ns);
    }
  }
  s.heading("Scaling and threads: " + reference(2) +
            " cost per vertex from 1.4 thousand to 1.44 million vertices, "
            "1 and 2 threads")
      .table(std::move(tab));
  if (lo > 0.0)
    s.text("Per-vertex time, 1 thread: max/min = " + fmt("%.2f", hi / lo) +
           " over the levels above (target: within 20%, i.e. <= 1.2).");
}

// `curvbench estimate` end to end on 1.44 million vertices (tools/bench.sh).
void end_to_end_table(report::Section& s, const std::string& path) {
  if (!fs::exists(path)) return;
  const CsvTable t = read_csv_table(path);
  s.heading("End to end: `curvbench estimate` on 1.44 million vertices")
      .text(reference(2) +
            " on the torus-structured level-6 mesh (1441792 vertices, 2883584 triangles), "
            "binary PLY in, CSV out (`--timing`, seconds of wall time per stage; estimation and "
            "writing alternate block by block, a CSV block formatted and written by two background "
            "threads while the next is estimated; each stage is the sum of its own parts; fit = "
            "normals, neighbourhoods and fits; write = the time the estimation waited for the "
            "output). Peak resident set size from `/usr/bin/time -v`. Targets "
            "(docs/performance.md): read <= 0.3 s, end to end <= 1.5 s on one thread, peak RSS <= "
            "350 MB.");
  report::Table tab;
  tab.id = "table5-end-to-end";
  tab.columns = {"threads", "read", "orientation", "fit", "write", "wall (m:ss)", "peak RSS (MB)"};
  const size_t cth = t.col("threads"), cw = t.col("wall_s"), cm = t.col("peak_rss_mb");
  for (size_t i = 0; i < t.rows.size(); ++i) {
    std::vector<report::Cell> row{report::Cell::number(t.number(i, cth), t.text(i, cth))};
    for (const char* stage : {"read_s", "orientation_s", "fit_s", "write_s"}) {
      const double x = t.number(i, t.col(stage));
      row.push_back(report::Cell::number(x, fmt("%.3f", x)));
    }
    const double wall = t.number(i, cw);
    const int minutes = static_cast<int>(wall / 60.0);
    row.push_back(report::Cell::number(
        wall, std::to_string(minutes) + ":" + fmt("%05.2f", wall - 60.0 * minutes)));
    row.push_back(report::Cell::number(t.number(i, cm), t.text(i, cm)));
    tab.add(std::move(row));
  }
  s.table(std::move(tab));
}

// The limits table (bench/bench_limits.cpp): each stage of `curvbench estimate` at 1.44 million
// vertices against the bound this machine's hardware sets on it.
void limits_table(report::Section& s, const std::string& path) {
  if (!fs::exists(path)) return;
  const CsvTable t = read_csv_table(path);
  s.heading("How far each stage is from the hardware's limit")
      .text(
          "`curvbench estimate` at 1.44 million vertices, one thread, each stage measured in "
          "process (the minimum of 3) against the bound this machine sets on it, measured "
          "alongside: a plain copy or write of the same bytes, memory and cache bandwidth, the "
          "peak vector multiply-add rate (docs/performance.md). Data: `limits.csv`.");
  report::Table tab;
  tab.id = "limits";
  tab.columns = {"stage", "measured (s)", "bound (s)", "bound", "measured / bound", "notes"};
  tab.numeric = {false, true, true, false, true, false};
  const size_t cs = t.col("stage"), cm = t.col("measured_seconds"), cb = t.col("bound_seconds"),
               ck = t.col("bound_kind"), cr = t.col("ratio"), cn = t.col("notes");
  for (size_t i = 0; i < t.rows.size(); ++i) {
    const double m = t.number(i, cm), b = t.number(i, cb), r = t.number(i, cr);
    tab.add({t.text(i, cs), report::Cell::number(m, fmt("%.3f", m)),
             report::Cell::number(b, fmt("%.3f", b)), t.text(i, ck),
             report::Cell::number(r, fmt("%.1f", r)), t.text(i, cn)});
  }
  s.table(std::move(tab));
}

}  // namespace

report::Section table5_section(const std::string& results_dir) {
  report::Section s{"table5", "Table 5: timing (generated by `make bench`)", {}};
  const std::string csv = results_dir + "/table5_timing.csv";
  if (!fs::exists(csv)) {
    s.text("Not measured yet: run `make bench`.");
    return s;
  }
  const std::vector<BenchRow> rows = read_timings(csv);
  const Lookup t(rows);
  const std::string machine = machine_line(csv);
  s.text("Machine: " + (machine.empty() ? std::string("not recorded") : machine) + ".");
  s.text(
      "Measured by `bench/bench_estimators` (Google Benchmark): seconds = median wall time of "
      "`estimate_mesh()` over every timed whole-mesh pass (all iterations of 9 repetitions), i.e. "
      "the per-vertex stage for the whole mesh including neighbourhoods and the area-weighted "
      "normals, excluding I/O and mesh generation; one thread unless stated. Memory freed by "
      "a pass stays in the process for the next (bench/table5.h, keep_freed_memory), so "
      "passes do not pay for page faults caused by the benchmark that ran before them. Meshes: "
      "the well-shaped unstructured torus (`torus-unstructured`, levels 1-4; the scaling "
      "sweep's levels 5-6 are `torus-structured`). Paper: 3 GHz Pentium 4, gcc 4.2.4 "
      "(docs/claims.md, F). Data: `table5_timing.csv`, `table5_scaling.csv`, `end_to_end.csv`.");
  times_tables(s, rows, t);
  ratio_table(s, rows, t);
  solver_table(s, rows, t);
  scaling_table(s, rows, read_timings(results_dir + "/table5_scaling.csv"));
  limits_table(s, results_dir + "/limits.csv");
  end_to_end_table(s, results_dir + "/end_to_end.csv");
  return s;
}

}  // namespace curvbench
