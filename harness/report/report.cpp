#include "harness/report/report.h"

#include <sys/wait.h>

#include <algorithm>
#include <cmath>
#include <csignal>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <map>
#include <memory>
#include <set>
#include <sstream>

#include "core/atomic_file.h"
#include "core/build_info.h"
#include "core/errors.h"
#include "harness/model/metrics.h"
#include "harness/model/paper_tables.h"
#include "harness/report/causes.h"
#include "harness/report/field.h"
#include "harness/report/plot_styles.h"
#include "harness/report/point_clouds.h"
#include "harness/report/radius_scaling.h"
#include "harness/report/sweeps.h"
#include "harness/report/table5.h"
#include "harness/report/well_shaped_torus_table.h"
#include "mesh/io.h"
#include "mesh/rings.h"
#include "meshgen/generate.h"
#include "meshgen/torus_isosurface.h"

namespace curvbench {

namespace fs = std::filesystem;

namespace {

std::string sci(double x, int digits = 2) {
  if (!std::isfinite(x)) return std::isnan(x) ? "n/a" : "inf";
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.*e", digits, x);
  return buf;
}

// A value of the paper's tables as it prints it: 3.60e-3 (3 significant digits, short exponent).
std::string paper_sci(double x) {
  const int ex = static_cast<int>(std::floor(std::log10(x)));
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.2fe%d", x / std::pow(10.0, ex), ex);
  return buf;
}

std::string paper_g(double x) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%g", x);
  return buf;
}

std::string family_caption(const std::string& family) {
  try {
    return mesh_family(family).caption;
  } catch (const UsageError&) {
    return family;  // not a generated family
  }
}

// Rows of one panel on one family, grouped by method in first-seen order.
struct Series {
  std::string method;
  std::map<int, const ErrorRow*> by_level;
};

std::vector<Series> series_of(const std::vector<const ErrorRow*>& rows) {
  std::vector<Series> out;
  std::map<std::string, size_t> index;
  for (const ErrorRow* r : rows) {
    auto [it, inserted] = index.try_emplace(r->method, out.size());
    if (inserted) out.push_back({r->method, {}});
    out[it->second].by_level[r->level] = r;
  }
  return out;
}

double series_rate(const Series& s) {
  if (s.by_level.size() < 2) return std::nan("");
  const ErrorRow* a = s.by_level.begin()->second;
  const ErrorRow* b = s.by_level.rbegin()->second;
  return convergence_rate(a->error, b->error, a->h, b->h);
}

// The paper's rate, assuming each level halves h (harness/model/metrics.h).
double series_halving_rate(const Series& s) {
  if (s.by_level.size() < 2) return std::nan("");
  const auto& [la, a] = *s.by_level.begin();
  const auto& [lb, b] = *s.by_level.rbegin();
  return level_halving_rate(a->error, b->error, la, lb);
}

}  // namespace

void write_table2_csv(const std::string& path) {
  // Every vertex of the structured torus has valence 6 (docs/algorithms.md §10.1(b)); level 2 is
  // large enough (128 x 44) that a 3.5-ring does not wrap around the tube.
  MeshSpec spec;
  spec.family = "torus-structured";
  spec.level = 2;
  const GeneratedMesh g = generate_mesh(spec);
  RingCollector rc(g.mesh);
  std::ostringstream out;
  out << provenance_comment() << "\n"
      << "degree,coefficients,ring,points_with_centre,paper_points\n";
  for (int d = 1; d <= 6; ++d) {
    rc.collect(0, default_ring(d));
    out << d << ',' << num_coefficients(d) << ',' << default_ring(d) << ','
        << rc.neighbours().size() + 1 << ',' << paper::kTable2[d - 1].points_with_centre << "\n";
  }
  write_file_atomic(path, out.str());
}

void write_table4_csv(const std::string& path, int max_grid_points) {
  const auto rows = table4(max_grid_points);
  std::ostringstream out;
  out << provenance_comment() << "\n"
      << "grid_points,vertices,mean_edge_length,paper_edge_length,rms_error,max_error\n";
  for (const auto& r : rows)
    out << r.grid_points << ',' << r.vertices << ',' << format_double(r.mean_edge_length) << ','
        << format_double(0.5 * r.mean_edge_length) << ',' << format_double(r.rms_error) << ','
        << format_double(r.max_error) << "\n";
  write_file_atomic(path, out.str());
}

