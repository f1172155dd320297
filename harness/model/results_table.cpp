#include "harness/model/results_table.h"

#include <signal.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <map>
#include <set>
#include <sstream>
#include <tuple>

#include "core/build_info.h"
#include "core/errors.h"
#include "core/text.h"
#include "harness/model/metrics.h"
#include "mesh/io.h"
#include "methods/estimator.h"

namespace curvbench {

namespace {

constexpr const char* kErrorHeader =
    "experiment,surface,family,level,vertices,h,method,degree,rings,noise,vertex_set,quantity,"
    "norm,error,counted,excluded,degree_reduced,failed";
constexpr const char* kRateHeader =
    "experiment,family,method,degree,rings,noise,vertex_set,quantity,norm,levels,h_first,h_last,"
    "e_first,e_last,rate,pairwise_rates";

// One line's fields, split at commas outside double quotes (RFC 4180: a quoted field may hold
// commas, and "" inside it is one quote; make bench's limits.csv quotes its notes).
std::vector<std::string> split_csv(const std::string& line) {
  std::vector<std::string> out;
  std::string cur;
  bool quoted = false;
  for (size_t i = 0; i < line.size(); ++i) {
    const char c = line[i];
    if (quoted) {
      if (c != '"')
        cur += c;
      else if (i + 1 < line.size() && line[i + 1] == '"')
        cur += line[++i];
      else
        quoted = false;
    } else if (c == '"') {
      quoted = true;
    } else if (c == ',') {
      out.push_back(cur);
      cur.clear();
    } else if (c != '\r') {
      cur += c;
    }
  }
  out.push_back(cur);
  return out;
}

}  // namespace

std::string scientific(double x, const char* not_finite) {
  if (!std::isfinite(x)) return not_finite;
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.2e", x);
  return buf;
}

std::string two_decimals(double x) {
  if (!std::isfinite(x)) return "n/a";
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.2f", x);
  return buf;
}

std::string format_double(double x) {
  if (std::isnan(x)) return "nan";
  if (std::isinf(x)) return x > 0 ? "inf" : "-inf";
  char buf[40];
  std::snprintf(buf, sizeof buf, "%.17g", x);
  return buf;
}

int remove_stale_temp_files(const std::string& directory) {
  namespace fs = std::filesystem;
  std::error_code ec;
  if (!fs::is_directory(directory, ec)) return 0;
  std::vector<fs::path> stale;
  for (auto it = fs::recursive_directory_iterator(directory, ec);
       !ec && it != fs::recursive_directory_iterator(); it.increment(ec)) {
    if (!it->is_regular_file(ec)) continue;
    const std::string name = it->path().filename().string();
    const auto at = name.rfind(".tmp.");
    if (at == std::string::npos || at + 5 == name.size()) continue;
    const std::string pid_text = name.substr(at + 5);
    if (pid_text.find_first_not_of("0123456789") != std::string::npos || pid_text.size() > 9)
      continue;
    const pid_t pid = static_cast<pid_t>(std::stol(pid_text));
    // Still running (or not ours to signal): keep. Gone (ESRCH): its writer is dead.
    if (pid > 0 && ::kill(pid, 0) == -1 && errno == ESRCH) stale.push_back(it->path());
  }
  int removed = 0;
  for (const auto& p : stale) removed += fs::remove(p, ec) ? 1 : 0;
  return removed;
}

std::string error_csv_text(const std::vector<ErrorRow>& rows, const std::string& comment) {
  std::ostringstream out;
  out << comment << "\n" << kErrorHeader << "\n";
  for (const auto& r : rows) {
    out << r.experiment << ',' << r.surface << ',' << r.family << ',' << r.level << ','
        << r.vertices << ',' << format_double(r.h) << ',' << r.method << ',' << r.degree << ','
        << r.rings << ',' << r.noise << ',' << r.vertex_set << ',' << r.quantity << ',' << r.norm
        << ',' << format_double(r.error) << ',' << r.counted << ',' << r.excluded << ','
        << r.degree_reduced << ',' << r.failed << "\n";
  }
  return out.str();
}

void write_error_csv(const std::string& path, const std::vector<ErrorRow>& rows) {
  write_file_atomic(path, error_csv_text(rows, provenance_comment()));
}

void write_timing_csv(const std::string& path, const std::vector<ErrorRow>& rows) {
  std::ostringstream out;
  out << provenance_comment() << "\n"
      << "experiment,family,level,vertices,method,seconds,us_per_vertex\n";
  std::set<std::tuple<std::string, int, std::string>> seen;
  for (const auto& r : rows) {
    if (!seen.insert({r.family, r.level, r.method}).second) continue;
    out << r.experiment << ',' << r.family << ',' << r.level << ',' << r.vertices << ',' << r.method
        << ',' << format_double(r.seconds) << ','
        << format_double(r.vertices > 0 ? 1e6 * r.seconds / r.vertices : r.seconds) << "\n";
  }
  write_file_atomic(path, out.str());
}

std::vector<TimingRow> read_timing_csv(const std::string& path) {
  const CsvTable t = read_csv_table(path);
  const size_t ce = t.col("experiment"), cf = t.col("family"), cl = t.col("level"),
               cv = t.col("vertices"), cm = t.col("method"), cs = t.col("seconds");
  std::vector<TimingRow> out;
  for (size_t i = 0; i < t.rows.size(); ++i)
    out.push_back({t.text(i, ce), t.text(i, cf), t.text(i, cm), t.integer(i, cl), t.integer(i, cv),
                   t.number(i, cs)});
  return out;
}

void write_skipped_csv(const std::string& path, const std::vector<SkippedMethod>& rows) {
  if (rows.empty()) {
    std::error_code ec;
    std::filesystem::remove(path, ec);
    return;
  }
  std::ostringstream out;
  out << provenance_comment() << "\n"
      << "experiment,method,cases,reason\n";
  for (const auto& r : rows) {
    std::string reason = r.reason;
    std::replace(reason.begin(), reason.end(), ',', ';');
    out << r.experiment << ',' << r.method << ',' << r.cases << ',' << reason << "\n";
  }
  write_file_atomic(path, out.str());
}

std::vector<SkippedMethod> read_skipped_csv(const std::string& path) {
  std::vector<SkippedMethod> out;
  if (!std::filesystem::exists(path)) return out;
  const CsvTable t = read_csv_table(path);
  const size_t ce = t.col("experiment"), cm = t.col("method"), cc = t.col("cases"),
               cr = t.col("reason");
  for (size_t i = 0; i < t.rows.size(); ++i)
    out.push_back({t.text(i, ce), t.text(i, cm), t.integer(i, cc), t.text(i, cr)});
  return out;
}

void write_rate_csv(const std::string& path, const std::vector<RateRow>& rows) {
  std::ostringstream out;
  out << provenance_comment() << "\n" << kRateHeader << "\n";
  for (const auto& r : rows) {
    out << r.experiment << ',' << r.family << ',' << r.method << ',' << r.degree << ',' << r.rings
        << ',' << r.noise << ',' << r.vertex_set << ',' << r.quantity << ',' << r.norm << ','
        << r.levels << ',' << format_double(r.h_first) << ',' << format_double(r.h_last) << ','
        << format_double(r.e_first) << ',' << format_double(r.e_last) << ','
        << format_double(r.rate) << ',';
    for (size_t i = 0; i < r.pairwise.size(); ++i)
      out << (i ? ";" : "") << format_double(r.pairwise[i]);
    out << "\n";
  }
  write_file_atomic(path, out.str());
}

size_t CsvTable::col(const std::string& name) const {
  for (size_t i = 0; i < header.size(); ++i)
    if (header[i] == name) return i;
  throw InputError(path + ": no column '" + name + "'");
}

double CsvTable::number(size_t row, size_t c) const {
  return parse_double(rows[row][c], path + ":" + std::to_string(lines[row]));
}

int CsvTable::integer(size_t row, size_t c) const {
  return static_cast<int>(parse_integer(rows[row][c], path + ":" + std::to_string(lines[row])));
}

CsvTable read_csv_table(const std::string& path) {
  return parse_csv_table(read_file(path), path);
}

CsvTable parse_csv_table(const std::string& text, const std::string& path) {
  std::istringstream in(text);
  CsvTable t;
  t.path = path;
  std::string line;
  int lineno = 0;
  bool have_header = false;
  while (std::getline(in, line)) {
    ++lineno;
    if (line.empty() || line == "\r" || line.rfind('#', 0) == 0) continue;
    auto fields = split_csv(line);
    if (!have_header) {
      t.header = std::move(fields);
      have_header = true;
      continue;
    }
    if (fields.size() != t.header.size())
      throw InputError(path + ":" + std::to_string(lineno) + ": expected " +
                       std::to_string(t.header.size()) + " fields, got " +
                       std::to_string(fields.size()));
    t.rows.push_back(std::move(fields));
    t.lines.push_back(lineno);
  }
  if (!have_header) throw InputError(path + ": empty file (no header)");
  return t;
}

std::vector<ErrorRow> read_error_csv(const std::string& path) {
  return parse_error_csv(read_file(path), path);
}

RadiusLabel split_radius_label(const std::string& label) {
  for (NeighbourhoodSize size : kNeighbourhoodSizes) {
    const std::string option = radius_option(size);
    if (option.empty()) continue;
    const std::string key = " " + option + "=";
    const auto at = label.rfind(key);
    if (at == std::string::npos) continue;
    const std::string value = label.substr(at + key.size());
    char* end = nullptr;
    const double x = std::strtod(value.c_str(), &end);
    if (value.empty() || *end != '\0' || !std::isfinite(x)) continue;
    return {label.substr(0, at), option, x};
  }
  return {label, "", std::nan("")};
}

void type_columns(ErrorRow& row) {
  const RadiusLabel radius = split_radius_label(row.method);
  row.method_base = radius.method;
  row.radius_parameter = radius.parameter;
  row.radius = radius.radius;
  row.noise_level = parse_noise_label(row.noise);
}

std::vector<ErrorRow> parse_error_csv(const std::string& text, const std::string& path) {
  const CsvTable t = parse_csv_table(text, path);
  std::string header;
  for (const auto& h : t.header) header += (header.empty() ? "" : ",") + h;
  if (header != kErrorHeader)
    throw InputError(path + ": unexpected header (not an errors CSV of this version)");
  std::vector<ErrorRow> rows;
  for (size_t i = 0; i < t.rows.size(); ++i) {
    ErrorRow r;
    r.experiment = t.text(i, 0);
    r.surface = t.text(i, 1);
    r.family = t.text(i, 2);
    r.level = t.integer(i, 3);
    r.vertices = t.integer(i, 4);
    r.h = t.number(i, 5);
    r.method = t.text(i, 6);
    r.degree = t.integer(i, 7);
    r.rings = t.text(i, 8);
    r.noise = t.text(i, 9);
    r.vertex_set = t.text(i, 10);
    r.quantity = t.text(i, 11);
    r.norm = t.text(i, 12);
    r.error = t.number(i, 13);
    r.counted = t.integer(i, 14);
    r.excluded = t.integer(i, 15);
    r.degree_reduced = t.integer(i, 16);
    r.failed = t.integer(i, 17);
    type_columns(r);
    rows.push_back(std::move(r));
  }
  return rows;
}

std::vector<RateRow> compute_rates(const std::vector<ErrorRow>& rows) {
  using Key = std::tuple<std::string, std::string, std::string, std::string, std::string,
                         std::string, std::string, std::string>;
  std::map<Key, std::vector<const ErrorRow*>> groups;
  std::vector<Key> order;  // first-seen order keeps the output in the experiment's order
  for (const auto& r : rows) {
    Key k{r.experiment, r.family, r.method, r.rings, r.noise, r.vertex_set, r.quantity, r.norm};
    auto [it, inserted] = groups.try_emplace(k);
    if (inserted) order.push_back(k);
    it->second.push_back(&r);
  }
  std::vector<RateRow> out;
  for (const auto& k : order) {
    auto g = groups[k];
    std::sort(g.begin(), g.end(),
              [](const ErrorRow* a, const ErrorRow* b) { return a->level < b->level; });
    RateRow rr;
    const ErrorRow& first = *g.front();
    const ErrorRow& last = *g.back();
    rr.experiment = first.experiment;
    rr.family = first.family;
    rr.method = first.method;
    rr.degree = first.degree;
    rr.rings = first.rings;
    rr.noise = first.noise;
    rr.vertex_set = first.vertex_set;
    rr.quantity = first.quantity;
    rr.norm = first.norm;
    rr.levels = std::to_string(first.level) + "-" + std::to_string(last.level);
    rr.h_first = first.h;
    rr.h_last = last.h;
    rr.e_first = first.error;
    rr.e_last = last.error;
    rr.rate =
        g.size() >= 2 ? convergence_rate(first.error, last.error, first.h, last.h) : std::nan("");
    std::vector<double> e, h;
    for (const auto* r : g) {
      e.push_back(r->error);
      h.push_back(r->h);
    }
    rr.pairwise = pairwise_rates(e, h);
    out.push_back(std::move(rr));
  }
  return out;
}

}  // namespace curvbench
