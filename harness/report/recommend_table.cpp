#include "harness/report/recommend_table.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <memory>

#include <dlfcn.h>
#include <sys/auxv.h>

#include "core/errors.h"
#include "core/text.h"
#include "harness/model/results_table.h"
#include "harness/report/sweeps.h"
#include "mesh/io.h"
#include "mesh/orientation.h"
#include "methods/estimator.h"
#include "methods/option_schema.h"

namespace curvbench {

namespace {

bool same_level(double a, double b) {
  return std::fabs(a - b) <= 1e-9 * std::fmax(1.0, b);
}

std::string seconds_text(double s) {
  if (!std::isfinite(s)) return "no timing";
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.3g s", s);
  return buf;
}

// The columns the advice reads; the others (best_method, ...) are the same facts spelled out.
constexpr const char* kColumns[] = {
    "quality",        "sigma_over_h",    "status",       "experiment",
    "family",         "level",           "vertices",     "h",
    "noise",          "quantity",        "norm",         "cases",
    "best_label",     "best_error",      "best_seconds", "cheapest_label",
    "cheapest_error", "cheapest_seconds"};

}  // namespace

RecommendationTable parse_recommendations_csv(const std::string& text, const std::string& name) {
  RecommendationTable table;
  table.name = name;
  // The provenance: the first line, when it is a comment.
  if (text.rfind('#', 0) == 0) {
    std::string first = text.substr(0, text.find('\n'));
    if (!first.empty() && first.back() == '\r') first.pop_back();
    first.erase(0, first.find_first_not_of("# "));
    table.provenance = first;
  }
  const CsvTable t = parse_csv_table(text, name);
  table.header = t.header;
  std::vector<size_t> c;
  for (const char* column : kColumns) {
    bool found = false;
    for (size_t i = 0; i < t.header.size() && !found; ++i)
      if (t.header[i] == column) {
        c.push_back(i);
        found = true;
      }
    if (!found)
      throw InputError(name + ": no column '" + column +
                       "' (not a recommendations.csv of this curvbench)");
  }
  const auto& classes = quality_classes();
  const auto& levels = recommendation_noise_levels();
  for (size_t i = 0; i < t.rows.size(); ++i) {
    const std::string where = name + ":" + std::to_string(t.lines[i]);
    RecommendationRow r;
    r.line = t.lines[i];
    r.fields = t.rows[i];
    r.quality = t.text(i, c[0]);
    bool known = false;
    std::string names;
    for (const std::string& q : classes) {
      known = known || q == r.quality;
      names += (names.empty() ? "" : ", ") + q;
    }
    if (!known) throw InputError(where + ": quality '" + r.quality + "' is not one of " + names);
    r.sigma_over_h = t.number(i, c[1]);
    bool level = false;
    for (double l : levels) level = level || same_level(r.sigma_over_h, l);
    if (!level)
      throw InputError(where + ": sigma_over_h " + t.text(i, c[1]) +
                       " is not a noise level of the table (0, 0.01, 0.03, 0.1)");
    for (const RecommendationRow& other : table.rows)
      if (other.quality == r.quality && same_level(other.sigma_over_h, r.sigma_over_h))
        throw InputError(where + ": a second row for quality " + r.quality + " at sigma/h " +
                         format_g(r.sigma_over_h) + " (the first is line " +
                         std::to_string(other.line) + ")");
    const std::string& status = t.text(i, c[2]);
    if (status != "swept" && status != "not swept")
      throw InputError(where + ": status '" + status + "' is neither 'swept' nor 'not swept'");
    r.swept = status == "swept";
    if (r.swept) {
      r.experiment = t.text(i, c[3]);
      r.family = t.text(i, c[4]);
      r.level = t.integer(i, c[5]);
      r.vertices = t.integer(i, c[6]);
      r.h = t.number(i, c[7]);
      r.noise = t.text(i, c[8]);
      r.quantity = t.text(i, c[9]);
      r.norm = t.text(i, c[10]);
      r.cases = t.integer(i, c[11]);
      r.best_label = t.text(i, c[12]);
      r.best_error = t.number(i, c[13]);
      r.best_seconds = t.number(i, c[14]);
      r.cheapest_label = t.text(i, c[15]);
      if (!r.cheapest_label.empty()) {
        r.cheapest_error = t.number(i, c[16]);
        r.cheapest_seconds = t.number(i, c[17]);
      }
      for (const std::string* label : {&r.best_label, &r.cheapest_label}) {
        if (label->empty() && label == &r.cheapest_label) continue;
        try {
          (void)estimator_choice(*label);
        } catch (const UsageError& e) {
          throw InputError(where + ": case '" + *label +
                           "' is no estimator curvbench estimate runs (" + e.what() + ")");
        }
      }
    }
    table.rows.push_back(std::move(r));
  }
  for (const std::string& q : classes)
    for (double l : levels) {
      bool found = false;
      for (const RecommendationRow& r : table.rows)
        found = found || (r.quality == q && same_level(r.sigma_over_h, l));
      if (!found)
        throw InputError(name + ": no row for quality " + q + " at sigma/h " + format_g(l) +
                         " (a truncated table? `make experiments` writes a whole one)");
    }
  return table;
}

RecommendationTable read_recommendations_csv(const std::string& results_dir) {
  const std::string path = (std::filesystem::path(results_dir) / "recommendations.csv").string();
  std::error_code ec;
  if (!std::filesystem::is_regular_file(path, ec))
    throw InputError(path + ": not found (`make experiments` writes it into results/)");
  return parse_recommendations_csv(read_file(path), path);
}

std::vector<std::string> recommendations_search_paths() {
  namespace fs = std::filesystem;
  // The file of the code running this function: the executable it is linked into (curvbench),
  // or the shared object (libcurvbench.so, the Python module).
  static const int anchor = 0;
  Dl_info self{}, main_program{};
  fs::path object;
  std::error_code ec;
  if (dladdr(&anchor, &self) != 0 && self.dli_fname != nullptr) {
    const bool in_main =
        dladdr(reinterpret_cast<const void*>(getauxval(AT_PHDR)), &main_program) != 0 &&
        main_program.dli_fbase == self.dli_fbase;
    object = in_main ? fs::read_symlink("/proc/self/exe", ec) : fs::absolute(self.dli_fname, ec);
    if (ec) object.clear();
  }
  std::vector<std::string> paths;
  if (!object.empty()) {
    fs::path dir = fs::weakly_canonical(object, ec).parent_path();
    for (int up = 0; up < 3 && !dir.empty(); ++up, dir = dir.parent_path()) {
      paths.push_back((dir.parent_path() / "share" / "curvbench" / "recommendations.csv").string());
      if (dir == dir.root_path()) break;
    }
  }
  paths.push_back(std::string(CURVBENCH_SOURCE_RESULTS) + "/recommendations.csv");
  return paths;
}

std::string default_recommendations_path() {
  std::error_code ec;
  for (const std::string& p : recommendations_search_paths())
    if (std::filesystem::is_regular_file(p, ec)) return p;
  return "";
}

RecommendationTable default_recommendations() {
  const std::string path = default_recommendations_path();
  if (path.empty()) {
    std::string looked;
    for (const std::string& p : recommendations_search_paths())
      looked += (looked.empty() ? "" : ", ") + p;
    throw InputError("no recommendations.csv found (looked in " + looked + "); give --results DIR");
  }
  return parse_recommendations_csv(read_file(path), path);
}

std::string recommendations_provenance(const std::string& path) {
  std::ifstream in(path);
  std::string first;
  if (!std::getline(in, first) || first.rfind('#', 0) != 0) return "";
  if (!first.empty() && first.back() == '\r') first.pop_back();
  first.erase(0, first.find_first_not_of("# "));
  return first;
}

std::optional<AdviceTable> advice_cases_beside(const std::string& table_path) {
  const std::filesystem::path dir = std::filesystem::path(table_path).parent_path();
  std::error_code ec;
  if (!std::filesystem::is_regular_file(dir / "advice_cases.csv", ec)) return std::nullopt;
  return read_advice_cases_csv(dir.empty() ? "." : dir.string());
}

void measure_on_mesh(Advice& a, const Mesh& mesh, const AdviceTable* cases, int threads) {
  if (!cases)
    throw InputError("measure: no advice_cases.csv beside " + a.table +
                     " (the candidates it measures; `make experiments` writes it)");
  MeasuredRecommendation m;
  std::vector<std::string> labels;
  for (const AdviceCase& c : cases->cases) labels.push_back(c.label);
  try {
    m.candidates = distinct_estimator_choices(labels);
  } catch (const UsageError& e) {
    throw InputError(cases->name + ": a case is no estimator curvbench estimate runs (" + e.what() +
                     ")");
  }
  MeasuredAdviceOptions o;
  o.sigma_over_h = a.sigma_over_h;
  o.threads = threads;
  o.left_out = a.crease_vertex_ids;  // no smooth-surface curvature to be right about there
  m.advice = measure_advice(orient_mesh(mesh).mesh, m.candidates, o);
  for (const MeasuredQuantity& q : m.advice.quantities)
    if (q.chosen < 0)
      throw InputError(mesh.source() + ": no case gave a finite " +
                       advice_quantity_words(q.quantity) +
                       " on this mesh to measure the advice with");
  const std::filesystem::path measured_csv =
      std::filesystem::path(cases->name).parent_path() / "advice_measured.csv";
  std::vector<CrossValidationRow> regrets;
  std::error_code ec;
  if (std::filesystem::is_regular_file(measured_csv, ec))
    regrets = measured_regrets(read_measured_advice_csv(measured_csv.string()));
  for (const std::string& q : measured_quantities())
    m.validated.push_back(summarize_regret(regrets, q));
  // The curvature's measured choice replaces the learned one; no swept mesh stands behind it.
  const MeasuredQuantity& curvature = m.advice.quantities.back();
  a.choice = m.candidates[static_cast<size_t>(curvature.chosen)];
  a.has_choice = true;
  a.label = a.choice.label;
  a.quantity = curvature.quantity;
  a.error = curvature.cases[static_cast<size_t>(curvature.chosen)].predicted;
  a.experiment = "measured on the mesh";
  a.family.clear();
  a.level = 0;
  a.measured = std::move(m);
  a.has_measured = true;
}

bool Advice::choices_differ() const {
  if (quantities.size() < 2 || !quantities[0].pick.found || !quantities[1].pick.found) return false;
  return quantities[0].pick.label != quantities[1].pick.label;
}

namespace {

// The pick for a quantity with what cross-validation measured on the meshes it read.
QuantityAdvice quantity_advice(const AdviceTable& cases, const MeshFeatures& features,
                               double sigma_over_h, const std::string& quantity,
                               const std::vector<CrossValidationRow>& validation) {
  QuantityAdvice q;
  q.pick = pick_advice(cases.cases, features, sigma_over_h, quantity);
  if (!q.pick.found) return q;
  try {
    q.choice = estimator_choice(q.pick.label);
  } catch (const UsageError& e) {
    throw InputError(cases.name + ": case '" + q.pick.label +
                     "' is no estimator curvbench estimate runs (" + e.what() + ")");
  }
  std::vector<CrossValidationRow> read;
  for (const AdviceNeighbour& n : q.pick.neighbours) {
    for (const CrossValidationRow& r : validation)
      if (r.family == n.family && r.level == n.level && r.quantity == quantity &&
          same_level(r.sigma_over_h, n.sigma_over_h))
        read.push_back(r);
    if (std::isfinite(n.error)) {
      q.lowest_error = std::isfinite(q.lowest_error) ? std::fmin(q.lowest_error, n.error) : n.error;
      q.highest_error =
          std::isfinite(q.highest_error) ? std::fmax(q.highest_error, n.error) : n.error;
    }
  }
  q.validated = summarize_regret(read, quantity);
  for (const CrossValidationRow& r : read)
    if (std::isfinite(r.regret))
      q.lowest_regret =
          std::isfinite(q.lowest_regret) ? std::fmin(q.lowest_regret, r.regret) : r.regret;
  return q;
}

}  // namespace

Advice advise(const Mesh& mesh, double noise, const RecommendationTable& table,
              const AdviceTable* cases) {
  if (!std::isnan(noise) && !(noise >= 0 && std::isfinite(noise)))
    throw UsageError("noise " + format_g(noise) + ": sigma/h must be finite and >= 0");
  Advice a;
  a.mesh_class = classify_mesh(mesh);
  a.noise_estimated = std::isnan(noise);
  const Creases creases = detect_creases(mesh, a.crease_angle);
  a.sharp_edges = creases.num_edges();
  a.crease_vertices = creases.num_vertices();
  a.crease_vertex_ids = creases.vertices;
  if (a.noise_estimated) {
    const NoiseEstimate e = estimate_noise(mesh, a.crease_angle);
    a.sigma_over_h = e.sigma_over_h;
    a.noise_crease_vertices = e.crease_vertices;
    a.noise_near_crease_vertices = e.near_crease_vertices;
  } else {
    a.sigma_over_h = noise;
  }
  a.noise_level = nearest_noise_level(a.sigma_over_h);
  a.table = table.name;
  a.provenance = table.provenance;
  a.header = table.header;
  a.vertices = mesh.num_vertices();
  a.h = mesh.mean_edge_length();
  a.sigma_over_h2 = a.sigma_over_h / a.h;
  if (cases) {
    a.has_feature_advice = true;
    a.advice_table = cases->name;
    a.features = measure_mesh_features(mesh);
    a.out_of_range = features_out_of_range(cases->cases, a.features);
    const std::vector<CrossValidationRow> validation = cross_validate(cases->cases);
    for (const std::string& q : advice_quantities())
      a.quantities.push_back(quantity_advice(*cases, a.features, a.sigma_over_h, q, validation));
  }
  for (const RecommendationRow& r : table.rows)
    if (r.quality == a.mesh_class.quality && same_level(r.sigma_over_h, a.noise_level)) {
      a.row = r;
      if (a.has_feature_advice) {
        const QuantityAdvice& curvature = a.quantities.back();
        a.has_choice = curvature.pick.found;
        if (a.has_choice) {
          const AdviceNeighbour& nearest = curvature.pick.neighbours.front();
          a.choice = curvature.choice;
          a.label = curvature.pick.label;
          a.quantity = curvature.pick.quantity;
          a.norm = kAdviceNorm;
          a.error = nearest.error;
          a.experiment = nearest.experiment;
          a.family = nearest.family;
          a.level = nearest.level;
        }
      } else if (r.swept) {
        a.has_choice = true;
        a.choice = estimator_choice(r.best_label);
        a.label = r.best_label;
        a.quantity = r.quantity;
        a.norm = r.norm;
        a.error = r.best_error;
        a.experiment = r.experiment;
        a.family = r.family;
        a.level = r.level;
      }
      return a;
    }
  // parse_recommendations_csv checked that every cell has a row.
  throw InputError(table.name + ": no row for quality " + a.mesh_class.quality + " at sigma/h " +
                   format_g(a.noise_level));
}

bool is_auto_method(const std::string& method) {
  return ascii_lower(method) == "auto";
}

EstimatorOptions auto_options(const EstimatorChoice& choice, const EstimatorOptions& given,
                              bool python_keywords) {
  EstimatorOptions out = choice.options;
  for (const OptionInfo& info : estimator_option_schema()) {
    if (info.role == OptionRole::run) {
      set_option(out, info.name, option_text(given, info));
      continue;
    }
    if (!option_is_default(given, info)) {
      std::string runs;
      for (const OptionInfo& o : estimator_option_schema())
        if (o.role == OptionRole::run)
          runs += (runs.empty() ? "" : ", ") + (python_keywords ? o.python_name : "--" + o.name);
      throw UsageError(
          "method auto chooses the estimator and its radius from the recommendations: " +
          (python_keywords ? info.python_name : "--" + info.name) +
          " cannot be given with it (only " + runs + "; or name the method)");
    }
  }
  return out;
}

std::string shell_quote(const std::string& word) {
  bool plain = !word.empty();
  for (char ch : word) {
    const auto u = static_cast<unsigned char>(ch);
    plain = plain && (std::isalnum(u) || std::string("_./:=+,@%-").find(ch) != std::string::npos);
  }
  if (plain) return word;
  std::string out = "'";
  for (char ch : word) out += ch == '\'' ? std::string("'\\''") : std::string(1, ch);
  return out + "'";
}

std::string advice_output_path(const std::string& mesh_path) {
  std::filesystem::path p(mesh_path);
  p.replace_extension(".curvatures.csv");
  return p.string();
}

std::string estimate_command(const std::string& program, const std::string& mesh_path,
                             const EstimatorChoice& choice, bool skip_invalid,
                             const std::string& output) {
  std::vector<std::string> words{program, "estimate", mesh_path};
  for (const std::string& f : choice.flags()) words.push_back(f);
  if (skip_invalid) words.push_back("--skip-invalid");
  words.push_back("--output");
  words.push_back(output);
  std::string s;
  for (const std::string& w : words) {
    if (!s.empty()) s += ' ';
    s += shell_quote(w);  // appended, not operator+: GCC 12 warns falsely (-Wrestrict)
  }
  return s;
}

namespace {

std::string number_text(const char* format, double x) {
  char buf[64];
  std::snprintf(buf, sizeof buf, format, x);
  return buf;
}

// The lines of the advice from mesh features (advice_text).
std::string feature_advice_text(const Advice& a) {
  const MeshFeatures& f = a.features;
  std::string s =
      "features:   " + number_text("%.1f%%", 100 * f.small_angle_share) +
      " of the angles below 20 deg, " + number_text("%.1f%%", 100 * f.obtuse_angle_share) +
      " above 100 deg, " + number_text("%.0f%%", 100 * f.irregular_valence_share) +
      " of the interior vertices of valence other than 6, anisotropy " +
      number_text("%.2f", f.anisotropy) + ", density ratio " +
      number_text("%.2f", f.density_ratio) + ", " + number_text("%.1f%%", 100 * f.boundary_share) +
      " boundary vertices; size " + number_text("%.3g", f.size_over_h) + " h\n";
  if (a.out_of_range.empty()) {
    s += "coverage:   every feature within the range of the swept meshes\n";
  } else {
    s += "coverage:   OUTSIDE what the sweeps cover: ";
    for (size_t i = 0; i < a.out_of_range.size(); ++i) {
      const FeatureOutOfRange& o = a.out_of_range[i];
      s += (i ? "; " : "") + std::string(o.name) + " " + number_text("%.3g", o.value) +
           " (swept meshes " + number_text("%.3g", o.lowest) + " to " +
           number_text("%.3g", o.highest) + ")";
    }
    s += ": the advice below extrapolates, its error range is not measured for such meshes\n";
  }
  for (const QuantityAdvice& q : a.quantities) {
    const std::string head = q.pick.quantity == "normal" ? "normals:    " : "curvatures: ";
    if (!q.pick.found) {
      s += head + "none: no swept mesh has " + advice_quantity_words(q.pick.quantity) + "\n";
      continue;
    }
    std::string nearest;
    for (const AdviceNeighbour& n : q.pick.neighbours)
      nearest +=
          (nearest.empty() ? "" : ", ") + n.family + " at sigma/h " + format_g(n.sigma_over_h);
    s += head + q.choice.text() + "; case `" + q.pick.label + "`, the least error (" + kAdviceNorm +
         ", " + advice_quantity_words(q.pick.quantity) +
         ") relative to the best on the swept meshes nearest in these features: " + nearest + "\n";
    s += "            measured there: error " + scientific(q.lowest_error) + " to " +
         scientific(q.highest_error);
    if (q.validated.cases > 0)
      s += "; cross-validated (the advice learned without each of these families, followed on "
           "it): " +
           number_text("%.2f", q.lowest_regret) + " to " + regret_text(q.validated.worst) +
           " times the best error, median " + number_text("%.2f", q.validated.median);
    s += "\n";
  }
  if (a.choices_differ())
    s += "differ:     the normals' and the curvature's choices differ; the command below runs the "
         "curvature's (for the normals: " +
         a.quantities.front().choice.text() + ")\n";
  s += "cases:      " + a.advice_table + "\n";
  return s;
}

// The lines of the advice measured on the mesh (advice_text).
std::string measured_advice_text(const Advice& a) {
  const MeasuredRecommendation& m = a.measured;
  std::string s = "measured:   on this mesh: the " + std::to_string(m.candidates.size()) +
                  " cases run on it and on it perturbed " + std::to_string(kMeasuredPerturbations) +
                  " times by sigma/h " + number_text("%.3g", m.advice.perturbation_over_h) +
                  " along the normals of " + kMeasuredReferences[0] +
                  "; predicted error = sqrt(noise part^2 + bias part^2), the bias part against "
                  "a reference, the LHF-4 ring of least predicted error\n";
  for (size_t k = 0; k < m.advice.quantities.size(); ++k) {
    const MeasuredQuantity& q = m.advice.quantities[k];
    const std::string head = q.quantity == "normal" ? "normals:    " : "curvatures: ";
    const MeasuredCase& c = q.cases[static_cast<size_t>(q.chosen)];  // measure_on_mesh: >= 0
    s += head + m.candidates[static_cast<size_t>(q.chosen)].text() + "; case `" + c.label +
         "`, predicted " +
         (q.quantity == "normal" ? "RMS normal error " : "relative L2 error in H ") +
         scientific(c.predicted) + " (noise part " + scientific(c.noise_part) + ", bias part " +
         scientific(c.bias_part) + " against " + q.reference + ")\n";
    if (k < m.validated.size() && m.validated[k].cases > 0) {
      const RegretSummary& v = m.validated[k];
      s += "            on the swept meshes (exact answers known) this measurement advised "
           "within 2x of the best case in " +
           number_text("%.0f%%", 100 * v.within_goal) + " of " + std::to_string(v.cases) +
           " cases; median " + number_text("%.2f", v.median) + ", worst " + regret_text(v.worst) +
           " times the best error\n";
    }
  }
  s += "measured:   the command below runs the curvature's measured choice (not the learned one "
       "above)\n";
  return s;
}

// The fields of the advice from mesh features (advice_json).
std::string feature_advice_json(const Advice& a) {
  std::string j = ", \"features\": {";
  for (size_t i = 0; i < advice_features().size(); ++i) {
    const FeatureInfo& f = advice_features()[i];
    j += std::string(i ? ", " : "") + json_string(f.name) + ": " +
         json_number(a.features.*(f.field));
  }
  j += ", \"size_over_h\": " + json_number(a.features.size_over_h) + "}, \"out_of_range\": [";
  for (size_t i = 0; i < a.out_of_range.size(); ++i) {
    const FeatureOutOfRange& o = a.out_of_range[i];
    j += std::string(i ? ", " : "") + "{\"feature\": " + json_string(o.name) +
         ", \"value\": " + json_number(o.value) + ", \"lowest\": " + json_number(o.lowest) +
         ", \"highest\": " + json_number(o.highest) + "}";
  }
  j += "], \"advice\": {";
  for (size_t i = 0; i < a.quantities.size(); ++i) {
    const QuantityAdvice& q = a.quantities[i];
    j += std::string(i ? ", " : "") + json_string(q.pick.quantity) + ": {";
    if (!q.pick.found) {
      j += "\"label\": null}";
      continue;
    }
    j += "\"label\": " + json_string(q.pick.label) +
         ", \"method\": " + json_string(q.choice.method) + ", \"options\": {";
    if (!q.choice.parameter.empty())
      j += json_string(q.choice.parameter) + ": " + json_number(q.choice.radius);
    j += "}, \"lowest_error\": " + json_number(q.lowest_error) +
         ", \"highest_error\": " + json_number(q.highest_error) +
         ", \"lowest_regret\": " + json_number(q.lowest_regret) +
         ", \"median_regret\": " + json_number(q.validated.median) +
         ", \"worst_regret\": " + json_number(q.validated.worst) + ", \"neighbours\": [";
    for (size_t k = 0; k < q.pick.neighbours.size(); ++k) {
      const AdviceNeighbour& n = q.pick.neighbours[k];
      j += std::string(k ? ", " : "") + "{\"family\": " + json_string(n.family) +
           ", \"level\": " + std::to_string(n.level) +
           ", \"sigma_over_h\": " + json_number(n.sigma_over_h) +
           ", \"distance\": " + json_number(n.distance) + ", \"error\": " + json_number(n.error) +
           ", \"best_label\": " + json_string(n.best_label) +
           ", \"best_error\": " + json_number(n.best_error) + "}";
    }
    j += "]}";
  }
  return j + "}, \"choices_differ\": " + (a.choices_differ() ? "true" : "false") +
         ", \"advice_table\": " + json_string(a.advice_table);
}

}  // namespace

std::string advice_text(const Advice& a, const std::string& mesh_path, const std::string& command) {
  const RecommendationRow& r = a.row;
  char buf[64];
  std::snprintf(buf, sizeof buf, "%d vertices, h = %.4g", a.vertices, a.h);
  std::string s = "mesh:       " + mesh_path + " (" + buf + ")\n";
  s += "class:      " + a.mesh_class.quality + " (" + a.mesh_class.reason + ")\n";
  std::snprintf(buf, sizeof buf, "%.3g", a.sigma_over_h);
  s += "noise:      sigma/h = " + std::string(buf) +
       (a.noise_estimated ? " (estimated from the residuals of a degree-4 fit at each vertex)"
                          : " (given)") +
       (a.has_feature_advice
            ? ", the class table's nearest level " + format_g(a.noise_level) +
                  " (the advice below reads, on each swept mesh, the level nearest in the "
                  "quantity's unit)"
            : ", nearest level of the table " + format_g(a.noise_level)) +
       "\n";
  std::snprintf(buf, sizeof buf, "%.3g", a.sigma_over_h2);
  s += "curvature:  sigma/h^2 = " + std::string(buf) +
       " (per unit length: the scale of the curvature error this noise causes, where sigma/h is "
       "the normals')\n";
  s += "creases:    " + std::to_string(a.sharp_edges) + " sharp edges (face normals more than " +
       format_g(a.crease_angle) + " degrees apart), " + std::to_string(a.crease_vertices) +
       " crease vertices" +
       (a.crease_vertices > 0
            ? ": no smooth-surface curvature there (`--format json` lists them, crease_vertex_ids)"
            : "") +
       (a.noise_estimated && a.noise_crease_vertices > 0
            ? "; the noise estimate left out " + std::to_string(a.noise_crease_vertices) +
                  " crease vertices and the " + std::to_string(a.noise_near_crease_vertices) +
                  " next to them"
            : "") +
       "\n";
  if (a.has_feature_advice) {
    s += feature_advice_text(a);
  } else if (!a.has_choice) {
    s += "estimator:  none: no sweep ran for " + a.mesh_class.quality + " meshes at sigma/h " +
         format_g(a.noise_level) +
         " (`curvbench run --all --full` runs them all; then --results results)\n";
  } else {
    s += "estimator:  " + a.choice.text() + "; case `" + r.best_label +
         "`, the most accurate of the " + std::to_string(r.cases) +
         " cases (method and radius) the sweep compared\n";
    s += "error:      relative " + r.norm + " error in " + r.quantity + " " +
         scientific(r.best_error) + " (in " + seconds_text(r.best_seconds) + "), measured by " +
         r.experiment + " on " + r.family + " level " + std::to_string(r.level) + " (" +
         std::to_string(r.vertices) + " vertices, noise " + r.noise +
         "), the mesh that stands for the " + r.quality + " class\n";
    if (!r.cheapest_label.empty() && r.cheapest_label != r.best_label)
      s += "faster:     `" + r.cheapest_label +
           "`, the fastest case within 2x of that error: " + scientific(r.cheapest_error) + " in " +
           seconds_text(r.cheapest_seconds) + "\n";
  }
  if (a.has_measured) s += measured_advice_text(a);
  s += "table:      " + a.table + (a.provenance.empty() ? "" : ", " + a.provenance) + "\n";
  if (!command.empty()) s += "run:        " + command + "\n";
  return s;
}

std::string advice_json(const Advice& a, const std::string& mesh_path, const std::string& command) {
  const RecommendationRow& r = a.row;
  std::string j = "{\"mesh\": " + json_string(mesh_path) +
                  ", \"vertices\": " + std::to_string(a.vertices) + ", \"h\": " + json_number(a.h) +
                  ", \"quality\": " + json_string(a.mesh_class.quality) +
                  ", \"quality_reason\": " + json_string(a.mesh_class.reason) +
                  ", \"sigma_over_h\": " + json_number(a.sigma_over_h) +
                  ", \"noise\": " + json_string(a.noise_estimated ? "estimated" : "given") +
                  ", \"noise_level\": " + format_g(a.noise_level) +
                  ", \"swept\": " + (a.has_choice ? "true" : "false");
  if (a.has_choice) {
    j += ", \"method\": " + json_string(a.choice.method) + ", \"options\": {";
    if (!a.choice.parameter.empty())
      j += json_string(a.choice.parameter) + ": " + json_number(a.choice.radius);
    j += "}, \"label\": " + json_string(a.label) + ", \"quantity\": " + json_string(a.quantity) +
         ", \"norm\": " + json_string(a.norm) + ", \"error\": " + json_number(a.error) +
         ", \"command\": " + json_string(command);
  } else {
    j += ", \"method\": null, \"options\": {}, \"label\": null, \"quantity\": null, \"norm\": "
         "null, \"error\": null, \"command\": null";
  }
  j += ", \"sigma_over_h2\": " + json_number(a.sigma_over_h2) +
       ", \"crease_angle\": " + json_number(a.crease_angle) +
       ", \"sharp_edges\": " + std::to_string(a.sharp_edges) +
       ", \"crease_vertices\": " + std::to_string(a.crease_vertices) +
       ", \"noise_crease_vertices\": " + std::to_string(a.noise_crease_vertices) +
       ", \"noise_near_crease_vertices\": " + std::to_string(a.noise_near_crease_vertices) +
       ", \"crease_vertex_ids\": [";
  for (size_t i = 0; i < a.crease_vertex_ids.size(); ++i)
    j += (i ? ", " : "") + std::to_string(a.crease_vertex_ids[i]);
  j += "]";
  j += ", \"table\": " + json_string(a.table) + ", \"provenance\": " + json_string(a.provenance) +
       ", \"row\": {";
  for (size_t i = 0; i < a.header.size() && i < r.fields.size(); ++i)
    j += std::string(i ? ", " : "") + json_string(a.header[i]) + ": " + json_string(r.fields[i]);
  j += "}";
  if (a.has_feature_advice) j += feature_advice_json(a);
  if (a.has_measured) {
    const MeasuredRecommendation& m = a.measured;
    j += ", \"measured_advice\": {\"perturbation_over_h\": " +
         json_number(m.advice.perturbation_over_h) +
         ", \"perturbations\": " + std::to_string(m.advice.perturbations);
    for (size_t k = 0; k < m.advice.quantities.size(); ++k) {
      const MeasuredQuantity& q = m.advice.quantities[k];
      const MeasuredCase& c = q.cases[static_cast<size_t>(q.chosen)];  // measure_on_mesh: >= 0
      j += ", " + json_string(q.quantity) + ": {\"label\": " + json_string(c.label) +
           ", \"reference\": " + json_string(q.reference) +
           ", \"predicted\": " + json_number(c.predicted) +
           ", \"noise_part\": " + json_number(c.noise_part) +
           ", \"bias_part\": " + json_number(c.bias_part);
      if (k < m.validated.size()) {
        const RegretSummary& v = m.validated[k];
        j += ", \"validated\": {\"cases\": " + std::to_string(v.cases) +
             ", \"within_2x\": " + json_number(v.within_goal) +
             ", \"median_regret\": " + json_number(v.median) +
             ", \"worst_regret\": " + json_number(v.worst) + "}";
      }
      j += "}";
    }
    j += "}";
  }
  return j + "}\n";
}

std::string advice_csv(const Advice& a) {
  std::string header, row;
  for (const std::string& h : a.header) header += (header.empty() ? "" : ",") + h;
  for (size_t i = 0; i < a.row.fields.size(); ++i) row += (i ? "," : "") + a.row.fields[i];
  return header + "\n" + row + "\n";
}

}  // namespace curvbench
