#include "harness/report/radius_scaling.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <map>
#include <set>
#include <tuple>

#include "core/text.h"
#include "harness/model/metrics.h"

namespace curvbench {

namespace fs = std::filesystem;

RadiusScalingBounds radius_scaling_bounds(double alpha) {
  return {std::min(2.0 * alpha, 2.0 - alpha), std::min(alpha, 2.0 - 2.0 * alpha),
          std::min(2.0 * alpha, 2.0 - 2.0 * alpha)};
}

std::vector<RadiusScalingRate> radius_scaling_rates(const std::vector<ErrorRow>& rows,
                                                    double alpha) {
  // (family, method, quantity) -> level -> row, in the order first seen.
  std::map<std::tuple<std::string, std::string, std::string>, std::map<int, const ErrorRow*>>
      series;
  std::vector<std::tuple<std::string, std::string, std::string>> order;
  for (const ErrorRow& r : rows) {
    if (r.norm != "L2") continue;
    if (r.quantity != "normal" && r.quantity != "H" && r.quantity != "K") continue;
    // A method scored on another vertex set than all (Meyer and the normal cycle on the open
    // bump: interior vertices only) says so.
    const std::string method =
        r.vertex_set == "all" ? r.method : r.method + " (" + r.vertex_set + ")";
    const auto key = std::make_tuple(r.family, method, r.quantity);
    if (!series.count(key)) order.push_back(key);
    series[key][r.level] = &r;
  }
  std::vector<RadiusScalingRate> out;
  for (const auto& key : order) {
    const auto& by_level = series[key];
    if (by_level.size() < 2) continue;
    const ErrorRow& a = *by_level.begin()->second;
    const ErrorRow& b = *by_level.rbegin()->second;
    out.push_back({std::get<0>(key), std::get<1>(key), std::get<2>(key), alpha, a.level, b.level,
                   convergence_rate(a.error, b.error, a.h, b.h)});
  }
  return out;
}

namespace {

// A bound's cell: "*1.23*" (emphasis) with its number, or "n/a".
report::Cell emphasised(double x) {
  return std::isfinite(x)
             ? report::Cell::number(x, std::string("*").append(two_decimals(x)).append("*"))
             : report::Cell("n/a");
}

const char* quantity_heading(const std::string& q) {
  return q == "normal" ? "normals" : q == "H" ? "mean curvature H" : "Gaussian curvature K";
}

}  // namespace

report::Section radius_scaling_section(const std::vector<Experiment>& experiments,
                                       const ReportOptions& options) {
  report::Section s{"radius-scaling", "", {}};
  std::vector<RadiusScalingRate> rates;
  std::set<double> alphas;
  std::vector<std::string> sources;
  for (const Experiment& e : experiments) {
    if (!(e.radius_c > 0.0)) continue;
    const std::string csv = options.results_dir + "/" + e.name + ".csv";
    if (!fs::exists(csv)) continue;
    const auto r = radius_scaling_rates(read_error_csv(csv), e.radius_alpha);
    rates.insert(rates.end(), r.begin(), r.end());
    alphas.insert(e.radius_alpha);
    sources.push_back("`" + e.name + "` (alpha " + format_g(e.radius_alpha) + ", c " +
                      format_g(e.radius_c) + ")");
  }
  if (rates.empty()) return s;

  s.title = "Neighbourhoods that shrink more slowly than h";
  std::string intro =
      "Under O(h^2) input errors a fixed number of rings gives curvatures that do not converge; "
      "a radius c h^alpha with alpha < 1 trades the fit's truncation error against the input "
      "error (docs/algorithms.md §15). Experiments: ";
  for (size_t i = 0; i < sources.size(); ++i) intro += (i ? ", " : "") + sources[i];
  s.text(intro +
         "; their errors per level are in their sections above. Each cell is the L2 convergence "
         "rate log(e_first/e_last)/log(h_first/h_last) of a method over the levels it ran; the "
         "first rows are the rates the error bound predicts for a degree-2 fit, for curvatures "
         "with a general stencil and with the truncation's odd terms cancelling (symmetric "
         "stencils), for normals the one bound. The methods of a fixed 1-ring keep their "
         "1-ring at every alpha.");

  std::vector<std::string> families;
  for (const auto& r : rates)
    if (std::find(families.begin(), families.end(), r.family) == families.end())
      families.push_back(r.family);
  for (const std::string& family : families)
    for (const char* quantity : {"normal", "H", "K"}) {
      // The table's levels are those of its first series; a row over other levels (another
      // experiment, e.g. a diagnostic) names them.
      std::vector<std::string> methods;
      std::map<std::pair<std::string, double>, double> cell;
      std::string levels;
      for (const auto& r : rates) {
        if (r.family != family || r.quantity != quantity) continue;
        const std::string own = std::to_string(r.first_level) + "-" + std::to_string(r.last_level);
        if (levels.empty()) levels = own;
        const std::string name = own == levels ? r.method : r.method + " (levels " + own + ")";
        if (std::find(methods.begin(), methods.end(), name) == methods.end())
          methods.push_back(name);
        cell[{name, r.alpha}] = r.rate;
      }
      if (methods.empty()) continue;
      report::Table tab;
      tab.columns = {"rate"};
      for (double a : alphas) tab.columns.push_back("alpha = " + format_g(a));
      // One row: its first cell, then cell_of(alpha) per alpha.
      const auto row = [&](report::Cell first, auto&& cell_of) {
        std::vector<report::Cell> r{std::move(first)};
        for (double a : alphas) r.push_back(cell_of(a));
        tab.add(std::move(r));
      };
      const bool normals = std::string(quantity) == "normal";
      row(normals ? "*bound*" : "*bound, general stencil*", [&](double a) {
        const RadiusScalingBounds b = radius_scaling_bounds(a);
        return emphasised(normals ? b.normals : b.curvature);
      });
      if (!normals)
        row("*bound, odd terms cancel*",
            [](double a) { return emphasised(radius_scaling_bounds(a).curvature_symmetric); });
      for (const std::string& m : methods)
        row(m, [&](double a) {
          const auto it = cell.find({m, a});
          return it == cell.end() ? report::Cell("-")
                                  : report::Cell::number(it->second, two_decimals(it->second));
        });
      s.heading("`" + family + "`, " + quantity_heading(quantity) + " (levels " + levels + ")")
          .table(std::move(tab));
    }
  return s;
}

}  // namespace curvbench
