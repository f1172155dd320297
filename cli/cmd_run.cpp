// `curvbench run`: runs declarative experiments (experiments/*.exp) and regenerates results/:
// per-experiment error CSVs, rates.csv, table2.csv, table4.csv, REPORT.md, plots, CLAIMS.md.
// The pipeline itself is the library's run_pipeline (harness/run_pipeline.h); this file parses
// the options, handles signals and prints progress. Over a cluster: --list-cases, --shard K/N
// into a shared --cache, then --report-only.
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
#include <utility>
#include <vector>

#include "cli/commands.h"
#include "core/errors.h"
#include "core/text.h"
#include "harness/run_pipeline.h"

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

// The flags; those of the pipeline are bound straight into its options.
struct RunArgs {
  PipelineOptions pipeline;
  std::vector<std::string> experiments;
  bool all = false;
  bool list = false;
  bool list_cases = false;
  std::string shard;  ///< "K/N"
  bool claims_only = false;
  bool no_plots = false;
  bool no_readings = false;
  bool full = false;
  std::string experiments_dir = "experiments";
};

// Parses "K/N" (1 <= K <= N).
std::pair<int, int> parse_shard(const std::string& s) {
  const std::string bad = "--shard " + s + ": expected K/N with 1 <= K <= N, e.g. 2/8";
  const auto slash = s.find('/');
  if (slash == std::string::npos) throw UsageError(bad);
  long long k = 0, n = 0;
  try {
    k = parse_integer(s.substr(0, slash), "--shard");
    n = parse_integer(s.substr(slash + 1), "--shard");
  } catch (const InputError&) {
    throw UsageError(bad);
  }
  if (n < 1 || k < 1 || k > n || n > 1000000) throw UsageError(bad);
  return {static_cast<int>(k), static_cast<int>(n)};
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
  sub->add_flag("--full", args->full,
                "Also the full sweeps of <experiments-dir>/sweeps/ (each replaces the trimmed "
                "sweep of the same name): the study for a cluster (docs/cluster.md)");
  sub->add_flag("--list", args->list, "List the available experiments and exit");
  sub->add_flag("--list-cases", args->list_cases,
                "Print the id of every case (experiment/family_Llevel_method_hash) of the named "
                "experiments (default: all; with --shard: of that shard), one per line, and exit");
  sub->add_option("--shard", args->shard,
                  "Run only shard K of N (K/N, 1 <= K <= N): a fixed partition of the cases "
                  "balanced by expected cost; results go to the case store only");
  sub->add_option("--cache", args->pipeline.store_dir,
                  "Case store folder (default <output>/.cache); may be on a shared filesystem");
  sub->add_flag("--report-only", args->pipeline.report_only,
                "Compute nothing: write the experiment CSVs from the case store, then rates, "
                "REPORT.md, plots and CLAIMS.md; fails naming the missing cases if the store is "
                "incomplete (an experiment with no stored case keeps its existing CSV)");
  sub->add_flag("--claims-only", args->claims_only,
                "Compute nothing and rewrite nothing but <output>/CLAIMS.md, from the CSVs "
                "already in <output> and <output>/readings/");
  sub->add_flag("--no-plots", args->no_plots, "Do not render plots");
  sub->add_flag(
      "--no-readings", args->no_readings,
      "Do not run the experiments under the alternative readings of the paper "
      "(harness/readings/readings.cpp) into <output>/readings/; CLAIMS.md still reads any "
      "that are there");
  sub->add_flag("--force", args->pipeline.run.force,
                "Recompute every case instead of reusing the finished ones in <output>/.cache");
  sub->add_option("--experiments-dir", args->experiments_dir, "Folder of .exp files")
      ->capture_default_str();
  sub->add_option("--output", args->pipeline.output, "Results folder")->capture_default_str();
  sub->add_option("--threads", args->pipeline.run.threads, "OpenMP threads (0 = all cores)")
      ->check(CLI::NonNegativeNumber);
  sub->add_option("--table4-max", args->pipeline.table4_max,
                  "Largest isosurface grid for Table 4 (16..256)")
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
    if (args->claims_only) {
      if (args->pipeline.report_only || !args->shard.empty() || !args->experiments.empty() ||
          args->all)
        throw UsageError("--claims-only takes no experiments, --all, --shard or --report-only");
      int rep = 0, notrep = 0, na = 0;
      for (const auto& c : write_claims(args->pipeline.output)) {
        rep += c.verdict == Verdict::reproduced;
        notrep += c.verdict == Verdict::not_reproduced;
        na += c.verdict == Verdict::not_applicable;
      }
      std::fprintf(stderr,
                   "[run] wrote %s/CLAIMS.md: %d reproduced, %d not reproduced, %d not "
                   "applicable\n",
                   args->pipeline.output.c_str(), rep, notrep, na);
      return 0;
    }
    auto available = load_experiments(args->experiments_dir, args->full);
    if (args->list) {
      for (const auto& e : available)
        std::printf("%-10s  %s (paper §%s)  [%s]\n", e.name.c_str(), e.title.c_str(),
                    e.section.c_str(), e.source.c_str());
      return 0;
    }
    const auto [shard, shard_count] =
        args->shard.empty() ? std::pair<int, int>{1, 1} : parse_shard(args->shard);
    std::vector<Experiment> selected;
    if (args->all ||
        (args->experiments.empty() && (args->pipeline.report_only || args->list_cases))) {
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
    if (args->list_cases) {
      for (const auto& id : list_case_ids(selected, shard, shard_count))
        std::printf("%s\n", id.c_str());
      return 0;
    }

    // An experiment given as a file outside the experiments folder joins the rates and report.
    for (const auto& e : selected)
      if (std::none_of(available.begin(), available.end(),
                       [&](const Experiment& a) { return a.name == e.name; }))
        available.push_back(e);

    PipelineOptions& po = args->pipeline;
    po.experiments = selected;
    po.available = available;
    po.plots = !args->no_plots;
    po.readings = !args->no_readings;
    po.run.shard = shard;
    po.run.shard_count = shard_count;
    po.run.message = [](const std::string& line) { std::fprintf(stderr, "%s\n", line.c_str()); };
    po.run.progress = [](const RunProgress& p) {
      const RunCase& c = *p.current;
      const char* method = (c.method->is_external() ? c.method->label : c.method->spec).c_str();
      if (p.reused)
        std::fprintf(stderr, "[%3d/%3d] %-9s %-20s L%d %-7s %7d verts  reused\n", p.done, p.total,
                     c.experiment->name.c_str(), c.mesh->label().c_str(), c.level, method,
                     p.vertices);
      else if (p.skipped)
        std::fprintf(stderr, "[%3d/%3d] %-9s %-20s L%d %-7s  skipped (cannot run here)\n", p.done,
                     p.total, c.experiment->name.c_str(), c.mesh->label().c_str(), c.level, method);
      else
        std::fprintf(stderr, "[%3d/%3d] %-9s %-20s L%d %-7s %7d verts %6.2fs  elapsed %s  ETA %s\n",
                     p.done, p.total, c.experiment->name.c_str(), c.mesh->label().c_str(), c.level,
                     method, p.vertices, p.case_seconds, duration(p.elapsed_seconds).c_str(),
                     duration(p.eta_seconds).c_str());
    };
    po.run.stop = stop_requested;
    install_stop_handlers();
    const PipelineResult r = run_pipeline(po);
    return r.status == PipelineStatus::stopped ? stopped_exit_code() : 0;
  };
}

}  // namespace curvbench::cli