std::vector<report::Series> error_series(const std::vector<ErrorRow>& rows, bool rates,
                                         bool slopes) {
  std::vector<const ErrorRow*> ptrs;
  for (const auto& r : rows) ptrs.push_back(&r);
  const auto series = series_of(ptrs);
  std::vector<std::string> labels;
  for (const auto& s : series) labels.push_back(s.method);
  const std::vector<PlotStyle> styles = plot_styles(labels);  // one look per method everywhere
  std::vector<report::Series> out;
  std::set<int> orders;
  double h0 = 0.0, e0 = 0.0, h_last = INFINITY;
  for (size_t i = 0; i < series.size(); ++i) {
    report::Series se;
    const double rate = series_rate(series[i]);
    se.label = series[i].method + (rates ? " (rate " + two_decimals(rate) + ")" : "");
    se.color = styles[i].colour;
    se.marker = styles[i].marker;
    se.dash = styles[i].dash;
    for (const auto& [level, r] : series[i].by_level) {
      if (!std::isfinite(r->error) || r->error <= 0) continue;
      se.points.push_back({r->h, r->error,
                           "level " + std::to_string(level) + ", " + std::to_string(r->vertices) +
                               " vertices, " + r->family +
                               (r->noise != "none" ? ", noise " + r->noise : "")});
      if (r->h >= h0) {
        e0 = r->h > h0 ? r->error : std::max(e0, r->error);
        h0 = r->h;
      }
      h_last = std::min(h_last, r->h);
    }
    if (std::isfinite(rate)) orders.insert(std::clamp(static_cast<int>(std::lround(rate)), 1, 4));
    out.push_back(std::move(se));
  }
  // Dashed reference slopes O(h^p) for the orders the rates round to, anchored at half the
  // largest error at the coarsest h.
  if (slopes && h0 > 0 && e0 > 0 && std::isfinite(h_last) && h_last < h0)
    for (int p : orders) {
      report::Series ref;
      ref.label = "O(h^" + std::to_string(p) + ")";
      ref.color = "#808080";
      ref.marker = 0;
      ref.dash = 2;
      ref.points = {{h0, 0.5 * e0, "reference slope"},
                    {h_last, 0.5 * e0 * std::pow(h_last / h0, p), "reference slope"}};
      out.push_back(std::move(ref));
    }
  return out;
}

bool render_plot_files(report::Plot& plot, const std::string& results_dir,
                       const std::string& base) {
  std::ostringstream gp;
  gp << (plot.log_x && plot.log_y ? "set logscale xy\n"
         : plot.log_x             ? "set logscale x\n"
         : plot.log_y             ? "set logscale y\n"
                                  : "")
     << (plot.log_y ? "set format y '10^{%L}'\n" : "") << "set xlabel '" << plot.x_label << "'\n"
     << "set ylabel '" << plot.y_label << "'\nset key outside right top\nset grid\n"
     << (plot.reverse_x ? "set xrange [*:*] reverse\n" : "")
     // The bottom margin holds the x label and, below it, the provenance footer.
     << "set bmargin 5\n"
     << "set label 1 \"" << build_info() << ", " << utc_timestamp()
     << "\" at screen 0.01, screen 0.015 font ',8' noenhanced\n"
     << "set title \"" << plot.title << "\" noenhanced\n";
  std::ostringstream cmd;
  cmd << "plot ";
  int drawn = 0;
  for (size_t i = 0; i < plot.series.size(); ++i) {
    const report::Series& s = plot.series[i];
    gp << "$S" << i << " << EOD\n";
    for (const report::Point& p : s.points)
      if (std::isfinite(p.x) && std::isfinite(p.y) && (!plot.log_y || p.y > 0))
        gp << format_double(p.x) << ' ' << format_double(p.y) << "\n";
    gp << "EOD\n";
    const std::string look = "lc rgb '" + (s.color.empty() ? std::string("#000000") : s.color) +
                             "' dt " + std::to_string(s.dash);
    // A scatter series marks points on the curves (the sweeps' circled best radii): larger.
    cmd << (drawn++ ? ", " : "") << "$S" << i << " using 1:2 with "
        << (s.marker == 0   ? "lines lw 1 "
            : s.points_only ? "points ps 2.5 lw 2 pt " + std::to_string(s.marker) + " "
                            : "linespoints lw 2 ps 1.2 pt " + std::to_string(s.marker) + " ")
        << look << " title \"" << s.label << "\" noenhanced";
  }
  cmd << "\n";
  if (!run_gnuplot(results_dir + "/plots/" + base, gp.str(), cmd.str())) return false;
  plot.image = "plots/" + base + ".png";
  return true;
}

