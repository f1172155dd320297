// `curvbench estimate MESH --method M [estimator options] [--timing] [--skip-invalid]
//  [--color Q] [--block N] [--columns C,...] --output OUT.csv|OUT.ply|OUT.npy`: per-vertex normals
// and curvatures of one estimator. The estimator options (--degree, --rings, --threads, --noisy,
// --vertex-normals, ...) are the flags of the option table (methods/option_schema.h,
// add_estimator_option_flags).
//
// CSV: a header, then one row per vertex; PLY: the mesh with per-vertex properties; NPY: one
// record per vertex (harness/model/estimate_npy.h); all from the column table of
// harness/model/estimate_columns.h (--columns: only those asked for), written block by block as the
// estimates come
// (--block vertices at a time; the bytes do not depend on it or on --threads). The file is written
// to a temporary name and renamed, so a failed run never leaves a truncated OUT. A one-line summary
// goes to stderr, after a one-line warning for each kind of element the reader dropped (faces with
// fewer than 3 vertices or a repeated index; with --skip-invalid, vertices with NaN/Inf coordinates
// and their faces).
//
// With --skip-invalid the output has only the remaining vertices: the CSV "vertex" column then
// holds each vertex's index in the input file; the PLY gets a "source_vertex" property (the same
// index) and a header comment saying so.
#include <algorithm>
#include <array>
#include <cctype>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <iterator>
#include <memory>
#include <span>
#include <string>
#include <vector>

#include <unistd.h>

#include "cli/commands.h"
#include "cli/estimator_flags.h"
#include "core/errors.h"
#include "core/text.h"
#include "harness/model/estimate_columns.h"
#include "harness/model/estimate_npy.h"
#include "harness/model/results_table.h"
#include "harness/report/recommend_table.h"
#include "mesh/colormap.h"
#include "mesh/io.h"
#include "mesh/mesh_checks.h"
#include "methods/estimate_oriented.h"
#include "methods/estimator.h"

