#include "harness/report/recommend.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <map>
#include <sstream>
#include <tuple>

#include "core/atomic_file.h"
#include "core/build_info.h"
#include "core/errors.h"
#include "core/text.h"
#include "harness/report/advice.h"
#include "mesh/mesh_checks.h"
#include "meshgen/generate.h"

namespace curvbench {

namespace {

// The one table of which family stands for which mesh quality.
struct QualityFamily {
  const char* family;
  const char* quality;
};
constexpr QualityFamily kQualityFamilies[] = {
    {"torus-unstructured", "well-shaped"},
    {"torus-iso-projected", "isosurface"},
    {"bump-irregular", "irregular"},
};

std::string sci(double x) {
  return scientific(x);
}

std::string seconds_text(double s) {
  if (!std::isfinite(s)) return "no timing";
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.3g s", s);
  return buf;
}

// The case's label as in the errors CSV, with "(1-ring)" for a fixed method and "(largest)" for
// a best radius at the largest radius swept (radius_text()).
std::string case_text(const BestRadius& b) {
  const std::string radius = radius_text(b);
  if (b.parameter.empty()) return "`" + b.label + "` (" + radius + ")";
  return "`" + b.label + "`" + (radius.ends_with(" (largest)") ? " (largest)" : "");
}

bool same_level(double a, double b) {
  return std::fabs(a - b) <= 1e-9 * std::fmax(1.0, b);
}

}  // namespace

const std::vector<std::string>& quality_classes() {
  static const std::vector<std::string> classes = [] {
    std::vector<std::string> out;
    for (const QualityFamily& q : kQualityFamilies) out.push_back(q.quality);
    return out;
  }();
  return classes;
}

std::string quality_of_family(const std::string& family) {
  for (const QualityFamily& q : kQualityFamilies)
    if (family == q.family) return q.quality;
  return "";
}

const std::vector<double>& recommendation_noise_levels() {
  static const std::vector<double> levels{0.0, 0.01, 0.03, 0.1};
  return levels;
}

double nearest_noise_level(double s) {
  double best = recommendation_noise_levels().front();
  for (double level : recommendation_noise_levels())
    if (std::fabs(level - s) < std::fabs(best - s)) best = level;
  return best;
}

std::vector<Recommendation> recommendations(const std::vector<ErrorRow>& rows,
                                            const std::vector<TimingRow>& timings) {
  std::map<std::tuple<std::string, std::string, int, std::string>, double> seconds;
  for (const TimingRow& t : timings)
    seconds.try_emplace({t.experiment, t.family, t.level, t.method}, t.seconds);
  auto time_of = [&](const ErrorRow& r) {
    const auto it = seconds.find({r.experiment, r.family, r.level, r.method});
    return it == seconds.end() ? std::nan("") : it->second;
  };
  std::vector<Recommendation> out;
  for (const std::string& quality : quality_classes())
    for (double level : recommendation_noise_levels()) {
      Recommendation rec;
      rec.quality = quality;
      rec.sigma_over_h = level;
      // The cell's rows: the first (experiment, level) seen with this quality and noise.
      std::vector<ErrorRow> cell;
      for (const ErrorRow& r : rows) {
        if (r.quantity != kRecommendQuantity || r.norm != kRecommendNorm ||
            quality_of_family(r.family) != quality ||
            !same_level(normal_noise_sigma(r.noise_level), level))
          continue;
        if (!cell.empty() &&
            (r.experiment != cell.front().experiment || r.level != cell.front().level))
          continue;
        cell.push_back(r);
      }
      const std::vector<BestRadius> best = best_radii(cell);
      const BestRadius* pick = nullptr;
      double pick_seconds = std::nan("");
      for (const BestRadius& b : best) {
        if (!std::isfinite(b.error)) continue;
        double s = std::nan("");
        for (const ErrorRow& r : cell)
          if (r.method == b.label) s = time_of(r);
        const bool faster = std::isfinite(s) && (!std::isfinite(pick_seconds) || s < pick_seconds);
        if (!pick || b.error < pick->error || (b.error == pick->error && faster)) {
          pick = &b;
          pick_seconds = s;
        }
      }
      if (!pick) {
        out.push_back(rec);
        continue;
      }
      rec.swept = true;
      rec.best = *pick;
      rec.best_seconds = pick_seconds;
      rec.cases = static_cast<int>(cell.size());
      for (const ErrorRow& r : cell) {
        const double s = time_of(r);
        if (!std::isfinite(r.error) || r.error > 2.0 * pick->error || !std::isfinite(s)) continue;
        if (rec.has_cheapest && (s > rec.cheapest_seconds ||
                                 (s == rec.cheapest_seconds && r.error >= rec.cheapest.error)))
          continue;
        BestRadius c = *pick;
        c.method = r.method_base;
        c.parameter = r.radius_parameter;
        c.radius = r.radius;
        c.label = r.method;
        c.error = r.error;
        c.radii = 1;  // no "(largest)": only the best radius of a method says so
        rec.cheapest = c;
        rec.cheapest_seconds = s;
        rec.has_cheapest = true;
      }
      out.push_back(rec);
    }
  return out;
}

void write_recommendations_csv(const std::string& path, const std::vector<Recommendation>& recs) {
  std::ostringstream out;
  out << provenance_comment() << "\n"
      << "quality,sigma_over_h,status,experiment,family,level,vertices,h,noise,quantity,norm,"
         "cases,best_method,best_parameter,best_radius,best_label,best_error,best_seconds,"
         "cheapest_method,cheapest_parameter,cheapest_radius,cheapest_label,cheapest_error,"
         "cheapest_seconds\n";
  auto pick = [&](const BestRadius& b, double s) {
    out << ',' << b.method << ',' << (b.parameter.empty() ? "fixed" : b.parameter) << ','
        << format_double(b.radius) << ',' << b.label << ',' << format_double(b.error) << ','
        << format_double(s);
  };
  for (const Recommendation& r : recs) {
    out << r.quality << ',' << format_g(r.sigma_over_h) << ',' << (r.swept ? "swept" : "not swept");
    if (!r.swept) {
      out << std::string(21, ',') << "\n";
      continue;
    }
    const BestRadius& b = r.best;
    out << ',' << b.experiment << ',' << b.family << ',' << b.level << ',' << b.vertices << ','
        << format_double(b.h) << ',' << b.noise << ',' << b.quantity << ',' << b.norm << ','
        << r.cases;
    pick(b, r.best_seconds);
    if (r.has_cheapest)
      pick(r.cheapest, r.cheapest_seconds);
    else
      out << std::string(6, ',');
    out << "\n";
  }
  write_file_atomic(path, out.str());
}

report::Section recommendations_section(const std::vector<Recommendation>& recs) {
  report::Section s{"choosing", "Choosing an estimator and a radius", {}};
  s.text(
      "From the radius sweeps above, per mesh quality (the family that stands for it: "
      "well-shaped `torus-unstructured`, isosurface `torus-iso-projected`, irregular "
      "`bump-irregular`) and noise along the normal (sigma as a multiple of the mean edge "
      "length h): the most accurate method and radius, ranked by the relative L2 error in the "
      "mean curvature H, and the fastest case (method and radius) whose error is within 2x of "
      "it, timed by the case's own estimation (`timings/<experiment>.csv`; one timing per case "
      "label and mesh, the same at every noise level). A noise level no sweep ran says \"not "
      "swept\" (`curvbench run --all --full` runs them all). Every cell names its case label as "
      "in `<experiment>.csv`; the rows are in `recommendations.csv`. `curvbench recommend "
      "MESH` falls back on the row that matches a mesh when it has no advice cases (the "
      "advice from mesh features: next section). The times are wall times of single cases, a "
      "few milliseconds each on these meshes, taken while other cases run: unlike the errors "
      "they vary from run to run, and so may the cheapest pick (`make bench` measures "
      "speed).");
  report::Table tab;
  tab.id = "choosing-table";
  tab.columns = {"mesh quality", "noise sigma/h", "most accurate: case",
                 "H L2 error",   "time",          "cheapest within 2x: case",
                 "H L2 error",   "time",          "source"};
  tab.numeric = {false, true, false, true, true, false, true, true, false};
  // A pick's three cells: its case, its error and its time.
  const auto pick = [](std::vector<report::Cell>& row, const BestRadius& b, double seconds) {
    row.push_back(case_text(b));
    row.push_back(report::Cell::number(b.error, sci(b.error)));
    row.push_back(report::Cell::number(seconds, seconds_text(seconds)));
  };
  for (const Recommendation& r : recs) {
    std::vector<report::Cell> row{r.quality,
                                  report::Cell::number(r.sigma_over_h, format_g(r.sigma_over_h))};
    if (!r.swept) {
      row.insert(row.end(), {"not swept", "", "", "not swept", "", "", ""});
      tab.add(std::move(row));
      continue;
    }
    pick(row, r.best, r.best_seconds);
    if (r.has_cheapest)
      pick(row, r.cheapest, r.cheapest_seconds);
    else
      row.insert(row.end(), {"no timed case", "", ""});
    row.push_back("`" + r.best.experiment + "`, `" + r.best.family + "` level " +
                  std::to_string(r.best.level) + ", noise " + r.best.noise + " (" +
                  std::to_string(r.cases) + " cases)");
    tab.add(std::move(row));
  }
  return s.table(std::move(tab));
}

MeshClass classify_mesh(const Mesh& mesh) {
  if (mesh.num_vertices() < kMinRecommendVertices)
    throw InputError("recommend: cannot classify a mesh of " + std::to_string(mesh.num_vertices()) +
                     " vertices (at least " + std::to_string(kMinRecommendVertices) + " needed)");
  const MeshChecks c = check_mesh(mesh);
  if (mesh.num_nonmanifold_edges() > 0 || c.nonmanifold_vertices > 0)
    throw InputError("recommend: cannot classify a non-manifold mesh (" +
                     std::to_string(mesh.num_nonmanifold_edges()) + " non-manifold edges, " +
                     std::to_string(c.nonmanifold_vertices) + " non-manifold vertices)");
  const MeshQuality q = mesh_quality(mesh);
  char stats[200];
  std::snprintf(stats, sizeof stats,
                "smallest angle %.1f deg, %.2f%% of the angles below 10 deg, interior valence "
                "%d..%d",
                q.min_angle_deg, 100.0 * q.small_angle_fraction, q.min_valence, q.max_valence);
  char rule[160];
  if (q.small_angle_fraction >= kIsosurfaceSmallAngleFraction) {
    std::snprintf(rule, sizeof rule, "at least %g%% of the angles below 10 deg",
                  100.0 * kIsosurfaceSmallAngleFraction);
    return {"isosurface", std::string(stats) + ": " + rule};
  }
  if (q.min_angle_deg >= kWellShapedMinAngle) {
    std::snprintf(rule, sizeof rule,
                  "fewer than %g%% of the angles below 10 deg and none below %g deg",
                  100.0 * kIsosurfaceSmallAngleFraction, kWellShapedMinAngle);
    return {"well-shaped", std::string(stats) + ": " + rule};
  }
  std::snprintf(rule, sizeof rule,
                "fewer than %g%% of the angles below 10 deg but some below %g deg",
                100.0 * kIsosurfaceSmallAngleFraction, kWellShapedMinAngle);
  return {"irregular", std::string(stats) + ": " + rule};
}

}  // namespace curvbench