bool run_gnuplot(const std::string& base, const std::string& setup, const std::string& plot) {
  // The images are written by gnuplot to the temporary files of the project's atomic writer
  // (core/atomic_file.h) and renamed into place only if it succeeds; the script under a temporary
  // name too (swept by remove_stale_temp_files if killed).
  std::unique_ptr<AtomicFile> png, svg;
  try {
    png = std::make_unique<AtomicFile>(base + ".png");
    svg = std::make_unique<AtomicFile>(base + ".svg");
  } catch (const InputError&) {
    return false;
  }
  const std::string script_path = temp_path(base + ".gp");
  {
    std::ofstream out(script_path);
    out << setup << "set terminal pngcairo size 900,560 font 'sans,11'\nset output '"
        << png->temporary() << "'\n"
        << plot << "set terminal svg size 900,560 font 'sans,11'\nset output '" << svg->temporary()
        << "'\n"
        << plot << "unset output\n";
  }
  const std::string cmd = "gnuplot '" + script_path + "' > /dev/null 2>&1";
  const int rc = std::system(cmd.c_str());
  std::error_code ec;
  fs::remove(script_path, ec);
  if (rc != 0) {
    // The shell reports a child killed by signal s as exit status 128 + s.
    const int status = WIFEXITED(rc) ? WEXITSTATUS(rc) - 128 : WIFSIGNALED(rc) ? WTERMSIG(rc) : 0;
    if (status == SIGINT || status == SIGTERM) std::raise(status);
    return false;  // the temporaries are removed by png's and svg's destructors
  }
  try {
    png->commit();
    svg->commit();
  } catch (const InputError&) {
    return false;
  }
  return true;
}

std::string outside_method_notes(const Experiment& e, const std::string& results_dir) {
  std::string out;
  for (const ExperimentMethod& m : e.methods)
    if (m.is_external() && !m.description.empty())
      out += "- `" + m.label + "` (outside estimator): " + m.description + "\n";
  for (const SkippedMethod& s : read_skipped_csv(results_dir + "/skipped.csv"))
    if (s.experiment == e.name)
      out += "- `" + s.method + "` was skipped (" + std::to_string(s.cases) +
             " cases): its command cannot run here (" + s.reason +
             "). It has no rows below; install what it needs and rerun.\n";
  return out.empty() ? out : out + "\n";
}

namespace {

report::Section table2_section(const std::string& dir) {
  report::Section s{
      "table2",
      "Table 2. Numbers of coefficients in degree-d fittings versus numbers of points "
      "in typical (d+1)/2 rings",
      {}};
  const std::string csv = dir + "/table2.csv";
  if (!fs::exists(csv)) return s;
  const CsvTable t = read_csv_table(csv);
  s.text("Interior vertex of a regular valence-6 mesh (the structured torus), centre included.");
  report::Table tab;
  tab.id = "table2";
  tab.columns = {"degree (d)"};
  std::vector<report::Cell> coeffs{"#coeffs."}, ring{"ring"}, ours{"#points (ours)"},
      paper{"#points (paper)"};
  const size_t cd = t.col("degree"), cc = t.col("coefficients"), cr = t.col("ring"),
               cp = t.col("points_with_centre"), cq = t.col("paper_points");
  for (size_t i = 0; i < t.rows.size(); ++i) {
    tab.columns.push_back(t.text(i, cd));
    coeffs.push_back(report::Cell::number(t.number(i, cc), t.text(i, cc)));
    ring.push_back(report::Cell::number(t.number(i, cr), t.text(i, cr)));
    ours.push_back(report::Cell::number(t.number(i, cp), t.text(i, cp)));
    paper.push_back(report::Cell::number(t.number(i, cq), t.text(i, cq)));
  }
  tab.add(coeffs).add(ring).add(ours).add(paper);
  return s.table(std::move(tab));
}

}  // namespace

