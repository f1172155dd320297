// `curvbench recommend MESH [--noise SIGMA_OVER_H] [--results DIR]`: the row of
// <results>/recommendations.csv (harness/recommend.h) that matches a mesh: its quality class from
// its triangle angles (classify_mesh), its noise given or estimated (estimate_sigma_over_h),
// mapped to the nearest swept noise level.
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <memory>
#include <string>

#include "cli/commands.h"
#include "core/errors.h"
#include "core/text.h"
#include "harness/recommend.h"
#include "harness/results_table.h"

namespace curvbench::cli {

namespace {

struct RecommendOptions {
  std::string path;
  double noise = std::nan("");  // sigma/h; NaN: estimate
  std::string results = "results";
  bool skip_invalid = false;
};

int run_recommend(const RecommendOptions& o) {
  if (!std::isnan(o.noise) && !(o.noise >= 0 && std::isfinite(o.noise)))
    throw UsageError("--noise " + format_g(o.noise) + ": sigma/h must be finite and >= 0");
  const std::string csv = o.results + "/recommendations.csv";
  if (!std::filesystem::exists(csv))
    throw InputError(csv + ": not found (run `make experiments` to generate it)");
  MeshReadReport report;
  const Mesh mesh = read_input_mesh(o.path, o.skip_invalid, report);
  const MeshClass cls = classify_mesh(mesh);
  const bool estimated = std::isnan(o.noise);
  const double sigma = estimated ? estimate_sigma_over_h(mesh) : o.noise;
  const double level = nearest_noise_level(sigma);
  const CsvTable t = read_csv_table(csv);
  const size_t cq = t.col("quality"), cs = t.col("sigma_over_h");
  std::printf("mesh:          %s (%d vertices, h = %.4g)\n", o.path.c_str(), mesh.num_vertices(),
              mesh.mean_edge_length());
  std::printf("quality:       %s (%s)\n", cls.quality.c_str(), cls.reason.c_str());
  std::printf("noise:         sigma/h = %.3g (%s), nearest swept level %s\n", sigma,
              estimated ? "estimated from the LHF-4 fit residuals" : "given by --noise",
              format_g(level).c_str());
  for (size_t i = 0; i < t.rows.size(); ++i) {
    if (t.text(i, cq) != cls.quality || std::fabs(t.number(i, cs) - level) > 1e-12) continue;
    std::printf("row of %s (line %d):\n", csv.c_str(), t.lines[i]);
    for (size_t c = 0; c < t.header.size(); ++c)
      std::printf("  %-19s %s\n", t.header[c].c_str(), t.text(i, c).c_str());
    if (t.text(i, t.col("status")) == "not swept")
      std::printf("no sweep ran at this noise level: `curvbench run --all --full` runs them all\n");
    return 0;
  }
  throw InputError(csv + ": no row for quality " + cls.quality + " at sigma/h " + format_g(level) +
                   " (run `make experiments` to regenerate it)");
}

}  // namespace

Command add_recommend_command(CLI::App& app) {
  auto* sub = app.add_subcommand(
      "recommend",
      "Print the estimator and radius recommended for a mesh (the row of "
      "<results>/recommendations.csv for its quality class and noise level), with the reason");
  auto o = std::make_shared<RecommendOptions>();
  sub->add_option("MESH", o->path, "Mesh file (.off, .obj, .ply)")->required();
  sub->add_option("--noise", o->noise,
                  "Noise sigma/h of the mesh along the normal (default: estimated from the "
                  "residuals of a degree-4 fit at each vertex)");
  sub->add_option("--results", o->results,
                  "Results folder holding recommendations.csv (default: results)");
  sub->add_flag("--skip-invalid", o->skip_invalid,
                "Drop vertices with a NaN/Inf coordinate and the faces using them (reported) "
                "instead of failing");
  return [o]() { return run_recommend(*o); };
}

}  // namespace curvbench::cli
