#include "harness/experiment.h"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
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

bool to_bool(const std::string& s, const std::string& where) {
  if (s == "yes" || s == "true") return true;
  if (s == "no" || s == "false") return false;
  throw InputError(where + ": expected yes or no, got '" + s + "'");
}

}  // namespace

Experiment parse_experiment_text(const std::string& text, const std::string& source) {
  Experiment e;
  e.source = source;
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
        need(2);
        e.name = w[1];
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
          throw InputError(where + ": radius-scaling needs c > 0 and 0 < alpha <= 1");
      } else if (key == "noise") {
        need(2);
        for (size_t i = 1; i < w.size(); ++i) {
          std::string k, v;
          if (!split_option(w[i], k, v)) throw InputError(where + ": expected key=value");
          if (k == "order")
            e.noise_order = static_cast<int>(parse_integer(v, where));
          else if (k == "seed")
            e.noise_seed = static_cast<std::uint64_t>(parse_integer(v, where));
          else if (k == "alpha")
            try {
              e.noise_model.distribution = parse_noise_distribution(v);
            } catch (const UsageError& err) {
              throw InputError(where + ": " + err.what());
            }
          else if (k == "scale")
            e.noise_model.scale = parse_double(v, where);
          else
            throw InputError(where + ": unknown noise option '" + k +
                             "' (order, seed, alpha, scale)");
        }
        if (!(e.noise_model.scale >= 0.0) || !std::isfinite(e.noise_model.scale))
          throw InputError(where + ": noise scale must be finite and >= 0");
        if (e.noise_order != 2 && e.noise_order != 3)
          throw InputError(where + ": noise order must be 2 or 3");
      } else if (key == "mesh") {
        need(3);
        ExperimentMesh m;
        m.family = w[1];
        for (size_t i = 2; i < w.size(); ++i) {
          std::string k, v;
          if (split_option(w[i], k, v) && k == "noise-order") {
            m.noise_order = static_cast<int>(parse_integer(v, where));
            if (m.noise_order != 0 && m.noise_order != 2 && m.noise_order != 3)
              throw InputError(where + ": noise-order must be 0, 2 or 3");
            continue;
          }
          if (k != "levels" && std::any_of(mesh_option_table().begin(), mesh_option_table().end(),
                                           [&](const MeshOptionInfo& o) { return o.name == k; })) {
            set_mesh_option(m.shape, k, parse_double(v, where));
            continue;
          }
          if (k != "levels") {
            std::string options;
            for (const MeshOptionInfo& o : mesh_option_table())
              options += " [" + o.name + "=" + o.letter + "]";
            throw InputError(where + ": expected levels=1,2,3,4 [noise-order=K]" + options);
          }
          std::stringstream ss(v);
          std::string item;
          while (std::getline(ss, item, ','))
            m.levels.push_back(static_cast<int>(parse_integer(item, where)));
        }
        if (m.levels.empty()) throw InputError(where + ": no levels given");
        check_mesh_shape(m.family, m.shape);
        e.meshes.push_back(m);
      } else if (key == "method") {
        need(2);
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
              throw InputError(where + ": unknown method option '" + k + "' (valid: " + valid +
                               ")");
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
          if (!m.label.empty())
            throw InputError(where + ": method " + kAllOperators + " takes no label");
          for (const MethodInfo& info : method_table()) {
            if (info.is_fit()) continue;
            ExperimentMethod one = m;
            one.spec = info.name;
            make_estimator(one.spec, one.options);  // the options suit every operator
            e.methods.push_back(one);
          }
        } else {
          make_estimator(m.spec, m.options);  // a bad name, degree or option, with the line
          e.methods.push_back(m);
        }
      } else if (key == "panel") {
        need(5);
        e.panels.push_back({w[1], w[2], parse_quantity(w[3]), parse_norm(w[4])});
      } else {
        throw InputError(where + ": unknown key '" + key + "'");
      }
    } catch (const UsageError& err) {
      throw InputError(where + ": " + err.what());
    }
  }
  if (e.name.empty()) throw InputError(source + ": missing 'name'");
  if (e.meshes.empty()) throw InputError(source + ": no 'mesh' line");
  if (e.methods.empty()) throw InputError(source + ": no 'method' line");
  if (e.panels.empty()) throw InputError(source + ": no 'panel' line");
  return e;
}

Experiment parse_experiment(const std::string& path) {
  std::ifstream in(path);
  if (!in) throw InputError(path + ": cannot open experiment file");
  std::stringstream ss;
  ss << in.rdbuf();
  return parse_experiment_text(ss.str(), path);
}

std::vector<std::string> list_experiment_files(const std::string& directory) {
  std::vector<std::string> out;
  std::error_code ec;
  for (const auto& entry : std::filesystem::directory_iterator(directory, ec))
    if (entry.is_regular_file() && entry.path().extension() == ".exp")
      out.push_back(entry.path().string());
  if (ec) throw InputError(directory + ": cannot list experiments (" + ec.message() + ")");
  std::sort(out.begin(), out.end());
  // The diagnostic experiments behind CLAIMS.md's Why lines (experiments/diagnostics/).
  const std::filesystem::path diagnostics = std::filesystem::path(directory) / "diagnostics";
  if (std::filesystem::is_directory(diagnostics, ec)) {
    std::vector<std::string> more;
    for (const auto& entry : std::filesystem::directory_iterator(diagnostics, ec))
      if (entry.is_regular_file() && entry.path().extension() == ".exp")
        more.push_back(entry.path().string());
    std::sort(more.begin(), more.end());
    out.insert(out.end(), more.begin(), more.end());
  }
  return out;
}

}  // namespace curvbench
