// Google Benchmark suite for the paper's Table 5 (§5.4, §4.3.2): every estimator of Table 5
// plus CGAL's Jet_fitting_3, the in-house LSCM and the discrete operators (Meyer, Taubin,
// Rusinkiewicz, the libigl quadric, Goldfeather, the normal cycle) on the well-shaped
// (torus-unstructured) torus, levels 1-4, one thread; LHF-2 also with 2 threads; LHF-2, LHF-4
// and LOP-2 also with the scalar fitting kernel (rows "LHF-2 scalar", ...; the plain rows are
// the default batched kernel, EstimatorOptions::kernel). Scaling: LHF-2
// with 1 and 2 threads on torus-structured levels 5 and 6 as well (1024x352 and 2048x704 = 1.44
// million vertices), written to table5_scaling.csv (table5_timing.csv is Table 5's four levels).
//
// Timed: estimate_mesh() = the per-vertex stage for the whole mesh (area-weighted normals,
// neighbourhoods, fits, formulas); the meshes are generated once before any benchmark runs and
// no I/O is timed. Counters: tris/s (rate), verts, tris; Complexity(oN) over N = triangles.
//
// Extra flags (removed before benchmark::Initialize):
//   --table5_dir=DIR      write DIR/table5_timing.csv (Table 5's levels, with the rows of
//                         --table5_extra) and DIR/table5_scaling.csv (the scaling sweep's levels
//                         5-6) after the run; CSV only (the report renders them:
//                         harness/report/table5.h)
//   --table5_extra=FILE   rows written by bench_solvers (QR vs SVD) to merge into the first
//   --build_info=TEXT     build type and flags, in the CSV's comment line "# machine: ..."
// seconds in the CSV = median of the wall times of every timed whole-mesh pass (all
// iterations of all repetitions).
#include <benchmark/benchmark.h>

#include <algorithm>
#include <array>
#include <chrono>
#include <cstdio>
#include <fstream>
#include <memory>
#include <optional>
#include <string>
#include <thread>
#include <vector>

#include "bench/table5.h"
#include "mesh/neighbourhood_table.h"
#include "meshgen/generate.h"
#include "methods/estimator.h"
#include "methods/fits/ring_fit_estimator.h"

// GCC 12 reports a false -Wrestrict in std::string operator+ (const char*, string&&) at -O3
// (GCC bug 105329).
#pragma GCC diagnostic ignored "-Wrestrict"

