// `curvbench recommend MESH [--noise SIGMA_OVER_H] [--results DIR] [--format text|csv|json]
// [--measure [--threads N]]`: the advice for a mesh (harness/report/recommend_table.h): its
// quality class from its triangle angles (classify_mesh), its noise given or estimated
// (estimate_noise), its features, and per quantity the estimator and radius learned from the
// swept meshes nearest in them with the cross-validated range (advice_cases.csv beside the table,
// harness/report/advice.h; without it the class table's row), with --measure the advice measured
// on the mesh itself (measure_on_mesh), and the `curvbench estimate` command line that runs them.
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <memory>
#include <string>
#include <string_view>

#include "cli/commands.h"
#include "core/errors.h"
#include "core/text.h"
#include "harness/report/recommend_table.h"

namespace curvbench::cli {

namespace {

struct RecommendOptions {
  std::string path;
  double noise = std::nan("");  // sigma/h; NaN: estimate
  std::string results;          // "": the default table
  std::string format = "text";
  bool skip_invalid = false;
  bool measure = false;
  int threads = 0;
};

// The program the printed command runs: "curvbench" when that name on PATH is this executable,
// else this executable's absolute path, so that the line runs as printed.
std::string program_name() {
  namespace fs = std::filesystem;
  std::error_code ec;
  const fs::path self = fs::read_symlink("/proc/self/exe", ec);
  if (ec) return "curvbench";
  if (const char* path = std::getenv("PATH")) {
    std::string_view rest = path;
    while (true) {
      const auto colon = rest.find(':');
      const fs::path candidate = fs::path(rest.substr(0, colon)) / "curvbench";
      if (!rest.substr(0, colon).empty() && fs::exists(candidate, ec))
        return fs::equivalent(candidate, self, ec) ? "curvbench" : self.string();
      if (colon == std::string_view::npos) break;
      rest.remove_prefix(colon + 1);
    }
  }
  return self.string();
}

int run_recommend(const RecommendOptions& o) {
  if (!std::isnan(o.noise) && !(o.noise >= 0 && std::isfinite(o.noise)))
    throw UsageError("--noise " + format_g(o.noise) + ": sigma/h must be finite and >= 0");
  const RecommendationTable table =
      o.results.empty() ? default_recommendations() : read_recommendations_csv(o.results);
  MeshReadReport report;
  const Mesh mesh = read_input_mesh(o.path, o.skip_invalid, report);
  const std::optional<AdviceTable> cases = advice_cases_beside(table.name);
  Advice a = advise(mesh, o.noise, table, cases ? &*cases : nullptr);
  if (o.measure) {
    std::fprintf(stderr, "curvbench: measuring the swept cases on %s...\n", o.path.c_str());
    measure_on_mesh(a, mesh, cases ? &*cases : nullptr, o.threads);
  }
  const std::string command = a.has_choice
                                  ? estimate_command(program_name(), o.path, a.choice,
                                                     o.skip_invalid, advice_output_path(o.path))
                                  : std::string();
  const std::string out = o.format == "csv"    ? advice_csv(a)
                          : o.format == "json" ? advice_json(a, o.path, command)
                                               : advice_text(a, o.path, command);
  std::fputs(out.c_str(), stdout);
  return 0;
}

}  // namespace

Command add_recommend_command(CLI::App& app) {
  const std::string table = default_recommendations_path();
  const std::string provenance = table.empty() ? "" : recommendations_provenance(table);
  auto* sub = app.add_subcommand(
      "recommend",
      "Print the estimator and radius recommended for a mesh, for normals and for curvatures "
      "(learned from the swept meshes nearest in its features, or the recommendations table's "
      "row for its quality class and noise level), why, the error the radius sweeps measured "
      "and the range cross-validation measured, features outside what the sweeps cover, and "
      "the `curvbench estimate` command line that runs them. Default table: " +
          (table.empty() ? std::string("none found (give --results DIR)")
                         : table + (provenance.empty() ? "" : " (" + provenance + ")")));
  auto o = std::make_shared<RecommendOptions>();
  sub->add_option("MESH", o->path, "Mesh file (.off, .obj, .ply)")->required();
  sub->add_option("--noise", o->noise,
                  "Noise sigma/h of the mesh along the normal (default: estimated from the "
                  "residuals of a degree-4 fit at each vertex)");
  sub->add_option("--results", o->results,
                  "Folder holding the recommendations.csv to read instead of the default table "
                  "(e.g. results, after `make experiments`)");
  sub->add_option("--format", o->format,
                  "text: the advice in words and the command line (default); csv: the table's "
                  "header and row; json: the advice as one object")
      ->check(CLI::IsMember({"text", "csv", "json"}));
  CLI::Option* measure = sub->add_flag(
      "--measure", o->measure,
      "Also measure the advice on the mesh itself: run every swept case on it and on it "
      "perturbed by its noise, predict each case's error from the change and from its "
      "distance to a degree-4 fit, and advise the least (docs/advice.md; slower: each "
      "case runs 3 times); the command then runs its curvature choice");
  sub->add_option("--threads", o->threads, "OpenMP threads of --measure (0: all cores)")
      ->check(CLI::NonNegativeNumber)
      ->needs(measure);
  sub->add_flag("--skip-invalid", o->skip_invalid,
                "Drop vertices with a NaN/Inf coordinate and the faces using them (reported) "
                "instead of failing (the printed command passes it on)");
  return [o]() { return run_recommend(*o); };
}

}  // namespace curvbench::cli
