#include "harness/results_table.h"

#include <unistd.h>
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>
#include <tuple>

#include "core/build_info.h"
#include "core/errors.h"
#include "core/text.h"
#include "harness/metrics.h"

namespace curvbench {

namespace {

int to_int(const std::string& s, const std::string& where) {
  return static_cast<int>(parse_integer(s, where));
}

constexpr const char* kErrorHeader =
    "experiment,surface,family,level,vertices,h,method,degree,rings,noise,vertex_set,quantity,"
    "norm,error,counted,excluded,degree_reduced,failed";
constexpr const char* kRateHeader =
    "experiment,family,method,degree,rings,noise,vertex_set,quantity,norm,levels,h_first,h_last,"
    "e_first,e_last,rate,pairwise_rates";

std::vector<std::string> split_csv(const std::string& line) {
  std::vector<std::string> out;
  std::string cur;
  for (char c : line) {
    if (c == ',') {
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

std::string format_double(double x) {
  if (std::isnan(x)) return "nan";
  if (std::isinf(x)) return x > 0 ? "inf" : "-inf";
  char buf[40];
  std::snprintf(buf, sizeof buf, "%.17g", x);
  return buf;
}

void write_file_atomic(const std::string& path, const std::string& content) {
  namespace fs = std::filesystem;
  const fs::path target(path);
  if (target.has_parent_path()) {
    std::error_code ec;
    fs::create_directories(target.parent_path(), ec);
  }
  const std::string tmp = path + ".tmp." + std::to_string(::getpid());
  {
    std::ofstream out(tmp, std::ios::binary);
    if (!out) throw InputError(path + ": cannot write (" + tmp + ")");
    out << content;
    out.flush();
    if (!out) {
      std::error_code ec;
      fs::remove(tmp, ec);
      throw InputError(path + ": write failed");
    }
  }
  std::error_code ec;
  fs::rename(tmp, target, ec);
  if (ec) {
    fs::remove(tmp, ec);
    throw InputError(path + ": cannot rename into place");
  }
}

void write_error_csv(const std::string& path, const std::vector<ErrorRow>& rows) {
  std::ostringstream out;
  out << provenance_comment() << "\n" << kErrorHeader << "\n";
  for (const auto& r : rows) {
    out << r.experiment << ',' << r.surface << ',' << r.family << ',' << r.level << ','
        << r.vertices << ',' << format_double(r.h) << ',' << r.method << ',' << r.degree << ','
        << r.rings << ',' << r.noise << ',' << r.vertex_set << ',' << r.quantity << ',' << r.norm
        << ',' << format_double(r.error) << ',' << r.counted << ',' << r.excluded << ','
        << r.degree_reduced << ',' << r.failed << "\n";
  }
  write_file_atomic(path, out.str());
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

std::vector<ErrorRow> read_error_csv(const std::string& path) {
  std::ifstream in(path);
  if (!in) throw InputError(path + ": cannot open results CSV");
  std::string line;
  int lineno = 0;
  bool have_header = false;
  while (std::getline(in, line)) {  // comment lines ('#', provenance) come before the header
    ++lineno;
    if (line.rfind('#', 0) == 0) continue;
    have_header = true;
    break;
  }
  if (!have_header || line != kErrorHeader)
    throw InputError(path + ":" + std::to_string(lineno) +
                     ": unexpected header (not an errors CSV of this version)");
  std::vector<ErrorRow> rows;
  while (std::getline(in, line)) {
    ++lineno;
    if (line.empty() || line.rfind('#', 0) == 0) continue;
    const std::string where = path + ":" + std::to_string(lineno);
    const auto f = split_csv(line);
    if (f.size() != 18)
      throw InputError(where + ": expected 18 fields, got " + std::to_string(f.size()));
    ErrorRow r;
    r.experiment = f[0];
    r.surface = f[1];
    r.family = f[2];
    r.level = to_int(f[3], where);
    r.vertices = to_int(f[4], where);
    r.h = parse_double(f[5], where);
    r.method = f[6];
    r.degree = to_int(f[7], where);
    r.rings = f[8];
    r.noise = f[9];
    r.vertex_set = f[10];
    r.quantity = f[11];
    r.norm = f[12];
    r.error = parse_double(f[13], where);
    r.counted = to_int(f[14], where);
    r.excluded = to_int(f[15], where);
    r.degree_reduced = to_int(f[16], where);
    r.failed = to_int(f[17], where);
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