namespace curvbench::bench {
namespace {

constexpr int kLevels = 4;         // Table 5
constexpr int kScalingLevels = 6;  // linear-scaling check, 1.4 thousand to 1.44 million vertices
// Table 5 on the paper's well-shaped family (levels 1-4); the scaling sweep's levels 5-6 on the
// structured torus (torus-unstructured stops at the paper's finest level 4).
const char* const kFamily = "torus-unstructured";
const char* const kScalingFamily = "torus-structured";
const char* family_of(int level) {
  return level <= kLevels ? kFamily : kScalingFamily;
}

struct MethodSpec {
  std::string name;  ///< make_estimator name
  int degree;
  int threads;
  bool scaling = false;             ///< levels 5-6 of the scaling sweep (logged in g_scaling)
  Kernel kernel = Kernel::batched;  ///< LHF/LOP: the scalar rows are labelled "... scalar"
  /// Neighbourhoods from a table built once per mesh before timing (NeighbourhoodCache, as the
  /// experiment runner sweeps methods and degrees on one mesh); rows labelled "... cached".
  bool cached = false;
  /// LHF only: the whole estimator with this solver instead of the safeguarded QR (claim F7's
  /// whole-estimator comparison); rows labelled "LHF-2 whole-estimator SVD (Jacobi)".
  std::optional<LsqSolver> solver = std::nullopt;
};

// The row label: the estimator's, plus " scalar" for the scalar fitting kernel and " cached"
// for neighbourhoods from a prebuilt table.
std::string row_label(const Estimator& est, bool cached,
                      std::optional<LsqSolver> solver = std::nullopt) {
  if (solver) return est.label() + " whole-estimator SVD (Jacobi)";
  return est.label() + (est.options().kernel == Kernel::scalar ? " scalar" : "") +
         (cached ? " cached" : "");
}

// The estimator of a row, with its solver replaced where the row asks for one.
std::unique_ptr<Estimator> make_row_estimator(const MethodSpec& spec, const EstimatorOptions& o) {
  std::unique_ptr<Estimator> est = make_estimator(spec.name, o);
  if (spec.solver) dynamic_cast<RingFitEstimator&>(*est).set_solver(*spec.solver);
  return est;
}

// The label without spaces, for --benchmark_filter ("LHF-2 scalar" -> "LHF-2_scalar").
std::string benchmark_name(std::string label) {
  std::replace(label.begin(), label.end(), ' ', '_');
  return label;
}

// Every registered method at its bench degrees (MethodInfo::bench_degrees; 0: a degree-free
// operator), one thread, in registry order; then the extra rows: LHF-2 on 2 threads, the scalar
// kernel of LHF-2, LHF-4 and LOP-2, LHF-2 and LHF-4 with prebuilt neighbourhoods, and LHF-2 with
// the Jacobi SVD in place of the safeguarded QR.
std::vector<MethodSpec> methods_to_time() {
  std::vector<MethodSpec> out;
  for (const MethodInfo& m : method_table())
    for (int degree : m.bench_degrees) out.push_back({m.name, degree, 1});
  out.push_back({"lhf", 2, 2});
  for (const auto& [name, degree] : {std::pair{"lhf", 2}, {"lhf", 4}, {"lop", 2}})
    out.push_back({name, degree, 1, false, Kernel::scalar});
  for (int degree : {2, 4}) out.push_back({"lhf", degree, 1, false, Kernel::batched, true});
  out.push_back({"lhf", 2, 1, false, Kernel::batched, false, LsqSolver::jacobi_svd});
  return out;
}

std::array<std::optional<GeneratedMesh>, kScalingLevels + 1> g_meshes;
std::array<std::unique_ptr<NeighbourhoodCache>, kScalingLevels + 1> g_neighbourhoods;
SampleLog g_log;      // Table 5
SampleLog g_scaling;  // levels 5-6 of the scaling sweep

// The torus of a level, generated on first use (levels 5-6 only if a scaling benchmark runs).
const Mesh& torus(int level) {
  auto& slot = g_meshes[static_cast<size_t>(level)];
  if (!slot) slot = generate_mesh({family_of(level), level, 0, 1, false});
  return slot->mesh;
}

void BM_Estimate(benchmark::State& state, const MethodSpec spec) {
  const int level = static_cast<int>(state.range(0));
  const Mesh& mesh = torus(level);
  EstimatorOptions o;
  o.degree = spec.degree;
  o.threads = spec.threads;
  o.kernel = spec.kernel;
  const std::unique_ptr<Estimator> est = make_row_estimator(spec, o);
  Sample& s = (spec.scaling ? g_scaling : g_log)
                  .get({family_of(level),
                        level,
                        mesh.num_vertices(),
                        mesh.num_faces(),
                        row_label(*est, spec.cached, spec.solver),
                        spec.degree,
                        spec.threads,
                        {}});
  NeighbourhoodCache* cache = nullptr;
  if (spec.cached) {
    auto& slot = g_neighbourhoods[static_cast<size_t>(level)];
    if (!slot) slot = std::make_unique<NeighbourhoodCache>(mesh);
    cache = slot.get();
    estimate_mesh(mesh, *est, cache);  // builds the table outside the timed passes
  }
  for (auto _ : state) {
    const auto t0 = std::chrono::steady_clock::now();
    std::vector<VertexEstimate> res = estimate_mesh(mesh, *est, cache);
    benchmark::DoNotOptimize(res.data());
    benchmark::ClobberMemory();
    s.seconds.push_back(
        std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count());
  }
  const double tris = mesh.num_faces();
  state.counters["tris/s"] =
      benchmark::Counter(tris, benchmark::Counter::kIsIterationInvariantRate);
  state.counters["verts"] = mesh.num_vertices();
  state.counters["tris"] = tris;
  // Seconds per vertex, printed with an SI prefix (e.g. 850ns).
  state.counters["time/vertex"] =
      benchmark::Counter(mesh.num_vertices(), benchmark::Counter::kIsIterationInvariantRate |
                                                  benchmark::Counter::kInvert);
  state.SetComplexityN(mesh.num_faces());
}

void register_all() {
  for (const MethodSpec& m : methods_to_time()) {
    EstimatorOptions o;
    o.degree = m.degree;
    o.kernel = m.kernel;
    const std::string label = row_label(*make_row_estimator(m, o), m.cached, m.solver);
    // Samples in registration order, so the rows keep it when repetitions run interleaved.
    for (int level = 1; level <= kLevels; ++level)
      g_log.get({kFamily,
                 level,
                 torus(level).num_vertices(),
                 torus(level).num_faces(),
                 label,
                 m.degree,
                 m.threads,
                 {}});
    level_sweep(
        benchmark::RegisterBenchmark(
            ("Estimate/" + benchmark_name(label) + "/threads:" + std::to_string(m.threads)).c_str(),
            BM_Estimate, m),
        kLevels);
  }
  for (int threads : {1, 2}) {
    const MethodSpec m{"lhf", 2, threads, true};
    benchmark::RegisterBenchmark(("Scaling/LHF-2/threads:" + std::to_string(threads)).c_str(),
                                 BM_Estimate, m)
        ->DenseRange(kLevels + 1, kScalingLevels)
        ->ArgName("level")
        ->UseRealTime()
        ->MinTime(0.1)
        ->Repetitions(9)
        ->Unit(benchmark::kMillisecond);
  }
}

// ---- results/table5_timing.csv ---------------------------------------------------------------

// The machine, compiler and build of the run, for table5_timing.csv's comment line
// "# machine: ..." (the report's Table 5 quotes it: harness/report/table5.h).
std::string machine_comment(const std::string& build_info) {
  std::string cpu = "unknown";
  std::ifstream in("/proc/cpuinfo");
  for (std::string line; std::getline(in, line);)
    if (line.rfind("model name", 0) == 0) {
      const size_t c = line.find(':');
      cpu = c == std::string::npos ? line : line.substr(c + 2);
      break;
    }
  return "# machine: " + cpu + ", nproc " + std::to_string(std::thread::hardware_concurrency()) +
         ". Compiler: GCC " + __VERSION__ +
         ". Build: " + (build_info.empty() ? std::string("unknown") : build_info);
}

}  // namespace
}  // namespace curvbench::bench

