// Google Benchmark suite for the solver comparison of paper §4.3 (F7: "QR with safeguard is
// roughly a factor of five faster than SVD") and for neighbourhood gathering alone.
//
//   Fit/<solver>/level:L    fit_polynomial() over the stored LHF-2 systems of every vertex of
//                           the well-shaped torus, level L (Vandermonde fill, row weights,
//                           column scaling, solve, Taylor coefficients; only the solver differs)
//   Solve/<solver>/level:3  the solve alone on stored weighted Vandermonde systems A (m x 6) and
//                           heights B (m x 1): copy into the scratch, then the safeguarded QR,
//                           or 2-norm column scaling + truncated SVD (JacobiSVD / BDCSVD) or
//                           Eigen's general dynamic-size HouseholderQR (no safeguard; "generic
//                           QR": a library QR, as the paper's would have been, for claim F7)
//   Rings/level:L           RingCollector::collect_at_least over all vertices with LHF-2's
//                           parameters (1.5-ring, >= 9 neighbours, up to a 3-ring)
// The LHF-2 systems are those of the driver's first fit attempt, taken from the estimator itself
// (RingFitEstimator::first_system): local frame of the area-weighted normal, centre row plus
// neighbours with gamma = max(0, m_i . m0) > 0, heights (p_i - p0) . m0, eq. (15) weights. They
// are built once, outside the timing.
// SVD settings are RingFitEstimator::set_solver's defaults (absolute threshold 1e-8, 2-norm
// column scaling).
//
// Extra flag: --table5_rows=FILE writes the Fit rows ("LHF-2 QR", "LHF-2 SVD (Jacobi)",
// "LHF-2 SVD (BDC)", "LHF-2 generic QR (Eigen)") in the table5_timing.csv format; bench_estimators
// merges them.
#include <benchmark/benchmark.h>

#include <array>
#include <chrono>
#include <cstdio>
#include <optional>
#include <string>
#include <vector>

#include "bench/table5.h"
#include "mesh/rings.h"
#include "meshgen/generate.h"
#include "methods/estimator.h"
#include "methods/fits/least_squares.h"
#include "methods/fits/polynomial_fit.h"
#include "methods/fits/ring_fit_estimator.h"
#include "methods/fits/safeguarded_qr.h"
#include "methods/fits/weights.h"
#include "methods/local_frame.h"

