#include "harness/report/field.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <functional>
#include <map>
#include <set>
#include <sstream>
#include <string>

#include "harness/model/metrics.h"
#include "harness/model/results_table.h"

namespace curvbench {

namespace fs = std::filesystem;

namespace {

constexpr Quantity kQuantities[] = {Quantity::normal, Quantity::H, Quantity::K, Quantity::d1};

// The sections of REPORT.md written here, each over the experiments of its report section
// (`report field|hard`): a heading and the words before the per-mesh tables.
struct FieldSection {
  ReportSection section;
  const char* heading;
  const char* intro;
};
const FieldSection kFieldSections[] = {
    {ReportSection::field, "The estimators in common use",
     "Every built-in estimator on the same meshes with the same metrics (experiments "
     "`field-estimators*.exp`)."},
    {ReportSection::hard, "Meshes that break estimators",
     "Every built-in estimator and the outside ones on meshes known to break estimators "
     "(experiment `hard-meshes.exp`; docs/mesh_families.md): the Schwarz lantern of a cylinder "
     "whose normals and area converge (`lantern`) and one whose positions converge but whose "
     "face normals and area do not (`lantern-squeezed`), triangles stretched A = 4 and 16 times "
     "(`-A4`, `-A16`), sampling density varying D = 8 times (`bump-density-D8`), and the "
     "ellipsoid. Where a family runs at two settings, the ratio of the finest-level errors "
     "follows its tables."},
};

bool in_section(const Experiment& e, const FieldSection& section) {
  return e.report == section.section;
}

// "1.23e-04", or "n/a" when not finite.
std::string error_text(double e) {
  return scientific(e);
}

// One method's rows on one family: (quantity, norm) -> level -> row.
struct MethodRows {
  std::string method;
  std::map<std::pair<std::string, std::string>, std::map<int, const ErrorRow*>> series;

  const std::map<int, const ErrorRow*>* find(Quantity q, Norm n) const {
    const auto it = series.find({to_string(q), to_string(n)});
    return it == series.end() ? nullptr : &it->second;
  }
};

// Average rate over the first and last level, and the rate between the two finest levels.
std::pair<double, double> rates(const std::map<int, const ErrorRow*>& s) {
  if (s.size() < 2) return {std::nan(""), std::nan("")};
  const ErrorRow* first = s.begin()->second;
  const ErrorRow* last = s.rbegin()->second;
  const ErrorRow* before_last = std::prev(s.end(), 2)->second;
  return {convergence_rate(first->error, last->error, first->h, last->h),
          convergence_rate(before_last->error, last->error, before_last->h, last->h)};
}

bool converges(const std::pair<double, double>& r) {
  return r.first >= kConvergenceRateThreshold && r.second >= kConvergenceRateThreshold;
}

std::string quantity_name(Quantity q) {
  switch (q) {
    case Quantity::normal:
      return "normals";
    case Quantity::H:
      return "mean curvature H";
    case Quantity::K:
      return "Gaussian curvature K";
    case Quantity::d1:
      return "principal direction d1";
    default:
      return to_string(q);
  }
}

// "0.0123 s".
std::string seconds_text(double s) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.3g s", s);
  return buf;
}

bool reaches(const ErrorRow& r, double target) {
  return std::isfinite(r.error) && r.error <= target && std::isfinite(r.seconds);
}

}  // namespace

CheapestToReach cheapest_to_reach(const std::vector<ErrorRow>& rows, double target) {
  CheapestToReach out;
  out.target = target;
  // Per method, its cheapest row reaching the target; then the two cheapest methods.
  std::map<std::string, const ErrorRow*> per_method;
  for (const ErrorRow& r : rows) {
    if (!reaches(r, target)) continue;
    const ErrorRow*& m = per_method[r.method];
    if (m == nullptr || r.seconds < m->seconds) m = &r;
  }
  for (const auto& [method, r] : per_method) {
    if (out.best == nullptr || r->seconds < out.best->seconds) {
      out.runner_up = out.best;
      out.best = r;
    } else if (out.runner_up == nullptr || r->seconds < out.runner_up->seconds) {
      out.runner_up = r;
    }
  }
  return out;
}

std::vector<double> time_targets(const std::vector<ErrorRow>& rows) {
  std::map<std::string, const ErrorRow*> cheapest;  // each method's cheapest timed row
  for (const ErrorRow& r : rows) {
    if (!std::isfinite(r.seconds)) continue;
    const ErrorRow*& m = cheapest[r.method];
    if (m == nullptr || r.seconds < m->seconds) m = &r;
  }
  std::vector<double> out;
  for (int k = 1; k <= 8 && !cheapest.empty(); ++k) {
    const double target = 1.0 / std::pow(10.0, k);
    const bool reached = std::any_of(rows.begin(), rows.end(),
                                     [&](const ErrorRow& r) { return reaches(r, target); });
    if (!reached) {
      out.push_back(target);
      break;
    }
    const bool at_once = std::all_of(cheapest.begin(), cheapest.end(),
                                     [&](const auto& m) { return reaches(*m.second, target); });
    if (!at_once) out.push_back(target);
  }
  return out;
}