namespace curvbench::cli {

namespace {

struct EstimateOptions {
  std::string mesh;
  std::string method;
  EstimatorOptionFlags estimator;  // --degree, --rings, ... (the option table)
  bool timing = false;
  bool skip_invalid = false;
  std::string color;    // "", H, K, k1 or k2: PLY per-vertex RGB (mesh/colormap.h)
  std::string columns;  // --columns: "" (the format's own) or names, "H,K"
  std::string output;
  int block = kEstimateBlock;  // vertices estimated and written at a time
};

// --color: the diverging map of one quantity (mesh/colormap.h) over every vertex, and the header
// comment with its range.
VertexColors color_of(const std::string& quantity, std::span<const VertexEstimate> est,
                      std::vector<std::string>& comments) {
  std::vector<double> x(est.size());
  for (size_t v = 0; v < est.size(); ++v)
    x[v] = quantity == "H"    ? est[v].H
           : quantity == "K"  ? est[v].K
           : quantity == "k1" ? est[v].k1
                              : est[v].k2;
  VertexColors c = diverging_colors(x);
  comments.push_back("color: " + quantity + ", blue -L .. white 0 .. red +L, L = " +
                     format_g(c.limit) + " (98th percentile of |" + quantity + "|)");
  return c;
}

// --method auto: the estimator and radius the default recommendations table gives the mesh
// (harness/report/recommend_table.h, as `curvbench recommend`), said on stderr.
std::unique_ptr<Estimator> auto_estimator(const std::string& path, const Mesh& mesh,
                                          const EstimatorOptions& given) {
  const RecommendationTable table = default_recommendations();
  const std::optional<AdviceTable> cases = advice_cases_beside(table.name);
  const Advice a = advise(mesh, std::nan(""), table, cases ? &*cases : nullptr);
  if (!a.has_choice)
    throw InputError(a.table + ": no sweep ran for " + a.mesh_class.quality +
                     " meshes at sigma/h " + format_g(a.noise_level) +
                     ", so --method auto has no choice for " + path + "; give --method");
  std::unique_ptr<Estimator> est =
      make_estimator(a.choice.method, auto_options(a.choice, given, false));
  std::string flags;
  for (const std::string& f : a.choice.flags()) flags += (flags.empty() ? "" : " ") + f;
  std::fprintf(stderr,
               "curvbench estimate: --method auto chose %s (case '%s') for %s: %s mesh, sigma/h "
               "%.3g estimated (table level %s); the sweep measured a relative %s error in %s "
               "of %s on %s level %d; table %s\n",
               flags.c_str(), a.label.c_str(), path.c_str(), a.mesh_class.quality.c_str(),
               a.sigma_over_h, format_g(a.noise_level).c_str(), a.norm.c_str(), a.quantity.c_str(),
               scientific(a.error).c_str(), a.family.c_str(), a.level,
               (a.has_feature_advice ? a.advice_table : a.table).c_str());
  return est;
}

int run_estimate(const EstimateOptions& o) {
  const std::string ext = lower_extension(o.output);
  if (ext != "csv" && ext != "ply" && ext != "npy")
    throw UsageError("--output " + o.output + ": extension must be .csv, .ply or .npy");
  const std::vector<int> columns =
      o.columns.empty() ? std::vector<int>() : parse_estimate_columns(o.columns);
  if (!o.color.empty() && ext != "ply") throw UsageError("--color needs a .ply --output");
  if (o.block < 1) throw UsageError("--block must be at least 1");
  const EstimatorOptions eo = o.estimator.options();
  // --method auto: the estimator is chosen from the mesh, once it is read.
  const bool automatic = is_auto_method(o.method);
  std::unique_ptr<Estimator> est = automatic ? nullptr : make_estimator(o.method, eo);
  if (est && eo.degree != 0 && est->options().degree != eo.degree)
    throw UsageError("--method " + o.method + " names degree " +
                     std::to_string(est->options().degree) + " but --degree is " +
                     std::to_string(eo.degree));

  using Clock = std::chrono::steady_clock;
  const auto since = [](Clock::time_point t) {
    return std::chrono::duration<double>(Clock::now() - t).count();
  };
  const auto t_read = Clock::now();
  MeshReadReport report;
  Mesh input = read_input_mesh(o.mesh, o.skip_invalid, report);
  const double read_seconds = since(t_read);
  if (automatic) est = auto_estimator(o.mesh, input, eo);
  const int n = input.num_vertices();

  // The output is written as the estimates come, a block of vertices at a time
  // (methods/estimate_oriented.h): no record per vertex is kept for the whole mesh. --color needs
  // the colour range over every vertex first: one block then.
  const int block = o.color.empty() ? o.block : std::max(n, 1);
  std::unique_ptr<EstimateCsvWriter> csv;
  std::unique_ptr<PlyWriter> ply;
  std::unique_ptr<EstimateNpyWriter> npy;
  std::vector<PlyWriter::Property> types = estimate_ply_types(columns);
  const std::size_t ply_columns = types.size();
  std::vector<double> rows;
  VertexColors colors;  // --color: over every vertex (one block)
  const auto t_open = Clock::now();
  if (ext == "csv")
    csv = std::make_unique<EstimateCsvWriter>(o.output, report.source_vertex, eo.threads, columns);
  else if (ext == "npy")
    npy = std::make_unique<EstimateNpyWriter>(o.output, n, report.source_vertex, columns);
  double open_seconds = since(t_open);
  // Failed, excluded and partial vertices by what the mesh shows at them (mesh/mesh_checks.h),
  // computed at the first block that has one.
  constexpr VertexStatus kExplained[] = {VertexStatus::failed, VertexStatus::excluded,
                                         VertexStatus::partial};
  std::vector<VertexDefect> defects;
  std::array<std::array<int, kVertexDefectCount>, std::size(kExplained)> by_defect{};
  const auto count_defects = [&](const Mesh& mesh, int first, std::span<const VertexEstimate> out) {
    for (size_t i = 0; i < out.size(); ++i) {
      const auto k = static_cast<size_t>(
          std::find(std::begin(kExplained), std::end(kExplained), out[i].status) -
          std::begin(kExplained));
      if (k == std::size(kExplained)) continue;
      if (defects.empty()) defects = vertex_defects(mesh);
      ++by_defect[k][static_cast<size_t>(defects[static_cast<size_t>(first) + i])];
    }
  };
  const EstimateSink sink = [&](const Mesh& mesh, int first, std::span<const VertexEstimate> out) {
    count_defects(mesh, first, out);
    if (csv) {
      csv->write(first, out);
      return;
    }
    if (npy) {
      npy->write(first, out);
      return;
    }
    if (!ply) {  // the header, at the first block (it names the colour range)
      std::vector<std::string> comments;
      if (!report.source_vertex.empty()) {
        types.push_back({"source_vertex", true});
        comments.push_back("--skip-invalid: " + std::to_string(report.vertices_skipped) + " of " +
                           std::to_string(report.vertices_in_file) +
                           " input vertices (NaN/Inf coordinates) and " +
                           std::to_string(report.faces_skipped) +
                           " faces dropped; source_vertex = index in the input file");
      }
      if (!o.color.empty()) {
        colors = color_of(o.color, out, comments);
        for (const char* name : {"red", "green", "blue"}) types.push_back({name, true});
      }
      ply = std::make_unique<PlyWriter>(o.output, mesh, types, comments);
    }
    // The rows of the PLY properties, at most o.block vertices at a time (--color hands over
    // every vertex at once).
    for (size_t i0 = 0; i0 < out.size(); i0 += static_cast<size_t>(o.block)) {
      const size_t count = std::min(out.size() - i0, static_cast<size_t>(o.block));
      rows.resize(count * types.size());
      for (size_t i = i0; i < i0 + count; ++i) {
        double* row = rows.data() + (i - i0) * types.size();
        estimate_ply_row(out[i], row, columns);
        std::size_t p = ply_columns;
        if (!report.source_vertex.empty())
          row[p++] = report.source_vertex[static_cast<size_t>(first) + i];
        if (!o.color.empty())
          for (int j = 0; j < 3; ++j) row[p++] = colors.rgb[i][static_cast<size_t>(j)];
      }
      ply->write_vertices(first + static_cast<int>(i0), static_cast<int>(count), rows.data());
    }
  };
  // Consistent orientation, closed parts outward (in place, no copy of a mesh that already is),
  // then the estimates block by block into the sink.
  const auto t_orient = Clock::now();
  OrientedRun run = estimate_oriented(std::move(input), *est, block, sink);
  const double total_seconds = since(t_orient);
  for (const std::string& w : orientation_warnings(run.orientation))
    std::fprintf(stderr, "curvbench: warning: %s: %s\n", o.mesh.c_str(), w.c_str());
  const auto t_commit = Clock::now();
  if (csv) csv->commit();
  if (npy) npy->commit();
  if (ply) ply->commit();  // the faces
  const double write_seconds = open_seconds + run.sink_seconds + since(t_commit);
  const double seconds = run.estimate_seconds;
  const double orient_seconds = total_seconds - run.estimate_seconds - run.sink_seconds;

  std::string counts;
  for (int s = 0; s < kVertexStatusCount; ++s)
    counts += std::string(s > 0 ? ", " : "") + to_string(static_cast<VertexStatus>(s)) + " " +
              std::to_string(run.status_counts[static_cast<size_t>(s)]);
  std::fprintf(stderr,
               "curvbench estimate: %s on %s: %d vertices (%s) in %.3f s (%.2f us/vertex) -> %s\n",
               est->label().c_str(), o.mesh.c_str(), n, counts.c_str(), seconds,
               n > 0 ? 1e6 * seconds / n : 0.0, o.output.c_str());
  // Why: failed, excluded and partial vertices by the mesh's defect there ("none": the method's
  // own failure, Estimator::failure_without_defect, or for excluded its own rule).
  for (size_t k = 0; k < std::size(kExplained); ++k) {
    std::string why;
    for (int d = 0; d < kVertexDefectCount; ++d)
      if (const int c = by_defect[static_cast<size_t>(k)][static_cast<size_t>(d)]; c > 0)
        why += std::string(why.empty() ? "" : ", ") +
               (d > 0 ? to_string(static_cast<VertexDefect>(d))
                : kExplained[k] == VertexStatus::excluded
                    ? "no mesh defect (the method's own rule, e.g. a region reaching the "
                      "boundary)"
                    : "no mesh defect (" + est->failure_without_defect() + ")") +
               " " + std::to_string(c);
    if (!why.empty())
      std::fprintf(stderr, "curvbench estimate: %s vertices by cause: %s\n",
                   to_string(kExplained[k]), why.c_str());
  }
  if (o.timing) {
    // Per-stage wall times. Estimation and writing alternate block by block; each line is the sum
    // of its own parts: neighbourhoods+fit = normals, neighbourhoods and fits (MeshEstimation);
    // write = the time the estimation waited for the output: a CSV block is formatted and then
    // written by two background threads while the next ones are estimated (EstimateCsvWriter),
    // so only what does not overlap counts; a PLY is written in the foreground, faces included.
    std::fprintf(stderr, "timing: read %.6f s\n", read_seconds);
    std::fprintf(stderr, "timing: orientation %.6f s\n", orient_seconds);
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
                  "Method: " + names +
                      " (case-insensitive; the degree may be attached, LHF-2), or auto: the "
                      "estimator and radius `curvbench recommend` gives the mesh (said on stderr)")
      ->required();
  o->estimator.add_to(*sub);
  sub->add_flag(
      "--timing", o->timing,
      "Print per-stage wall times (read, orientation, neighbourhoods+fit, write) to stderr");
  sub->add_flag("--skip-invalid", o->skip_invalid,
                "Drop vertices with a NaN/Inf coordinate and the faces using them instead of "
                "failing; the output then has only the remaining vertices (CSV 'vertex' = index "
                "in the input file; PLY: property 'source_vertex' and a header comment)");
  sub->add_option("--color", o->color,
                  "PLY only: per-vertex red/green/blue of H, K, k1 or k2 (diverging map, symmetric "
                  "range: 98th percentile of |value|)")
      ->check(CLI::IsMember({"H", "K", "k1", "k2"}));
  sub->add_option("--columns", o->columns,
                  "Write only these columns, in this order (comma-separated, e.g. H,K; names: "
                  "nx,ny,nz,k1,k2,H,K,d1x,d1y,d1z,d2x,d2y,d2z,degree,points,ring,status); the "
                  "CSV and .npy keep their leading vertex index");
  sub->add_option("--output", o->output,
                  "Output file: .csv, .ply (binary, the mesh with per-vertex properties) or .npy "
                  "(NumPy records, one field per column)")
      ->required();
  sub->add_option("--block", o->block,
                  "Vertices estimated and written at a time (default 65536; memory vs. overhead; "
                  "the output is the same for any value)");
  return [o]() { return run_estimate(*o); };
}

}  // namespace curvbench::cli
