// `make bench`'s limits table (results/limits.csv, docs/performance.md "Limits"): each stage of
// `curvbench estimate` on one mesh (tools/bench.sh passes the 1.44-million-vertex torus), its
// measured time and the bound this machine's hardware sets on it, each measured here, in this
// process, the minimum over --repeat runs (a shared machine only ever adds time):
//
//   read         read_mesh (file -> Mesh with its adjacency)  vs  a plain copy of the file's
//                bytes (read(2) through a 1 MiB buffer, the page cache warm as for the reader)
//   orientation  orient_mesh on a consistent mesh  vs  one streaming pass over the bytes it must
//                read at least: the faces, their neighbours across edges, the vertices
//   fit          the estimation pass (normals, neighbourhoods, fits; --threads)  vs  the largest
//                of: its floating-point work at the measured peak vector rate, the bytes it
//                gathers per vertex at the measured L2 rate, and the mesh's bytes at the
//                measured memory rate
//   write-csv    the CSV of every vertex (EstimateCsvWriter)  vs  a plain write(2) of as many bytes
//   write-npy    the same estimates as .npy  vs  a plain write(2) of as many bytes
//
// CSV columns: stage,measured_seconds,bound_seconds,bound_kind,ratio,notes (ratio = measured /
// bound). Written atomically (core/atomic_file.h). Usage:
//   bench_limits --mesh M.ply --output results/limits.csv [--method lhf-2] [--threads 1]
//                [--repeat 3] [--scratch DIR]
#include <fcntl.h>
#include <unistd.h>

#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <functional>
#include <memory>
#include <numeric>
#include <string>
#include <vector>

#include "bench/timing.h"
#include "core/atomic_file.h"
#include "core/text.h"
#include "harness/model/estimate_columns.h"
#include "harness/model/estimate_npy.h"
#include "harness/model/shortest_double.h"
#include "mesh/io.h"
#include "mesh/orientation.h"
#include "mesh/read_soup.h"
#include "methods/estimate_oriented.h"
#include "methods/estimator.h"

