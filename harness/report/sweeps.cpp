#include "harness/report/sweeps.h"

#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <map>
#include <set>
#include <tuple>

#include "core/atomic_file.h"
#include "core/build_info.h"
#include "core/text.h"
#include "harness/model/metrics.h"
#include "harness/report/advice.h"
#include "harness/report/plot_styles.h"
#include "harness/report/recommend.h"
#include "meshgen/generate.h"
#include "methods/estimator.h"

namespace curvbench {

namespace fs = std::filesystem;

namespace {

// The registered methods whose neighbourhood size `option` sets (radius_option of their
// registry line's NeighbourhoodSize), by display name: "LHF, LOP, ..., Quadric".
std::string methods_sized_by(const std::string& option) {
  std::string out;
  for (const MethodInfo& m : method_table()) {
    if (radius_option(m.radius) != option) continue;
    out += (out.empty() ? "" : ", ") + display_name(m);
  }
  return out.empty() ? "none" : out;
}

// The radius options of a plot in words: "rings", "rings; ball factor C".
std::string radius_words(const std::set<std::string>& parameters) {
  std::string out;
  for (const std::string& p : parameters)
    out += (out.empty() ? "" : "; ") + (p == "ball-factor" ? std::string("ball factor C") : p);
  return out;
}

constexpr Quantity kQuantities[] = {Quantity::normal, Quantity::H, Quantity::K};

// [A-Za-z0-9.-] kept, anything else '_' (plot file names).
std::string file_safe(const std::string& s) {
  std::string out;
  for (char c : s)
    out += (std::isalnum(static_cast<unsigned char>(c)) || c == '.' || c == '-') ? c : '_';
  return out;
}

std::string quantity_words(Quantity q) {
  switch (q) {
    case Quantity::normal:
      return "normals";
    case Quantity::H:
      return "mean curvature H";
    default:
      return "Gaussian curvature K";
  }
}

// A sweep plot of the L2 error (log y) against `x_label`; rendered to plots/<file_safe(base)>
// .{png,svg} with options.plots. False if options.stop asked to stop.
bool sweep_plot(report::Section& out, report::Plot plot, const std::string& base,
                const ReportOptions& options, int& missing_plots) {
  plot.id = file_safe(base);
  plot.y_label = "L2 error";
  plot.reverse_x = false;
  if (options.plots) {
    if (options.stop && options.stop()) return false;
    if (!render_plot_files(plot, options.results_dir, plot.id)) ++missing_plots;
  }
  out.plot(std::move(plot));
  return true;
}

// A series in the look of its method (plot_styles.h).
report::Series styled_series(const std::string& label, const PlotStyle& style) {
  report::Series se;
  se.label = label;
  se.color = style.colour;
  se.marker = style.marker;
  se.dash = style.dash;
  return se;
}

// The rows of one experiment's CSV, or none when it has not been run.
std::vector<ErrorRow> rows_of(const Experiment& e, const std::string& dir) {
  const std::string csv = dir + "/" + e.name + ".csv";
  return fs::exists(csv) ? read_error_csv(csv) : std::vector<ErrorRow>{};
}

// Values in first-seen order.
template <class F>
std::vector<std::string> distinct(const std::vector<ErrorRow>& rows, F&& key) {
  std::vector<std::string> out;
  std::set<std::string> seen;
  for (const ErrorRow& r : rows)
    if (seen.insert(key(r)).second) out.push_back(key(r));
  return out;
}

// The radius sweep of one experiment: tables and plots per (family, noise).
bool radius_sweep(report::Section& out, const Experiment& e, const std::vector<ErrorRow>& rows,
                  const std::vector<BestRadius>& best, const ReportOptions& options,
                  int& missing_plots) {
  for (const std::string& family : distinct(rows, [](const ErrorRow& r) { return r.family; }))
    for (const std::string& noise : distinct(rows, [](const ErrorRow& r) { return r.noise; })) {
      std::vector<const ErrorRow*> sel;
      for (const ErrorRow& r : rows)
        if (r.family == family && r.noise == noise && r.norm == "L2") sel.push_back(&r);
      if (sel.empty()) continue;
      out.heading("`" + family + "` level " + std::to_string(sel.front()->level) + " (" +
                      std::to_string(sel.front()->vertices) +
                      " vertices, h = " + scientific(sel.front()->h) + "), noise " + noise,
                  2);
      report::Table tab;
      tab.columns = {"method", "radius swept"};
      tab.numeric = {false, false};
      for (Quantity q : kQuantities) {
        tab.columns.push_back(std::string("best for ") + to_string(q));
        tab.columns.push_back("L2 error");
        tab.numeric.insert(tab.numeric.end(), {false, true});
      }
      std::vector<std::string> methods;
      for (const BestRadius& b : best)
        if (b.experiment == e.name && b.family == family && b.noise == noise &&
            std::find(methods.begin(), methods.end(), b.method) == methods.end())
          methods.push_back(b.method);
      for (const std::string& method : methods) {
        std::string swept = "-";
        std::vector<report::Cell> cells;
        for (Quantity q : kQuantities) {
          const BestRadius* found = nullptr;
          for (const BestRadius& b : best)
            if (b.experiment == e.name && b.family == family && b.noise == noise &&
                b.method == method && b.quantity == to_string(q) && b.norm == "L2")
              found = &b;
          if (found && !found->parameter.empty())
            swept = found->parameter + " (" + std::to_string(found->radii) + " values)";
          if (!found) {
            cells.insert(cells.end(), {"-", "-"});
            continue;
          }
          cells.push_back(report::Cell::number(found->radius, radius_text(*found)));
          cells.push_back(report::Cell::number(found->error, scientific(found->error)));
        }
        std::vector<report::Cell> row{method, swept};
        row.insert(row.end(), cells.begin(), cells.end());
        tab.add(std::move(row));
      }
      out.table(std::move(tab));
      for (Quantity q : kQuantities) {
        // Swept methods: (radius, error) in radius order; fixed ones: their error.
        std::map<std::string, std::map<double, double>> curves;
        std::vector<std::string> order;
        std::vector<std::pair<std::string, double>> fixed;
        double lowest = INFINITY, highest = -INFINITY;  // the radii swept
        std::set<std::string> parameters;               // the radius options swept
        for (const ErrorRow* r : sel) {
          if (r->quantity != to_string(q) || !std::isfinite(r->error) || r->error <= 0) continue;
          if (r->radius_parameter.empty()) {
            fixed.push_back({r->method_base, r->error});
            continue;
          }
          if (!curves.count(r->method_base)) order.push_back(r->method_base);
          parameters.insert(r->radius_parameter);
          curves[r->method_base][r->radius] = r->error;
          lowest = std::min(lowest, r->radius);
          highest = std::max(highest, r->radius);
        }
        if (order.empty() && fixed.empty()) continue;  // a quantity no panel asked for
        if (order.empty()) lowest = highest = 1.0;     // fixed methods only: their 1-ring
        // One look per method (plot_styles.h), the swept curves first, then the fixed lines.
        std::vector<std::string> labels = order;
        for (const auto& f : fixed) labels.push_back(f.first);
        const std::vector<PlotStyle> styles = plot_styles(labels);
        report::Plot plot;
        plot.title = "L2 error in " + quantity_words(q) + " against the radius [" + family +
                     ", noise " + noise + "]";
        plot.x_label = "radius / h (" + radius_words(parameters) + ")";
        plot.log_x = false;
        for (size_t i = 0; i < order.size(); ++i) {
          report::Series se = styled_series(order[i], styles[i]);
          for (const auto& [x, y] : curves[order[i]])
            se.points.push_back({x, y, order[i] + ", radius " + format_g(x)});
          plot.series.push_back(std::move(se));
        }
        for (size_t i = 0; i < fixed.size(); ++i) {
          // A horizontal line over the radii swept: the method's colour, dotted.
          report::Series se = styled_series(fixed[i].first + " (1-ring)", styles[order.size() + i]);
          se.marker = 0;
          se.dash = 3;
          se.points = {{lowest, fixed[i].second, fixed[i].first + " (1-ring)"},
                       {highest, fixed[i].second, fixed[i].first + " (1-ring)"}};
          plot.series.push_back(std::move(se));
        }
        report::Series circles;  // each curve's best radius, circled
        circles.label = "best radius";
        circles.color = "#000000";
        circles.marker = 6;
        circles.points_only = true;
        for (const BestRadius& b : best)
          if (b.experiment == e.name && b.family == family && b.noise == noise &&
              b.quantity == to_string(q) && b.norm == "L2" && !b.parameter.empty() && b.error > 0)
            circles.points.push_back({b.radius, b.error, "best radius of " + b.method});
        plot.series.push_back(std::move(circles));
        if (!sweep_plot(out, std::move(plot),
                        e.name + "_" + family + "_" + noise + "_" + to_string(q), options,
                        missing_plots))
          return false;
      }
    }
  return true;
}

// The noise sweep of one experiment: per family, the outlier table and one plot per (quantity,
// model) against sigma/h.
bool noise_sweep(report::Section& out, const Experiment& e, const std::vector<ErrorRow>& rows,
                 const ReportOptions& options, int& missing_plots) {
  for (const std::string& family : distinct(rows, [](const ErrorRow& r) { return r.family; })) {
    std::vector<ErrorRow> fam;
    for (const ErrorRow& r : rows)
      if (r.family == family && r.norm == "L2") fam.push_back(r);
    if (fam.empty()) continue;
    out.heading("`" + family + "` level " + std::to_string(fam.front().level) + " (" +
                    std::to_string(fam.front().vertices) +
                    " vertices, h = " + scientific(fam.front().h) + ")",
                2);
    const auto methods = distinct(fam, [](const ErrorRow& r) { return r.method; });
    // Outliers: methods x (none, each outlier label), per quantity.
    std::vector<std::string> columns{"none"};
    for (const std::string& n : distinct(fam, [](const ErrorRow& r) { return r.noise; }))
      if (n.rfind("outliers", 0) == 0) columns.push_back(n);
    std::map<std::tuple<std::string, std::string, std::string>, double> err;
    for (const ErrorRow& r : fam) err[{r.method, r.noise, r.quantity}] = r.error;
    if (columns.size() > 1) {
      report::Table tab;
      tab.caption =
          "L2 errors without noise and with outliers (a fraction of the vertices moved by 3h "
          "along the normal):";
      tab.columns = {"method"};
      for (Quantity q : kQuantities)
        for (const std::string& c : columns)
          tab.columns.push_back(std::string(to_string(q)) + ", " + c);
      for (const std::string& m : methods) {
        std::vector<report::Cell> row{m};
        for (Quantity q : kQuantities)
          for (const std::string& c : columns) {
            const auto it = err.find({m, c, to_string(q)});
            row.push_back(it == err.end()
                              ? report::Cell("-")
                              : report::Cell::number(it->second, scientific(it->second)));
          }
        tab.add(std::move(row));
      }
      out.table(std::move(tab));
    }
    std::vector<std::string> models;
    for (const ErrorRow& r : fam)
      if (const std::string& m = r.noise_level.model;
          !m.empty() && std::find(models.begin(), models.end(), m) == models.end())
        models.push_back(m);
    const std::vector<PlotStyle> styles = plot_styles(methods);  // one look per method
    for (Quantity q : kQuantities)
      for (const std::string& model : models) {
        report::Plot plot;
        plot.title = "L2 error in " + quantity_words(q) + ", " + model + " noise [" + family + "]";
        plot.x_label = "noise amplitude sigma / h";
        for (size_t i = 0; i < methods.size(); ++i) {
          std::map<double, double> curve;
          for (const ErrorRow& r : fam)
            if (r.method == methods[i] && r.quantity == to_string(q) &&
                r.noise_level.model == model && std::isfinite(r.error) && r.error > 0)
              curve[r.noise_level.sigma_over_h] = r.error;
          if (curve.empty()) continue;
          report::Series se = styled_series(methods[i], styles[i]);
          for (const auto& [x, y] : curve)
            se.points.push_back({x, y, methods[i] + ", sigma/h " + format_g(x)});
          plot.series.push_back(std::move(se));
        }
        if (plot.series.empty()) continue;  // a quantity no panel asked for
        if (!sweep_plot(out, std::move(plot),
                        e.name + "_" + family + "_" + model + "_" + to_string(q), options,
                        missing_plots))
          return false;
      }
  }
  return true;
}

}  // namespace

std::string radius_text(const BestRadius& b) {
  if (b.parameter.empty()) return "1-ring";
  std::string s = b.parameter == "rings" ? "rings " : "C = ";
  s += format_g(b.radius);
  if (b.radii > 1 && b.radius == b.highest) s += " (largest)";
  return s;
}

std::vector<BestRadius> best_radii(const std::vector<ErrorRow>& rows) {
  using Key =
      std::tuple<std::string, std::string, int, std::string, std::string, std::string, std::string>;
  std::map<Key, size_t> index;
  std::vector<BestRadius> out;
  for (const ErrorRow& r : rows) {
    const Key key{r.experiment, r.family, r.level, r.noise, r.method_base, r.quantity, r.norm};
    auto [it, inserted] = index.try_emplace(key, out.size());
    if (inserted) {
      BestRadius b;
      b.experiment = r.experiment;
      b.family = r.family;
      b.level = r.level;
      b.vertices = r.vertices;
      b.h = r.h;
      b.noise = r.noise;
      b.noise_level = r.noise_level;
      b.method = r.method_base;
      b.parameter = r.radius_parameter;
      b.radius = r.radius;
      b.label = r.method;
      b.quantity = r.quantity;
      b.norm = r.norm;
      b.error = r.error;
      b.radii = 1;
      b.lowest = b.highest = r.radius;
      out.push_back(b);
      continue;
    }
    BestRadius& b = out[it->second];
    ++b.radii;
    b.lowest = std::fmin(b.lowest, r.radius);
    b.highest = std::fmax(b.highest, r.radius);
    const bool better = std::isfinite(r.error) && (!std::isfinite(b.error) || r.error < b.error ||
                                                   (r.error == b.error && r.radius < b.radius));
    if (better) {
      b.parameter = r.radius_parameter;
      b.radius = r.radius;
      b.label = r.method;
      b.error = r.error;
    }
  }
  return out;
}

void write_best_radius_csv(const std::string& path, const std::vector<BestRadius>& rows) {
  std::ostringstream out;
  out << provenance_comment() << "\n"
      << "experiment,family,level,vertices,h,noise,sigma_over_h,method,parameter,best_radius,label,"
         "quantity,norm,error,radii,lowest_radius,highest_radius\n";
  for (const BestRadius& b : rows)
    out << b.experiment << ',' << b.family << ',' << b.level << ',' << b.vertices << ','
        << format_double(b.h) << ',' << b.noise << ',' << format_double(b.noise_level.sigma_over_h)
        << ',' << b.method << ',' << (b.parameter.empty() ? "fixed" : b.parameter) << ','
        << format_double(b.radius) << ',' << b.label << ',' << b.quantity << ',' << b.norm << ','
        << format_double(b.error) << ',' << b.radii << ',' << format_double(b.lowest) << ','
        << format_double(b.highest) << "\n";
  write_file_atomic(path, out.str());
}

bool sweeps_section(const std::vector<Experiment>& experiments, const ReportOptions& options,
                    int& missing_plots, report::Section& out) {
  const std::string dir = options.results_dir;
  bool header = false;
  std::vector<BestRadius> all_best;
  std::vector<ErrorRow> radius_rows;  // the recommendations' input
  std::vector<TimingRow> timings;
  std::map<std::string, ExperimentMesh> swept_meshes;  // by the results' family label
  std::vector<SweptNoisyMesh> noisy_meshes;            // the advice measured on the mesh reads
  bool any_radius = false;
  // The radius sweeps first (the noise sweeps use their best radii), then the noise sweeps.
  std::vector<const Experiment*> sweeps;
  for (const char* kind : {"radius", "noise"})
    for (const Experiment& e : experiments)
      if (e.sweep == kind) sweeps.push_back(&e);
  for (const Experiment* ep : sweeps) {
    const Experiment& e = *ep;
    const std::vector<ErrorRow> rows = rows_of(e, dir);
    if (rows.empty()) continue;
    if (!header) {
      out.title = "Sweeps at a fixed mesh";
      out.text(
          "One mesh level per family; the neighbourhood radius or the noise varies "
          "(experiments with `sweep radius` or `sweep noise`; `curvbench run --all --full` runs "
          "the full sweeps of `experiments/sweeps/` in place of the trimmed ones). Errors are "
          "L2: normals absolute, curvatures relative (as above). Radii are in units of the mean "
          "edge length h: rings for " +
          methods_sized_by("rings") + ", the ball factor C (ball of radius C h) for " +
          methods_sized_by("ball-factor") +
          " (their registry lines' neighbourhood size); a fit asked for fewer rings than its "
          "degree needs "
          "grows by half rings until it has enough points (paper §4.1), so its smallest radii "
          "are lower bounds. Noise: sigma = (sigma/h) h, Gaussian or centred uniform (same "
          "standard deviation), along the exact normal, isotropic, or tangential (vertices "
          "stay on the surface); outliers: a fraction of the vertices moved by 3h along the "
          "normal (meshgen/noise.h).");
      header = true;
    }
    out.heading(e.name + ": " + e.title).text("Source: `" + experiment_source_name(e) + "`.");
    if (e.sweep == "radius") {
      const std::vector<BestRadius> best = best_radii(rows);
      all_best.insert(all_best.end(), best.begin(), best.end());
      radius_rows.insert(radius_rows.end(), rows.begin(), rows.end());
      for (const ExperimentMesh& m : e.meshes) {
        swept_meshes.try_emplace(m.label(), m);
        const int order = e.noise_order_of(m);
        const double sigma = normal_noise_sigma(noise_level(order, e.noise_model_of(m)));
        if (std::isnan(sigma)) continue;
        for (int level : m.levels)
          noisy_meshes.push_back({m.label(), level, sigma, e.mesh_spec(m, level)});
      }
      const std::string timing_csv = dir + "/timings/" + e.name + ".csv";
      if (fs::exists(timing_csv))
        for (const TimingRow& t : read_timing_csv(timing_csv)) timings.push_back(t);
      any_radius = true;
      out.text(
          "Best radius: the radius of the smallest L2 error of each method (circled in the "
          "plots; every method's rows in `best_radius.csv`).");
      if (!radius_sweep(out, e, rows, best, options, missing_plots)) return false;
    } else {
      if (!noise_sweep(out, e, rows, options, missing_plots)) return false;
    }
  }
  if (any_radius) {
    if (options.write_tables) write_best_radius_csv(dir + "/best_radius.csv", all_best);
    const std::vector<Recommendation> recs = recommendations(radius_rows, timings);
    // The recommendations follow as a part of this section, under a heading of its level.
    report::Section choosing = recommendations_section(recs);
    out.heading(choosing.title, 0);
    for (report::Block& b : choosing.blocks) out.blocks.push_back(std::move(b));
    if (options.write_tables) write_recommendations_csv(dir + "/recommendations.csv", recs);
    // The advice from mesh features and its leave-one-family-out cross-validation (advice.h),
    // the features measured on the swept meshes without noise (a label no mesh line gives is
    // read as a family name with its default options).
    const auto features_of = [&](const std::string& label, int level) {
      MeshSpec spec;
      spec.family = label;
      spec.level = level;
      if (const auto it = swept_meshes.find(label); it != swept_meshes.end()) {
        spec.family = it->second.family;
        spec.shape = it->second.shape;
      }
      return measure_mesh_features(generate_mesh(spec).mesh);
    };
    const std::vector<AdviceCase> cases = advice_cases(radius_rows, features_of);
    const std::vector<CrossValidationRow> validation = cross_validate(cases);
    // The advice measured on each swept mesh (computed with the tables; a render-only report
    // reads the last one's CSV).
    std::vector<MeasuredAdviceRow> measured;
    const std::string measured_csv = dir + "/advice_measured.csv";
    if (options.write_tables) {
      const auto t0 = std::chrono::steady_clock::now();
      std::fprintf(stderr, "curvbench: measuring the advice on %zu swept meshes...\n",
                   noisy_meshes.size());
      measured = measure_swept_advice(noisy_meshes, cases, [&](const SweptNoisyMesh& m, size_t i) {
        std::fprintf(stderr, "[advice] %zu/%zu %s level %d sigma/h %s\n", i + 1,
                     noisy_meshes.size(), m.family.c_str(), m.level,
                     format_g(m.sigma_over_h).c_str());
      });
      std::fprintf(stderr, "curvbench: advice measured in %.0f s\n",
                   std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count());
    } else if (fs::exists(measured_csv)) {
      measured = read_measured_advice_csv(measured_csv);
    }
    report::Section held_out = cross_validation_section(validation, measured_regrets(measured));
    out.heading(held_out.title, 0);
    for (report::Block& b : held_out.blocks) out.blocks.push_back(std::move(b));
    if (options.write_tables) {
      write_advice_cases_csv(dir + "/advice_cases.csv", cases);
      write_cross_validation_csv(dir + "/advice_cross_validation.csv", validation);
      write_measured_advice_csv(measured_csv, measured);
    }
  }
  return true;
}

}  // namespace curvbench
