#include "harness/report/leaderboard.h"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <map>
#include <set>
#include <sstream>

#include "core/build_info.h"
#include "harness/model/metrics.h"
#include "methods/estimator.h"

namespace curvbench {

namespace fs = std::filesystem;

namespace {

bool is_torus_grid(const std::string& f) {
  return f == "torus-unstructured" || f == "torus-structured" || f == "torus-jittered";
}
bool is_bump(const std::string& f) {
  return f == "bump-irregular" || f == "bump-48";
}

}  // namespace

const std::vector<MeshClassRule>& mesh_classes() {
  static const std::vector<MeshClassRule> table = {
      {"well-shaped", "well-shaped",
       [](ReportSection e, const std::string& f, const std::string& n, const std::string& v) {
         return e != ReportSection::hard && is_torus_grid(f) && n == "none" && v == "all";
       }},
      {"isosurface", "isosurface",
       [](ReportSection e, const std::string& f, const std::string& n, const std::string& v) {
         return e != ReportSection::hard && f == "torus-iso-projected" && n == "none" && v == "all";
       }},
      {"irregular", "irregular / 4-8",
       [](ReportSection e, const std::string& f, const std::string& n, const std::string& v) {
         return e != ReportSection::hard && is_bump(f) && n == "none" && v == "all";
       }},
      {"boundary-ring", "boundary ring",
       [](ReportSection, const std::string&, const std::string& n, const std::string& v) {
         return n == "none" && v == "boundary-ring";
       }},
      // The unprojected isosurface torus has O(h^2) position errors (Table 4).
      {"noisy-h2", "noisy O(h^2)",
       [](ReportSection, const std::string&, const std::string& n, const std::string& v) {
         return (n == "h^2" || n == "isosurface") && v == "all";
       }},
      {"noisy-h3", "noisy O(h^3)",
       [](ReportSection, const std::string&, const std::string& n, const std::string& v) {
         return n == "h^3" && v == "all";
       }},
      {"hard", "hard meshes",
       [](ReportSection e, const std::string&, const std::string& n, const std::string& v) {
         return e == ReportSection::hard && n == "none" && v == "all";
       }},
  };
  return table;
}

bool feeds_leaderboard(const Experiment& e) {
  return e.report == ReportSection::paper || e.report == ReportSection::field ||
         e.report == ReportSection::hard;
}

std::vector<LeaderRow> leaderboard_rows(const std::vector<Experiment>& experiments,
                                        const std::string& results_dir) {
  // One series per (method, family, noise, vertex set, quantity, norm): the first experiment
  // that has it (the same case in two experiments gives the same numbers).
  struct SeriesKey {
    std::string method, family, noise, set, quantity, norm;
    auto operator<=>(const SeriesKey&) const = default;
  };
  struct SeriesData {
    std::string experiment;
    ReportSection section = ReportSection::extra;
    std::map<int, ErrorRow> by_level;
  };
  std::map<SeriesKey, SeriesData> series;
  std::vector<std::string> method_order;
  std::map<std::tuple<std::string, std::string, int, std::string>, double> us;  // e,f,l,m
  for (const Experiment& e : experiments) {
    if (!feeds_leaderboard(e)) continue;
    const std::string csv = results_dir + "/" + e.name + ".csv";
    if (!fs::exists(csv)) continue;
    for (ErrorRow& r : read_error_csv(csv)) {
      SeriesKey k{r.method, r.family, r.noise, r.vertex_set, r.quantity, r.norm};
      auto [it, inserted] = series.try_emplace(k, SeriesData{e.name, e.report, {}});
      if (!inserted && it->second.experiment != e.name) continue;
      if (std::find(method_order.begin(), method_order.end(), r.method) == method_order.end())
        method_order.push_back(r.method);
      it->second.by_level[r.level] = std::move(r);
    }
    const std::string timings = results_dir + "/timings/" + e.name + ".csv";
    if (fs::exists(timings))
      for (const TimingRow& t : read_timing_csv(timings))
        if (t.vertices > 0 && std::isfinite(t.seconds))
          us[{e.name, t.family, t.level, t.method}] = 1e6 * t.seconds / t.vertices;
  }
  // A method scored on the interior vertices only (paper §5.2: Xu-2, and the operators undefined
  // at a boundary) stands in the class with its interior series, its mesh marked "(interior)".
  for (auto it = series.begin(); it != series.end();) {
    SeriesKey all = it->first;
    if (all.set != "interior") {
      ++it;
      continue;
    }
    all.set = "all";
    if (series.count(all)) {
      ++it;
      continue;
    }
    SeriesData moved = std::move(it->second);
    it = series.erase(it);
    all.family += "(interior)";
    series.emplace(all, std::move(moved));
  }
  struct Cell {
    double error = -INFINITY, rate = INFINITY, us = std::nan("");
    int largest = -1, finest = 0;
    std::set<std::string> meshes;  // each once, sorted (a family may run at several noises)
    std::string experiment;
  };
  std::map<std::tuple<std::string, std::string, std::string, std::string>, Cell> cells;
  for (const auto& [k, s] : series) {
    if (s.by_level.size() < 2) continue;
    const MeshClassRule* cls = nullptr;
    const std::string family = k.family.substr(0, k.family.find("(interior)"));
    for (const MeshClassRule& c : mesh_classes())
      if (c.member(s.section, family, k.noise, k.set)) {
        cls = &c;
        break;
      }
    if (cls == nullptr) continue;
    const ErrorRow& first = s.by_level.begin()->second;
    const ErrorRow& last = s.by_level.rbegin()->second;
    const double rate = convergence_rate(first.error, last.error, first.h, last.h);
    Cell& c = cells[{k.method, cls->id, k.quantity, k.norm}];
    const double err = std::isfinite(last.error) ? last.error : INFINITY;
    if (err > c.error) {
      c.error = err;
      c.experiment = s.experiment;
      c.finest = last.level;
    }
    c.rate = std::isfinite(rate) ? std::min(c.rate, rate) : std::nan("");
    c.meshes.insert(k.family);
    if (last.vertices > c.largest) {
      c.largest = last.vertices;
      const auto t = us.find({s.experiment, family, last.level, k.method});
      c.us = t == us.end() ? std::nan("") : t->second;
    }
  }
  std::vector<LeaderRow> out;
  for (const std::string& m : method_order)
    for (const MeshClassRule& cls : mesh_classes())
      for (const char* q : {"normal", "H", "K", "k1", "k2", "d1"})
        for (const char* n : {"L2", "Linf"}) {
          const auto it = cells.find({m, cls.id, q, n});
          if (it == cells.end()) continue;
          const Cell& c = it->second;
          std::string meshes;
          for (const auto& w : c.meshes) meshes += (meshes.empty() ? "" : " ") + w;
          out.push_back({m, to_string(method_group(m)), cls.id, q, n, c.error, c.rate, c.us, meshes,
                         c.experiment, c.finest});
        }
  return out;
}

void write_leaderboard_csv(const std::string& path, const std::vector<LeaderRow>& rows) {
  std::ostringstream out;
  out << provenance_comment() << "\n"
      << "method,group,mesh_class,quantity,norm,error,rate,us_per_vertex,meshes,experiment,"
         "finest_level\n";
  for (const LeaderRow& r : rows)
    out << r.method << ',' << r.group << ',' << r.mesh_class << ',' << r.quantity << ',' << r.norm
        << ',' << format_double(r.error) << ',' << format_double(r.rate) << ','
        << format_double(r.us_per_vertex) << ',' << r.meshes << ',' << r.experiment << ','
        << r.finest_level << "\n";
  write_file_atomic(path, out.str());
}

std::vector<LeaderRow> read_leaderboard_csv(const std::string& path) {
  const CsvTable t = read_csv_table(path);
  const size_t cm = t.col("method"), cg = t.col("group"), cc = t.col("mesh_class"),
               cq = t.col("quantity"), cn = t.col("norm"), ce = t.col("error"), cr = t.col("rate"),
               cu = t.col("us_per_vertex"), cs = t.col("meshes"), cx = t.col("experiment"),
               cl = t.col("finest_level");
  std::vector<LeaderRow> out;
  for (size_t i = 0; i < t.rows.size(); ++i)
    out.push_back({t.text(i, cm), t.text(i, cg), t.text(i, cc), t.text(i, cq), t.text(i, cn),
                   t.number(i, ce), t.number(i, cr), t.number(i, cu), t.text(i, cs), t.text(i, cx),
                   t.integer(i, cl)});
  return out;
}

}  // namespace curvbench