namespace {

using namespace curvbench;
namespace fs = std::filesystem;
using bench::best_of;
using bench::seconds_of;

volatile double g_sink = 0;  // keeps the measured loops

/// Seconds to read the whole file through a 1 MiB buffer (read(2)).
double copy_file_seconds(const std::string& path) {
  std::vector<char> buffer(1 << 20);
  return seconds_of([&] {
    const int fd = ::open(path.c_str(), O_RDONLY | O_CLOEXEC);
    if (fd < 0) throw std::runtime_error("cannot open " + path);
    ssize_t got;
    std::size_t total = 0;
    while ((got = ::read(fd, buffer.data(), buffer.size())) > 0) total += static_cast<size_t>(got);
    ::close(fd);
    g_sink = g_sink + static_cast<double>(total) + buffer[0];
  });
}

/// Seconds to write `bytes` bytes (1 MiB writes of a touched buffer) to a new file in `dir` and
/// close it; the file is removed afterwards. Like the writers' runs (whose previous output is
/// removed before each), it takes page-cache pages the kernel has just freed: a fresh page of
/// this virtual machine costs a hypervisor fault on first touch (docs/performance.md).
double plain_write_seconds(const fs::path& dir, std::size_t bytes) {
  std::vector<char> buffer(1 << 20, 'x');
  const std::string path = (dir / "bench_limits_plain.tmp").string();
  const double s = seconds_of([&] {
    const int fd = ::open(path.c_str(), O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC, 0644);
    if (fd < 0) throw std::runtime_error("cannot write " + path);
    for (std::size_t left = bytes; left > 0;) {
      const ssize_t w = ::write(fd, buffer.data(), std::min(left, buffer.size()));
      if (w <= 0) throw std::runtime_error("cannot write " + path);
      left -= static_cast<std::size_t>(w);
    }
    ::close(fd);
  });
  fs::remove(path);
  return s;
}

/// Bytes per second of a streaming read (a sum) over `bytes` bytes, best of `repeat` passes
/// after one that faults the buffer in.
double read_bandwidth(std::size_t bytes, int repeat) {
  std::vector<double> x(bytes / sizeof(double), 1.0);
  const int passes = static_cast<int>(std::max<std::size_t>(1, (std::size_t{1} << 30) / bytes));
  const double s = best_of(repeat, [&] {
    double a0 = 0, a1 = 0, a2 = 0, a3 = 0;
    for (int p = 0; p < passes; ++p)
      for (std::size_t i = 0; i + 4 <= x.size(); i += 4) {
        a0 += x[i];
        a1 += x[i + 1];
        a2 += x[i + 2];
        a3 += x[i + 3];
      }
    g_sink = g_sink + a0 + a1 + a2 + a3;
  });
  return static_cast<double>(bytes) * passes / s;
}

// Peak floating-point rate: independent multiply-adds on the widest vectors the CPU has (the
// estimators' batched kernels dispatch at run time to the same width), 12 accumulators.
typedef double V8d __attribute__((vector_size(64)));
typedef double V4d __attribute__((vector_size(32)));
typedef double V2d __attribute__((vector_size(16)));

// One body per width, each compiled for its instruction set (a template would not be inlined
// across the target attribute). 12 independent multiply-adds per iteration, contracted to fused
// multiply-adds where the CPU has them.
#define CURVBENCH_FMA_LOOP(NAME, V, TARGET)                                           \
  TARGET __attribute__((optimize("fp-contract=fast"))) double NAME(long iterations) { \
    constexpr int kLanes = sizeof(V) / sizeof(double);                                \
    V acc[12], m, c;                                                                  \
    for (int l = 0; l < kLanes; ++l) {                                                \
      m[l] = 0.999999999;                                                             \
      c[l] = 1e-9;                                                                    \
      for (int j = 0; j < 12; ++j) acc[j][l] = 1.0 + 1e-9 * (j + l);                  \
    }                                                                                 \
    for (long i = 0; i < iterations; ++i)                                             \
      for (int j = 0; j < 12; ++j) acc[j] = acc[j] * m + c;                           \
    double s = 0;                                                                     \
    for (int j = 0; j < 12; ++j)                                                      \
      for (int l = 0; l < kLanes; ++l) s += acc[j][l];                                \
    return s;                                                                         \
  }

CURVBENCH_FMA_LOOP(fma_loop_avx512, V8d, __attribute__((target("avx512f"))))
CURVBENCH_FMA_LOOP(fma_loop_avx2, V4d, __attribute__((target("avx2,fma"))))
CURVBENCH_FMA_LOOP(fma_loop_sse2, V2d, )

/// Peak double-precision flops per second (one core) and the vector width used.
std::pair<double, int> peak_flops(int repeat) {
  const long iterations = 20'000'000;
  int lanes = 2;
  std::function<double(long)> loop = fma_loop_sse2;
  __builtin_cpu_init();
  if (__builtin_cpu_supports("avx512f")) {
    lanes = 8;
    loop = fma_loop_avx512;
  } else if (__builtin_cpu_supports("avx2") && __builtin_cpu_supports("fma")) {
    lanes = 4;
    loop = fma_loop_avx2;
  }
  const double s = best_of(repeat, [&] { g_sink = g_sink + loop(iterations); });
  return {2.0 * lanes * 12 * static_cast<double>(iterations) / s, lanes};
}

struct Row {
  std::string stage;
  double measured, bound;
  std::string kind, notes;
};

std::string csv_field(const std::string& s) {
  if (s.find_first_of(",\"\n") == std::string::npos) return s;
  std::string q = "\"";
  for (char c : s) q += c == '"' ? std::string("\"\"") : std::string(1, c);
  return q + "\"";
}

std::string fmt(double x, const char* spec = "%.4g") {
  char b[64];
  std::snprintf(b, sizeof b, spec, x);
  return b;
}

int run(int argc, char** argv) {
  std::string mesh_path, output, method = "lhf-2", scratch;
  int threads = 1, repeat = 3;
  for (int i = 1; i < argc; ++i) {
    const std::string a = argv[i];
    const auto value = [&]() -> std::string {
      if (i + 1 >= argc) throw std::runtime_error(a + " needs a value");
      return argv[++i];
    };
    if (a == "--mesh")
      mesh_path = value();
    else if (a == "--output")
      output = value();
    else if (a == "--method")
      method = value();
    else if (a == "--threads")
      threads = std::stoi(value());
    else if (a == "--repeat")
      repeat = std::max(1, std::stoi(value()));
    else if (a == "--scratch")
      scratch = value();
    else
      throw std::runtime_error("unknown argument " + a);
  }
  if (mesh_path.empty() || output.empty())
    throw std::runtime_error(
        "usage: bench_limits --mesh M.ply --output limits.csv [--method M] "
        "[--threads T] [--repeat R] [--scratch DIR]");
  const fs::path dir = scratch.empty() ? fs::path(output).parent_path() : fs::path(scratch);
  std::vector<Row> rows;

  // ---- read -------------------------------------------------------------------------------
  const std::size_t file_bytes = fs::file_size(mesh_path);
  copy_file_seconds(mesh_path);  // the page cache warm for both
  Mesh mesh;
  const double read_s = best_of(
      repeat, [&] { mesh = read_mesh(mesh_path); }, [&] { mesh = Mesh(); });
  const double copy_s = best_of(repeat, [&] { copy_file_seconds(mesh_path); });
  VertexMatrix V;
  FaceMatrix F;
  Mesh rebuilt;
  const double adjacency_s = best_of(
      repeat, [&] { rebuilt = Mesh(std::move(V), std::move(F)); },
      [&] {
        rebuilt = Mesh();
        V = mesh.vertices();
        F = mesh.faces();
      });
  rebuilt = Mesh();
  // The parse alone: the binary PLY reader into its soup (the arrays the Mesh then takes over).
  io_detail::Soup soup;
  const double parse_s = best_of(
      repeat,
      [&] {
        const int fd = ::open(mesh_path.c_str(), O_RDONLY | O_CLOEXEC);
        const bool binary =
            fd >= 0 && io_detail::read_binary_ply_file(mesh_path, fd, file_bytes, false, &soup);
        if (fd >= 0) ::close(fd);
        if (!binary) soup = io_detail::Soup();
      },
      [&] { soup = io_detail::Soup(); });
  soup = io_detail::Soup();
  const int n = mesh.num_vertices(), m = mesh.num_faces();
  const double mem_bw = read_bandwidth(std::size_t{512} << 20, repeat);
  rows.push_back({"read", read_s, copy_s, "plain copy of the file's bytes (read(2), 1 MiB buffer)",
                  std::to_string(file_bytes) + " bytes, " + std::to_string(n) +
                      " vertices: file to Mesh, the parse and the adjacency below"});
  rows.push_back({"read-parse", parse_s, copy_s,
                  "plain copy of the file's bytes (read(2), 1 MiB buffer)",
                  "binary PLY into the vertex and face arrays (no soup copy)"});
  // The adjacency at least reads the faces and writes vertex-face lists, face neighbours and
  // offsets once: 12 + 12 + 12 bytes per face and 4 per vertex.
  const double adjacency_bytes = 36.0 * m + 4.0 * n;
  rows.push_back(
      {"read-adjacency", adjacency_s, adjacency_bytes / mem_bw,
       "faces read and adjacency written once at memory bandwidth",
       fmt(adjacency_bytes / 1e6, "%.0f") + " MB at " + fmt(mem_bw / 1e9, "%.1f") +
           " GB/s; Mesh(V, F): vertex-face lists, face neighbours, checks, edge lengths"});

  // ---- bandwidths and peak -----------------------------------------------------------------
  const double l2_bw = read_bandwidth(std::size_t{256} << 10, repeat);
  const auto [flops, lanes] = peak_flops(repeat);

  // ---- orientation ---------------------------------------------------------------------------
  Mesh copy;
  double orient_s = best_of(
      repeat, [&] { const OrientationResult r = orient_mesh(std::move(copy)); },
      [&] { copy = mesh; });
  // At least: the faces (12 bytes), their neighbours across the 3 edges (12 bytes) and, for the
  // signed volume of a closed patch, the 3 corner positions (cached: the vertices once, 24 bytes).
  const double orient_bytes = 24.0 * m + 24.0 * n;
  rows.push_back({"orientation", orient_s, orient_bytes / mem_bw,
                  "one streaming pass over faces, face neighbours and vertices at memory bandwidth",
                  fmt(orient_bytes / 1e6, "%.0f") + " MB at " + fmt(mem_bw / 1e9, "%.1f") +
                      " GB/s; " + std::to_string(m) + " faces, mesh " +
                      (mesh.is_consistently_oriented() ? "consistent" : "inconsistent")});

  // ---- fit -----------------------------------------------------------------------------------
  EstimatorOptions options;
  options.threads = threads;
  const std::unique_ptr<Estimator> est = make_estimator(method, options);
  std::vector<VertexEstimate> estimates(static_cast<std::size_t>(n));
  const double fit_s = best_of(repeat, [&] {
    MeshEstimation run(mesh, *est);
    run.run(0, estimates);
  });
  // The work model of a degree-d height fit with m points and k = (d+1)(d+2)/2 - 1 unknowns
  // (docs/performance.md "Limits"): Householder QR 2mk^2 - 2k^3/3, the right-hand side 4mk, each
  // point's frame coordinates, weight and monomials about 40, and about 300 for the vertex
  // normal, the frame and the curvatures.
  double points = 0;
  for (const VertexEstimate& e : estimates) points += e.points;
  const double mpts = points / std::max(n, 1);
  const int degree = std::max(1, est->options().degree);
  const double k = (degree + 1) * (degree + 2) / 2.0 - 1;
  const double flop_per_vertex =
      2 * mpts * k * k - 2 * k * k * k / 3 + 4 * mpts * k + 40 * mpts + 300;
  const double used_threads = threads < 1 ? 1 : threads;
  const double flop_bound = flop_per_vertex * n / (flops * used_threads);
  // Gathered per vertex: each stencil point's position (24 bytes) and index (4), and the rings'
  // faces and adjacency (about 6 faces per point, 12 + 12 bytes each), from cache at best.
  const double gathered = mpts * (24 + 4 + 6 * 24);
  const double gather_bound = gathered * n / (l2_bw * used_threads);
  // The mesh itself from memory at least once: vertices, faces, face neighbours, vertex faces.
  const double mesh_bytes = 24.0 * n + 12.0 * m + 12.0 * m + 4.0 * (n + 1) + 12.0 * m;
  const double memory_bound = mesh_bytes / mem_bw;
  const double fit_bound = std::max({flop_bound, gather_bound, memory_bound});
  const char* fit_kind = fit_bound == flop_bound     ? "floating-point work at peak vector rate"
                         : fit_bound == gather_bound ? "bytes gathered at L2 bandwidth"
                                                     : "mesh bytes at memory bandwidth";
  rows.push_back({"fit", fit_s, fit_bound, fit_kind,
                  method + ", " + std::to_string(threads) + " thread(s), " + fmt(mpts, "%.1f") +
                      " points/vertex; work " + fmt(flop_per_vertex, "%.0f") + " flop/vertex at " +
                      fmt(flops / 1e9, "%.1f") + " Gflop/s (" + std::to_string(lanes) +
                      " lanes) = " + fmt(flop_bound, "%.3f") + " s; gathered " +
                      fmt(gathered, "%.0f") + " B/vertex at " + fmt(l2_bw / 1e9, "%.1f") +
                      " GB/s (L2) = " + fmt(gather_bound, "%.3f") + " s; mesh " +
                      fmt(mesh_bytes / 1e6, "%.0f") + " MB at " + fmt(mem_bw / 1e9, "%.1f") +
                      " GB/s = " + fmt(memory_bound, "%.3f") + " s"});

  // ---- write ---------------------------------------------------------------------------------
  const std::string csv = (dir / "bench_limits.csv.tmp").string();
  const double csv_s = best_of(
      repeat,
      [&] {
        EstimateCsvWriter w(csv, {}, threads);
        for (int first = 0; first < n; first += kEstimateBlock)
          w.write(first, std::span(estimates).subspan(
                             static_cast<std::size_t>(first),
                             static_cast<std::size_t>(std::min(kEstimateBlock, n - first))));
        w.commit();
      },
      [&] { fs::remove(csv); });
  const std::size_t csv_bytes = fs::file_size(csv);
  fs::remove(csv);
  // The formatting alone, into memory (the writer's pieces, no file).
  std::string text;
  const double format_s = best_of(
      repeat,
      [&] {
        for (int first = 0; first < n; first += 8192) {
          text.clear();
          append_estimate_csv_rows(
              text, first,
              std::span(estimates).subspan(static_cast<std::size_t>(first),
                                           static_cast<std::size_t>(std::min(8192, n - first))),
              {}, threads);
        }
      },
      [&] { text.reserve(8192 * 600); });
  // The doubles alone, through harness/model/shortest_double.h and through libstdc++'s
  // std::to_chars (the CSV's formatter before it, the same bytes), for the ratio in the notes.
  std::vector<char> chars(std::size_t{8192} * 13 * 64);
  const auto doubles_seconds = [&](auto&& put) {
    return best_of(repeat, [&] {
      const std::span<const EstimateColumn> table = estimate_columns();
      for (int first = 0; first < n; first += 8192) {
        char* p = chars.data();
        for (int v = first; v < std::min(n, first + 8192); ++v)
          for (const EstimateColumn& c : table)
            if (c.in_csv && !c.integer) {
              p = put(p, c.value(estimates[static_cast<std::size_t>(v)]));
              *p++ = ',';
            }
        g_sink = g_sink + static_cast<double>(p - chars.data());
      }
    });
  };
  const double to_chars_s =
      doubles_seconds([](char* p, double x) { return std::to_chars(p, p + 32, x).ptr; });
  const double shortest_s = doubles_seconds([](char* p, double x) {
    return std::isnan(x) ? std::copy_n("nan", 3, p) : write_shortest(p, x);
  });
  const double csv_plain = best_of(repeat, [&] { plain_write_seconds(dir, csv_bytes); });
  rows.push_back({"write-csv", csv_s, csv_plain, "plain write(2) of as many bytes (page cache)",
                  std::to_string(csv_bytes) + " bytes, every column, shortest round-trip text, " +
                      std::to_string(threads) + " formatting thread(s); formatting alone " +
                      fmt(format_s, "%.3f") + " s; its " + std::to_string(13 * n) +
                      " doubles alone " + fmt(shortest_s, "%.3f") +
                      " s, through libstdc++'s std::to_chars (the formatter before) " +
                      fmt(to_chars_s, "%.3f") + " s"});
  const std::string npy = (dir / "bench_limits.npy.tmp").string();
  const double npy_s = best_of(
      repeat,
      [&] {
        EstimateNpyWriter w(npy, n, {});
        for (int first = 0; first < n; first += kEstimateBlock)
          w.write(first, std::span(estimates).subspan(
                             static_cast<std::size_t>(first),
                             static_cast<std::size_t>(std::min(kEstimateBlock, n - first))));
        w.commit();
      },
      [&] { fs::remove(npy); });
  const std::size_t npy_bytes = fs::file_size(npy);
  fs::remove(npy);
  const double npy_plain = best_of(repeat, [&] { plain_write_seconds(dir, npy_bytes); });
  rows.push_back({"write-npy", npy_s, npy_plain, "plain write(2) of as many bytes (page cache)",
                  std::to_string(npy_bytes) + " bytes, every column, binary records"});

  std::string out = "stage,measured_seconds,bound_seconds,bound_kind,ratio,notes\n";
  for (const Row& r : rows) {
    out += r.stage + "," + fmt(r.measured, "%.4f") + "," + fmt(r.bound, "%.4f") + "," +
           csv_field(r.kind) + "," + fmt(r.measured / r.bound, "%.2f") + "," + csv_field(r.notes) +
           "\n";
    std::printf("%-12s measured %8.4f s  bound %8.4f s  x%.2f  (%s)\n", r.stage.c_str(), r.measured,
                r.bound, r.measured / r.bound, r.kind.c_str());
  }
  write_file_atomic(output, out);
  std::printf("bench_limits: wrote %s\n", output.c_str());
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  curvbench::bench::keep_freed_memory();  // bench/timing.h
  try {
    return run(argc, argv);
  } catch (const std::exception& e) {
    std::fprintf(stderr, "bench_limits: %s\n", e.what());
    return 1;
  }
}
