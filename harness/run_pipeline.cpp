#include "harness/run_pipeline.h"
#include "harness/well_shaped_torus_table.h"

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <map>
#include <optional>

#include "core/build_info.h"
#include "core/errors.h"
#include "harness/case_store.h"
#include "harness/claims.h"
#include "harness/leaderboard.h"
#include "harness/readings.h"
#include "harness/report.h"
#include "harness/report_pages.h"
#include "harness/results_table.h"

namespace curvbench {

namespace {

namespace fs = std::filesystem;

std::string format(const char* fmt, auto... args) {
  char buf[512];
  std::snprintf(buf, sizeof buf, fmt, args...);
  return buf;
}

// Report-only: each experiment's rows from the store, their errors by cause into `causes` and
// the cases recorded as skipped (an outside estimator that could not run) into `skipped`, each
// if given. Throws InputError naming the missing cases of an experiment that is partly stored
// (or not stored and without a CSV).
std::map<std::string, std::vector<ErrorRow>> stored_rows(
    const std::vector<Experiment>& experiments, const CaseStore& store, const std::string& output,
    std::map<std::string, std::vector<CauseRow>>* causes = nullptr,
    std::vector<SkippedMethod>* skipped = nullptr) {
  const auto cases = expand_cases(experiments);
  std::map<std::string, std::vector<ErrorRow>> rows;
  std::map<std::string, int> found;
  std::vector<std::string> missing;
  std::map<std::string, std::vector<std::string>> missing_of;
  for (const RunCase& c : cases) {
    const std::string& name = c.experiment->name;
    std::vector<CauseRow> case_causes;
    if (auto r = store.load(c, &case_causes)) {
      rows[name].insert(rows[name].end(), r->begin(), r->end());
      if (causes)
        (*causes)[name].insert((*causes)[name].end(), case_causes.begin(), case_causes.end());
      ++found[name];
    } else if (auto reason = store.load_skipped(c)) {
      rows[name];  // the experiment's CSV is written even if every case was skipped
      ++found[name];
      if (!skipped) continue;
      const auto same = std::find_if(skipped->begin(), skipped->end(), [&](const auto& s) {
        return s.experiment == name && s.method == c.method->label;
      });
      if (same != skipped->end())
        ++same->cases;
      else
        skipped->push_back({name, c.method->label, 1, *reason});
    } else {
      missing_of[name].push_back(case_id(c));
    }
  }
  for (const Experiment& e : experiments) {
    const auto m = missing_of.find(e.name);
    if (m == missing_of.end()) continue;
    if (found[e.name] == 0 && fs::exists(fs::path(output) / (e.name + ".csv"))) {
      rows.erase(e.name);  // nothing stored: keep the existing CSV
      if (causes) causes->erase(e.name);
      continue;
    }
    missing.insert(missing.end(), m->second.begin(), m->second.end());
  }
  if (!missing.empty()) {
    std::string list;
    for (size_t i = 0; i < missing.size() && i < 20; ++i) list += " " + missing[i];
    if (missing.size() > 20) list += " ...";
    throw InputError(store.directory() + ": " + std::to_string(missing.size()) + " of " +
                     std::to_string(cases.size()) +
                     " cases missing or stale (run their shards first):" + list);
  }
  return rows;
}

// skipped.csv: these skips replace those of the experiments just run or reported.
void write_skipped(const std::string& output, const std::vector<Experiment>& experiments,
                   const std::vector<SkippedMethod>& now) {
  std::vector<SkippedMethod> skipped;
  for (const SkippedMethod& s : read_skipped_csv(output + "/skipped.csv"))
    if (std::none_of(experiments.begin(), experiments.end(),
                     [&](const Experiment& e) { return e.name == s.experiment; }))
      skipped.push_back(s);
  skipped.insert(skipped.end(), now.begin(), now.end());
  write_skipped_csv(output + "/skipped.csv", skipped);
}

}  // namespace

std::vector<std::string> list_case_ids(const std::vector<Experiment>& experiments, int shard,
                                       int shard_count) {
  const auto cases = expand_cases(experiments);
  std::vector<std::string> ids;
  if (shard_count > 1) {
    for (size_t i : shard_cases(cases, shard, shard_count)) ids.push_back(case_id(cases[i]));
  } else {
    for (const RunCase& c : cases) ids.push_back(case_id(c));
  }
  return ids;
}

PipelineResult run_pipeline(const PipelineOptions& o) {
  const auto say = [&](const std::string& line) {
    if (o.message) o.message(line);
  };
  const auto stop = [&] { return o.stop && o.stop(); };
  const bool sharded = o.shard_count > 1;
  if (sharded && o.report_only) throw UsageError("--shard and --report-only exclude each other");
  if (sharded) shard_cases({}, o.shard, o.shard_count);  // validates K/N
  const std::string store_dir =
      o.store_dir.empty() ? (fs::path(o.output) / ".cache").string() : o.store_dir;
  PipelineResult result;
  if (!o.report_only)
    result.total =
        static_cast<int>(sharded ? list_case_ids(o.experiments, o.shard, o.shard_count).size()
                                 : expand_cases(o.experiments).size());
  fs::create_directories(o.output);
  // Temporary files of an earlier run that was killed before it could rename them. Not in a
  // shard: other shards (possibly on other hosts, whose process ids mean nothing here) may be
  // writing into the same folders.
  if (!sharded)
    if (const int stale = remove_stale_temp_files(o.output); stale > 0)
      say(format("[run] removed %d temporary files left by a killed run", stale));

  const auto stopped = [&](int done) {
    say(format("[run] interrupted after %d of %d cases (%d reused, %d computed); rerun to continue",
               done, result.total, result.reused, result.computed));
    result.status = PipelineStatus::stopped;
    return result;
  };

  if (o.report_only) {
    const CaseStore store(store_dir);
    std::vector<SkippedMethod> skipped_now;
    std::map<std::string, std::vector<CauseRow>> causes;
    const auto rows = stored_rows(o.experiments, store, o.output, &causes, &skipped_now);
    for (const auto& [name, r] : rows) {
      write_error_csv(o.output + "/" + name + ".csv", r);
      write_timing_csv(o.output + "/timings/" + name + ".csv", r);
      write_cause_csv(o.output + "/errors_by_cause/" + name + ".csv", causes[name]);
      say("[run] wrote " + o.output + "/" + name + ".csv from the case store");
    }
    write_skipped(o.output, o.experiments, skipped_now);
  }
  if (!sharded) {
    say("[run] Table 2 (ring sizes)");
    write_table2_csv(o.output + "/table2.csv");
    if (stop()) return stopped(0);
    say(format("[run] Table 4 (isosurface torus, n = 16..%d)", o.table4_max));
    write_table4_csv(o.output + "/table4.csv", o.table4_max);
    if (stop()) return stopped(0);
    const auto uses_family = [](const Experiment& e, const std::string& family) {
      return std::any_of(e.meshes.begin(), e.meshes.end(),
                         [&](const ExperimentMesh& m) { return m.family == family; });
    };
    if (std::any_of(o.experiments.begin(), o.experiments.end(),
                    [&](const Experiment& e) { return uses_family(e, "torus-unstructured"); })) {
      say("[run] well-shaped torus meshes (torus-unstructured, levels 1-4)");
      write_well_shaped_torus_csv(o.output + "/torus_unstructured.csv");
      if (stop()) return stopped(0);
    }
  }
  // Commands of outside estimators found unable to run here, carried into the readings' runs.
  std::map<std::string, std::string> unavailable;
  if (!o.report_only) {
    RunOptions ro;
    ro.threads = o.threads;
    ro.message = o.message;
    ro.store_dir = store_dir;
    ro.force = o.force;
    ro.stop = o.stop;
    ro.progress = o.progress;
    ro.shard = o.shard;
    ro.shard_count = o.shard_count;
    const std::string out_dir = o.output;
    // Each experiment's CSV lands as soon as its last case is done.
    ro.experiment_done = [&say, out_dir](const Experiment& e, const std::vector<ErrorRow>& rows) {
      write_error_csv(out_dir + "/" + e.name + ".csv", rows);
      write_timing_csv(out_dir + "/timings/" + e.name + ".csv", rows);
      say("[run] wrote " + out_dir + "/" + e.name + ".csv");
    };
    ro.causes_done = [out_dir](const Experiment& e, const std::vector<CauseRow>& rows) {
      write_cause_csv(out_dir + "/errors_by_cause/" + e.name + ".csv", rows);
    };
    if (sharded)
      say(format("[run] shard %d/%d: %d cases of %zu experiments", o.shard, o.shard_count,
                 result.total, o.experiments.size()));
    else
      say(format("[run] %zu experiments, %d cases (method x mesh level)", o.experiments.size(),
                 result.total));
    const RunSummary done = run_experiments(o.experiments, ro);
    result.total = done.total;
    result.reused = done.reused;
    result.computed = done.computed;
    if (done.interrupted || stop()) return stopped(done.reused + done.computed + done.skipped);
    say(format("[run] reused %d of %d cases, computed %d", done.reused, done.total, done.computed) +
        (done.skipped > 0
             ? format(", skipped %d (outside estimators that cannot run here)", done.skipped)
             : std::string()));
    if (!sharded) write_skipped(o.output, o.experiments, done.skipped_methods);
    unavailable = done.unavailable;
  }

  // The alternative readings: the experiments each changes, in their own folder and case store
  // (<store>/readings/<reading>=<choice>). A shard computes its part of each reading's cases too;
  // --report-only writes each reading's CSVs from that store.
  if (o.readings) {
    for (const Reading& reading : readings())
      for (size_t i = 1; i < reading.choices.size(); ++i) {
        const ReadingChoice& choice = reading.choices[i];
        const std::vector<Experiment> changed = apply_reading(o.experiments, choice);
        if (changed.empty()) continue;
        const std::string folder = reading_folder(o.output, reading, choice);
        const std::string reading_store =
            (fs::path(store_dir) / "readings" / fs::path(folder).filename()).string();
        fs::create_directories(folder);
        if (o.report_only) {
          for (const auto& [name, r] : stored_rows(changed, CaseStore(reading_store), folder))
            write_error_csv(folder + "/" + name + ".csv", r);
          say(format("[run] reading %s=%s: wrote %zu CSVs from the case store", reading.id.c_str(),
                     choice.name.c_str(), changed.size()));
          continue;
        }
        say(format("[run] reading %s=%s: %zu experiments, %zu cases", reading.id.c_str(),
                   choice.name.c_str(), changed.size(), expand_cases(changed).size()));
        RunOptions ro;
        ro.threads = o.threads;
        ro.message = o.message;
        ro.store_dir = reading_store;
        ro.force = o.force;
        ro.stop = o.stop;
        ro.progress = o.progress;
        ro.shard = o.shard;
        ro.shard_count = o.shard_count;
        ro.unavailable = unavailable;
        if (!sharded)
          ro.experiment_done = [folder](const Experiment& e, const std::vector<ErrorRow>& rows) {
            write_error_csv(folder + "/" + e.name + ".csv", rows);
          };
        const RunSummary done = run_experiments(changed, ro);
        if (done.interrupted || stop()) return stopped(done.reused + done.computed + done.skipped);
        unavailable = done.unavailable;
      }
  }
  if (sharded) {
    say("[run] shard " + std::to_string(o.shard) + "/" + std::to_string(o.shard_count) +
        " done; stored in " + store_dir);
    return result;
  }

  // Rates over every experiment CSV present (all of them, not only the ones just run); not the
  // sweeps, which have one level.
  std::vector<ErrorRow> all_rows;
  for (const auto& e : o.available) {
    if (!e.sweep.empty()) continue;
    const std::string csv = o.output + "/" + e.name + ".csv";
    if (fs::exists(csv)) {
      auto rows = read_error_csv(csv);
      all_rows.insert(all_rows.end(), rows.begin(), rows.end());
    }
  }
  write_rate_csv(o.output + "/rates.csv", compute_rates(all_rows));

  RenderOptions ro;
  ro.experiments = o.available;
  ro.output = o.output;
  ro.plots = o.plots;
  ro.message = o.message;
  ro.stop = o.stop;
  const RenderResult rendered = render_results(ro);
  if (rendered.stopped || stop()) {
    say("[run] interrupted while writing the report (REPORT.md and CLAIMS.md not updated); "
        "rerun to finish");
    result.status = PipelineStatus::stopped;
    return result;
  }
  result.report = rendered.report;
  result.reproduced = rendered.reproduced;
  result.not_reproduced = rendered.not_reproduced;
  result.not_applicable = rendered.not_applicable;
  say(
      format("[run] wrote %s, %s/CLAIMS.md and %s: %d reproduced, %d not reproduced, %d not "
             "applicable",
             rendered.report.c_str(), o.output.c_str(), rendered.site.c_str(), result.reproduced,
             result.not_reproduced, result.not_applicable));
  return result;
}

namespace {

// A claim as the report shows it: its verdicts under each reading, and the experiments its
// evidence and Why line name (their pages hold its numbers).
std::vector<ClaimView> claim_views(const std::vector<ClaimResult>& claims,
                                   const std::vector<ReadingResults>& readings,
                                   const std::vector<Experiment>& experiments) {
  std::vector<ClaimView> out;
  for (const ClaimResult& c : claims) {
    ClaimView v;
    v.id = c.id;
    v.statement = c.statement;
    v.band = c.band;
    v.verdict = to_string(c.verdict);
    v.halving_verdict = to_string(c.halving_verdict);
    v.why = c.why;
    for (const ReadingResults& r : readings)
      for (const ClaimResult& rc : r.results)
        if (rc.id == c.id)
          v.readings.push_back({r.reading + "=" + r.choice, to_string(rc.verdict)});
    const std::string text = c.evidence + "\n" + c.why;
    for (const Experiment& e : experiments)
      if (e.sweep.empty() && text.find(e.name) != std::string::npos)
        v.experiments.push_back(e.name);
    out.push_back(std::move(v));
  }
  return out;
}

}  // namespace

RenderResult render_results(const RenderOptions& o) {
  const auto say = [&](const std::string& line) {
    if (o.message) o.message(line);
  };
  RenderResult result;
  if (o.require_all)
    for (const Experiment& e : o.experiments) {
      const std::string csv = o.output + "/" + e.name + ".csv";
      if (!fs::exists(csv))
        throw InputError(csv +
                         ": not found (run `make experiments`, or `curvbench run "
                         "--experiments " +
                         e.name + "`)");
    }
  const auto claims = evaluate_claims(o.output);
  const auto readings = evaluate_readings(o.output);
  const std::vector<ClaimView> views = claim_views(claims, readings, o.experiments);
  for (const auto& c : claims) {
    result.reproduced += c.verdict == Verdict::reproduced;
    result.not_reproduced += c.verdict == Verdict::not_reproduced;
    result.not_applicable += c.verdict == Verdict::not_applicable;
  }
  ReportOptions rep;
  rep.results_dir = o.output;
  rep.plots = o.plots && o.markdown;
  rep.stop = o.stop;
  say("[report] building the report" + std::string(rep.plots ? " and its plots" : ""));
  const std::optional<ReportContent> content = build_report(o.experiments, rep);
  if (!content || (o.stop && o.stop())) {
    result.stopped = true;
    return result;
  }
  const std::vector<LeaderRow> board = leaderboard_rows(o.experiments, o.output);
  ReportFiles files;
  files.results_dir = o.output;
  files.site_dir = o.site_dir;
  files.chart_js = o.chart_js;
  if (o.markdown) {
    write_leaderboard_csv(o.output + "/leaderboard.csv", board);
    result.report = write_markdown_report(*content, board, views, files);
    write_file_atomic(
        o.output + "/CLAIMS.md",
        claims_markdown(claims, "Generated by " + build_info() + " on " + utc_timestamp() + ".",
                        readings));
  }
  if (o.site && !o.require_all && !fs::exists(o.chart_js)) {
    // A run still writes every other output; `curvbench report` (require_all) fails instead.
    say("[report] the site is not written: " + o.chart_js +
        " not found (install Debian's libjs-chart.js: make deps)");
  } else if (o.site) {
    result.site = write_site(o.experiments, *content, board, views, files);
    say("[report] wrote " + result.site);
  }
  return result;
}

}  // namespace curvbench
