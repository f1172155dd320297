#include "harness/run/case_store.h"

#include <unistd.h>

#include <cmath>
#include <cstdio>
#include <ctime>
#include <filesystem>
#include <set>

#include "core/build_info.h"
#include "core/errors.h"
#include "core/text.h"
#include "harness/model/results_table.h"
#include "harness/run/external_estimator.h"
#include "mesh/io.h"
#include "methods/option_schema.h"

namespace curvbench {

namespace fs = std::filesystem;

namespace {

// Free text inside case_inputs: ';', '=' and line breaks escaped so fields cannot run together.
std::string escaped(const std::string& s) {
  std::string out;
  for (char ch : s) {
    if (ch == '\\' || ch == ';' || ch == '=') out += '\\';
    if (ch == '\n')
      out += "\\n";
    else if (ch == '\r')
      out += "\\r";
    else
      out += ch;
  }
  return out;
}

// A file-name-safe form of a name: [A-Za-z0-9.+-] kept, anything else '_'.
std::string file_safe(const std::string& s) {
  std::string out;
  for (char ch : s) {
    const bool keep = (ch >= 'a' && ch <= 'z') || (ch >= 'A' && ch <= 'Z') ||
                      (ch >= '0' && ch <= '9') || ch == '.' || ch == '+' || ch == '-';
    out += keep ? ch : '_';
  }
  return out.empty() ? "_" : out;
}

// Line 3 of a case file: the estimation time of the case, in seconds.
constexpr const char* kSecondsComment = "# estimate-seconds ";
// The line before the errors by cause of a case file.
constexpr const char* kCausesComment = "# errors by cause\n";

const char* yes_no(bool b) {
  return b ? "yes" : "no";
}

// An outside estimator's command and the contents of the files it names (e.g. its script).
std::string external_inputs(const ExperimentMethod& m) {
  std::string s = ";command=" + escaped(m.command);
  for (const std::string& f : files_named_in(m.command)) {
    std::string hash;
    try {
      hash = hex64(fnv1a64(read_file(f)));
    } catch (const InputError&) {
      hash = "unreadable";
    }
    s += ";file=" + escaped(f) + ":" + hash;
  }
  return s;
}

// The method's part of case_inputs: its spec, label, vertex set and every estimator option it
// sets away from the default (so that a new option leaves the keys of stored cases as they were).
std::string method_inputs(const ExperimentMethod& m) {
  std::string s =
      "method=" + escaped(m.spec) + ";label=" + escaped(m.label) +
      ";method-vertex-set=" + std::string(m.has_vertex_set ? to_string(m.vertex_set) : "default");
  for (const OptionInfo& option : estimator_option_schema())
    if (option.role == OptionRole::result && !option_is_default(m.options, option))
      s += ";" + option.name + "=" + option_text(m.options, option);
  return s + (m.is_external() ? external_inputs(m) : std::string());
}

// The noise model's part of case_inputs: only what differs from the default model (so that the
// keys of the stored cases of the paper's noise stay as they were).
std::string noise_inputs(const NoiseModel& model) {
  if (model.is_default()) return "";
  std::string s = ";noise-alpha=" + std::string(to_string(model.distribution)) +
                  ";noise-scale=" + format_double(model.scale);
  if (model.direction != NoiseDirection::normal)
    s += ";noise-model=" + std::string(to_string(model.direction));
  if (model.is_outliers()) s += ";outliers=" + format_double(model.outlier_fraction);
  return s;
}

std::string first_line(std::uint64_t inputs, std::uint64_t content) {
  return "# curvbench case: inputs " + hex64(inputs) + " content " + hex64(content);
}

// Hash of the running executable, or a per-process value (no reuse) if it cannot be read.
std::string executable_hash() {
  try {
    return hex64(fnv1a64(read_file("/proc/self/exe")));
  } catch (const InputError&) {
    return "unreadable-" + std::to_string(::getpid()) + "-" + std::to_string(std::time(nullptr));
  }
}

}  // namespace

std::string hex64(std::uint64_t x) {
  char buf[17];
  std::snprintf(buf, sizeof buf, "%016llx", static_cast<unsigned long long>(x));
  return buf;
}

const std::string& code_version() {
  static const std::string version = [] {
    const std::string info = build_info();
    // A committed build is named by its commit; otherwise the binary itself is the version.
    const bool exact =
        info.find("-dirty") == std::string::npos && info.find("(git unknown)") == std::string::npos;
    return exact ? info : info + " exe " + executable_hash();
  }();
  return version;
}

std::string case_inputs(const RunCase& c) {
  const Experiment& e = *c.experiment;
  std::string measures;
  for (const auto& [q, norm] : panel_measures(e))
    measures += std::string(measures.empty() ? "" : ",") + to_string(q) + "/" + to_string(norm);
  return "experiment=" + escaped(e.name) + ";family=" + escaped(c.mesh->family) +
         mesh_shape_key(c.mesh->family, c.mesh->shape) + ";level=" + std::to_string(c.level) +
         ";noise-order=" + std::to_string(e.noise_order_of(*c.mesh)) +
         ";noise-seed=" + std::to_string(e.noise_seed) + noise_inputs(e.noise_model_of(*c.mesh)) +
         ";noisy=" + yes_no(e.noisy) + (e.noisy_quadratic_only ? ";noisy-rings=quadratic" : "") +
         (e.radius_c > 0.0 ? ";radius-alpha=" + format_double(e.radius_alpha) +
                                 ";radius-c=" + format_double(e.radius_c)
                           : std::string()) +
         ";vertex-set=" + std::string(to_string(e.vertex_set)) + ";" + method_inputs(*c.method) +
         ";measures=" + measures +
         (finest_level(*c.mesh, c.level)
              ? ";causes=" + std::string(to_string(kCauseQuantity)) + "/" + to_string(kCauseNorm)
              : std::string());
}

std::uint64_t case_hash(const RunCase& c, const std::string& version) {
  return fnv1a64(version, fnv1a64(";code=", fnv1a64(case_inputs(c))));
}

CaseStore::CaseStore(std::string directory, std::string version)
    : directory_(std::move(directory)), version_(std::move(version)) {}

std::string case_id(const RunCase& c) {
  const ExperimentMethod& m = *c.method;
  const std::string method = file_safe(m.label.empty() ? m.spec : m.label);
  const std::string options = hex64(fnv1a64(method_inputs(m))).substr(0, 8);
  // A mesh line's own noise (the sweeps) is named in the id: such meshes share their family.
  const std::string mesh =
      c.mesh->has_noise_model
          ? c.mesh->label() + "~" +
                noise_label(c.experiment->noise_order_of(*c.mesh), c.mesh->noise_model)
          : c.mesh->label();
  return file_safe(c.experiment->name) + "/" + file_safe(mesh) + "_L" + std::to_string(c.level) +
         "_" + method + "_" + options;
}

namespace {
// The text after the first line of a store file, if that line is the stamp of `hash` and of
// the text (first_line); nothing for a missing, unreadable, stale or corrupt file.
std::optional<std::string> read_stamped(const std::string& path, std::uint64_t hash) {
  std::error_code ec;
  if (!fs::is_regular_file(path, ec)) return std::nullopt;
  std::string text;
  try {
    text = read_file(path);
  } catch (const InputError&) {
    return std::nullopt;
  }
  const auto nl = text.find('\n');
  if (nl == std::string::npos) return std::nullopt;
  std::string rest = text.substr(nl + 1);
  if (text.compare(0, nl, first_line(hash, fnv1a64(rest))) != 0) return std::nullopt;
  return rest;
}

std::string skipped_path(const std::string& case_path) {
  return case_path.substr(0, case_path.size() - 4) + ".skipped";
}
}  // namespace

std::string CaseStore::path(const RunCase& c) const {
  return (fs::path(directory_) / (case_id(c) + ".csv")).string();
}

std::optional<std::vector<ErrorRow>> CaseStore::load(const RunCase& c,
                                                     std::vector<CauseRow>* causes) const {
  const std::string p = path(c);
  const std::optional<std::string> body = read_stamped(p, case_hash(c, version_));
  if (!body) return std::nullopt;  // missing, stale (other inputs or code) or corrupt
  std::string_view rest = *body;
  // The errors by cause, if any, follow the errors.
  std::string_view cause_text;
  if (const auto at = rest.find("\n" + std::string(kCausesComment)); at != std::string_view::npos) {
    cause_text = rest.substr(at + 1 + std::string_view(kCausesComment).size());
    rest = rest.substr(0, at + 1);
  }
  std::vector<ErrorRow> rows;
  std::vector<CauseRow> cause_rows;
  try {
    rows = parse_error_csv(std::string(rest), p);
    if (!cause_text.empty()) cause_rows = parse_cause_csv(std::string(cause_text), p);
  } catch (const InputError&) {
    return std::nullopt;
  }
  // A consistent file of this case has at most one row per panel measure (none for a quantity
  // the method does not compute, e.g. an outside estimator's normals), all of this case.
  {
    const auto measures = panel_measures(*c.experiment);
    std::set<std::pair<std::string, std::string>> wanted, seen;
    for (const auto& [q, norm] : measures) wanted.insert({to_string(q), to_string(norm)});
    for (const auto& r : rows)
      if (!wanted.count({r.quantity, r.norm}) || !seen.insert({r.quantity, r.norm}).second)
        return std::nullopt;
  }
  // The estimation time measured when the case was computed (kept, so that a reused case
  // reports the same time).
  const std::string key = "\n" + std::string(kSecondsComment);
  if (const auto at = rest.find(key); at != std::string_view::npos) {
    const auto from = at + key.size();
    const std::string value(rest.substr(from, rest.find('\n', from) - from));
    double seconds;
    try {
      seconds = parse_double(value, p);
    } catch (const InputError&) {
      return std::nullopt;
    }
    for (auto& r : rows) r.seconds = seconds;
  }
  for (const auto& r : rows)
    if (r.experiment != c.experiment->name || r.family != c.mesh->label() || r.level != c.level)
      return std::nullopt;
  for (const auto& r : cause_rows)
    if (r.experiment != c.experiment->name || r.family != c.mesh->label() || r.level != c.level)
      return std::nullopt;
  if (causes) *causes = std::move(cause_rows);
  return rows;
}

void CaseStore::save(const RunCase& c, const std::vector<ErrorRow>& rows,
                     const std::vector<CauseRow>& causes) const {
  const double seconds = rows.empty() ? std::nan("") : rows.front().seconds;
  std::string rest = error_csv_text(rows, "# " + case_inputs(c) + ";code=" + escaped(version_) +
                                              "\n" + kSecondsComment + format_double(seconds));
  if (!causes.empty()) rest += kCausesComment + cause_csv_text(causes, "");
  write_file_atomic(path(c), first_line(case_hash(c, version_), fnv1a64(rest)) + "\n" + rest);
  std::error_code ec;
  fs::remove(skipped_path(path(c)), ec);
}

void CaseStore::save_skipped(const RunCase& c, const std::string& reason) const {
  const std::string rest = reason + "\n";
  write_file_atomic(skipped_path(path(c)),
                    first_line(case_hash(c, version_), fnv1a64(rest)) + "\n" + rest);
}

std::optional<std::string> CaseStore::load_skipped(const RunCase& c) const {
  const std::optional<std::string> body =
      read_stamped(skipped_path(path(c)), case_hash(c, version_));
  if (!body || body->empty() || body->back() != '\n') return std::nullopt;
  return body->substr(0, body->size() - 1);
}

int CaseStore::prune(const std::vector<RunCase>& cases) const {
  std::set<fs::path> keep, folders;
  for (const auto& c : cases) {
    const fs::path p = path(c);
    keep.insert(p);
    keep.insert(skipped_path(p.string()));
    folders.insert(p.parent_path());
  }
  int removed = 0;
  for (const auto& folder : folders) {
    std::error_code ec;
    if (!fs::is_directory(folder, ec)) continue;
    std::vector<fs::path> extra;
    for (const auto& entry : fs::directory_iterator(folder, ec))
      if (entry.is_regular_file() &&
          (entry.path().extension() == ".csv" || entry.path().extension() == ".skipped") &&
          !keep.count(entry.path()))
        extra.push_back(entry.path());
    for (const auto& p : extra) removed += fs::remove(p, ec) ? 1 : 0;
  }
  return removed;
}

}  // namespace curvbench
