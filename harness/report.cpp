#include "harness/report.h"

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
#include "harness/error_causes.h"
#include "harness/metrics.h"
#include "harness/paper_tables.h"
#include "harness/plot_styles.h"
#include "harness/report_field.h"
#include "harness/report_radius_scaling.h"
#include "harness/report_sweeps.h"
#include "harness/well_shaped_torus_table.h"
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

// The text of an optional input; empty when the file does not exist.
std::string read_text(const std::string& path) {
  return fs::exists(path) ? read_file(path) : "";
}

// Header then rows of a results CSV; empty when the file does not exist (not generated yet).
std::vector<std::vector<std::string>> read_simple_csv(const std::string& path) {
  if (!fs::exists(path)) return {};
  CsvTable t = read_csv_table(path);
  std::vector<std::vector<std::string>> out{std::move(t.header)};
  for (auto& row : t.rows) out.push_back(std::move(row));
  return out;
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

// The paper's rate, assuming each level halves h (harness/metrics.h).
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

bool render_plot(const std::string& base, const std::string& title,
                 const std::vector<ErrorRow>& rows, const PlotAxis& x_axis) {
  std::vector<const ErrorRow*> ptrs;
  for (const auto& r : rows) ptrs.push_back(&r);
  const auto series = series_of(ptrs);
  std::ostringstream gp;
  gp << "set logscale xy\nset format y '10^{%L}'\nset xlabel '" << x_axis.label << "'\n"
     << "set ylabel 'error'\nset key outside right top\nset grid\n"
     << (x_axis.reversed ? "set xrange [*:*] reverse\n" : "")
     // The bottom margin holds the x label and, below it, the provenance footer.
     << "set bmargin 5\n"
     << "set label 1 \"" << build_info() << ", " << utc_timestamp()
     << "\" at screen 0.01, screen 0.015 font ',8' noenhanced\n"
     << "set title \"" << title << "\" noenhanced\n";
  for (size_t i = 0; i < series.size(); ++i) {
    gp << "$S" << i << " << EOD\n";
    for (const auto& [level, r] : series[i].by_level)
      if (std::isfinite(r->error) && r->error > 0)
        gp << format_double(r->h) << ' ' << format_double(r->error) << "\n";
    gp << "EOD\n";
  }
  std::vector<std::string> labels;
  for (const auto& s : series) labels.push_back(s.method);
  const std::vector<PlotStyle> styles = plot_styles(labels);  // one look per method everywhere
  std::ostringstream plot;
  plot << "plot ";
  for (size_t i = 0; i < series.size(); ++i) {
    const double rate = series_rate(series[i]);
    plot << (i ? ", " : "") << "$S" << i << " using 1:2 with linespoints lw 2 ps 1.2 "
         << gnuplot_style(styles[i]) << " title \"" << series[i].method
         << (x_axis.rate_in_legend ? " (rate " + two_decimals(rate) + ")" : "") << "\" noenhanced";
  }
  // Dashed reference slopes O(h^p) for the orders the panel's rates round to (1-4), anchored at
  // half the largest error at the coarsest h.
  std::set<int> orders;
  double h0 = 0.0, e0 = 0.0;
  for (const auto& sr : series) {
    const double rate = series_rate(sr);
    if (std::isfinite(rate)) orders.insert(std::clamp(static_cast<int>(std::lround(rate)), 1, 4));
    for (const auto& [level, r] : sr.by_level)
      if (std::isfinite(r->error) && r->error > 0 && r->h >= h0) {
        e0 = r->h > h0 ? r->error : std::max(e0, r->error);
        h0 = r->h;
      }
  }
  if (x_axis.reference_slopes && h0 > 0 && e0 > 0)
    for (int p : orders)
      plot << ", " << format_double(0.5 * e0) << "*(x/" << format_double(h0) << ")**" << p
           << " with lines dt 2 lw 1 lc rgb '#808080' title 'O(h^" << p << ")'";
  plot << "\n";
  return run_gnuplot(base, gp.str(), plot.str());
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

std::string write_report(const std::vector<Experiment>& experiments, const ReportOptions& options) {
  const std::string dir = options.results_dir;
  fs::create_directories(fs::path(dir) / "plots");
  std::ostringstream md;
  md << "# curvbench results\n\n"
     << "Reproduction of the numerical experiments of Wang, Jiao et al., *An Analysis and "
        "Comparison of Parameterization-Based Computation of Differential Quantities for "
        "Discrete Surfaces* (CAGD 2009), §5.\n\n"
     << "Generated by " << build_info() << " on " << utc_timestamp()
     << ". Regenerate with `make experiments`; the paper's claims are checked in "
        "[CLAIMS.md](CLAIMS.md).\n\n"
     << "Errors (paper §5): normals are absolute (RMS = L2, max = Linf of |n~ - n|); "
        "curvatures are relative norm ratios |e|/|k|. Each table lists the error per mesh level "
        "and, at the end of the row, two average convergence rates: ours, log(e1/eN)/log(h1/hN) "
        "with the measured mean edge length h, and the paper's, (1/(N-1)) log2(e1/eN), which "
        "assumes that each level halves h. Xu-2 on open surfaces is scored over interior "
        "vertices only (paper §5.2).\n\n";

  // Table 2.
  const auto t2 = read_simple_csv(dir + "/table2.csv");
  if (t2.size() > 1) {
    md << "## Table 2. Numbers of coefficients in degree-d fittings versus numbers of points in "
          "typical (d+1)/2 rings\n\n"
       << "Interior vertex of a regular valence-6 mesh (the structured torus), centre included."
          "\n\n| degree (d) | ";
    for (size_t i = 1; i < t2.size(); ++i) md << t2[i][0] << " | ";
    md << "\n|---|";
    for (size_t i = 1; i < t2.size(); ++i) md << "---|";
    md << "\n| #coeffs. | ";
    for (size_t i = 1; i < t2.size(); ++i) md << t2[i][1] << " | ";
    md << "\n| ring | ";
    for (size_t i = 1; i < t2.size(); ++i) md << t2[i][2] << " | ";
    md << "\n| #points (ours) | ";
    for (size_t i = 1; i < t2.size(); ++i) md << t2[i][3] << " | ";
    md << "\n| #points (paper) | ";
    for (size_t i = 1; i < t2.size(); ++i) md << t2[i][4] << " | ";
    md << "\n\n";
  }

  // Table 4.
  const auto t4 = read_simple_csv(dir + "/table4.csv");
  if (t4.size() > 1) {
    md << "## Table 4. Input position errors of torus meshes extracted by marching cubes\n\n"
       << "Signed distance function of the torus (R = 1, r = 0.3) sampled at n points per axis "
          "on [-1.5, 1.5]^3, one vertex per sign-changing grid edge (docs/algorithms.md §10.1(a))."
          " The paper's \"average edge length\" column equals half the true mean edge length "
          "(see the last two columns).\n\n"
       << "| n | #verts (ours / paper) | L2 (ours / paper) | Linf (ours / paper) | rate L2 | "
          "rate Linf | mean edge length | its half / paper's column |\n"
       << "|---|---|---|---|---|---|---|---|\n";
    for (size_t i = 1; i < t4.size(); ++i) {
      const auto& r = t4[i];
      const double h = std::stod(r[2]), rms = std::stod(r[4]), mx = std::stod(r[5]);
      std::string rate_l2 = "-", rate_inf = "-";
      if (i > 1) {
        const auto& p = t4[i - 1];
        rate_l2 = two_decimals(std::log2(std::stod(p[4]) / rms));
        rate_inf = two_decimals(std::log2(std::stod(p[5]) / mx));
      }
      const paper::Table4Row* p = i - 1 < paper::kTable4.size() ? &paper::kTable4[i - 1] : nullptr;
      md << "| " << r[0] << "^3 | " << r[1] << " / " << (p ? std::to_string(p->vertices) : "-")
         << " | " << sci(rms) << " / " << (p ? paper_sci(p->l2) : "-") << " | " << sci(mx) << " / "
         << (p ? paper_sci(p->linf) : "-") << " | " << rate_l2 << " | " << rate_inf << " | "
         << sci(h, 3) << " | " << sci(0.5 * h, 2) << " / " << (p ? paper_g(p->edge_column) : "-")
         << " |\n";
    }
    md << "\n";
  }

  md << well_shaped_torus_markdown(dir + "/torus_unstructured.csv");

  // Table 5 (performance issue), if present.
  const std::string t5 = read_text(dir + "/table5_timing.md");
  if (!t5.empty()) md << t5 << "\n";

  // Figures.
  int missing_plots = 0;
  // The paper's figures first (experiments named fig...), then the extra studies.
  std::vector<const Experiment*> ordered;
  for (const auto& e : experiments) ordered.push_back(&e);
  std::stable_partition(ordered.begin(), ordered.end(),
                        [](const Experiment* e) { return e->name.rfind("fig", 0) == 0; });
  for (const Experiment* ep : ordered) {
    const Experiment& e = *ep;
    if (!e.sweep.empty()) continue;  // the sweeps' own section (report_sweeps.h)
    const std::string csv = dir + "/" + e.name + ".csv";
    if (!fs::exists(csv)) {
      md << "## " << e.title << " (" << e.name << ")\n\nNot run yet: " << csv << " is missing.\n\n";
      continue;
    }
    const auto rows = read_error_csv(csv);
    md << "## " << e.name << ": " << e.title
       << (e.section == "beyond" ? std::string(" (beyond the paper)")
                                 : std::string(" (paper §").append(e.section).append(")"))
       << "\n\n"
       << "Source: `" << experiment_source_name(e) << "`.\n\n"
       << outside_method_notes(e, dir);
    for (const auto& panel : e.panels) {
      md << "### " << panel.caption << "\n\n";
      for (const auto& m : e.meshes) {
        std::vector<const ErrorRow*> sel;
        std::vector<ErrorRow> sel_rows;
        for (const auto& r : rows)
          if (r.family == m.label() && r.quantity == to_string(panel.quantity) &&
              r.norm == to_string(panel.norm)) {
            sel.push_back(&r);
            sel_rows.push_back(r);
          }
        if (sel.empty()) continue;
        const auto series = series_of(sel);
        std::set<int> levels;
        std::map<int, const ErrorRow*> any_at;
        for (const auto* r : sel) {
          levels.insert(r->level);
          any_at[r->level] = r;
        }
        md << "**" << family_caption(m.family) << "** (`" << m.label() << "`, vertex set "
           << sel.front()->vertex_set << (sel.front()->noise != "none" ? ", noise " : "")
           << (sel.front()->noise != "none" ? sel.front()->noise : "") << ")\n\n| method |";
        for (int l : levels) md << " level " << l << " |";
        md << " rate (h) | rate (halving) |\n|---|";
        for (size_t i = 0; i <= levels.size() + 1; ++i) md << "---|";
        md << "\n| *h (#verts)* |";
        for (int l : levels) md << " " << sci(any_at[l]->h) << " (" << any_at[l]->vertices << ") |";
        md << " | |\n";
        for (const auto& s : series) {
          md << "| " << s.method << " |";
          for (int l : levels) {
            auto it = s.by_level.find(l);
            md << " " << (it == s.by_level.end() ? "-" : sci(it->second->error)) << " |";
          }
          md << " **" << two_decimals(series_rate(s)) << "** | "
             << two_decimals(series_halving_rate(s)) << " |\n";
        }
        const std::string base = panel.id + "_" + m.label();
        md << "\n";
        if (options.plots) {
          if (options.stop && options.stop()) return "";
          // Two title lines: "Fig. 6 (left). [family]" and the rest of the caption (gnuplot
          // turns \n inside a double-quoted title into a line break).
          const size_t after_fig = panel.caption.rfind("Fig. ", 0) == 0 ? 5 : 0;
          const auto cut = panel.caption.find(". ", after_fig);
          const std::string title = cut == std::string::npos
                                        ? panel.caption + " [" + m.label() + "]"
                                        : panel.caption.substr(0, cut + 1) + " [" + m.label() +
                                              "]\\n" + panel.caption.substr(cut + 2);
          if (render_plot(dir + "/plots/" + base, title, sel_rows))
            md << "![" << panel.id << " " << m.label() << "](plots/" << base << ".png) "
               << "([svg](plots/" << base << ".svg))\n\n";
          else
            ++missing_plots;
        }
      }
    }
    md << cause_tables_markdown(e, dir);
  }
  if (!append_field_estimators_section(md, experiments, options, missing_plots)) return "";
  append_radius_scaling_section(md, experiments, options);
  if (!append_sweeps_section(md, experiments, options, missing_plots)) return "";
  if (missing_plots > 0)
    std::fprintf(stderr, "report: %d plots not rendered (is gnuplot installed?)\n", missing_plots);
  const std::string path = dir + "/REPORT.md";
  write_file_atomic(path, md.str());
  return path;
}

}  // namespace curvbench
