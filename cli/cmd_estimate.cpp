// `curvbench estimate MESH --method M --degree D [--rings R] [--threads N] [--noisy] [--timing]
//  [--skip-invalid] --output OUT.csv|OUT.ply`: per-vertex normals and curvatures of one estimator.
//
// CSV: a header, then one row per vertex; PLY: the mesh with per-vertex properties; both from
// the column table of harness/estimate_columns.h. The file is written
// to a temporary name and renamed, so a failed run never leaves a truncated OUT. A one-line summary
// goes to stderr, after a one-line warning for each kind of element the reader dropped (faces with
// fewer than 3 vertices or a repeated index; with --skip-invalid, vertices with NaN/Inf coordinates
// and their faces).
//
// With --skip-invalid the output has only the remaining vertices: the CSV "vertex" column then
// holds each vertex's index in the input file; the PLY gets a "source_vertex" property (the same
// index) and a header comment saying so.
#include <algorithm>
#include <cctype>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <memory>
#include <string>
#include <vector>

#include <unistd.h>

#include "cli/commands.h"
#include "core/errors.h"
#include "core/text.h"
#include "harness/estimate_columns.h"
#include "mesh/colormap.h"
#include "mesh/io.h"
#include "methods/estimate_oriented.h"
#include "methods/estimator.h"

