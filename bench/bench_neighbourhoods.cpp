// `make bench`'s neighbourhood table (results/neighbourhoods.csv, docs/performance.md
// "Neighbourhoods of point sets"), two parts, each time the minimum over --repeat runs (a shared
// machine only ever adds time):
//
//   search  the neighbour search of points/point_search.h over --points area-uniform samples of
//           the torus R = 1, r = 0.4 (meshgen/point_samples.h, seed 1): nanoflann's k-d tree's
//           build (one thread), then for k = 12, 20, 30 (the default K of degrees 2, 3, 4,
//           docs/point_sets.md)
//             knn-query  PointSearch::knn (the tree) at every point's position, in the tree's leaf
//                        order, one thread: the bare query (its k hits include the point
//                        itself), sorted by distance
//             knn-of-tree PointSearch::knn_of (the tree) of every point in leaf order, one
//                        thread: the rows as the tree alone gives them, without their layout
//             knn-rows   knn_rows: every point's k nearest others in the table's layout (what a
//                        point neighbourhood costs; the grid of cells, built in the time, the
//                        tree for rows the grid cannot settle), on 1 and 2 threads
//             ball-rows  ball_rows with the radius whose disc holds k points on average
//                        (n pi r^2 / area = k), on 1 and 2 threads
//   lhf-2   LHF-2 on each mesh of --meshes (family:level), three ways, on 1 and 2 threads:
//             mesh-rings   the mesh with its rings (the default)
//             mesh-knn     the same mesh with neighbourhood=knn=12 (its faces ignored; the
//                          normals still the area-weighted ones)
//             points-knn   its vertices as a point set (a Mesh without faces): PCA normals
//                          oriented over the MST, and knn=12
//           stages: setup (MeshEstimation's constructor: normals, and for k-NN the search and the
//           table of rows), estimate (MeshEstimation::run: for the rings, gathering them and the
//           fits; for k-NN, the fits on the table's rows), total (the minimum of their sums),
//           from-arrays (the Mesh built from its vertex and face arrays, then setup and estimate:
//           the rings' adjacency counted as the k-NN search is); for
//           points-knn also the setup's parts: normals-rows (16-NN), normals-pca, normals-orient
//           (one thread whatever the count); the table's rows are the first 12 of those 16. The
//           row `table` is the NeighbourhoodTable of knn=12 built alone (its own search), as a
//           NeighbourhoodCache builds it.
//
// CSV columns: part,input,points,stage,neighbourhood,threads,seconds,ns_per_point,
// neighbours_per_point,ns_per_neighbour (the last two empty where they do not apply). Written
// atomically (core/atomic_file.h). Usage:
//   bench_neighbourhoods --output results/neighbourhoods.csv [--points 1000000] [--repeat 5]
//                        [--meshes torus-unstructured:4,torus-structured:6]

#include <cmath>
#include <cstdio>
#include <memory>
#include <numbers>
#include <string>
#include <vector>

#include "bench/timing.h"
#include "core/atomic_file.h"
#include "mesh/neighbourhood_table.h"
#include "meshgen/generate.h"
#include "meshgen/point_samples.h"
#include "methods/estimator.h"
#include "points/point_normals.h"
#include "points/point_search.h"

