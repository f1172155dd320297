#include "harness/report/advice.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <map>
#include <sstream>

#include "core/atomic_file.h"
#include "core/build_info.h"
#include "core/errors.h"
#include "core/text.h"
#include "harness/model/noise_estimate.h"
#include "mesh/io.h"

namespace curvbench {

namespace {

bool same_level(double a, double b) {
  return std::fabs(a - b) <= 1e-9 * std::fmax(1.0, b);
}

// A swept mesh: the cases of one (experiment, family, level).
struct SweptMesh {
  std::string experiment, family;
  int level = 0;
  MeshFeatures features;
};

bool same_mesh(const AdviceCase& c, const SweptMesh& m) {
  return c.experiment == m.experiment && c.family == m.family && c.level == m.level;
}

std::vector<SweptMesh> swept_meshes(const std::vector<AdviceCase>& cases,
                                    const std::string& exclude_family) {
  std::vector<SweptMesh> out;
  for (const AdviceCase& c : cases) {
    if (c.family == exclude_family) continue;
    bool seen = false;
    for (const SweptMesh& m : out) seen = seen || same_mesh(c, m);
    if (!seen) out.push_back({c.experiment, c.family, c.level, c.features});
  }
  return out;
}

// The standard deviation of each advice feature's coordinate over the meshes, at least the floor.
std::vector<double> feature_scales(const std::vector<SweptMesh>& meshes) {
  std::vector<double> scales;
  for (const FeatureInfo& f : advice_features()) {
    double sum = 0.0, sum2 = 0.0;
    for (const SweptMesh& m : meshes) {
      const double x = feature_coordinate(f, m.features);
      sum += x;
      sum2 += x * x;
    }
    const double n = static_cast<double>(meshes.size());
    const double var = n > 0 ? std::fmax(0.0, sum2 / n - (sum / n) * (sum / n)) : 0.0;
    scales.push_back(std::fmax(std::sqrt(var), kFeatureScaleFloor));
  }
  return scales;
}

double feature_distance(const MeshFeatures& a, const MeshFeatures& b,
                        const std::vector<double>& scales) {
  double d2 = 0.0;
  for (size_t i = 0; i < advice_features().size(); ++i) {
    const FeatureInfo& f = advice_features()[i];
    const double d = (feature_coordinate(f, a) - feature_coordinate(f, b)) / scales[i];
    d2 += d * d;
  }
  return std::sqrt(d2);
}

// The noise in the quantity's unit, as a logarithm (advice.h, step 2).
double noise_coordinate(const std::string& quantity, double sigma_over_h, double size_over_h) {
  if (quantity == "normal") return std::log(std::fmax(sigma_over_h, kNormalNoiseFloor));
  return std::log(std::fmax(sigma_over_h * size_over_h, kCurvatureNoiseFloor));
}

// The errors of the cases of mesh m at noise level s for `quantity`, in the rows' order.
std::vector<const AdviceCase*> cell_cases(const std::vector<AdviceCase>& cases, const SweptMesh& m,
                                          double s, const std::string& quantity) {
  std::vector<const AdviceCase*> out;
  for (const AdviceCase& c : cases)
    if (same_mesh(c, m) && c.quantity == quantity && same_level(c.sigma_over_h, s))
      out.push_back(&c);
  return out;
}

const AdviceCase* best_of(const std::vector<const AdviceCase*>& cell) {
  const AdviceCase* best = nullptr;
  for (const AdviceCase* c : cell)
    if (std::isfinite(c->error) && c->error > 0 && (!best || c->error < best->error)) best = c;
  return best;
}

std::string share_text(double s) {
  if (!std::isfinite(s)) return "n/a";
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.0f%%", 100.0 * s);
  return buf;
}

constexpr const char* kCaseColumns[] = {"experiment", "family", "level", "vertices", "h"};
constexpr const char* kCaseTailColumns[] = {"size_over_h", "sigma_over_h", "quantity",
                                            "norm",        "label",        "error"};

}  // namespace

std::string regret_text(double r) {
  if (!std::isfinite(r)) return "n/a";
  char buf[32];
  std::snprintf(buf, sizeof buf, r < 1000 ? "%.2f" : "%.2g", r);
  return buf;
}

const std::vector<std::string>& advice_quantities() {
  return measured_quantities();
}

std::string advice_quantity_words(const std::string& quantity) {
  return quantity == "normal" ? "normals" : quantity == "H" ? "mean curvature H" : quantity;
}

double normal_noise_sigma(const NoiseLevel& noise) {
  if (noise.sigma_over_h == 0.0) return 0.0;
  return noise.model == noise_level(1, {}).model ? noise.sigma_over_h : std::nan("");
}

std::vector<AdviceCase> advice_cases(const std::vector<ErrorRow>& rows,
                                     const FeaturesOf& features_of) {
  std::map<std::pair<std::string, int>, MeshFeatures> features;
  std::vector<AdviceCase> out;
  for (const ErrorRow& r : rows) {
    const auto& q = advice_quantities();
    if (r.norm != kAdviceNorm || std::find(q.begin(), q.end(), r.quantity) == q.end()) continue;
    const double s = normal_noise_sigma(r.noise_level);
    if (std::isnan(s)) continue;
    auto f = features.find({r.family, r.level});
    if (f == features.end())
      f = features.emplace(std::make_pair(r.family, r.level), features_of(r.family, r.level)).first;
    AdviceCase c;
    c.experiment = r.experiment;
    c.family = r.family;
    c.level = r.level;
    c.vertices = r.vertices;
    c.h = r.h;
    c.features = f->second;
    c.sigma_over_h = s;
    c.quantity = r.quantity;
    c.label = r.method;
    c.error = r.error;
    out.push_back(std::move(c));
  }
  return out;
}

void write_advice_cases_csv(const std::string& path, const std::vector<AdviceCase>& cases) {
  std::ostringstream out;
  out << provenance_comment() << "\n";
  std::string header;
  for (const char* c : kCaseColumns) header += std::string(header.empty() ? "" : ",") + c;
  for (const FeatureInfo& f : advice_features()) header += std::string(",") + f.name;
  for (const char* c : kCaseTailColumns) header += std::string(",") + c;
  out << header << "\n";
  for (const AdviceCase& c : cases) {
    out << c.experiment << ',' << c.family << ',' << c.level << ',' << c.vertices << ','
        << format_double(c.h);
    for (const FeatureInfo& f : advice_features())
      out << ',' << format_double(c.features.*(f.field));
    out << ',' << format_double(c.features.size_over_h) << ',' << format_g(c.sigma_over_h) << ','
        << c.quantity << ',' << kAdviceNorm << ',' << c.label << ',' << format_double(c.error)
        << "\n";
  }
  write_file_atomic(path, out.str());
}

AdviceTable parse_advice_cases_csv(const std::string& text, const std::string& name) {
  AdviceTable table;
  table.name = name;
  if (text.rfind('#', 0) == 0) {
    std::string first = text.substr(0, text.find('\n'));
    if (!first.empty() && first.back() == '\r') first.pop_back();
    first.erase(0, first.find_first_not_of("# "));
    table.provenance = first;
  }
  const CsvTable t = parse_csv_table(text, name);
  const size_t ce = t.col("experiment"), cf = t.col("family"), cl = t.col("level"),
               cv = t.col("vertices"), ch = t.col("h"), csize = t.col("size_over_h"),
               cs = t.col("sigma_over_h"), cq = t.col("quantity"), cla = t.col("label"),
               cerr = t.col("error");
  std::vector<size_t> cfeat;
  for (const FeatureInfo& f : advice_features()) cfeat.push_back(t.col(f.name));
  const auto& quantities = advice_quantities();
  for (size_t i = 0; i < t.rows.size(); ++i) {
    AdviceCase c;
    c.experiment = t.text(i, ce);
    c.family = t.text(i, cf);
    c.level = t.integer(i, cl);
    c.vertices = t.integer(i, cv);
    c.h = t.number(i, ch);
    for (size_t k = 0; k < cfeat.size(); ++k)
      c.features.*(advice_features()[k].field) = t.number(i, cfeat[k]);
    c.features.size_over_h = t.number(i, csize);
    c.sigma_over_h = t.number(i, cs);
    c.quantity = t.text(i, cq);
    if (std::find(quantities.begin(), quantities.end(), c.quantity) == quantities.end())
      throw InputError(name + ":" + std::to_string(t.lines[i]) + ": quantity '" + c.quantity +
                       "' is not one the advice chooses for (normal, H)");
    c.label = t.text(i, cla);
    c.error = t.number(i, cerr);
    table.cases.push_back(std::move(c));
  }
  if (table.cases.empty())
    throw InputError(name + ": no cases (`make experiments` writes them from the radius sweeps)");
  return table;
}

AdviceTable read_advice_cases_csv(const std::string& results_dir) {
  const std::string path = (std::filesystem::path(results_dir) / "advice_cases.csv").string();
  std::error_code ec;
  if (!std::filesystem::is_regular_file(path, ec))
    throw InputError(path + ": not found (`make experiments` writes it into results/)");
  return parse_advice_cases_csv(read_file(path), path);
}

AdvicePick pick_advice(const std::vector<AdviceCase>& cases, const MeshFeatures& features,
                       double sigma_over_h, const std::string& quantity,
                       const std::string& exclude_family) {
  AdvicePick pick;
  pick.quantity = quantity;
  std::vector<SweptMesh> meshes = swept_meshes(cases, exclude_family);
  const std::vector<double> scales = feature_scales(meshes);
  // The meshes with cases of this quantity, nearest first (a tie keeps the rows' order).
  std::vector<std::pair<double, const SweptMesh*>> by_distance;
  for (const SweptMesh& m : meshes) {
    bool has = false;
    for (const AdviceCase& c : cases) has = has || (same_mesh(c, m) && c.quantity == quantity);
    if (has) by_distance.emplace_back(feature_distance(features, m.features, scales), &m);
  }
  std::stable_sort(by_distance.begin(), by_distance.end(),
                   [](const auto& a, const auto& b) { return a.first < b.first; });
  if (by_distance.size() > static_cast<size_t>(kAdviceNeighbours))
    by_distance.resize(kAdviceNeighbours);
  if (by_distance.empty()) return pick;

  const double target = noise_coordinate(quantity, sigma_over_h, features.size_over_h);
  std::vector<std::vector<const AdviceCase*>> cells;
  for (const auto& [distance, m] : by_distance) {
    // The mesh's noise levels, increasing; the nearest in the quantity's unit (a tie: the lower).
    std::vector<double> levels;
    for (const AdviceCase& c : cases)
      if (same_mesh(c, *m) && c.quantity == quantity &&
          std::none_of(levels.begin(), levels.end(),
                       [&](double l) { return same_level(l, c.sigma_over_h); }))
        levels.push_back(c.sigma_over_h);
    std::sort(levels.begin(), levels.end());
    double level = levels.front();
    for (double l : levels)
      if (std::fabs(noise_coordinate(quantity, l, m->features.size_over_h) - target) <
          std::fabs(noise_coordinate(quantity, level, m->features.size_over_h) - target))
        level = l;
    cells.push_back(cell_cases(cases, *m, level, quantity));
    AdviceNeighbour n;
    n.experiment = m->experiment;
    n.family = m->family;
    n.level = m->level;
    n.distance = distance;
    n.sigma_over_h = level;
    if (const AdviceCase* best = best_of(cells.back())) {
      n.best_label = best->label;
      n.best_error = best->error;
    }
    pick.neighbours.push_back(n);
  }
  // The candidates: the first neighbour's cases, in its rows' order.
  for (const AdviceCase* candidate : cells.front()) {
    double sum = 0.0;
    bool everywhere = true;
    for (size_t i = 0; i < cells.size() && everywhere; ++i) {
      const AdviceNeighbour& n = pick.neighbours[i];
      const AdviceCase* there = nullptr;
      for (const AdviceCase* c : cells[i])
        if (c->label == candidate->label) there = c;
      everywhere =
          there && std::isfinite(there->error) && there->error > 0 && std::isfinite(n.best_error);
      if (everywhere) sum += std::log(there->error / n.best_error);
    }
    if (!everywhere) continue;
    const double score = sum / static_cast<double>(cells.size());
    if (pick.found && score >= pick.mean_log_regret) continue;
    pick.found = true;
    pick.label = candidate->label;
    pick.mean_log_regret = score;
  }
  if (pick.found)
    for (size_t i = 0; i < cells.size(); ++i)
      for (const AdviceCase* c : cells[i])
        if (c->label == pick.label) pick.neighbours[i].error = c->error;
  return pick;
}

std::vector<FeatureOutOfRange> features_out_of_range(const std::vector<AdviceCase>& cases,
                                                     const MeshFeatures& features) {
  std::vector<FeatureOutOfRange> out;
  const std::vector<SweptMesh> meshes = swept_meshes(cases, "");
  if (meshes.empty()) return out;
  for (const FeatureInfo& f : advice_features()) {
    double lo = std::numeric_limits<double>::infinity(), hi = -lo;
    for (const SweptMesh& m : meshes) {
      lo = std::fmin(lo, m.features.*(f.field));
      hi = std::fmax(hi, m.features.*(f.field));
    }
    const double x = feature_coordinate(f, features);
    MeshFeatures lo_m, hi_m;
    lo_m.*(f.field) = lo;
    hi_m.*(f.field) = hi;
    if (x < feature_coordinate(f, lo_m) - kFeatureScaleFloor ||
        x > feature_coordinate(f, hi_m) + kFeatureScaleFloor)
      out.push_back({f.name, f.words, features.*(f.field), lo, hi});
  }
  return out;
}

std::vector<CrossValidationRow> cross_validate(const std::vector<AdviceCase>& cases) {
  std::vector<CrossValidationRow> out;
  for (const SweptMesh& m : swept_meshes(cases, "")) {
    std::vector<double> levels;
    for (const AdviceCase& c : cases)
      if (same_mesh(c, m) && std::none_of(levels.begin(), levels.end(),
                                          [&](double l) { return same_level(l, c.sigma_over_h); }))
        levels.push_back(c.sigma_over_h);
    for (double s : levels)
      for (const std::string& quantity : advice_quantities()) {
        const std::vector<const AdviceCase*> cell = cell_cases(cases, m, s, quantity);
        const AdviceCase* best = best_of(cell);
        if (!best) continue;
        CrossValidationRow r;
        r.family = m.family;
        r.level = m.level;
        r.sigma_over_h = s;
        r.quantity = quantity;
        r.best = best->label;
        r.best_error = best->error;
        const AdvicePick pick = pick_advice(cases, m.features, s, quantity, m.family);
        for (const AdviceNeighbour& n : pick.neighbours)
          r.neighbours += (r.neighbours.empty() ? "" : "; ") + n.family;
        if (pick.found) {
          r.advised = pick.label;
          for (const AdviceCase* c : cell)
            if (c->label == pick.label) r.advised_error = c->error;
          r.regret = r.advised_error / r.best_error;
        }
        out.push_back(std::move(r));
      }
  }
  return out;
}

bool RegretSummary::meets_goal() const {
  return cases > 0 && within_goal >= kRegretGoalShare && worst <= kRegretLimit;
}

RegretSummary summarize_regret(const std::vector<CrossValidationRow>& rows,
                               const std::string& quantity, double sigma_over_h,
                               const std::string& family) {
  std::vector<double> regrets;
  for (const CrossValidationRow& r : rows)
    if (r.quantity == quantity &&
        (std::isnan(sigma_over_h) || same_level(r.sigma_over_h, sigma_over_h)) &&
        (family.empty() || r.family == family) && std::isfinite(r.regret))
      regrets.push_back(r.regret);
  RegretSummary s;
  s.cases = static_cast<int>(regrets.size());
  if (regrets.empty()) return s;
  std::sort(regrets.begin(), regrets.end());
  const size_t n = regrets.size();
  s.median = n % 2 ? regrets[n / 2] : 0.5 * (regrets[n / 2 - 1] + regrets[n / 2]);
  s.worst = regrets.back();
  s.within_goal = static_cast<double>(std::count_if(regrets.begin(), regrets.end(),
                                                    [](double r) { return r <= kRegretGoal; })) /
                  static_cast<double>(n);
  return s;
}

void write_cross_validation_csv(const std::string& path,
                                const std::vector<CrossValidationRow>& rows) {
  std::ostringstream out;
  out << provenance_comment() << "\n"
      << "family,level,sigma_over_h,quantity,norm,advised,advised_error,best,best_error,regret,"
         "neighbours\n";
  for (const CrossValidationRow& r : rows)
    out << r.family << ',' << r.level << ',' << format_g(r.sigma_over_h) << ',' << r.quantity << ','
        << kAdviceNorm << ',' << r.advised << ',' << format_double(r.advised_error) << ',' << r.best
        << ',' << format_double(r.best_error) << ',' << format_double(r.regret) << ','
        << r.neighbours << "\n";
  write_file_atomic(path, out.str());
}

std::vector<MeasuredAdviceRow> measure_swept_advice(
    const std::vector<SweptNoisyMesh>& meshes, const std::vector<AdviceCase>& cases,
    const std::function<void(const SweptNoisyMesh&, size_t index)>& progress) {
  std::vector<MeasuredAdviceRow> out;
  for (size_t i = 0; i < meshes.size(); ++i) {
    const SweptNoisyMesh& m = meshes[i];
    if (progress) progress(m, i);
    // The candidates: the cases the sweep ran on this mesh with a true error in every quantity
    // measured, so that whichever is chosen is scored.
    std::map<std::pair<std::string, std::string>, double> error;  // (quantity, label)
    std::vector<std::string> labels;
    for (const AdviceCase& c : cases)
      if (c.family == m.family && c.level == m.level &&
          same_level(c.sigma_over_h, m.sigma_over_h)) {
        error[{c.quantity, c.label}] = c.error;
        labels.push_back(c.label);
      }
    std::erase_if(labels, [&](const std::string& l) {
      return std::any_of(measured_quantities().begin(), measured_quantities().end(),
                         [&](const std::string& q) {
                           return !error.count({q, l});
                         });
    });
    const std::vector<EstimatorChoice> candidates = distinct_estimator_choices(labels);
    if (candidates.empty()) continue;
    const Mesh mesh = generate_mesh(m.spec).mesh;
    MeasuredAdviceOptions o;
    o.sigma_over_h = estimate_noise(mesh).sigma_over_h;
    const MeasuredAdvice a = measure_advice(mesh, candidates, o);
    for (const MeasuredQuantity& q : a.quantities)
      for (size_t k = 0; k < q.cases.size(); ++k) {
        const auto e = error.find({q.quantity, q.cases[k].label});
        MeasuredAdviceRow r;
        r.family = m.family;
        r.level = m.level;
        r.sigma_over_h = m.sigma_over_h;
        r.estimated_sigma_over_h = a.sigma_over_h;
        r.quantity = q.quantity;
        r.label = q.cases[k].label;
        r.noise_part = q.cases[k].noise_part;
        r.bias_part = q.cases[k].bias_part;
        r.predicted = q.cases[k].predicted;
        r.error = e->second;
        r.chosen = static_cast<int>(k) == q.chosen;
        out.push_back(std::move(r));
      }
  }
  return out;
}

std::vector<CrossValidationRow> measured_regrets(const std::vector<MeasuredAdviceRow>& rows) {
  std::vector<CrossValidationRow> out;
  for (size_t i = 0; i < rows.size();) {
    size_t j = i + 1;  // rows of one mesh, noise level and quantity are consecutive
    while (j < rows.size() && rows[j].family == rows[i].family && rows[j].level == rows[i].level &&
           same_level(rows[j].sigma_over_h, rows[i].sigma_over_h) &&
           rows[j].quantity == rows[i].quantity)
      ++j;
    CrossValidationRow r;
    r.family = rows[i].family;
    r.level = rows[i].level;
    r.sigma_over_h = rows[i].sigma_over_h;
    r.quantity = rows[i].quantity;
    r.neighbours = "measured on the mesh";
    for (size_t k = i; k < j; ++k) {
      if (std::isfinite(rows[k].error) && (r.best.empty() || rows[k].error < r.best_error)) {
        r.best = rows[k].label;
        r.best_error = rows[k].error;
      }
      if (rows[k].chosen) {
        r.advised = rows[k].label;
        r.advised_error = rows[k].error;
      }
    }
    if (!r.advised.empty()) r.regret = r.advised_error / r.best_error;
    out.push_back(std::move(r));
    i = j;
  }
  return out;
}

void write_measured_advice_csv(const std::string& path,
                               const std::vector<MeasuredAdviceRow>& rows) {
  std::ostringstream out;
  out << provenance_comment() << "\n"
      << "family,level,sigma_over_h,estimated_sigma_over_h,quantity,norm,label,noise_part,"
         "bias_part,predicted,error,chosen\n";
  for (const MeasuredAdviceRow& r : rows)
    out << r.family << ',' << r.level << ',' << format_g(r.sigma_over_h) << ','
        << format_double(r.estimated_sigma_over_h) << ',' << r.quantity << ',' << kAdviceNorm << ','
        << r.label << ',' << format_double(r.noise_part) << ',' << format_double(r.bias_part) << ','
        << format_double(r.predicted) << ',' << format_double(r.error) << ',' << (r.chosen ? 1 : 0)
        << "\n";
  write_file_atomic(path, out.str());
}

std::vector<MeasuredAdviceRow> read_measured_advice_csv(const std::string& path) {
  const CsvTable t = read_csv_table(path);
  const size_t cf = t.col("family"), cl = t.col("level"), cs = t.col("sigma_over_h"),
               ce = t.col("estimated_sigma_over_h"), cq = t.col("quantity"), cb = t.col("label"),
               cn = t.col("noise_part"), cbp = t.col("bias_part"), cp = t.col("predicted"),
               cer = t.col("error"), cc = t.col("chosen");
  std::vector<MeasuredAdviceRow> rows;
  for (size_t i = 0; i < t.rows.size(); ++i) {
    MeasuredAdviceRow r;
    r.family = t.text(i, cf);
    r.level = t.integer(i, cl);
    r.sigma_over_h = t.number(i, cs);
    r.estimated_sigma_over_h = t.number(i, ce);
    r.quantity = t.text(i, cq);
    r.label = t.text(i, cb);
    r.noise_part = t.number(i, cn);
    r.bias_part = t.number(i, cbp);
    r.predicted = t.number(i, cp);
    r.error = t.number(i, cer);
    r.chosen = t.integer(i, cc) == 1;
    rows.push_back(std::move(r));
  }
  return rows;
}

std::vector<CrossValidationRow> read_cross_validation_csv(const std::string& path) {
  const CsvTable t = read_csv_table(path);
  const size_t cf = t.col("family"), cl = t.col("level"), cs = t.col("sigma_over_h"),
               cq = t.col("quantity"), ca = t.col("advised"), cae = t.col("advised_error"),
               cb = t.col("best"), cbe = t.col("best_error"), cr = t.col("regret"),
               cn = t.col("neighbours");
  std::vector<CrossValidationRow> rows;
  for (size_t i = 0; i < t.rows.size(); ++i) {
    CrossValidationRow r;
    r.family = t.text(i, cf);
    r.level = t.integer(i, cl);
    r.sigma_over_h = t.number(i, cs);
    r.quantity = t.text(i, cq);
    r.advised = t.text(i, ca);
    r.advised_error = t.number(i, cae);
    r.best = t.text(i, cb);
    r.best_error = t.number(i, cbe);
    r.regret = t.number(i, cr);
    r.neighbours = t.text(i, cn);
    rows.push_back(std::move(r));
  }
  return rows;
}

namespace {

// "LHF-4 rings=2, LHF-4 rings=3, LHF-4 rings=4".
std::string reference_ladder_text() {
  std::string t;
  for (const char* r : kMeasuredReferences) t += (t.empty() ? "" : ", ") + std::string(r);
  return t;
}

// Per quantity, a row per noise level and one for all: cases, median and worst regret, the share
// within 2x and the goal.
report::Table regret_summary_table(const std::string& id, const std::string& cases_column,
                                   const std::vector<CrossValidationRow>& rows,
                                   const std::vector<double>& levels) {
  report::Table sum;
  sum.id = id;
  sum.columns = {"quantity",     "noise sigma/h", cases_column, "median regret",
                 "worst regret", "within 2x",     "goal"};
  sum.numeric = {false, true, true, true, true, true, false};
  for (const std::string& q : advice_quantities()) {
    auto add = [&](double level, const std::string& level_text) {
      const RegretSummary r = summarize_regret(rows, q, level);
      if (r.cases == 0) return;
      sum.add({advice_quantity_words(q), report::Cell::number(level, level_text),
               report::Cell::number(r.cases, std::to_string(r.cases)),
               report::Cell::number(r.median, regret_text(r.median)),
               report::Cell::number(r.worst, regret_text(r.worst)),
               report::Cell::number(r.within_goal, share_text(r.within_goal)),
               r.meets_goal() ? "met" : "missed"});
    };
    for (double l : levels) add(l, format_g(l));
    add(std::nan(""), "all");
  }
  return sum;
}

}  // namespace

report::Section cross_validation_section(const std::vector<CrossValidationRow>& rows,
                                         const std::vector<CrossValidationRow>& measured) {
  report::Section s{"advice-cross-validation", "Advice on meshes it never saw", {}};
  std::vector<std::string> families;
  std::vector<double> levels;
  for (const std::vector<CrossValidationRow>* set : {&rows, &measured})
    for (const CrossValidationRow& r : *set) {
      if (std::find(families.begin(), families.end(), r.family) == families.end())
        families.push_back(r.family);
      if (std::none_of(levels.begin(), levels.end(),
                       [&](double l) { return same_level(l, r.sigma_over_h); }))
        levels.push_back(r.sigma_over_h);
    }
  std::sort(levels.begin(), levels.end());
  char goal[200];
  std::snprintf(goal, sizeof goal,
                "within %gx of the best in at least %g%% of the held-out cases and never worse "
                "than %gx",
                kRegretGoal, 100.0 * kRegretGoalShare, kRegretLimit);
  s.text(
      "Leave-one-family-out cross-validation of `curvbench recommend`'s advice "
      "(docs/advice.md): for each family of the radius sweeps and each noise level, the "
      "advice is learned from the other families only (the " +
      std::to_string(kAdviceNeighbours) +
      " swept meshes nearest in the mesh features, the noise level nearest in the quantity's "
      "unit), followed on the held-out mesh, and scored by its regret: the L2 error of the "
      "advised case over the least L2 error of all cases on that mesh (1 = the best choice). "
      "Normals and the mean curvature H are advised separately. The goal: " +
      std::string(goal) + ". Rows: `advice_cross_validation.csv`; the cases: `advice_cases.csv`.");
  if (rows.empty()) return s.text("No radius sweep with the advice's quantities ran.");

  s.table(regret_summary_table("advice-regret-summary", "held-out cases", rows, levels));
  if (!measured.empty()) {
    s.text(
        "Measured on the mesh (`curvbench recommend --measure`; docs/advice.md): each held-out "
        "mesh's own noise estimated, every case run on it and on it perturbed " +
        std::to_string(kMeasuredPerturbations) + " times by that noise along the normals of " +
        std::string(kMeasuredReferences[0]) +
        "; a case's error predicted as the root of the sum of squares of the change the "
        "perturbations cause (the noise part) and of its distance to a reference, less the "
        "noise in that distance (the bias part); the reference is the rung of " +
        reference_ladder_text() +
        " of least predicted error against the first; the least "
        "prediction advised. It learns nothing from the other families. Rows: "
        "`advice_measured.csv`.");
    s.table(regret_summary_table("advice-measured-summary", "meshes", measured, levels));
  }

  report::Table tab;
  tab.id = "advice-regret-table";
  tab.sortable = true;
  tab.columns = {"held-out family", "noise sigma/h", "normals: advised", "regret",
                 "H: advised",      "regret",        "H: best",          "neighbours (H)"};
  tab.numeric = {false, true, false, true, false, true, false, false};
  if (!measured.empty()) {
    tab.columns.insert(tab.columns.end(), {"H: measured", "regret"});
    tab.numeric.insert(tab.numeric.end(), {false, true});
  }
  for (const std::string& f : families)
    for (double l : levels) {
      const CrossValidationRow* by_q[2] = {nullptr, nullptr};
      for (const CrossValidationRow& r : rows)
        if (r.family == f && same_level(r.sigma_over_h, l))
          for (size_t k = 0; k < 2; ++k)
            if (r.quantity == advice_quantities()[k]) by_q[k] = &r;
      if (!by_q[0] && !by_q[1]) continue;
      std::vector<report::Cell> row{f, report::Cell::number(l, format_g(l))};
      for (const CrossValidationRow* r : by_q) {
        if (!r) {
          row.insert(row.end(), {"", ""});
          continue;
        }
        row.push_back(r->advised.empty() ? "none" : "`" + r->advised + "`");
        row.push_back(report::Cell::number(r->regret, regret_text(r->regret)));
      }
      row.push_back(by_q[1] ? "`" + by_q[1]->best + "`" : "");
      row.push_back(by_q[1] ? by_q[1]->neighbours : "");
      if (!measured.empty()) {
        const CrossValidationRow* mh = nullptr;
        for (const CrossValidationRow& r : measured)
          if (r.family == f && same_level(r.sigma_over_h, l) && r.quantity == "H") mh = &r;
        row.push_back(mh && !mh->advised.empty() ? "`" + mh->advised + "`" : "");
        row.push_back(mh ? report::Cell::number(mh->regret, regret_text(mh->regret))
                         : report::Cell(""));
      }
      tab.add(std::move(row));
    }
  return s.table(std::move(tab));
}

std::optional<report::Section> cross_validation_section_of(const std::string& results_dir) {
  const std::string validation = results_dir + "/advice_cross_validation.csv";
  const std::string measured = results_dir + "/advice_measured.csv";
  if (!std::filesystem::exists(validation)) return std::nullopt;
  return cross_validation_section(read_cross_validation_csv(validation),
                                  std::filesystem::exists(measured)
                                      ? measured_regrets(read_measured_advice_csv(measured))
                                      : std::vector<CrossValidationRow>{});
}

}  // namespace curvbench
