// `curvbench run`: runs declarative experiments (experiments/*.exp) and regenerates results/:
// per-experiment error CSVs, rates.csv, table2.csv, table4.csv, REPORT.md, plots, CLAIMS.md.
//
// Runs that lose nothing: every finished case is kept in <output>/.cache (case_store.h) and a
// rerun recomputes only the missing or stale cases; every file is written under a temporary
// name and renamed into place; SIGINT/SIGTERM stop the run after the current case (a second
// signal kills it at once, which is safe for the same reason). An experiment's CSV is written as
// soon as its last case is done; rates.csv, REPORT.md, the plots and CLAIMS.md combine all
// experiments and are written only by a run that was not interrupted.
#include <signal.h>

#include <algorithm>
#include <cmath>
#include <csignal>
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
#include "harness/well_shaped_torus_table.h"

namespace curvbench::cli {

namespace {

// The signal that asked the run to stop (0 = none).
volatile std::sig_atomic_t g_stop_signal = 0;

void on_stop_signal(int sig) {
  g_stop_signal = sig;
}

// SIGINT and SIGTERM set g_stop_signal; the handler is reset by its first delivery
// (SA_RESETHAND), so a second Ctrl-C terminates at once. A signal ignored by the parent (e.g.
// SIGINT of a background job) stays ignored.
void install_stop_handlers() {
  g_stop_signal = 0;
  for (int sig : {SIGINT, SIGTERM}) {
    struct sigaction old {};
    if (sigaction(sig, nullptr, &old) == 0 && old.sa_handler == SIG_IGN) continue;
    struct sigaction sa {};
    sa.sa_handler = on_stop_signal;
    sigemptyset(&sa.sa_mask);
    sa.sa_flags = SA_RESETHAND | SA_RESTART;
    sigaction(sig, &sa, nullptr);
  }
}

bool stop_requested() {
  return g_stop_signal != 0;
}

// Exit status of a run stopped by signal sig: 128 + sig (130 for SIGINT, 143 for SIGTERM).
int stopped_exit_code() {
  return 128 + static_cast<int>(g_stop_signal);
}

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
  bool force = false;
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
  sub->add_flag("--force", args->force,
                "Recompute every case instead of reusing the finished ones in <output>/.cache");
  sub->add_option("--experiments-dir", args->experiments_dir, "Folder of .exp files")
      ->capture_default_str();
  sub->add_option("--output", args->output, "Results folder")->capture_default_str();
  sub->add_option("--threads", args->threads, "OpenMP threads (0 = all cores)")
      ->check(CLI::NonNegativeNumber);
  sub->add_option("--table4-max", args->table4_max, "Largest isosurface grid for Table 4 (16..256)")
      ->check(CLI::IsMember({16, 32, 64, 128, 256}))
      ->capture_default_str();
  sub->footer(
      "Finished cases are stored in <output>/.cache/<experiment>/ (one file per mesh level and "
      "method, stamped with a hash of its settings and the code version); a rerun, e.g. after "
      "an interruption or a crash, recomputes only the missing or stale cases (--force: all) and "
      "reports how many it reused. Ctrl-C (SIGINT) or SIGTERM stops after the current case (exit "
      "130 or 143); a second Ctrl-C stops at once. Every output file is written under a "
      "temporary name and renamed into place, so no file is ever left truncated.\n\n"
      "Environment: SOURCE_DATE_EPOCH=<seconds since 1970-01-01 UTC> is the date written into "
      "the outputs instead of the current time, so that two runs give byte-identical files.");

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
    install_stop_handlers();
    // Temporary files of an earlier run that was killed before it could rename them.
    if (const int stale = remove_stale_temp_files(args->output); stale > 0)
      std::fprintf(stderr, "[run] removed %d temporary files left by a killed run\n", stale);

    if (!args->report_only) {
      const auto cases = expand_cases(selected);
      auto interrupted = [&](int done, int reused, int computed) {
        std::fprintf(stderr,
                     "[run] interrupted after %d of %zu cases (%d reused, %d computed); rerun to "
                     "continue\n",
                     done, cases.size(), reused, computed);
        return stopped_exit_code();
      };
      std::fprintf(stderr, "[run] Table 2 (ring sizes)\n");
      write_table2_csv(args->output + "/table2.csv");
      if (stop_requested()) return interrupted(0, 0, 0);
      std::fprintf(stderr, "[run] Table 4 (isosurface torus, n = 16..%d)\n", args->table4_max);
      write_table4_csv(args->output + "/table4.csv", args->table4_max);
      if (stop_requested()) return interrupted(0, 0, 0);
      if (std::any_of(selected.begin(), selected.end(), [](const Experiment& e) {
            return std::any_of(e.meshes.begin(), e.meshes.end(), [](const ExperimentMesh& m) {
              return m.family == "torus-unstructured";
            });
          })) {
        std::fprintf(stderr, "[run] well-shaped torus meshes (torus-unstructured, levels 1-4)\n");
        write_well_shaped_torus_csv(args->output + "/torus_unstructured.csv");
        if (stop_requested()) return interrupted(0, 0, 0);
      }

      std::fprintf(stderr, "[run] %zu experiments, %zu cases (method x mesh level)\n",
                   selected.size(), cases.size());
      RunOptions ro;
      ro.threads = args->threads;
      ro.store_dir = (std::filesystem::path(args->output) / ".cache").string();
      ro.force = args->force;
      ro.stop = stop_requested;
      ro.progress = [](const RunProgress& p) {
        const RunCase& c = *p.current;
        if (p.reused)
          std::fprintf(stderr, "[%3d/%3d] %-9s %-20s L%d %-7s %7d verts  reused\n", p.done, p.total,
                       c.experiment->name.c_str(), c.mesh->family.c_str(), c.level,
                       c.method->spec.c_str(), p.vertices);
        else
          std::fprintf(stderr,
                       "[%3d/%3d] %-9s %-20s L%d %-7s %7d verts %6.2fs  elapsed %s  ETA %s\n",
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
      const RunSummary done = run_experiments(selected, ro);
      const int finished = done.reused + done.computed;
      if (done.interrupted || stop_requested())
        return interrupted(finished, done.reused, done.computed);
      std::fprintf(stderr, "[run] reused %d of %d cases, computed %d\n", done.reused, done.total,
                   done.computed);
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
    rep.stop = stop_requested;
    const std::string report = write_report(available, rep);
    if (report.empty() || stop_requested()) {
      std::fprintf(stderr,
                   "[run] interrupted while writing the report (REPORT.md and CLAIMS.md not "
                   "updated); rerun to finish\n");
      return stopped_exit_code();
    }
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