namespace {

// The finest level of mesh `label` (its level and h) and each method's L2 error in H there.
struct FinestHErrors {
  int level = 0;
  double h = 0.0;
  std::map<std::string, double> error;  // method -> error
};

FinestHErrors finest_h_errors(const std::vector<ErrorRow>& rows, const std::string& label) {
  FinestHErrors out;
  for (const ErrorRow& r : rows)
    if (r.family == label && r.level > out.level) {
      out.level = r.level;
      out.h = r.h;
    }
  for (const ErrorRow& r : rows)
    if (r.family == label && r.level == out.level && r.quantity == "H" && r.norm == "L2" &&
        r.vertex_set == "all")
      out.error[r.method] = r.error;
  return out;
}

// One bullet per family that runs at two settings (e.g. aspect 4 and 16): the ratio of each
// method's finest-level L2 error in H, the stronger setting over the weaker.
std::string setting_ratios(const Experiment& e, const std::vector<ErrorRow>& rows) {
  std::ostringstream md;
  for (size_t i = 0; i < e.meshes.size(); ++i)
    for (size_t j = i + 1; j < e.meshes.size(); ++j) {
      const ExperimentMesh& a = e.meshes[i];
      const ExperimentMesh& b = e.meshes[j];
      if (a.family != b.family || a.label() == b.label()) continue;
      const FinestHErrors ea = finest_h_errors(rows, a.label()),
                          eb = finest_h_errors(rows, b.label());
      std::vector<std::pair<double, std::string>> ratios;
      for (const auto& [m, x] : ea.error)
        if (const auto it = eb.error.find(m);
            it != eb.error.end() && std::isfinite(x) && x > 0 && std::isfinite(it->second))
          ratios.push_back({it->second / x, m});
      if (ratios.empty()) continue;
      std::sort(ratios.begin(), ratios.end());
      md << "- `" << b.label() << "` (level " << eb.level << ", h = " << scientific(eb.h)
         << ") against `" << a.label() << "` (level " << ea.level << ", h = " << scientific(ea.h)
         << "), finest-level L2 error in H, ratio per method (smallest first): ";
      for (size_t k = 0; k < ratios.size(); ++k)
        md << (k ? ", " : "") << ratios[k].second << " " << two_decimals(ratios[k].first);
      md << ".\n";
    }
  return md.str();
}

// The words before a group's per-mesh parts: what each table, plot and sentence shows.
std::string section_intro(const FieldSection& section) {
  return std::string(section.intro) +
         " Per mesh family: the errors at the finest level with, "
         "in brackets, the average convergence rate log(e1/eN)/log(h1/hN) of the series; "
         "the time per vertex of the estimation at the finest level (wall time of the whole "
         "mesh over its vertices, with the run's threads, measured when the case was "
         "computed); and the accuracy-versus-cost plot of the L2 error in H against the time "
         "per vertex, one point per method and level (levels joined, finest at the bottom "
         "right for a converging method); and the time to solution, the L2 error in H "
         "against the time of the whole mesh, with the cheapest estimator reaching each "
         "target error. A series *converges* when its average L2 rate and "
         "its rate between the two finest levels are both at least " +
         two_decimals(kConvergenceRateThreshold) + " (a finest-level error of at most " +
         error_text(kRoundOffError) +
         " counts as exact up to round-off); the words below are generated from the tables "
         "with that threshold.";
}

// The table of the finest level's errors (with each series' average rate) and time per vertex.
report::Table error_table(const std::vector<MethodRows>& methods, int finest,
                          const std::function<double(const std::string&)>& us_per_vertex) {
  report::Table tab;
  tab.columns = {"method"};
  for (Quantity q : kQuantities)
    for (Norm n : {Norm::L2, Norm::Linf})
      tab.columns.push_back(std::string(to_string(q)) + " " + to_string(n));
  tab.columns.push_back("us/vertex");
  for (const MethodRows& m : methods) {
    std::vector<report::Cell> row{m.method};
    for (Quantity q : kQuantities)
      for (Norm n : {Norm::L2, Norm::Linf}) {
        const auto* s = m.find(q, n);
        if (s == nullptr || s->empty() || s->rbegin()->first != finest) {
          row.push_back("-");
          continue;
        }
        const double err = s->rbegin()->second->error;
        row.push_back(report::Cell::number(
            err, error_text(err) + " (" + two_decimals(rates(*s).first) + ")"));
      }
    const double us = us_per_vertex(m.method);
    row.push_back(std::isfinite(us) ? report::Cell::number(us, two_decimals(us))
                                    : report::Cell("n/a"));
    tab.add(std::move(row));
  }
  return tab;
}

// Which estimators converge, per quantity (L2), and the most accurate one in H and its cost.
std::string convergence_words(const std::vector<MethodRows>& methods, int finest,
                              const std::function<double(const std::string&)>& us_per_vertex) {
  std::ostringstream md;
  for (Quantity q : kQuantities) {
    std::string yes, no, exact;
    for (const MethodRows& m : methods) {
      const auto* s = m.find(q, Norm::L2);
      if (s == nullptr || s->size() < 2) continue;
      const auto r = rates(*s);
      if (s->rbegin()->second->error <= kRoundOffError)
        exact += (exact.empty() ? "" : ", ") + m.method;
      else if (converges(r))
        yes += (yes.empty() ? "" : ", ") + m.method + " (" + two_decimals(r.first) + ")";
      else
        no += (no.empty() ? "" : ", ") + m.method + " (" + two_decimals(r.first) + ", last " +
              two_decimals(r.second) + ")";
    }
    if (yes.empty() && no.empty() && exact.empty()) continue;
    md << "- " << quantity_name(q) << ": "
       << (yes.empty() ? "no estimator converges" : "converge: " + yes)
       << (no.empty() ? "" : "; do not converge (average rate, last rate): " + no)
       << (exact.empty()
               ? ""
               : "; exact up to round-off (error <= " + error_text(kRoundOffError) + "): " + exact)
       << ".\n";
  }
  const MethodRows* best = nullptr;
  double best_error = INFINITY;
  for (const MethodRows& m : methods)
    if (const auto* s = m.find(Quantity::H, Norm::L2); s && !s->empty()) {
      const double err = s->rbegin()->second->error;
      if (std::isfinite(err) && err < best_error) {
        best_error = err;
        best = &m;
      }
    }
  if (best != nullptr) {
    const double us = us_per_vertex(best->method);
    md << "- Smallest L2 error in H at level " << finest << ": " << best->method << " ("
       << error_text(best_error)
       << (std::isfinite(us) ? ", " + two_decimals(us) + " us/vertex" : std::string()) << ").\n";
  }
  return md.str();
}

// The cheapest method reaching each target error of time_targets(timed), and the runner-up;
// an empty table when there is no target.
report::Table cheapest_table(const std::vector<ErrorRow>& timed, const std::string& label,
                             int first_level, int finest) {
  report::Table tab;
  const std::vector<double> targets = time_targets(timed);
  if (targets.empty()) return tab;
  tab.caption = "Cheapest estimator reaching a target L2 error in H on `" + label +
                "` (the least time of the whole mesh's estimation over the levels where the "
                "error is at most the target; levels " +
                std::to_string(first_level) + "-" + std::to_string(finest) + "):";
  tab.columns = {"target", "cheapest (level, time, error)", "runner-up (level, time, error)"};
  tab.numeric = {true, false, false};
  // A pick's cell: its words, and its time as the number.
  const auto cell = [](const ErrorRow* r) {
    return r == nullptr
               ? report::Cell("-")
               : report::Cell::number(r->seconds, r->method + " (" + std::to_string(r->level) +
                                                      ", " + seconds_text(r->seconds) + ", " +
                                                      error_text(r->error) + ")");
  };
  for (double target : targets) {
    const CheapestToReach c = cheapest_to_reach(timed, target);
    tab.add(
        {report::Cell::number(target, error_text(target)),
         c.best == nullptr ? report::Cell("no estimator reaches it at these levels") : cell(c.best),
         cell(c.runner_up)});
  }
  return tab;
}

bool field_group(const FieldSection& section, const std::vector<Experiment>& experiments,
                 const ReportOptions& options, int& missing_plots, report::Section& out);

}  // namespace