namespace curvbench::cli {

namespace {

struct EstimateOptions {
  std::string mesh;
  std::string method;
  int degree = 2;
  double rings = 0.0;
  int threads = 0;
  bool noisy = false;
  bool timing = false;
  bool skip_invalid = false;
  std::string color;  // "", H, K, k1 or k2: PLY per-vertex RGB (mesh/colormap.h)
  std::string output;
};

// --color: red, green, blue properties from a diverging map of one quantity (mesh/colormap.h).
void add_color_properties(const std::string& quantity, const std::vector<VertexEstimate>& est,
                          std::vector<VertexProperty>& props, std::vector<std::string>& comments) {
  std::vector<double> x(est.size());
  for (size_t v = 0; v < est.size(); ++v)
    x[v] = quantity == "H"    ? est[v].H
           : quantity == "K"  ? est[v].K
           : quantity == "k1" ? est[v].k1
                              : est[v].k2;
  const VertexColors c = diverging_colors(x);
  const char* names[3] = {"red", "green", "blue"};
  for (int j = 0; j < 3; ++j) {
    VertexProperty p{names[j], std::vector<double>(est.size()), true};
    for (size_t v = 0; v < est.size(); ++v) p.values[v] = c.rgb[v][static_cast<size_t>(j)];
    props.push_back(std::move(p));
  }
  comments.push_back("color: " + quantity + ", blue -L .. white 0 .. red +L, L = " +
                     format_g(c.limit) + " (98th percentile of |" + quantity + "|)");
}

int run_estimate(const EstimateOptions& o, bool degree_given) {
  const std::string ext = lower_extension(o.output);
  if (ext != "csv" && ext != "ply")
    throw UsageError("--output " + o.output + ": extension must be .csv or .ply");
  if (!o.color.empty() && ext != "ply") throw UsageError("--color needs a .ply --output");
  EstimatorOptions eo;
  eo.degree = degree_given ? o.degree : 0;  // 0: the method's default (none if degree-free)
  eo.ring = o.rings;
  eo.threads = o.threads;
  eo.noisy = o.noisy;
  std::unique_ptr<Estimator> est = make_estimator(o.method, eo);
  if (degree_given && est->options().degree != o.degree)
    throw UsageError("--method " + o.method + " names degree " +
                     std::to_string(est->options().degree) + " but --degree is " +
                     std::to_string(o.degree));

  using Clock = std::chrono::steady_clock;
  const auto since = [](Clock::time_point t) {
    return std::chrono::duration<double>(Clock::now() - t).count();
  };
  const auto t_read = Clock::now();
  MeshReadReport report;
  const Mesh input = read_input_mesh(o.mesh, o.skip_invalid, report);
  const double read_seconds = since(t_read);
  const auto t0 = Clock::now();
  // Consistent orientation, closed parts outward, then the estimates (methods/estimate_oriented.h).
  OrientedEstimate oriented = estimate_oriented(input, *est);
  const double seconds = since(t0);
  for (const std::string& w : orientation_warnings(oriented.orientation))
    std::fprintf(stderr, "curvbench: warning: %s: %s\n", o.mesh.c_str(), w.c_str());
  const Mesh& mesh = oriented.orientation.mesh;
  std::vector<VertexEstimate>& res = oriented.estimates;
  int counts[6] = {0, 0, 0, 0, 0, 0};  // by VertexStatus code
  for (const VertexEstimate& e : res) ++counts[static_cast<int>(e.status)];

  const auto t_write = Clock::now();

  if (ext == "csv") {
    write_estimate_csv_atomic(o.output, res, report.source_vertex);
  } else {
    std::vector<VertexProperty> props = estimate_ply_properties(res);
    std::vector<std::string> comments;
    if (!report.source_vertex.empty()) {
      props.push_back(
          {"source_vertex",
           std::vector<double>(report.source_vertex.begin(), report.source_vertex.end()), true});
      comments.push_back("--skip-invalid: " + std::to_string(report.vertices_skipped) + " of " +
                         std::to_string(report.vertices_in_file) +
                         " input vertices (NaN/Inf coordinates) and " +
                         std::to_string(report.faces_skipped) +
                         " faces dropped; source_vertex = index in the input file");
    }
    if (!o.color.empty()) add_color_properties(o.color, res, props, comments);
    write_mesh(o.output, mesh, props, comments);  // atomic itself (mesh/io.h)
  }
  const double write_seconds = since(t_write);

  const int n = mesh.num_vertices();
  std::fprintf(stderr,
               "curvbench estimate: %s on %s: %d vertices (ok %d, degree_reduced %d, failed %d, "
               "excluded %d, disk_cut %d, sign_undetermined %d) in %.3f s (%.2f us/vertex) -> %s\n",
               est->label().c_str(), o.mesh.c_str(), n, counts[0], counts[1], counts[2], counts[3],
               counts[4], counts[5], seconds, n > 0 ? 1e6 * seconds / n : 0.0, o.output.c_str());
  if (o.timing) {
    // Per-stage wall times; neighbourhoods and fits are interleaved per vertex, so they are one
    // stage (estimate_mesh, including the area-weighted normals).
    std::fprintf(stderr, "timing: read %.6f s\n", read_seconds);
    std::fprintf(stderr, "timing: neighbourhoods+fit %.6f s\n", seconds);
    std::fprintf(stderr, "timing: write %.6f s\n", write_seconds);
  }
  return 0;
}

}  // namespace

Command add_estimate_command(CLI::App& app) {
  auto* sub = app.add_subcommand(
      "estimate", "Estimate per-vertex normals, principal curvatures and directions, H and K");
  auto o = std::make_shared<EstimateOptions>();
  sub->add_option("MESH", o->mesh, "Mesh file (.off, .obj, .ply)")->required();
  std::string names;
  for (const std::string& n : estimator_names()) names += (names.empty() ? "" : ", ") + n;
  sub->add_option("--method", o->method,
                  "Method: " + names + " (case-insensitive; the degree may be attached, LHF-2)")
      ->required();
  auto* degree = sub->add_option(
      "--degree", o->degree, "Fitting degree of a fit (default 2); degree-free methods take none");
  sub->add_option(
      "--rings", o->rings,
      "Ring size 1, 1.5, 2, ... (default: method default, (d+1)/2; Xu 1; quadric 5, integers)");
  sub->add_option("--threads", o->threads, "OpenMP threads (default: all)");
  sub->add_flag("--noisy", o->noisy, "Noisy input: default ring + 0.5 (paper §5.3)");
  sub->add_flag("--timing", o->timing,
                "Print per-stage wall times (read, neighbourhoods+fit, write) to stderr");
  sub->add_flag("--skip-invalid", o->skip_invalid,
                "Drop vertices with a NaN/Inf coordinate and the faces using them instead of "
                "failing; the output then has only the remaining vertices (CSV 'vertex' = index "
                "in the input file; PLY: property 'source_vertex' and a header comment)");
  sub->add_option("--color", o->color,
                  "PLY only: per-vertex red/green/blue of H, K, k1 or k2 (diverging map, symmetric "
                  "range: 98th percentile of |value|)")
      ->check(CLI::IsMember({"H", "K", "k1", "k2"}));
  sub->add_option("--output", o->output, "Output file (.csv or .ply)")->required();
  return [o, degree]() { return run_estimate(*o, degree->count() > 0); };
}

}  // namespace curvbench::cli