namespace curvbench::bench {
namespace {

constexpr int kLevels = 4;
constexpr int kDegree = 2;
constexpr int kSolveLevel = 3;
const char* const kFamily = "torus-unstructured";

/// The weighted LHF-2 systems of all vertices, rows stored contiguously.
struct Systems {
  long verts = 0;
  long tris = 0;
  std::vector<int> begin;  ///< rows of system i: [begin[i], begin[i+1])
  std::vector<double> u, v, f, w;
};

Systems build_systems(const Mesh& mesh) {
  Systems s;
  s.verts = mesh.num_vertices();
  s.tris = mesh.num_faces();
  // Exactly the systems LHF-2 fits first at every vertex, assembled by the estimator itself.
  EstimatorOptions o;
  o.degree = kDegree;
  const auto est = make_estimator("lhf", o);
  const auto& lhf = dynamic_cast<const RingFitEstimator&>(*est);
  const VertexMatrix normals = mesh.area_weighted_normals();
  const MeshContext ctx{mesh, normals};
  const auto ws = lhf.make_workspace(mesh);
  RingFitEstimator::FitSystem sys;
  for (int c = 0; c < mesh.num_vertices(); ++c) {
    s.begin.push_back(static_cast<int>(s.u.size()));
    if (!lhf.first_system(ctx, c, *ws, sys)) continue;
    const auto m = static_cast<size_t>(sys.u.size());
    s.u.insert(s.u.end(), sys.u.data(), sys.u.data() + m);
    s.v.insert(s.v.end(), sys.v.data(), sys.v.data() + m);
    s.f.insert(s.f.end(), sys.f.data(), sys.f.data() + m);  // one right-hand side (heights)
    s.w.insert(s.w.end(), sys.w.data(), sys.w.data() + m);
  }
  s.begin.push_back(static_cast<int>(s.u.size()));
  return s;
}

std::array<std::optional<GeneratedMesh>, kLevels + 1> g_meshes;
std::array<Systems, kLevels + 1> g_systems;
SampleLog g_log;

struct SolverSpec {
  const char* name;   ///< benchmark name part
  const char* label;  ///< table5 method label
  LsqSolver solver;
};
const std::vector<SolverSpec> kSolvers = {
    {"QR", "LHF-2 QR", LsqSolver::safeguarded_qr},
    {"JacobiSVD", "LHF-2 SVD (Jacobi)", LsqSolver::jacobi_svd},
    {"BDCSVD", "LHF-2 SVD (BDC)", LsqSolver::bdc_svd},
    {"GenericQR", "LHF-2 generic QR (Eigen)", LsqSolver::generic_qr}};

void BM_Fit(benchmark::State& state, const SolverSpec spec) {
  const int level = static_cast<int>(state.range(0));
  const Systems& s = g_systems[static_cast<size_t>(level)];
  FitSettings settings;
  settings.degree = kDegree;
  settings.solver = spec.solver;  // threshold 1e-8 absolute, 2-norm scaling: set_solver defaults
  FitScratch scratch;
  RowVector u, v, w;
  RhsMatrix f;
  Sample& sample = g_log.get({kFamily, level, s.verts, s.tris, spec.label, kDegree, 1, {}});
  for (auto _ : state) {
    const auto t0 = std::chrono::steady_clock::now();
    double sum = 0.0;
    for (size_t i = 0; i + 1 < s.begin.size(); ++i) {
      const int b = s.begin[i];
      const int m = s.begin[i + 1] - b;
      u = Eigen::Map<const Eigen::VectorXd>(s.u.data() + b, m);
      v = Eigen::Map<const Eigen::VectorXd>(s.v.data() + b, m);
      w = Eigen::Map<const Eigen::VectorXd>(s.w.data() + b, m);
      f = Eigen::Map<const Eigen::VectorXd>(s.f.data() + b, m);
      const FitResult r = fit_polynomial(u, v, f, w, settings, scratch);
      sum += r.taylor(kFuu, 0);
    }
    benchmark::DoNotOptimize(sum);
    sample.seconds.push_back(
        std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count());
  }
  state.counters["tris/s"] = benchmark::Counter(static_cast<double>(s.tris),
                                                benchmark::Counter::kIsIterationInvariantRate);
  state.counters["systems"] = static_cast<double>(s.verts);
  state.SetComplexityN(s.tris);
}

// Weighted Vandermonde systems of one level, stored for the solve-only benchmark.
struct WeightedSystems {
  std::vector<int> begin;
  std::vector<double> A;  ///< m x 6 column-major per system, at 6 * begin[i]
  std::vector<double> B;  ///< m per system, at begin[i]
};

WeightedSystems g_weighted;

void build_weighted(const Systems& s) {
  const int n = num_columns(kDegree, true);
  FitMatrix V;
  RowVector u, v;
  g_weighted.begin = s.begin;
  g_weighted.A.resize(s.u.size() * static_cast<size_t>(n));
  g_weighted.B.resize(s.u.size());
  for (size_t i = 0; i + 1 < s.begin.size(); ++i) {
    const int b = s.begin[i];
    const int m = s.begin[i + 1] - b;
    u = Eigen::Map<const Eigen::VectorXd>(s.u.data() + b, m);
    v = Eigen::Map<const Eigen::VectorXd>(s.v.data() + b, m);
    fill_vandermonde(u, v, kDegree, true, V);
    for (int r = 0; r < m; ++r) {
      V.row(r) *= s.w[static_cast<size_t>(b + r)];
      g_weighted.B[static_cast<size_t>(b + r)] =
          s.f[static_cast<size_t>(b + r)] * s.w[static_cast<size_t>(b + r)];
    }
    Eigen::Map<Eigen::MatrixXd>(g_weighted.A.data() + static_cast<size_t>(n) * b, m, n) = V;
  }
}

void BM_Solve(benchmark::State& state, const SolverSpec spec) {
  const int n = num_columns(kDegree, true);
  const WeightedSystems& s = g_weighted;
  FitMatrix A;
  RhsMatrix B;
  CoeffMatrix X;
  ColVector scale;
  LeastSquaresScratch lsq;
  for (auto _ : state) {
    double sum = 0.0;
    for (size_t i = 0; i + 1 < s.begin.size(); ++i) {
      const int b = s.begin[i];
      const int m = s.begin[i + 1] - b;
      A = Eigen::Map<const Eigen::MatrixXd>(s.A.data() + static_cast<size_t>(n) * b, m, n);
      B = Eigen::Map<const Eigen::VectorXd>(s.B.data() + b, m);
      if (spec.solver == LsqSolver::safeguarded_qr) {
        safeguarded_qr_solve(A, B, kDegree, true, 1e-3, X, scale);
      } else if (spec.solver == LsqSolver::generic_qr) {
        scale_columns(A, n, ColumnScaling::two_norm, scale);
        generic_qr_solve(A, B, X, lsq);
      } else {
        scale_columns(A, n, ColumnScaling::two_norm, scale);
        truncated_svd_solve(
            A, B, spec.solver == LsqSolver::jacobi_svd ? SvdAlgorithm::jacobi : SvdAlgorithm::bdc,
            1e-8, false, X, lsq);
      }
      sum += X.sum();
    }
    benchmark::DoNotOptimize(sum);
  }
  state.counters["systems/s"] = benchmark::Counter(static_cast<double>(s.begin.size() - 1),
                                                   benchmark::Counter::kIsIterationInvariantRate);
}

void BM_Rings(benchmark::State& state) {
  const int level = static_cast<int>(state.range(0));
  const Mesh& mesh = g_meshes[static_cast<size_t>(level)]->mesh;
  RingCollector rings(mesh);
  const double r0 = default_ring(kDegree);
  for (auto _ : state) {
    size_t total = 0;
    for (int c = 0; c < mesh.num_vertices(); ++c) {
      rings.collect_at_least(c, r0, min_neighbours(kDegree), 2.0 * r0);
      total += rings.neighbours().size();
    }
    benchmark::DoNotOptimize(total);
  }
  state.counters["tris/s"] = benchmark::Counter(static_cast<double>(mesh.num_faces()),
                                                benchmark::Counter::kIsIterationInvariantRate);
  state.SetComplexityN(mesh.num_faces());
}

void register_all() {
  // Samples in registration order, so the rows keep it when repetitions run interleaved.
  for (const SolverSpec& sp : kSolvers)
    for (int level = 1; level <= kLevels; ++level) {
      const Systems& s = g_systems[static_cast<size_t>(level)];
      g_log.get({kFamily, level, s.verts, s.tris, sp.label, kDegree, 1, {}});
    }
  for (const SolverSpec& sp : kSolvers)
    level_sweep(benchmark::RegisterBenchmark((std::string("Fit/") + sp.name).c_str(), BM_Fit, sp),
                kLevels);
  for (const SolverSpec& sp : kSolvers)
    benchmark::RegisterBenchmark((std::string("Solve/") + sp.name).c_str(), BM_Solve, sp)
        ->Arg(kSolveLevel)
        ->ArgName("level")
        ->UseRealTime()
        ->MinTime(0.2)
        ->Unit(benchmark::kMillisecond);
  benchmark::RegisterBenchmark("Rings/LHF-2", BM_Rings)
      ->DenseRange(1, kLevels)
      ->ArgName("level")
      ->UseRealTime()
      ->MinTime(0.1)
      ->Unit(benchmark::kMillisecond)
      ->Complexity(benchmark::oN);
}

}  // namespace
}  // namespace curvbench::bench

int main(int argc, char** argv) {
  using namespace curvbench;
  using namespace curvbench::bench;
  keep_freed_memory();
  const std::string rows_file = take_flag(argc, argv, "table5_rows");
  benchmark::Initialize(&argc, argv);
  if (benchmark::ReportUnrecognizedArguments(argc, argv)) return 1;
  for (int level = 1; level <= kLevels; ++level) {
    g_meshes[static_cast<size_t>(level)] = generate_mesh({kFamily, level, 0, 1, false});
    g_systems[static_cast<size_t>(level)] =
        build_systems(g_meshes[static_cast<size_t>(level)]->mesh);
  }
  build_weighted(g_systems[kSolveLevel]);
  register_all();
  benchmark::RunSpecifiedBenchmarks();
  benchmark::Shutdown();
  if (!rows_file.empty()) {
    try {
      write_file_atomic(rows_file, format_rows(rows_from_samples(g_log)));
    } catch (const std::exception& e) {
      std::fprintf(stderr, "bench_solvers: %s\n", e.what());
      return 1;
    }
  }
  return 0;
}