report::Section table4_section(const std::vector<Table4Row>& rows) {
  report::Section s{
      "table4", "Table 4. Input position errors of torus meshes extracted by marching cubes", {}};
  s.text(
      "Signed distance function of the torus (R = 1, r = 0.3) sampled at n points per axis "
      "on [-1.5, 1.5]^3, one vertex per sign-changing grid edge (docs/algorithms.md §10.1(a))."
      " Rates: log2(e(n/2) / e(n)). The paper's \"average edge length\" column equals half "
      "the true mean edge length (see the last two columns).");
  report::Table tab;
  tab.id = "table4";
  tab.columns = {"n",
                 "#verts (ours / paper)",
                 "L2 (ours / paper)",
                 "Linf (ours / paper)",
                 "rate L2 (ours / paper)",
                 "rate Linf (ours / paper)",
                 "mean edge length",
                 "its half / paper's column"};
  for (size_t i = 0; i < rows.size(); ++i) {
    const Table4Row& r = rows[i];
    const paper::Table4Row* p = nullptr;
    for (const auto& pr : paper::kTable4)
      if (pr.grid_points == r.grid_points) p = &pr;
    const auto paper_rate = [&](double x) { return p && std::isfinite(x) ? two_decimals(x) : "-"; };
    report::Cell rate_l2("-"), rate_inf("-");
    if (i > 0) {
      const double r2 = std::log2(rows[i - 1].rms_error / r.rms_error);
      const double ri = std::log2(rows[i - 1].max_error / r.max_error);
      rate_l2 = report::Cell::number(r2, two_decimals(r2) + " / " + paper_rate(p ? p->rate_l2 : 0));
      rate_inf =
          report::Cell::number(ri, two_decimals(ri) + " / " + paper_rate(p ? p->rate_linf : 0));
    }
    const double h = r.mean_edge_length;
    tab.add(
        {report::Cell::number(r.grid_points, std::to_string(r.grid_points) + "^3"),
         report::Cell::number(r.vertices, std::to_string(r.vertices) + " / " +
                                              (p ? std::to_string(p->vertices) : "-")),
         report::Cell::number(r.rms_error, sci(r.rms_error) + " / " + (p ? paper_sci(p->l2) : "-")),
         report::Cell::number(r.max_error,
                              sci(r.max_error) + " / " + (p ? paper_sci(p->linf) : "-")),
         rate_l2, rate_inf, report::Cell::number(h, sci(h, 3)),
         report::Cell::number(0.5 * h,
                              sci(0.5 * h, 2) + " / " + (p ? paper_g(p->edge_column) : "-"))});
  }
  return s.table(std::move(tab));
}

namespace {

// Table 4 from results/table4.csv (write_table4_csv).
report::Section table4_section(const std::string& dir) {
  const std::string csv = dir + "/table4.csv";
  if (!fs::exists(csv))
    return {
        "table4", "Table 4. Input position errors of torus meshes extracted by marching cubes", {}};
  const CsvTable t = read_csv_table(csv);
  const size_t cg = t.col("grid_points"), cv = t.col("vertices"), ch = t.col("mean_edge_length"),
               cr = t.col("rms_error"), cm = t.col("max_error");
  std::vector<Table4Row> rows;
  for (size_t i = 0; i < t.rows.size(); ++i)
    rows.push_back(
        {t.integer(i, cg), t.integer(i, cv), t.number(i, ch), t.number(i, cr), t.number(i, cm)});
  return table4_section(rows);
}

// The vertex sets of the rows, in first-seen order.
std::vector<std::string> vertex_sets_of(const std::vector<const ErrorRow*>& rows) {
  std::vector<std::string> out;
  for (const ErrorRow* r : rows)
    if (std::find(out.begin(), out.end(), r->vertex_set) == out.end()) out.push_back(r->vertex_set);
  return out;
}

// One experiment: per panel and mesh (and vertex set), the table of errors by level with both
// rates, and the panel's plot; then the errors by cause.
bool experiment_section(const Experiment& e, const ReportOptions& options, int& missing_plots,
                        report::Section& s) {
  const std::string dir = options.results_dir;
  s.id = e.name;
  s.title = e.name + ": " + e.title +
            (e.section == "beyond" ? std::string(" (beyond the paper)")
                                   : std::string(" (paper §").append(e.section).append(")"));
  const std::string csv = dir + "/" + e.name + ".csv";
  if (!fs::exists(csv)) {
    s.text("Not run yet: " + csv + " is missing.");
    return true;
  }
  const auto rows = read_error_csv(csv);
  s.text("Source: `" + experiment_source_name(e) + "`.");
  s.text(outside_method_notes(e, dir));
  for (const auto& panel : e.panels) {
    s.heading(panel.caption);
    for (const auto& m : e.meshes) {
      std::vector<const ErrorRow*> all;
      for (const auto& r : rows)
        if (r.family == m.label() && r.quantity == to_string(panel.quantity) &&
            r.norm == to_string(panel.norm))
          all.push_back(&r);
      // One table and plot per vertex set: rows of different sets never share a series.
      const std::vector<std::string> sets = vertex_sets_of(all);
      for (const std::string& set : sets) {
        std::vector<const ErrorRow*> sel;
        std::vector<ErrorRow> sel_rows;
        for (const ErrorRow* r : all)
          if (r->vertex_set == set) {
            sel.push_back(r);
            sel_rows.push_back(*r);
          }
        const auto series = series_of(sel);
        std::set<int> levels;
        std::map<int, const ErrorRow*> any_at;
        for (const auto* r : sel) {
          levels.insert(r->level);
          any_at[r->level] = r;
        }
        const std::string noise = sel.front()->noise;
        report::Table tab;
        tab.caption = "**" + family_caption(m.family) + "** (`" + m.label() + "`, vertex set " +
                      set + (noise != "none" ? ", noise " + noise : "") + ")";
        tab.columns = {"method"};
        for (int l : levels) tab.columns.push_back("level " + std::to_string(l));
        tab.columns.push_back("rate (h)");
        tab.columns.push_back("rate (halving)");
        std::vector<report::Cell> h_row{"*h (#verts)*"};
        for (int l : levels)
          h_row.push_back(report::Cell::number(
              any_at[l]->h, sci(any_at[l]->h) + " (" + std::to_string(any_at[l]->vertices) + ")"));
        h_row.push_back({});
        h_row.push_back({});
        tab.add(std::move(h_row));
        for (const auto& sr : series) {
          std::vector<report::Cell> row{sr.method};
          for (int l : levels) {
            auto it = sr.by_level.find(l);
            row.push_back(it == sr.by_level.end()
                              ? report::Cell("-")
                              : report::Cell::number(it->second->error, sci(it->second->error)));
          }
          const double rate = series_rate(sr), halving = series_halving_rate(sr);
          report::Cell rc = report::Cell::number(rate, two_decimals(rate));
          rc.strong = true;  // the rate the report leads with
          row.push_back(rc);
          row.push_back(report::Cell::number(halving, two_decimals(halving)));
          tab.add(std::move(row));
        }
        s.table(std::move(tab));
        const std::string base = panel.id + "_" + m.label() + (set != "all" ? "_" + set : "");
        // Two title lines: "Fig. 6 (left). [family]" and the rest of the caption.
        const size_t after_fig = panel.caption.rfind("Fig. ", 0) == 0 ? 5 : 0;
        const auto cut = panel.caption.find(". ", after_fig);
        report::Plot plot;
        plot.id = base;
        plot.title = cut == std::string::npos
                         ? panel.caption + " [" + m.label() + ", " + set + "]"
                         : panel.caption.substr(0, cut + 1) + " [" + m.label() + ", " + set +
                               "]\\n" + panel.caption.substr(cut + 2);
        plot.series = error_series(sel_rows);
        if (is_point_set_family(m.family)) plot.x_label = "nominal spacing h = sqrt(area / n)";
        if (options.plots) {
          if (options.stop && options.stop()) return false;
          if (!render_plot_files(plot, dir, base)) ++missing_plots;
        }
        s.plot(std::move(plot));
      }
    }
  }
  cause_tables(e, dir, s);
  return true;
}

}  // namespace

