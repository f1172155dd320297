// The whole `curvbench run` pipeline as a library function: runs experiments through the case
// store (runner.h, case_store.h), writes each experiment's error CSV, its timings and errors by
// cause (results_table.h, error_causes.h), table2.csv, table4.csv,
// rates.csv, REPORT.md with the plots, and CLAIMS.md into the output folder; and the experiments
// each alternative reading changes (readings.h) into <output>/readings/.
//
// Three modes:
//   full run       every case (reusing the stored ones), then every output
//   shard K of N   only the cases of shard K (runner.h shard_cases) into the store; no other output
//   report only    every output from a complete store (nothing is computed); an incomplete store
//                  fails naming the missing cases. An experiment none of whose cases is stored
//                  keeps its existing CSV (e.g. the committed results/).
// Every file is written atomically (results_table.h write_file_atomic); a stop request is honoured
// between cases and between plots, leaving REPORT.md and CLAIMS.md untouched.
#pragma once

#include <functional>
#include <string>
#include <vector>

#include "harness/claims/claims.h"
#include "harness/model/experiment.h"
#include "harness/run/runner.h"

namespace curvbench {

struct PipelineOptions {
  std::vector<Experiment> experiments;  ///< the experiments to run
  std::vector<Experiment> available;    ///< every experiment the report and rates cover
  std::string output = "results";       ///< results folder
  std::string store_dir;                ///< case store; empty = <output>/.cache
  int table4_max = 256;                 ///< largest isosurface grid of Table 4
  bool plots = true;                    ///< render the plots (gnuplot)
  bool report_only = false;             ///< build the outputs from the store, compute nothing
  /// Also run, for each alternative reading (readings.h), the experiments it changes into
  /// <output>/readings/<reading>=<choice>/ (full runs only; CLAIMS.md reads whatever is there).
  bool readings = true;
  /// The runner's options, passed whole to every run of cases (the adopted reading's and each
  /// alternative's): threads, force, shard K of N (run.shard_count > 1 runs only that shard's
  /// cases), progress after each case, message for each line of progress ("[run] ...", without
  /// newline) and stop, polled between cases and plots. The pipeline sets its store_dir,
  /// experiment_done, causes_done and unavailable per run; their values here are ignored.
  RunOptions run;
};

enum class PipelineStatus {
  done,     ///< every requested output written
  stopped,  ///< options.run.stop() asked to stop; rerun to continue
};

struct PipelineResult {
  PipelineStatus status = PipelineStatus::done;
  int total = 0, reused = 0, computed = 0;  ///< cases of this run
  std::string report;                       ///< path of REPORT.md ("" if not written)
  int reproduced = 0, not_reproduced = 0, not_applicable = 0;  ///< claim verdicts
};

/// Runs the pipeline. Throws UsageError/InputError for bad options or inputs; InputError names
/// the missing cases of an incomplete store in report-only mode.
PipelineResult run_pipeline(const PipelineOptions& options);

/// What render_results writes from the CSVs of a results folder (nothing is computed).
struct RenderOptions {
  std::vector<Experiment> experiments;  ///< every experiment the report covers
  std::string output = "results";       ///< the results folder
  std::string site_dir;                 ///< "" = <output>/site
  bool plots = true;     ///< render the PNG/SVG plots of the markdown report (gnuplot)
  bool markdown = true;  ///< REPORT.md, report/*.md, leaderboard.csv and CLAIMS.md
  bool site = true;      ///< the results site
  /// Every experiment's CSV must exist (else InputError naming it): `curvbench report`.
  bool require_all = false;
  std::string chart_js = "/usr/share/javascript/chart.js/chart.min.js";
  std::function<void(const std::string&)> message;
  std::function<bool()> stop;
};

struct RenderResult {
  bool stopped = false;
  std::string report;  ///< REPORT.md ("" if not written)
  std::string site;    ///< site/index.html ("" if not written)
  int reproduced = 0, not_reproduced = 0, not_applicable = 0;  ///< claim verdicts
};

/// REPORT.md (a summary), results/report/*.md, the plots, leaderboard.csv, CLAIMS.md and the
/// results site from the CSVs in options.output. Throws InputError naming a CSV that is missing
/// (with require_all), truncated or written by another version (a missing column).
RenderResult render_results(const RenderOptions& options);

/// Writes <results_dir>/CLAIMS.md from the CSVs already in results_dir and its readings/ folders
/// (claims.h evaluate_claims, evaluate_readings), computing and rewriting nothing else; returns
/// the claims under the adopted readings. `curvbench run --claims-only`, and the last step of a
/// full or report-only run.
std::vector<ClaimResult> write_claims(const std::string& results_dir);

/// The stable ids (case_store.h case_id) of the cases of the experiments, in case order; with
/// shard_count > 1 only those of shard `shard`.
std::vector<std::string> list_case_ids(const std::vector<Experiment>& experiments, int shard = 1,
                                       int shard_count = 1);

}  // namespace curvbench