namespace {

using namespace curvbench;
using bench::best_of;

constexpr double kTorusR = 1.0, kTorusr = 0.4;
constexpr int kKs[] = {12, 20, 30};  // the default K of degrees 2, 3, 4
constexpr int kThreads[] = {1, 2};
constexpr int kLhfK = 12;  // LHF-2's default K on a point set

struct Row {
  std::string part, input;
  long long points = 0;
  std::string stage, neighbourhood;
  int threads = 1;
  double seconds = 0;
  double neighbours_per_point = 0;  ///< 0: not a neighbour search
};

std::string format_row(const Row& r) {
  char b[512];
  const double per_point = r.seconds / static_cast<double>(r.points) * 1e9;
  if (r.neighbours_per_point > 0)
    std::snprintf(b, sizeof b, "%s,%s,%lld,%s,%s,%d,%.4f,%.1f,%.2f,%.2f\n", r.part.c_str(),
                  r.input.c_str(), r.points, r.stage.c_str(), r.neighbourhood.c_str(), r.threads,
                  r.seconds, per_point, r.neighbours_per_point, per_point / r.neighbours_per_point);
  else
    std::snprintf(b, sizeof b, "%s,%s,%lld,%s,%s,%d,%.4f,%.1f,,\n", r.part.c_str(), r.input.c_str(),
                  r.points, r.stage.c_str(), r.neighbourhood.c_str(), r.threads, r.seconds,
                  per_point);
  return b;
}

void report(std::vector<Row>& rows, Row r) {
  std::fputs(format_row(r).c_str(), stdout);
  std::fflush(stdout);
  rows.push_back(std::move(r));
}

volatile double g_sink = 0;  // keeps the measured loops

// ---- search ----------------------------------------------------------------------------------

void search_part(int n, int repeat, std::vector<Row>& rows) {
  const VertexMatrix points = sample_torus_points(n, kTorusR, kTorusr, 1);
  const std::string input = "torus-points";
  std::unique_ptr<PointSearch> search;
  const double build_s = best_of(
      repeat,
      [&] {
        search = std::make_unique<PointSearch>(points);
        search->leaf_order();  // the tree is built on first use
      },
      [&] { search.reset(); });
  report(rows, {"search", input, n, "build", "", 1, build_s, 0});
  const double area = 4.0 * std::numbers::pi * std::numbers::pi * kTorusR * kTorusr;
  for (const int k : kKs) {
    const std::string knn = "knn=" + std::to_string(k);
    std::vector<PointHit> hits;
    const double query_s = best_of(repeat, [&] {
      std::size_t found = 0;
      for (const std::uint32_t i : search->leaf_order()) {
        search->knn(points.row(i).transpose(), k, hits);
        found += hits.size();
      }
      g_sink = g_sink + static_cast<double>(found);
    });
    report(rows, {"search", input, n, "knn-query", knn, 1, query_s, static_cast<double>(k)});
    const double tree_rows_s = best_of(repeat, [&] {
      std::size_t found = 0;
      for (const std::uint32_t i : search->leaf_order()) {
        search->knn_of(static_cast<int>(i), k, hits);
        found += hits.size();
      }
      g_sink = g_sink + static_cast<double>(found);
    });
    report(rows, {"search", input, n, "knn-of-tree", knn, 1, tree_rows_s, static_cast<double>(k)});
    for (const int threads : kThreads) {
      PointRows knn_r;
      const double rows_s = best_of(
          repeat, [&] { knn_r = knn_rows(*search, k, threads); }, [&] { knn_r = {}; });
      report(rows, {"search", input, n, "knn-rows", knn, threads, rows_s,
                    static_cast<double>(knn_r.neighbours.size()) / n});
    }
    // The radius whose disc holds k points on average.
    const double radius = std::sqrt(k * area / (std::numbers::pi * n));
    char ball[64];
    std::snprintf(ball, sizeof ball, "radius=%.5f", radius);
    for (const int threads : kThreads) {
      PointRows ball_r;
      const double rows_s = best_of(
          repeat, [&] { ball_r = ball_rows(*search, radius, threads); }, [&] { ball_r = {}; });
      report(rows, {"search", input, n, "ball-rows", ball, threads, rows_s,
                    static_cast<double>(ball_r.neighbours.size()) / n});
    }
  }
}

// ---- LHF-2: rings against k-NN -------------------------------------------------------------

struct Stages {
  double setup, estimate, total;
};

// MeshEstimation's constructor and run() over every vertex, each the minimum over the runs, and
// the minimum of their sums.
Stages time_estimation(const Mesh& mesh, const Estimator& est, int repeat) {
  Stages best{INFINITY, INFINITY, INFINITY};
  std::vector<VertexEstimate> out(static_cast<std::size_t>(mesh.num_vertices()));
  for (int r = 0; r < repeat; ++r) {
    std::unique_ptr<MeshEstimation> run;
    const double setup =
        bench::seconds_of([&] { run = std::make_unique<MeshEstimation>(mesh, est); });
    const double estimate = bench::seconds_of([&] { run->run(0, out); });
    g_sink = g_sink + out.back().H;
    best = {std::min(best.setup, setup), std::min(best.estimate, estimate),
            std::min(best.total, setup + estimate)};
  }
  return best;
}

// The same from the arrays: the Mesh built from (vertices, faces) inside the time, as a caller
// with arrays in memory pays it (the rings need the mesh's adjacency, the k-NN rows their grid or
// tree, both built in the time), the minimum over the runs.
double time_from_arrays(const VertexMatrix& vertices, const FaceMatrix& faces, const Estimator& est,
                        int repeat) {
  double best = INFINITY;
  std::vector<VertexEstimate> out(static_cast<std::size_t>(vertices.rows()));
  for (int r = 0; r < repeat; ++r) {
    const double seconds = bench::seconds_of([&] {
      const Mesh mesh(vertices, faces, "bench");
      MeshEstimation(mesh, est).run(0, out);
    });
    g_sink = g_sink + out.back().H;
    best = std::min(best, seconds);
  }
  return best;
}

void lhf_part(const std::string& family, int level, int repeat, std::vector<Row>& rows) {
  const GeneratedMesh generated = generate_mesh({family, level, 0, 1, false});
  const Mesh& mesh = generated.mesh;
  const Mesh points(mesh.vertices(), FaceMatrix(0, 3), "points");
  const std::string input = family + "-" + std::to_string(level);
  const long long n = mesh.num_vertices();
  const std::string knn = "knn=" + std::to_string(kLhfK);
  for (const int threads : kThreads) {
    EstimatorOptions rings_o;
    rings_o.degree = 2;
    rings_o.threads = threads;
    EstimatorOptions knn_o = rings_o;
    knn_o.neighbourhood = {PointNeighbourhood::Kind::knn, static_cast<double>(kLhfK)};
    struct Way {
      const char* name;
      const Mesh& mesh;
      const EstimatorOptions& options;
      std::string neighbourhood;
    };
    for (const Way& way :
         {Way{"mesh-rings", mesh, rings_o, "rings"}, Way{"mesh-knn", mesh, knn_o, knn},
          Way{"points-knn", points, knn_o, knn}}) {
      const auto est = make_estimator("lhf", way.options);
      const Stages s = time_estimation(way.mesh, *est, repeat);
      const std::string part = std::string("lhf-2 ") + way.name;
      report(rows, {part, input, n, "setup", way.neighbourhood, threads, s.setup, 0});
      report(rows, {part, input, n, "estimate", way.neighbourhood, threads, s.estimate, 0});
      report(rows, {part, input, n, "total", way.neighbourhood, threads, s.total, 0});
      const double arrays_s = time_from_arrays(way.mesh.vertices(), way.mesh.faces(), *est, repeat);
      report(rows, {part, input, n, "from-arrays", way.neighbourhood, threads, arrays_s, 0});
    }
    // The point set's setup in its parts (points/point_normals.h: the 16-NN rows, PCA, the
    // orientation over the MST), and the table of knn=12 built alone.
    const auto search = std::make_unique<PointSearch>(points.vertices());  // nothing built yet
    PointRows normal_rows;
    const double normal_rows_s = best_of(
        repeat, [&] { normal_rows = knn_rows(*search, kNormalNeighbours, threads); },
        [&] { normal_rows = {}; });
    const std::string knn16 = "knn=" + std::to_string(kNormalNeighbours);
    report(rows, {"lhf-2 points-knn", input, n, "normals-rows", knn16, threads, normal_rows_s,
                  static_cast<double>(kNormalNeighbours)});
    std::vector<unsigned char> degenerate;
    VertexMatrix normals;
    const double pca_s = best_of(repeat, [&] {
      normals = pca_normals(points.vertices(), normal_rows, threads, degenerate);
    });
    report(rows, {"lhf-2 points-knn", input, n, "normals-pca", knn16, threads, pca_s, 0});
    const VertexMatrix unoriented = normals;
    const double orient_s = best_of(
        repeat,
        [&] { orient_normals(points.vertices(), normal_rows, normals, degenerate, nullptr); },
        [&] { normals = unoriented; });
    report(rows, {"lhf-2 points-knn", input, n, "normals-orient", knn16, 1, orient_s, 0});
    std::unique_ptr<NeighbourhoodTable> table;
    const NeighbourhoodSpec spec =
        NeighbourhoodSpec::point_rule(NeighbourhoodSpec::Points::knn, kLhfK);
    const double table_s = best_of(
        repeat, [&] { table = std::make_unique<NeighbourhoodTable>(points, spec, false, threads); },
        [&] { table.reset(); });
    report(rows, {"lhf-2 points-knn", input, n, "table", knn, threads, table_s,
                  static_cast<double>(kLhfK)});
  }
}

int run(int argc, char** argv) {
  std::string output, meshes = "torus-unstructured:4,torus-structured:6";
  int points = 1000000, repeat = 5;
  for (int i = 1; i < argc; ++i) {
    const std::string a = argv[i];
    const auto value = [&]() -> std::string {
      if (i + 1 >= argc) throw std::runtime_error(a + " needs a value");
      return argv[++i];
    };
    if (a == "--output")
      output = value();
    else if (a == "--points")
      points = std::stoi(value());
    else if (a == "--repeat")
      repeat = std::max(1, std::stoi(value()));
    else if (a == "--meshes")
      meshes = value();
    else
      throw std::runtime_error("unknown argument " + a);
  }
  if (output.empty())
    throw std::runtime_error(
        "usage: bench_neighbourhoods --output neighbourhoods.csv [--points N] [--repeat R] "
        "[--meshes family:level,...]");
  std::vector<Row> rows;
  std::printf(
      "part,input,points,stage,neighbourhood,threads,seconds,ns_per_point,neighbours_per_point,"
      "ns_per_neighbour\n");
  if (points > 0) search_part(points, repeat, rows);
  for (std::size_t start = 0; start < meshes.size();) {
    std::size_t end = meshes.find(',', start);
    if (end == std::string::npos) end = meshes.size();
    const std::string item = meshes.substr(start, end - start);
    const std::size_t colon = item.find(':');
    if (colon == std::string::npos)
      throw std::runtime_error("--meshes: " + item + " is not family:level");
    lhf_part(item.substr(0, colon), std::stoi(item.substr(colon + 1)), repeat, rows);
    start = end + 1;
  }
  std::string csv = "# bench_neighbourhoods: seconds = the minimum over " + std::to_string(repeat) +
                    " runs\npart,input,points,stage,neighbourhood,threads,seconds,ns_per_point,"
                    "neighbours_per_point,ns_per_neighbour\n";
  for (const Row& r : rows) csv += format_row(r);
  write_file_atomic(output, csv);
  std::printf("bench_neighbourhoods: wrote %s\n", output.c_str());
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  curvbench::bench::keep_freed_memory();  // bench/timing.h
  try {
    return run(argc, argv);
  } catch (const std::exception& e) {
    std::fprintf(stderr, "bench_neighbourhoods: %s\n", e.what());
    return 1;
  }
}
