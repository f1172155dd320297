// `curvbench run`: runs declarative experiments (experiments/*.exp) and regenerates results/:
// per-experiment error CSVs, rates.csv, table2.csv, table4.csv, REPORT.md, plots, CLAIMS.md.
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <iostream>
#include <memory>
#include <string>
#include <vector>

#include "core/build_info.h"
#include "core/errors.h"
#include "harness/claims.h"
#include "harness/commands.h"
#include "harness/report.h"
#include "harness/runner.h"

namespace curvbench::cli {

namespace {

std::string duration(double s) {
  char buf[32];
  if (s < 60)
    std::snprintf(buf, sizeof buf, "%.0fs", s);
  else
    std::snprintf(buf, sizeof buf, "%dm%02ds", static_cast<int>(s) / 60, static_cast<int>(s) % 60);
  return buf;
}

struct RunArgs {
  std::vector<std::string> experiments;
  bool all = false;
  bool list = false;
  bool report_only = false;
  bool no_plots = false;
  std::string experiments_dir = "experiments";
  std::string output = "results";
  int threads = 0;
  int table4_max = 256;
};

std::vector<Experiment> load_all(const std::string& dir) {
  std::vector<Experiment> out;
  for (const auto& f : list_experiment_files(dir)) out.push_back(parse_experiment(f));
  return out;
}

}  // namespace

Command add_run_command(CLI::App& app) {
  auto args = std::make_shared<RunArgs>();
  auto* sub = app.add_subcommand(
      "run",
      "Run experiments (experiments/*.exp) and regenerate results/ (CSVs, REPORT.md, "
      "plots, CLAIMS.md)");
  sub->add_option("EXPERIMENT", args->experiments,
                  "Experiment names (e.g. fig03-05) or .exp files");
  sub->add_flag("--all", args->all, "Run every experiment in the experiments folder");
  sub->add_flag("--list", args->list, "List the available experiments and exit");
  sub->add_flag("--report-only", args->report_only,
                "Rebuild REPORT.md, plots and CLAIMS.md from the existing CSVs");
  sub->add_flag("--no-plots", args->no_plots, "Do not render plots");
  sub->add_option("--experiments-dir", args->experiments_dir, "Folder of .exp files")
      ->capture_default_str();
  sub->add_option("--output", args->output, "Results folder")->capture_default_str();
  sub->add_option("--threads", args->threads, "OpenMP threads (0 = all cores)")
      ->check(CLI::NonNegativeNumber);
  sub->add_option("--table4-max", args->table4_max, "Largest isosurface grid for Table 4 (16..256)")
      ->check(CLI::IsMember({16, 32, 64, 128, 256}))
      ->capture_default_str();

  return [args]() {
    const auto available = load_all(args->experiments_dir);
    if (args->list) {
      for (const auto& e : available)
        std::printf("%-10s  %s (paper §%s)  [%s]\n", e.name.c_str(), e.title.c_str(),
                    e.section.c_str(), e.source.c_str());
      return 0;
    }
    std::vector<Experiment> selected;
    if (args->all || args->report_only) {
      selected = available;
    } else {
      if (args->experiments.empty())
        throw UsageError("name experiments to run, or use --all or --list");
      for (const auto& name : args->experiments) {
        if (std::filesystem::exists(name) && std::filesystem::path(name).extension() == ".exp") {
          selected.push_back(parse_experiment(name));
          continue;
        }
        bool found = false;
        for (const auto& e : available)
          if (e.name == name) {
            selected.push_back(e);
            found = true;
          }
        if (!found) {
          std::string names;
          for (const auto& e : available) names += (names.empty() ? "" : ", ") + e.name;
          throw UsageError("unknown experiment '" + name + "' (available: " + names + ")");
        }
      }
    }
    std::filesystem::create_directories(args->output);

    if (!args->report_only) {
      std::fprintf(stderr, "[run] Table 2 (ring sizes)\n");
      write_table2_csv(args->output + "/table2.csv");
      std::fprintf(stderr, "[run] Table 4 (isosurface torus, n = 16..%d)\n", args->table4_max);
      write_table4_csv(args->output + "/table4.csv", args->table4_max);

      const auto cases = expand_cases(selected);
      std::fprintf(stderr, "[run] %zu experiments, %zu cases (method x mesh level)\n",
                   selected.size(), cases.size());
      RunOptions ro;
      ro.threads = args->threads;
      ro.progress = [](const RunProgress& p) {
        const RunCase& c = *p.current;
        std::fprintf(stderr, "[%3d/%3d] %-9s %-20s L%d %-7s %7d verts %6.2fs  elapsed %s  ETA %s\n",
                     p.done, p.total, c.experiment->name.c_str(), c.mesh->family.c_str(), c.level,
                     c.method->spec.c_str(), p.vertices, p.case_seconds,
                     duration(p.elapsed_seconds).c_str(), duration(p.eta_seconds).c_str());
      };
      // Each experiment's CSV lands as soon as its last case is done.
      const std::string out_dir = args->output;
      ro.experiment_done = [out_dir](const Experiment& e, const std::vector<ErrorRow>& rows) {
        write_error_csv(out_dir + "/" + e.name + ".csv", rows);
        std::fprintf(stderr, "[run] wrote %s/%s.csv\n", out_dir.c_str(), e.name.c_str());
      };
      run_experiments(selected, ro);
    }

    // Rates over every experiment CSV present (all of them, not only the ones just run).
    std::vector<ErrorRow> all_rows;
    for (const auto& e : available) {
      const std::string csv = args->output + "/" + e.name + ".csv";
      if (std::filesystem::exists(csv)) {
        auto rows = read_error_csv(csv);
        all_rows.insert(all_rows.end(), rows.begin(), rows.end());
      }
    }
    write_rate_csv(args->output + "/rates.csv", compute_rates(all_rows));

    ReportOptions rep;
    rep.results_dir = args->output;
    rep.plots = !args->no_plots;
    const std::string report = write_report(available, rep);
    const auto claims = evaluate_claims(args->output);
    write_file_atomic(
        args->output + "/CLAIMS.md",
        claims_markdown(claims, "Generated by " + build_info() + " on " + utc_timestamp() + "."));
    int reproduced = 0, failed = 0, na = 0;
    for (const auto& c : claims) {
      reproduced += c.verdict == Verdict::reproduced;
      failed += c.verdict == Verdict::not_reproduced;
      na += c.verdict == Verdict::not_applicable;
    }
    std::fprintf(stderr,
                 "[run] wrote %s and %s/CLAIMS.md: %d reproduced, %d not reproduced, %d "
                 "not applicable\n",
                 report.c_str(), args->output.c_str(), reproduced, failed, na);
    return 0;
  };
}

}  // namespace curvbench::cli