std::optional<ReportContent> build_report(const std::vector<Experiment>& experiments,
                                          const ReportOptions& options) {
  const std::string dir = options.results_dir;
  fs::create_directories(fs::path(dir) / "plots");
  ReportContent out;
  out.paper.push_back(table2_section(dir));
  out.paper.push_back(table4_section(dir));
  out.paper.push_back(well_shaped_torus_section(dir + "/torus_unstructured.csv"));
  out.paper.push_back(table5_section(dir));

  int missing_plots = 0;
  // The paper's figures first (`report paper`), then the extra studies.
  std::vector<const Experiment*> ordered;
  for (const auto& e : experiments) ordered.push_back(&e);
  std::stable_partition(ordered.begin(), ordered.end(),
                        [](const Experiment* e) { return e->report == ReportSection::paper; });
  for (const Experiment* e : ordered) {
    if (e->report == ReportSection::sweeps) continue;  // their own section (report/sweeps.h)
    report::Section s;
    if (!experiment_section(*e, options, missing_plots, s)) return std::nullopt;
    out.experiments.push_back(std::move(s));
  }
  report::Section field{"field-studies", "", {}};
  if (!field_sections(experiments, options, missing_plots, field)) return std::nullopt;
  out.studies.push_back(std::move(field));
  out.studies.push_back(radius_scaling_section(experiments, options));
  report::Section sweeps{"sweeps", "", {}};
  if (!sweeps_section(experiments, options, missing_plots, sweeps)) return std::nullopt;
  out.studies.push_back(std::move(sweeps));
  out.studies.push_back(point_cloud_section(experiments, dir));
  out.point_cloud_summary = point_cloud_summary(experiments, dir);
  if (missing_plots > 0)
    std::fprintf(stderr, "report: %d plots not rendered (is gnuplot installed?)\n", missing_plots);
  return out;
}

}  // namespace curvbench