int main(int argc, char** argv) {
  using namespace curvbench;
  using namespace curvbench::bench;
  keep_freed_memory();
  const std::string dir = take_flag(argc, argv, "table5_dir");
  const std::string extra = take_flag(argc, argv, "table5_extra");
  const std::string build_info = take_flag(argc, argv, "build_info");
  benchmark::Initialize(&argc, argv);
  if (benchmark::ReportUnrecognizedArguments(argc, argv)) return 1;
  for (int level = 1; level <= kLevels; ++level) torus(level);  // before any timing
  register_all();
  benchmark::RunSpecifiedBenchmarks();
  benchmark::Shutdown();
  if (!dir.empty()) {
    try {
      std::vector<Table5Row> rows = rows_from_samples(g_log);
      if (!extra.empty()) {
        const std::vector<Table5Row> more = read_rows(extra);
        rows.insert(rows.end(), more.begin(), more.end());
      }
      // CSV only: the report renders Table 5 from these (harness/report/table5.h).
      write_file_atomic(dir + "/table5_timing.csv", format_rows(rows, machine_comment(build_info)));
      write_file_atomic(dir + "/table5_scaling.csv", format_rows(rows_from_samples(g_scaling)));
      std::fprintf(stderr,
                   "bench_estimators: wrote %s/table5_timing.csv (%zu rows) and "
                   "table5_scaling.csv\n",
                   dir.c_str(), rows.size());
    } catch (const std::exception& e) {
      std::fprintf(stderr, "bench_estimators: %s\n", e.what());
      return 1;
    }
  }
  return 0;
}
