#include "harness/model/experiment.h"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>

#include "core/errors.h"
#include "core/text.h"
#include "methods/option_schema.h"

namespace curvbench {

namespace {

// Splits a line into words; double quotes group words; '#' outside quotes ends the line.
std::vector<std::string> tokenize(const std::string& line, const std::string& where) {
  std::vector<std::string> out;
  std::string cur;
  bool in_quotes = false, have = false;
  for (char c : line) {
    if (in_quotes) {
      if (c == '"')
        in_quotes = false;
      else
        cur += c;
    } else if (c == '"') {
      in_quotes = have = true;
    } else if (c == '#') {
      break;
    } else if (c == ' ' || c == '\t' || c == '\r') {
      if (have) out.push_back(cur);
      cur.clear();
      have = false;
    } else {
      cur += c;
      have = true;
    }
  }
  if (in_quotes) throw InputError(where + ": unterminated quote");
  if (have) out.push_back(cur);
  return out;
}

bool split_option(const std::string& word, std::string& key, std::string& value) {
  const auto eq = word.find('=');
  if (eq == std::string::npos) return false;
  key = word.substr(0, eq);
  value = word.substr(eq + 1);
  return true;
}

// "1,1.5,2" -> {"1", "1.5", "2"}; an empty item is an error.
std::vector<std::string> split_list(const std::string& v) {
  std::vector<std::string> out;
  std::stringstream ss(v);
  std::string item;
  while (std::getline(ss, item, ',')) {
    if (item.empty()) throw UsageError("empty value in the list '" + v + "'");
    out.push_back(item);
  }
  if (out.empty() || v.back() == ',') throw UsageError("empty value in the list '" + v + "'");
  return out;
}

void parse_method(Experiment& e, const std::vector<std::string>& w, const std::string& where,
                  const std::pair<std::string, std::string>& listed);

bool to_bool(const std::string& s, const std::string& where) {
  if (s == "yes" || s == "true") return true;
  if (s == "no" || s == "false") return false;
  throw InputError(where + ": expected yes or no, got '" + s + "'");
}

}  // namespace

Experiment parse_experiment_text(const std::string& text, const std::string& source) {
  Experiment e;
  e.source = source;
  // One name per experiment: the file's (results/<name>.csv, the report's section id).
  e.name = std::filesystem::path(source).stem().string();
  if (e.name.empty() || e.name.find_first_of(", \t\"") != std::string::npos)
    throw InputError(source + ": the file name '" + e.name +
                     "' is the experiment's name: it must be non-empty, without commas, spaces "
                     "or quotes");
  std::istringstream in(text);
  std::string line;
  int lineno = 0;
  while (std::getline(in, line)) {
    ++lineno;
    const std::string where = source + ":" + std::to_string(lineno);
    const auto w = tokenize(line, where);
    if (w.empty()) continue;
    const std::string& key = w[0];
    auto need = [&](size_t n) {
      if (w.size() < n) throw InputError(where + ": '" + key + "' needs more values");
    };
    try {
      if (key == "name") {
        throw InputError(where + ": no 'name' line: the experiment's name is its file name ('" +
                         e.name + "')");
      } else if (key == "report") {
        need(2);
        e.report = parse_report_section(w[1]);
      } else if (key == "title") {
        need(2);
        e.title = w[1];
      } else if (key == "section") {
        need(2);
        e.section = w[1];
      } else if (key == "noisy") {
        need(2);
        e.noisy = to_bool(w[1], where);
        for (size_t i = 2; i < w.size(); ++i) {
          std::string k, v;
          if (!split_option(w[i], k, v) || k != "rings" || (v != "all" && v != "quadratic"))
            throw InputError(where + ": expected rings=all or rings=quadratic after noisy yes");
          e.noisy_quadratic_only = v == "quadratic";
        }
      } else if (key == "vertex-set") {
        need(2);
        e.vertex_set = parse_vertex_set(w[1]);
      } else if (key == "radius-scaling") {
        need(3);
        for (size_t i = 1; i < w.size(); ++i) {
          std::string k, v;
          if (!split_option(w[i], k, v) || (k != "alpha" && k != "c"))
            throw InputError(where + ": expected radius-scaling alpha=A c=C");
          (k == "alpha" ? e.radius_alpha : e.radius_c) = parse_double(v, where);
        }
        if (!(e.radius_c > 0.0) || !std::isfinite(e.radius_c) || !(e.radius_alpha > 0.0) ||
            !(e.radius_alpha <= 1.0))
          throw InputError(where + ": radius-scaling alpha=" + format_g(e.radius_alpha) +
                           " c=" + format_g(e.radius_c) + ": needs c > 0 and 0 < alpha <= 1");
      } else if (key == "noise") {
        need(2);
        bool order_given = false;
        for (size_t i = 1; i < w.size(); ++i) {
          std::string k, v;
          if (!split_option(w[i], k, v)) throw InputError(where + ": expected key=value");
          if (k == "order") {
            e.noise_order = static_cast<int>(parse_integer(v, where));
            check_noise_order(e.noise_order);
            order_given = true;
          } else if (k == "seed") {
            e.noise_seed = static_cast<std::uint64_t>(parse_integer(v, where));
          } else if (k == "alpha") {
            e.noise_model.distribution = parse_noise_distribution(v);
          } else if (k == "scale") {
            e.noise_model.scale = parse_double(v, where);
            if (!(e.noise_model.scale >= 0.0) || !std::isfinite(e.noise_model.scale))
              throw InputError(where + ": noise scale=" + v + " must be finite and >= 0");
          } else if (k == "model") {
            e.noise_model.direction = parse_noise_direction(v);
          } else if (k == "outliers") {
            e.noise_model.outlier_fraction = parse_double(v, where);
            if (!(e.noise_model.outlier_fraction > 0.0 && e.noise_model.outlier_fraction <= 1.0))
              throw InputError(where + ": noise outliers=" + v + " is outside (0, 1]");
            if (!order_given) e.noise_order = 1;
            order_given = true;
          } else {
            throw InputError(where + ": unknown noise option '" + k +
                             "' (order, seed, alpha, scale, model, outliers)");
          }
        }
      } else if (key == "sweep") {
        need(2);
        if (w[1] != "radius" && w[1] != "noise")
          throw InputError(where + ": sweep '" + w[1] + "' is not one of radius, noise");
        e.sweep = w[1];
      } else if (key == "mesh") {
        need(3);
        ExperimentMesh m;
        m.family = w[1];
        std::vector<double> sigmas, fractions;
        NoiseModel own;
        bool model_given = false;
        for (size_t i = 2; i < w.size(); ++i) {
          std::string k, v;
          split_option(w[i], k, v);
          if (k == "noise-order") {
            m.noise_order = static_cast<int>(parse_integer(v, where));
            check_noise_order(m.noise_order);
          } else if (k == "levels") {
            for (const std::string& item : split_list(v))
              m.levels.push_back(static_cast<int>(parse_integer(item, where)));
          } else if (k == "noise-sigma" || k == "outliers") {
            for (const std::string& item : split_list(v)) {
              const double x = parse_double(item, where);
              if (k == "noise-sigma" && !(x >= 0.0 && std::isfinite(x)))
                throw InputError(where + ": noise-sigma=" + item + " must be finite and >= 0");
              if (k == "outliers" && !(x >= 0.0 && x <= 1.0))
                throw InputError(where + ": outliers=" + item + " is outside [0, 1]");
              (k == "outliers" ? fractions : sigmas).push_back(x);
            }
          } else if (k == "noise-model") {
            own.direction = parse_noise_direction(v);
            model_given = true;
          } else if (k == "noise-alpha") {
            own.distribution = parse_noise_distribution(v);
            model_given = true;
          } else if (std::any_of(mesh_option_table().begin(), mesh_option_table().end(),
                                 [&](const MeshOptionInfo& o) { return o.name == k; })) {
            set_mesh_option(m.shape, k, parse_double(v, where));
          } else {
            std::string options;
            for (const MeshOptionInfo& o : mesh_option_table())
              options += " [" + o.name + "=" + o.letter + "]";
            throw InputError(where +
                             ": expected levels=1,2,3,4 [noise-order=K] [noise-sigma=S,...] "
                             "[noise-model=M] [noise-alpha=A] [outliers=P,...]" +
                             options);
          }
        }
        if (m.levels.empty()) throw InputError(where + ": no levels given");
        check_mesh_shape(m.family, m.shape);
        if (model_given && sigmas.empty())
          throw InputError(where + ": noise-model and noise-alpha need noise-sigma=S,...");
        if ((!sigmas.empty() || !fractions.empty()) && m.noise_order >= 0)
          throw InputError(where + ": noise-order excludes noise-sigma and outliers");
        std::vector<ExperimentMesh> variants;
        if (sigmas.empty() && fractions.empty()) variants.push_back(m);
        for (double sigma : sigmas) {
          ExperimentMesh v = m;
          v.noise_order = 0;  // sigma = 0: no noise
          if (sigma > 0.0) {
            v.noise_order = 1;
            v.has_noise_model = true;
            v.noise_model = own;
            v.noise_model.scale = sigma;
          }
          variants.push_back(v);
        }
        for (double p : fractions) {
          ExperimentMesh v = m;
          v.noise_order = 0;
          if (p > 0.0) {
            v.noise_order = 1;
            v.has_noise_model = true;
            v.noise_model.outlier_fraction = p;
          }
          variants.push_back(v);
        }
        for (const ExperimentMesh& v : variants)
          if (std::find(e.meshes.begin(), e.meshes.end(), v) == e.meshes.end())
            e.meshes.push_back(v);
      } else if (key == "method") {
        need(2);
        // One estimator option may list values: one method line per value.
        size_t list_at = 0;
        std::vector<std::string> values;
        if (w[1] != "external")
          for (size_t i = 2; i < w.size(); ++i) {
            std::string k, v;
            if (!split_option(w[i], k, v) || v.find(',') == std::string::npos || k == "label" ||
                k == "vertex-set")
              continue;
            if (list_at != 0)
              throw InputError(where + ": only one option of a method line may list values");
            list_at = i;
            values = split_list(v);
          }
        if (list_at == 0) {
          parse_method(e, w, where, {});
          continue;
        }
        std::string list_key, unused;
        split_option(w[list_at], list_key, unused);
        for (const std::string& v : values) {
          std::vector<std::string> one = w;
          one[list_at] = list_key + "=" + v;
          parse_method(e, one, where, {list_key, v});
        }
      } else if (key == "panel") {
        need(5);
        e.panels.push_back({w[1], w[2], parse_quantity(w[3]), parse_norm(w[4])});
        check_norm_applies(e.panels.back().quantity, e.panels.back().norm);
      } else {
        throw InputError(where + ": unknown key '" + key + "'");
      }
    } catch (const UsageError& err) {
      throw InputError(where + ": " + err.what());
    }
  }
  if (e.sweep.empty() != (e.report != ReportSection::sweeps))
    throw InputError(source + ": a 'sweep' line and 'report sweeps' go together");
  if (e.meshes.empty()) throw InputError(source + ": no 'mesh' line");
  if (e.methods.empty()) throw InputError(source + ": no 'method' line");
  if (e.panels.empty()) throw InputError(source + ": no 'panel' line");
  // Two methods that would report under one label (and vertex set) would mix their rows in
  // every table and rate: e.g. `method lhf-2` and `method lhf-2 centre=no` without label=.
  std::map<std::pair<std::string, int>, size_t> seen;
  for (size_t i = 0; i < e.methods.size(); ++i) {
    const ExperimentMethod& m = e.methods[i];
    const std::string label =
        !m.label.empty() ? m.label : make_estimator(m.spec, m.options)->label();
    const int set = m.has_vertex_set ? static_cast<int>(m.vertex_set) : -1;
    if (const auto [it, fresh] = seen.try_emplace({label, set}, i); !fresh)
      throw InputError(source + ": methods " + std::to_string(it->second + 1) + " (" +
                       e.methods[it->second].spec + ") and " + std::to_string(i + 1) + " (" +
                       m.spec + ") both report as '" + label +
                       "': give one a label=\"...\" of its own");
  }
  return e;
}

namespace {

// One `method` line's words; `listed` is the option and value of a line expanded from a list of
// values ({"rings", "1.5"}; empty else), whose label gains " rings=1.5".
void parse_method(Experiment& e, const std::vector<std::string>& w, const std::string& where,
                  const std::pair<std::string, std::string>& listed) {
  const std::string label_suffix =
      listed.first.empty() ? "" : " " + listed.first + "=" + listed.second;
  {
    {
      ExperimentMethod m;
      m.spec = w[1];
      for (size_t i = 2; i < w.size(); ++i) {
        std::string k, v;
        if (!split_option(w[i], k, v)) throw InputError(where + ": expected key=value");
        if (k == "label") {
          if (v.empty() || v.find(',') != std::string::npos)
            throw InputError(where + ": a label must be non-empty and contain no comma");
          m.label = v;
        } else if (k == "vertex-set") {
          m.vertex_set = parse_vertex_set(v);
          m.has_vertex_set = true;
        } else if (m.is_external() && k == "name") {
          if (v.empty() || v.find(',') != std::string::npos)
            throw InputError(where + ": a name must be non-empty and contain no comma");
          m.label = v;
        } else if (m.is_external() && k == "command") {
          m.command = v;
        } else if (m.is_external() && k == "description") {
          m.description = v;
        } else if (m.is_external() && k == "timeout") {
          m.timeout_seconds = parse_double(v, where);
          if (!(m.timeout_seconds > 0))
            throw InputError(where + ": timeout must be a positive number of seconds");
        } else if (!m.is_external()) {
          const auto& schema = estimator_option_schema();
          if (std::none_of(schema.begin(), schema.end(),
                           [&](const OptionInfo& o) { return o.name == k; })) {
            std::string valid = "label, vertex-set";
            for (const OptionInfo& o : schema)
              if (o.role == OptionRole::result) valid += ", " + o.name;
            throw InputError(where + ": unknown method option '" + k + "' (valid: " + valid + ")");
          }
          if (option_info(k).role != OptionRole::result)
            throw InputError(where + ": '" + k +
                             "' is not an experiment option (it does not change the results)");
          set_option(m.options, k, v);
        } else {
          throw InputError(where + ": unknown option '" + k + "' of method external");
        }
      }
      if (m.is_external()) {
        if (m.label.empty()) throw InputError(where + ": method external needs name=NAME");
        if (m.command.find("{mesh}") == std::string::npos ||
            m.command.find("{out}") == std::string::npos)
          throw InputError(where +
                           ": method external needs command=\"... {mesh} ... {out}\" (the "
                           "input mesh and the estimate CSV it writes)");
        e.methods.push_back(m);
      } else if (m.spec == kAllOperators) {
        if (!m.label.empty() || !label_suffix.empty())
          throw InputError(where + ": method " + kAllOperators + " takes no label or list");
        for (const MethodInfo& info : method_table()) {
          if (info.is_fit() || info.group != MethodGroup::discrete) continue;
          ExperimentMethod one = m;
          one.spec = info.name;
          make_estimator(one.spec, one.options);  // the options suit every operator
          e.methods.push_back(one);
        }
      } else {
        // a bad name, degree or option, with the line
        const auto est = make_estimator(m.spec, m.options);
        if (!label_suffix.empty()) {
          const std::string base = m.label.empty() ? est->label() : m.label;
          m.label = base + label_suffix;
          // A swept radius (rings=1,1.5,2 or ball-factor=2,4): the rows carry it typed.
          for (NeighbourhoodSize size : kNeighbourhoodSizes)
            if (listed.first == radius_option(size)) {
              m.radius_parameter = listed.first;
              m.radius = parse_double(listed.second, where);
              m.radius_base_label = base;
            }
        }
        e.methods.push_back(m);
      }
    }
  }
}

}  // namespace

const char* to_string(ReportSection section) {
  switch (section) {
    case ReportSection::paper:
      return "paper";
    case ReportSection::field:
      return "field";
    case ReportSection::hard:
      return "hard";
    case ReportSection::sweeps:
      return "sweeps";
    case ReportSection::points:
      return "points";
    case ReportSection::extra:
      return "extra";
  }
  return "?";
}

ReportSection parse_report_section(const std::string& keyword) {
  for (ReportSection s : {ReportSection::paper, ReportSection::field, ReportSection::hard,
                          ReportSection::sweeps, ReportSection::points, ReportSection::extra})
    if (keyword == to_string(s)) return s;
  throw UsageError("report '" + keyword +
                   "' is not one of paper, field, hard, sweeps, points, extra");
}

Experiment parse_experiment(const std::string& path) {
  std::ifstream in(path);
  if (!in) throw InputError(path + ": cannot open experiment file");
  std::stringstream ss;
  ss << in.rdbuf();
  return parse_experiment_text(ss.str(), path);
}

namespace {
// The subfolders of the experiments folder: the diagnostic experiments behind CLAIMS.md's Why
// lines, and the full sweeps (read with `full` only).
constexpr const char* kDiagnosticsFolder = "diagnostics";
constexpr const char* kSweepsFolder = "sweeps";
// The deep levels of `make experiments-deep`: read only when named as the experiments folder.
constexpr const char* kDeepFolder = "deep";
}  // namespace

std::string experiment_source_name(const Experiment& e) {
  const std::filesystem::path source(e.source);
  const std::string folder = source.parent_path().filename().string();
  std::string name = "experiments/";
  if (folder == kDiagnosticsFolder || folder == kSweepsFolder || folder == kDeepFolder)
    name.append(folder).append("/");
  return name.append(source.filename().string());
}

std::vector<std::string> list_experiment_files(const std::string& directory, bool full) {
  std::vector<std::string> out;
  std::error_code ec;
  const auto add_folder = [&](const std::filesystem::path& folder) {
    std::vector<std::string> more;
    for (const auto& entry : std::filesystem::directory_iterator(folder, ec))
      if (entry.is_regular_file() && entry.path().extension() == ".exp")
        more.push_back(entry.path().string());
    // By name ("field-estimators" before "field-estimators-noise-h2"), not by file name.
    std::sort(more.begin(), more.end(), [](const std::string& a, const std::string& b) {
      return std::filesystem::path(a).stem() < std::filesystem::path(b).stem();
    });
    out.insert(out.end(), more.begin(), more.end());
  };
  add_folder(directory);
  if (ec) throw InputError(directory + ": cannot list experiments (" + ec.message() + ")");
  for (const char* sub : {kDiagnosticsFolder, kSweepsFolder}) {
    if (sub == kSweepsFolder && !full) continue;
    const std::filesystem::path folder = std::filesystem::path(directory) / sub;
    if (std::filesystem::is_directory(folder, ec)) add_folder(folder);
  }
  return out;
}

std::vector<Experiment> load_experiments(const std::string& dir, bool full) {
  std::vector<Experiment> out;
  for (const auto& f : list_experiment_files(dir, full)) {
    Experiment e = parse_experiment(f);
    const auto same =
        std::find_if(out.begin(), out.end(), [&](const Experiment& o) { return o.name == e.name; });
    if (same != out.end())
      *same = std::move(e);
    else
      out.push_back(std::move(e));
  }
  return out;
}

}  // namespace curvbench
