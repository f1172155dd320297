#include "harness/report/point_clouds.h"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <iterator>
#include <map>
#include <string>
#include <utility>
#include <vector>

#include "core/errors.h"
#include "harness/model/metrics.h"
#include "harness/model/results_table.h"
#include "meshgen/generate.h"

namespace curvbench {

namespace fs = std::filesystem;

namespace {

struct Measure {
  Quantity quantity;
  Norm norm;
  const char* caption;
};

constexpr Measure kMeasures[] = {
    {Quantity::H, Norm::L2, "Mean curvature, relative L2 error (the paper's)"},
    {Quantity::normal, Norm::angle_rms, "Normals, RMS angle in degrees (PCPNet's, unoriented)"},
    {Quantity::H, Norm::rectified, "Mean curvature, rectified error |dH| / max(|H|, 1)"},
};

std::string series_name(const RateRow& r) {
  std::string name = r.family.rfind("points-", 0) == 0 ? r.family.substr(7) : r.family;
  if (r.noise != "none") name += ", " + r.noise;
  return name;
}

// "1.2e-03 (2.95)": the finest level's error and the average rate; the value is the error.
report::Cell error_and_rate(const RateRow& r) {
  return report::Cell::number(r.e_last, scientific(r.e_last) + " (" + two_decimals(r.rate) + ")");
}

struct StudyRows {
  const Experiment* experiment = nullptr;
  std::vector<RateRow> rates;
};

std::vector<StudyRows> study_rows(const std::vector<Experiment>& experiments,
                                  const std::string& dir) {
  std::vector<StudyRows> out;
  for (const Experiment& e : experiments) {
    if (e.report != ReportSection::points) continue;
    const std::string csv = dir + "/" + e.name + ".csv";
    if (!fs::exists(csv)) continue;
    out.push_back({&e, compute_rates(read_error_csv(csv))});
  }
  return out;
}

// One table: estimators (rows, first-appearance order) by the experiment's point-set series
// (columns, in mesh-line order), for one measure; the least error of each column is marked.
report::Table rate_table(const StudyRows& s, const Measure& m) {
  std::vector<std::string> columns, methods;
  std::map<std::pair<std::string, std::string>, const RateRow*> cell_of;  // (method, column)
  for (const RateRow& r : s.rates) {
    if (r.quantity != to_string(m.quantity) || r.norm != to_string(m.norm) ||
        !is_point_set_family(r.family) || r.vertex_set != "all")
      continue;
    const std::string c = series_name(r);
    if (std::find(columns.begin(), columns.end(), c) == columns.end()) columns.push_back(c);
    if (std::find(methods.begin(), methods.end(), r.method) == methods.end())
      methods.push_back(r.method);
    cell_of.try_emplace({r.method, c}, &r);
  }
  report::Table t;
  t.caption = std::string("**") + m.caption + "**: the finest level's error (average rate)";
  t.columns = {"estimator"};
  for (const std::string& c : columns) t.columns.push_back(c);
  std::vector<double> best(columns.size(), INFINITY);
  for (const std::string& method : methods) {
    std::vector<report::Cell> row{method};
    for (size_t i = 0; i < columns.size(); ++i) {
      const auto it = cell_of.find({method, columns[i]});
      if (it == cell_of.end()) {
        row.push_back("-");
        continue;
      }
      row.push_back(error_and_rate(*it->second));
      if (std::isfinite(it->second->e_last)) best[i] = std::min(best[i], it->second->e_last);
    }
    t.add(std::move(row));
  }
  for (auto& row : t.rows)
    for (size_t i = 0; i < columns.size(); ++i) row[i + 1].best = row[i + 1].value == best[i];
  return t;
}

// The first `pairs` surfaces of kSideBySide as meshes and as points, per estimator: normals L2
// and H L2, finest error and rate, from the first experiment of the study that has both.
report::Table side_by_side(const std::vector<StudyRows>& study, size_t pairs) {
  report::Table t;
  t.caption =
      "**The same surfaces as meshes (the estimators' rings) and as uniform points (k nearest "
      "points)**: the finest level's error (average rate)";
  t.columns = {"surface", "estimator", "normals, mesh",  "normals, points",
               "H, mesh", "H, points", "H points / mesh"};
  for (size_t p = 0; p < pairs && p < std::size(kSideBySide); ++p) {
    const MeshAndPoints& pair = kSideBySide[p];
    for (const StudyRows& s : study) {
      const auto find = [&](const std::string& method, const char* family,
                            Quantity q) -> const RateRow* {
        for (const RateRow& r : s.rates)
          if (r.method == method && r.family == family && r.quantity == to_string(q) &&
              r.norm == "L2" && r.noise == "none" && r.vertex_set == "all")
            return &r;
        return nullptr;
      };
      std::vector<std::string> methods;
      for (const RateRow& r : s.rates)
        if (r.family == pair.mesh && find(r.method, pair.points, Quantity::H) != nullptr &&
            std::find(methods.begin(), methods.end(), r.method) == methods.end())
          methods.push_back(r.method);
      if (methods.empty()) continue;
      const auto cell = [](const RateRow* r) {
        return r == nullptr ? report::Cell("-") : error_and_rate(*r);
      };
      for (const std::string& method : methods) {
        const RateRow* h_mesh = find(method, pair.mesh, Quantity::H);
        const RateRow* h_points = find(method, pair.points, Quantity::H);
        const double ratio = h_mesh != nullptr ? h_points->e_last / h_mesh->e_last : NAN;
        t.add({std::string("`") + pair.mesh + "` / `" + pair.points + "`", method,
               cell(find(method, pair.mesh, Quantity::normal)),
               cell(find(method, pair.points, Quantity::normal)), cell(h_mesh), cell(h_points),
               report::Cell::number(ratio, std::isfinite(ratio) ? two_decimals(ratio) : "-")});
      }
      break;  // the first experiment that has both
    }
  }
  t.numeric = {false, false, true, true, true, true, true};
  return t;
}

const char* const kIntro =
    "The estimators that need no faces on the analytic surfaces sampled without connectivity "
    "(docs/point_sets.md): uniform random points, blue noise (Poisson disk), anisotropic "
    "density (4x denser along x) and scan-like stripes on the torus, and uniform points on the "
    "ellipsoid and the Gaussian bump; 1,000 to 64,000 points, the levels halving the nominal "
    "spacing h = sqrt(area / n). Each estimator takes its default neighbourhood, the k = 2 n(d) "
    "nearest points (12 for degree 2, 30 for degree 4). Rates are against h. The surface "
    "variation (PCL's `curvature`, lambda0 / (lambda0 + lambda1 + lambda2)) sits in the H "
    "column to show what it is: unitless and unsigned, it is not a curvature and its error "
    "does not fall. PCL's own numbers come through the outside-estimator route "
    "(experiments/examples/pcl_curvatures.cpp) where PCL is installed: its H column is the "
    "same surface variation, and on points its normals keep PCL's own orientation, towards a "
    "viewpoint at the origin, which inside a torus turns part of them inward (the L2 error of "
    "the normals counts those; the RMS angle, unoriented, does not). APSS's H is its fitted "
    "sphere's, an average of k1 and k2 weighted by the neighbourhood's second moments "
    "(docs/methods.md), so where k1 != k2 and the sampling is irregular it does not converge, "
    "with PCA or jet starting normals alike (experiment point-clouds-normals). On the "
    "scan-like stripes the k nearest points lie on one to three scan lines, so the fits across "
    "the lines are poorly determined.";

}  // namespace

bool is_point_set_family(const std::string& family) {
  try {
    return mesh_family(family).point_set;
  } catch (const UsageError&) {
    return false;  // a family of an older run or a registered one since removed
  }
}

report::Section point_cloud_section(const std::vector<Experiment>& experiments,
                                    const std::string& results_dir) {
  report::Section s{"point-cloud-study", "Point clouds", {}};
  const std::vector<StudyRows> study = study_rows(experiments, results_dir);
  if (study.empty()) {
    s.text("No point-cloud experiment (`report points`) has results in this folder.");
    return s;
  }
  s.text(kIntro);
  report::Table side = side_by_side(study, std::size(kSideBySide));
  if (!side.rows.empty()) {
    s.heading("Meshes and point sets side by side");
    s.table(std::move(side));
  }
  for (const StudyRows& r : study) {
    s.heading(r.experiment->title);
    s.text("Every family's errors by level and the plots: [report/" + r.experiment->name + ".md](" +
           r.experiment->name + ".md).");
    for (const Measure& m : kMeasures) {
      report::Table t = rate_table(r, m);
      if (!t.rows.empty()) s.table(std::move(t));
    }
  }
  return s;
}

report::Section point_cloud_summary(const std::vector<Experiment>& experiments,
                                    const std::string& results_dir) {
  report::Section s{"point-cloud-study", "Point clouds", {}};
  const std::vector<StudyRows> study = study_rows(experiments, results_dir);
  if (study.empty()) return s;
  s.text(
      "Estimators without connectivity on sampled analytic surfaces, against the spacing h; "
      "errors, rates and the noisy samples: "
      "[report/point-cloud-study.md](report/point-cloud-study.md).");
  report::Table side = side_by_side(study, 1);  // the torus; the others in the study's page
  if (!side.rows.empty()) s.table(std::move(side));
  report::Table rates = rate_table(study.front(), kMeasures[0]);
  if (!rates.rows.empty()) s.table(std::move(rates));
  return s;
}

}  // namespace curvbench
