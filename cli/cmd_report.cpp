// `curvbench report [--results DIR] [--site-only] [--no-plots]`: re-renders REPORT.md,
// results/report/*.md, CLAIMS.md, leaderboard.csv and the results site from the CSVs of a
// results folder, computing nothing (harness/run_pipeline.h render_results). `make site` runs it
// with --site-only.
#include <cstdio>
#include <memory>
#include <string>

#include "cli/commands.h"
#include "harness/model/experiment.h"
#include "harness/run_pipeline.h"

namespace curvbench::cli {

namespace {

// The flags; those of render_results are bound straight into its options.
struct ReportArgs {
  RenderOptions render;
  std::string experiments_dir = "experiments";
  bool site_only = false;
  bool no_plots = false;
};

}  // namespace

Command add_report_command(CLI::App& app) {
  auto* sub = app.add_subcommand(
      "report",
      "Re-render the report (REPORT.md, report/*.md, CLAIMS.md, leaderboard.csv, plots) and the "
      "results site from the CSVs of a results folder, computing nothing");
  auto a = std::make_shared<ReportArgs>();
  sub->add_option("--results", a->render.output, "Results folder holding the CSVs")
      ->capture_default_str();
  sub->add_option("--site", a->render.site_dir, "Site folder (default: <results>/site)");
  sub->add_option("--experiments-dir", a->experiments_dir, "Folder of .exp files")
      ->capture_default_str();
  sub->add_option("--chart-js", a->render.chart_js,
                  "Chart.js to copy into the site (libjs-chart.js)")
      ->capture_default_str();
  sub->add_flag("--site-only", a->site_only,
                "Write only the site (seconds; the markdown files are left as they are)");
  sub->add_flag("--no-plots", a->no_plots, "Do not render the PNG/SVG plots of the markdown");
  sub->footer(
      "A CSV that an experiment needs and that is missing, truncated or written by another "
      "version (a missing column) stops the command with exit code 2, naming the file. The site "
      "is written into a temporary folder and renamed into place: nothing half written is left.");
  return [a]() {
    RenderOptions& o = a->render;
    o.experiments = load_experiments(a->experiments_dir);
    o.plots = !a->no_plots;
    o.markdown = !a->site_only;
    o.require_all = true;
    o.message = [](const std::string& line) { std::fprintf(stderr, "%s\n", line.c_str()); };
    const RenderResult r = render_results(o);
    if (!r.report.empty()) std::printf("%s\n", r.report.c_str());
    std::printf("%s\n", r.site.c_str());
    return 0;
  };
}

}  // namespace curvbench::cli