bool field_sections(const std::vector<Experiment>& experiments, const ReportOptions& options,
                    int& missing_plots, report::Section& out) {
  for (const FieldSection& section : kFieldSections)
    if (!field_group(section, experiments, options, missing_plots, out)) return false;
  return true;
}

namespace {

bool field_group(const FieldSection& section, const std::vector<Experiment>& experiments,
                 const ReportOptions& options, int& missing_plots, report::Section& out) {
  const std::string dir = options.results_dir;
  bool header_written = false;
  for (const Experiment& e : experiments) {
    if (!in_section(e, section)) continue;
    const std::string csv = dir + "/" + e.name + ".csv";
    if (!fs::exists(csv)) continue;
    const std::vector<ErrorRow> rows = read_error_csv(csv);
    // Microseconds per vertex and seconds of the whole case by (family, level, method), when the
    // timings were kept.
    std::map<std::tuple<std::string, int, std::string>, double> us_per_vertex, case_seconds;
    const std::string timings = dir + "/timings/" + e.name + ".csv";
    if (fs::exists(timings))
      for (const TimingRow& t : read_timing_csv(timings))
        if (t.vertices > 0 && std::isfinite(t.seconds)) {
          us_per_vertex[{t.family, t.level, t.method}] = 1e6 * t.seconds / t.vertices;
          case_seconds[{t.family, t.level, t.method}] = t.seconds;
        }

    if (!header_written) {
      out.heading(section.heading, 0).text(section_intro(section));
      header_written = true;
    }
    if (const std::string notes = outside_method_notes(e, dir); !notes.empty())
      out.text("Outside estimators of " + e.name + ":\n\n" + notes);
    for (const ExperimentMesh& mesh : e.meshes) {
      std::vector<MethodRows> methods;
      std::map<std::string, size_t> index;
      std::set<int> levels;
      const ErrorRow* any = nullptr;
      for (const ErrorRow& r : rows) {
        if (r.family != mesh.label()) continue;
        any = &r;
        levels.insert(r.level);
        auto [it, inserted] = index.try_emplace(r.method, methods.size());
        if (inserted) methods.push_back({r.method, {}});
        methods[it->second].series[{r.quantity, r.norm}][r.level] = &r;
      }
      if (any == nullptr) continue;
      const int finest = *levels.rbegin();
      const auto us_at_finest = [&](const std::string& method) {
        const auto t = us_per_vertex.find({mesh.label(), finest, method});
        return t == us_per_vertex.end() ? std::nan("") : t->second;
      };
      out.heading(e.name + ": `" + mesh.label() + "`" +
                      (any->noise != "none" ? " (noise " + any->noise + ")" : std::string()),
                  1)
          .text("Finest level " + std::to_string(finest) + ": " + std::to_string(any->vertices) +
                " vertices, h = " + error_text(any->h) + "; levels " +
                std::to_string(*levels.begin()) + "-" + std::to_string(finest) + ".")
          .table(error_table(methods, finest, us_at_finest))
          .text(convergence_words(methods, finest, us_at_finest));

      // Every method's L2 errors in H at the levels `x_of` (microseconds per vertex, seconds
      // of the mesh) has a value for, with that value as the plot's x (ErrorRow::h) and in
      // ErrorRow::seconds.
      const auto h_errors_against = [&](const auto& x_of) {
        std::vector<ErrorRow> points;
        for (const MethodRows& m : methods)
          if (const auto* s = m.find(Quantity::H, Norm::L2))
            for (const auto& [level, r] : *s) {
              const auto x = x_of.find({mesh.label(), level, m.method});
              if (x == x_of.end()) continue;
              ErrorRow p = *r;
              p.h = p.seconds = x->second;
              points.push_back(p);
            }
        return points;
      };
      // One plot of the L2 error in H against a cost (rendered to PNG and SVG with plots on).
      const auto cost_plot = [&](const std::string& kind, const std::string& x_label,
                                 const std::string& title, const std::vector<ErrorRow>& points) {
        const std::string base = kind + "_" + e.name + "_" + mesh.label();
        report::Plot plot;
        plot.id = base;
        plot.title = title + " [" + mesh.label() +
                     (any->noise != "none" ? ", noise " + any->noise : "") + "]";
        plot.x_label = x_label;
        plot.y_label = "L2 error in H";
        plot.reverse_x = false;
        plot.series = error_series(points, false, false);
        if (options.plots) {
          if (options.stop && options.stop()) return false;
          if (!render_plot_files(plot, dir, base)) ++missing_plots;
        }
        out.plot(std::move(plot));
        return true;
      };

      // Accuracy versus cost: L2 error in H against microseconds per vertex.
      const std::vector<ErrorRow> frontier = h_errors_against(us_per_vertex);
      if (!frontier.empty() &&
          !cost_plot("field-frontier", "time per vertex (microseconds)",
                     "Accuracy versus cost: L2 error in H against time per vertex", frontier))
        return false;

      // Time to solution: L2 error in H against the seconds of the whole mesh, per method over
      // the levels, and the cheapest method reaching each target error.
      const std::vector<ErrorRow> timed = h_errors_against(case_seconds);
      if (timed.empty()) continue;
      if (!cost_plot("field-time", "time of the whole mesh (seconds)",
                     "Time to solution: L2 error in H against the time of the mesh", timed))
        return false;
      if (report::Table t = cheapest_table(timed, mesh.label(), *levels.begin(), finest);
          !t.rows.empty())
        out.table(std::move(t));
    }
    out.text(setting_ratios(e, rows));
  }
  return true;
}

}  // namespace
}  // namespace curvbench
