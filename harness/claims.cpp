#include "harness/claims.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <functional>
#include <limits>
#include <map>
#include <optional>
#include <sstream>
#include <tuple>

#include "core/errors.h"
#include "core/text.h"
#include "harness/metrics.h"
#include "harness/results_table.h"
#include "mesh/io.h"

namespace curvbench {

const char* to_string(Verdict v) {
  switch (v) {
    case Verdict::reproduced:
      return "reproduced";
    case Verdict::not_reproduced:
      return "not reproduced";
    case Verdict::not_applicable:
      return "not applicable";
  }
  return "?";
}

namespace {

namespace fs = std::filesystem;

constexpr double kInf = std::numeric_limits<double>::infinity();

// ---- formatting -------------------------------------------------------------------------------

std::string non_finite(double x) {
  if (std::isnan(x)) return "nan";
  return x > 0 ? "inf" : "-inf";
}

std::string f2(double x) {  // rates and ratios
  if (!std::isfinite(x)) return non_finite(x);
  char buf[48];
  std::snprintf(buf, sizeof buf, "%.2f", x);
  return buf;
}

std::string e2(double x) {  // errors
  if (!std::isfinite(x)) return non_finite(x);
  char buf[48];
  std::snprintf(buf, sizeof buf, "%.2e", x);
  return buf;
}

std::string e3(double x) {  // Table 4 values, one digit more than the paper prints
  if (!std::isfinite(x)) return non_finite(x);
  char buf[48];
  std::snprintf(buf, sizeof buf, "%.3e", x);
  return buf;
}

std::string g3(double x) {  // seconds, ring sizes
  if (!std::isfinite(x)) return non_finite(x);
  char buf[48];
  std::snprintf(buf, sizeof buf, "%.3g", x);
  return buf;
}

std::string upper(std::string s) {
  for (char& ch : s) ch = static_cast<char>(std::toupper(static_cast<unsigned char>(ch)));
  return s;
}

std::string join(const std::vector<std::string>& parts, const std::string& sep) {
  std::string out;
  for (size_t i = 0; i < parts.size(); ++i) out += (i ? sep : "") + parts[i];
  return out;
}

// ---- evidence accumulator ---------------------------------------------------------------------

// Collects one line per check. Verdict: any missing input -> not applicable; else any failed
// check -> not reproduced; else reproduced (not applicable if nothing was checked).
class Check {
 public:
  void require(bool pass, const std::string& text) {
    lines_.push_back((pass ? "[ok] " : "[FAIL] ") + text);
    ++(pass ? passed_ : failed_);
  }
  void info(const std::string& text) { lines_.push_back("[info] " + text); }
  void missing(const std::string& text) {
    const std::string line = "[missing] " + text;
    if (std::find(lines_.begin(), lines_.end(), line) == lines_.end()) lines_.push_back(line);
    ++missing_;
  }
  Verdict verdict() const {
    if (missing_ > 0) return Verdict::not_applicable;
    if (failed_ > 0) return Verdict::not_reproduced;
    return passed_ > 0 ? Verdict::reproduced : Verdict::not_applicable;
  }
  std::string evidence() const { return join(lines_, "\n"); }

 private:
  std::vector<std::string> lines_;
  int passed_ = 0, failed_ = 0, missing_ = 0;
};

// ---- simple CSV tables with a header (table2/table4/table5_timing) ----------------------------

using Table = CsvTable;

std::optional<Table> read_table(const std::string& path) {
  if (!fs::exists(path)) return std::nullopt;
  return read_csv_table(path);
}

// ---- error series -----------------------------------------------------------------------------

struct Point {
  int level = 0;
  double h = 0.0;
  double e = 0.0;
};

// One (experiment, family, method, rings, noise, vertex set, quantity, norm) series.
struct Series {
  std::string experiment, family, method, rings, noise, vertex_set, quantity, norm;
  std::vector<Point> points;  // increasing level, >= 1

  const Point& first() const { return points.front(); }
  const Point& last() const { return points.back(); }
  // Same definition as compute_rates: first and last level present.
  double rate() const { return convergence_rate(first().e, last().e, first().h, last().h); }
  const Point* at(int level) const {
    for (const auto& p : points)
      if (p.level == level) return &p;
    return nullptr;
  }
  std::string label() const { return family + " " + method + " " + quantity + " " + norm; }
  // "errors at levels 1-4: a, b, c, d; level-to-level rates r12, r23, r34"
  std::string detail() const;
};

struct Query {
  std::string experiment;  ///< the experiment producing the series (preferred; named in hints)
  std::string family, method, quantity, norm;
  std::string noise = "none";
  std::string vertex_set;  ///< "" = the paper's rule: interior-only methods (Xu) on the bump
                           ///< interior, else all
  double ring = 0.0;       ///< ring of the claim's setup; 0 = not part of the setup
};

bool is_xu(const std::string& method) {
  return upper(method).rfind("XU", 0) == 0;
}

bool ring_equals(const std::string& label, double ring) {
  try {
    return std::abs(std::stod(label) - ring) < 1e-9;
  } catch (const std::exception&) {
    return false;
  }
}

// ---- timing (table5_timing.csv) --------------------------------------------------------------

struct TimingEntry {
  double seconds = kInf;  ///< minimum over repeated rows
  double verts = 0.0, tris = 0.0;
};
using TimingSeries = std::map<int, TimingEntry>;  // level -> entry

// ---- all inputs -------------------------------------------------------------------------------

class Data {
 public:
  explicit Data(const std::string& dir) {
    std::error_code ec;
    if (!fs::is_directory(dir, ec)) return;
    std::vector<fs::path> csvs;
    for (const auto& entry : fs::directory_iterator(dir))
      if (entry.is_regular_file() && entry.path().extension() == ".csv")
        csvs.push_back(entry.path());
    std::sort(csvs.begin(), csvs.end());
    for (const auto& p : csvs) {
      const std::string text = read_file(p.string());
      std::istringstream in(text);
      std::string head;
      while (std::getline(in, head) && head.rfind('#', 0) == 0) {
      }
      // The errors header starts like this; parse_error_csv validates the whole header.
      if (head.rfind("experiment,surface,family,level,", 0) != 0) continue;
      auto rows = parse_error_csv(text, p.string());
      rows_.insert(rows_.end(), rows.begin(), rows.end());
    }
    build_series();
    table2 = read_table(dir + "/table2.csv");
    table4 = read_table(dir + "/table4.csv");
    table5 = read_table(dir + "/table5_timing.csv");
    if (table5) build_timing();
  }

  const std::vector<ErrorRow>& rows() const { return rows_; }

  /// The series matching q, or nullptr after recording why in chk.
  const Series* find(Check& chk, const Query& q) const {
    const std::string vset =
        !q.vertex_set.empty()
            ? q.vertex_set
            : (scores_interior_only(q.method) && q.family.rfind("bump", 0) == 0 ? "interior"
                                                                                : "all");
    const std::string what = q.method + " " + q.quantity + " " + q.norm + " on " + q.family +
                             " (noise " + q.noise + ", vertex set " + vset + ")";
    std::vector<const Series*> cand;
    for (const auto& s : series_)
      if (s.family == q.family && upper(s.method) == upper(q.method) && s.quantity == q.quantity &&
          s.norm == q.norm && s.noise == q.noise && s.vertex_set == vset)
        cand.push_back(&s);
    if (cand.empty()) {
      for (const auto& s : series_)
        if (s.family == q.family && upper(s.method) == upper(q.method) &&
            s.quantity == q.quantity && s.norm == q.norm && s.noise == q.noise) {
          chk.missing("setup differs: no rows for " + what + "; experiment " + s.experiment +
                      " scored it over vertex set " + s.vertex_set);
          return nullptr;
        }
      chk.missing("no rows for " + what + ": experiment " + q.experiment +
                  " not run (make experiments)");
      return nullptr;
    }
    if (q.ring > 0) {
      std::vector<const Series*> ringed;
      for (const auto* s : cand)
        if (ring_equals(s->rings, q.ring)) ringed.push_back(s);
      if (ringed.empty()) {
        chk.missing("setup differs: " + what + " was run with ring " + cand.front()->rings +
                    " (experiment " + cand.front()->experiment + "), the claim's setup is ring " +
                    g3(q.ring));
        return nullptr;
      }
      cand = ringed;
    }
    const Series* pick = cand.front();
    for (const auto* s : cand)
      if (s->experiment == q.experiment) {
        pick = s;
        break;
      }
    if (pick->points.size() < 2) {
      chk.missing(what + ": only level " + std::to_string(pick->first().level) +
                  " present (a rate needs two levels)");
      return nullptr;
    }
    return pick;
  }

  /// Single-threaded torus-structured timings of a method label, or nullptr after recording.
  const TimingSeries* timing(Check& chk, const std::string& method) const {
    if (!table5) {
      chk.missing("table5_timing.csv not present: run make bench");
      return nullptr;
    }
    auto it = timing_.find(upper(method));
    if (it == timing_.end()) {
      chk.missing("table5_timing.csv has no single-threaded torus-structured rows for " + method);
      return nullptr;
    }
    return &it->second;
  }
  /// Method labels (upper case) of the timing table.
  std::vector<std::string> timing_methods() const {
    std::vector<std::string> out;
    for (const auto& [m, s] : timing_) out.push_back(m);
    return out;
  }

  std::optional<Table> table2, table4, table5;

 private:
  void build_series() {
    using Key = std::tuple<std::string, std::string, std::string, std::string, std::string,
                           std::string, std::string, std::string>;
    std::map<Key, size_t> index;
    for (const auto& r : rows_) {
      const Key k{r.experiment, r.family,     upper(r.method), r.rings,
                  r.noise,      r.vertex_set, r.quantity,      r.norm};
      auto [it, inserted] = index.try_emplace(k, series_.size());
      if (inserted)
        series_.push_back({r.experiment,
                           r.family,
                           r.method,
                           r.rings,
                           r.noise,
                           r.vertex_set,
                           r.quantity,
                           r.norm,
                           {}});
      auto& pts = series_[it->second].points;
      pts.erase(std::remove_if(pts.begin(), pts.end(),
                               [&](const Point& p) { return p.level == r.level; }),
                pts.end());
      pts.push_back({r.level, r.h, r.error});
    }
    for (auto& s : series_)
      std::sort(s.points.begin(), s.points.end(),
                [](const Point& a, const Point& b) { return a.level < b.level; });
  }

  void build_timing() {
    const Table& t = *table5;
    const size_t cm = t.col("mesh"), cl = t.col("level"), cv = t.col("verts"), ct = t.col("tris"),
                 cme = t.col("method"), cth = t.col("threads"), cs = t.col("seconds");
    for (size_t i = 0; i < t.rows.size(); ++i) {
      if (upper(t.text(i, cm)) != "TORUS-STRUCTURED" || t.number(i, cth) != 1.0) continue;
      auto& e = timing_[upper(t.text(i, cme))][static_cast<int>(t.number(i, cl))];
      const double s = t.number(i, cs);
      if (s < e.seconds) {
        e.seconds = s;
        e.verts = t.number(i, cv);
        e.tris = t.number(i, ct);
      }
    }
  }

  std::vector<ErrorRow> rows_;
  std::vector<Series> series_;
  std::map<std::string, TimingSeries> timing_;
};

// ---- comparison helpers -----------------------------------------------------------------------

struct LevelValue {
  int level = 0;
  double value = 0.0;
};

// "levels 1-4: a, b, c, d" (or "levels 1,2,4: ..." if not contiguous).
std::string levels_text(const std::vector<int>& levels, const std::vector<std::string>& values) {
  if (levels.empty()) return "no levels";
  bool contiguous = true;
  std::vector<std::string> ls;
  for (size_t i = 0; i < levels.size(); ++i) {
    contiguous = contiguous && (i == 0 || levels[i] == levels[i - 1] + 1);
    ls.push_back(std::to_string(levels[i]));
  }
  const std::string head = levels.size() == 1 ? "level " + ls.front()
                           : contiguous       ? "levels " + ls.front() + "-" + ls.back()
                                              : "levels " + join(ls, ",");
  return head + ": " + join(values, ", ");
}

std::string levels_text(const std::vector<LevelValue>& v) {
  std::vector<int> levels;
  std::vector<std::string> values;
  for (const auto& x : v) {
    levels.push_back(x.level);
    values.push_back(f2(x.value));
  }
  return levels_text(levels, values);
}

std::string Series::detail() const {
  std::vector<int> levels;
  std::vector<std::string> es, hs;
  std::vector<double> ev, hv;
  for (const auto& p : points) {
    levels.push_back(p.level);
    es.push_back(e2(p.e));
    ev.push_back(p.e);
    hv.push_back(p.h);
  }
  for (double r : pairwise_rates(ev, hv)) hs.push_back(f2(r));
  return "errors at " + levels_text(levels, es) + "; level-to-level rates " + join(hs, ", ");
}

// a.e / b.e at the levels present in both.
std::vector<LevelValue> error_ratios(const Series& a, const Series& b) {
  std::vector<LevelValue> out;
  for (const auto& p : a.points)
    if (const Point* q = b.at(p.level)) out.push_back({p.level, p.e / q->e});
  return out;
}

// a.e / min(others' e) at the levels present in all of them.
std::vector<LevelValue> ratios_to_min(const Series& a, const std::vector<const Series*>& others) {
  std::vector<LevelValue> out;
  for (const auto& p : a.points) {
    double m = kInf;
    bool all = true;
    for (const auto* o : others) {
      const Point* q = o->at(p.level);
      if (!q)
        all = false;
      else
        m = std::min(m, q->e);
    }
    if (all) out.push_back({p.level, p.e / m});
  }
  return out;
}

// max(e) / min(e) over the series at the levels present in all of them.
std::vector<LevelValue> spreads(const std::vector<const Series*>& ss) {
  std::vector<LevelValue> out;
  for (const auto& p : ss.front()->points) {
    double lo = kInf, hi = -kInf;
    bool all = true;
    for (const auto* s : ss) {
      const Point* q = s->at(p.level);
      if (!q) {
        all = false;
        continue;
      }
      lo = std::min(lo, q->e);
      hi = std::max(hi, q->e);
    }
    if (all) out.push_back({p.level, hi / lo});
  }
  return out;
}

std::vector<std::string> methods_of(const std::vector<const Series*>& ss) {
  std::vector<std::string> out;
  for (const auto* s : ss) out.push_back(s->method);
  return out;
}

// Every level value satisfies pred.
void require_every_level(Check& c, const std::vector<LevelValue>& v,
                         const std::function<bool(double)>& pred, const std::string& what,
                         const std::string& cond) {
  if (v.empty()) {
    c.missing(what + ": no level in common");
    return;
  }
  bool ok = true;
  for (const auto& x : v) ok = ok && pred(x.value);
  c.require(ok, what + " at " + levels_text(v) + " (" + cond + " at every level)");
}

// pred holds at >= 3/4 of the levels ("at >= 3 of 4 levels"); extra(x), described by
// extra_cond ("" = none), must hold wherever pred does.
void require_three_of_four(Check& c, const std::vector<LevelValue>& v,
                           const std::function<bool(double)>& pred, const std::string& what,
                           const std::string& cond,
                           const std::function<bool(double)>& extra = nullptr,
                           const std::string& extra_cond = "") {
  if (v.empty()) {
    c.missing(what + ": no level in common");
    return;
  }
  int count = 0;
  bool extra_ok = true;
  for (const auto& x : v)
    if (pred(x.value)) {
      ++count;
      extra_ok = extra_ok && (!extra || extra(x.value));
    }
  const int n = static_cast<int>(v.size());
  const int need = (3 * n + 3) / 4;
  c.require(count >= need && extra_ok,
            what + " at " + levels_text(v) + " (" + cond + " at " + std::to_string(count) + " of " +
                std::to_string(n) + " levels, need " + std::to_string(need) + ")" +
                (extra_cond.empty()
                     ? ""
                     : "; where it holds, " + extra_cond + ": " + (extra_ok ? "yes" : "no")));
}

std::string rate_line(const Series& s, const std::string& cond) {
  return s.label() + ": rate " + f2(s.rate()) + " " + cond + "; " + s.detail();
}

// "failed to converge" (PAPER_CLAIMS conventions). Returns the reasons; empty = converges.
std::vector<std::string> failure_reasons(const Series& s) {
  const double e1 = s.first().e, en = s.last().e, r = s.rate();
  std::vector<std::string> why;
  if (!std::isfinite(en)) why.push_back("non-finite error at the finest level");
  if (r <= 0.5) why.push_back("rate " + f2(r) + " <= 0.5");
  if (en >= 0.7 * e1) why.push_back("e_last/e_first " + f2(en / e1) + " >= 0.7");
  bool monotone = true;
  for (size_t i = 1; i < s.points.size(); ++i)
    monotone = monotone && s.points[i].e <= s.points[i - 1].e;
  if (!monotone && en >= e1) why.push_back("non-monotone with no net decrease");
  return why;
}

void require_failure(Check& c, const Series& s, const std::string& prefix = "") {
  const auto why = failure_reasons(s);
  if (!why.empty()) {
    c.require(true,
              prefix + s.label() + " fails to converge (" + join(why, ", ") + "); " + s.detail());
  } else {
    c.require(false, prefix + s.label() + " converges (rate " + f2(s.rate()) +
                         " > 0.5, e_last/e_first " + f2(s.last().e / s.first().e) + " < 0.7); " +
                         s.detail());
  }
}

// ---- claim constants --------------------------------------------------------------------------

// The well-shaped torus (the paper's unstructured GAMBIT meshes): the structured staggered mesh
// with seeded tangential jitter (ALGORITHM_NOTES §10.1(b)). The unjittered structured mesh is
// too symmetric to stand in for it (every vertex has the same stencil: its principal directions
// come out exact to roundoff and its Linf errors converge like its L2 errors).
const char* const kWell = "torus-jittered";
const char* const kPoor = "torus-iso-projected";
const char* const kNoisyTorus = "torus-iso";
const char* const kBumpIrr = "bump-irregular";
const char* const kBump48 = "bump-48";
const std::vector<std::string> kTori = {kWell, kPoor};
const std::vector<std::string> kBumps = {kBumpIrr, kBump48};
const std::vector<std::string> kDeg2Others = {"LHF-2", "LOP-2", "LSCM-2"};

Query query(const std::string& experiment, const std::string& family, const std::string& method,
            const std::string& quantity, const std::string& norm, const std::string& noise = "none",
            double ring = 0.0, const std::string& vertex_set = "") {
  Query q;
  q.experiment = experiment;
  q.family = family;
  q.method = method;
  q.quantity = quantity;
  q.norm = norm;
  q.noise = noise;
  q.ring = ring;
  q.vertex_set = vertex_set;
  return q;
}

// Degree of a label "XXX-d".
int degree_of(const std::string& method) {
  return method.back() - '0';
}

// Rings of the §5.1 (noise-free torus) and §5.3 (noisy torus) setups.
double torus_ring(const std::string& method) {
  if (is_xu(method)) return 1.0;
  return 0.5 * (degree_of(method) + 1);
}
double noisy_torus_ring(const std::string& method) {
  return is_xu(method) ? 1.0 : torus_ring(method) + 0.5;
}

// ---- A: exact facts ---------------------------------------------------------------------------

const int kGrid[5] = {16, 32, 64, 128, 256};

// Row of table4.csv for grid n, or -1 after recording it missing.
int table4_row(const Data& d, Check& c, int n) {
  const Table& t = *d.table4;
  const size_t cg = t.col("grid_points");
  for (size_t i = 0; i < t.rows.size(); ++i)
    if (t.number(i, cg) == n) return static_cast<int>(i);
  c.missing("table4.csv has no row for n = " + std::to_string(n) + " (run with --table4-max 256)");
  return -1;
}

bool have_table4(const Data& d, Check& c) {
  if (!d.table4) c.missing("table4.csv not present: run make experiments");
  return d.table4.has_value();
}

void claim_a1(const Data& d, Check& c) {
  if (!d.table2) {
    c.missing("table2.csv not present: run make experiments");
    return;
  }
  const Table& t = *d.table2;
  const size_t cd = t.col("degree"), cc = t.col("coefficients"), cp = t.col("points_with_centre"),
               cr = t.col("ring");
  const int points[6] = {7, 13, 19, 31, 37, 55};
  const int coeffs[6] = {3, 6, 10, 15, 21, 28};
  for (int deg = 1; deg <= 6; ++deg) {
    int row = -1;
    for (size_t i = 0; i < t.rows.size(); ++i)
      if (t.number(i, cd) == deg) row = static_cast<int>(i);
    if (row < 0) {
      c.missing("table2.csv has no row for d = " + std::to_string(deg));
      continue;
    }
    const double p = t.number(row, cp), k = t.number(row, cc);
    c.require(p == points[deg - 1] && k == coeffs[deg - 1],
              "d = " + std::to_string(deg) + ", " + t.text(row, cr) + "-ring: " + g3(p) +
                  " points with centre (paper " + std::to_string(points[deg - 1]) + "), " + g3(k) +
                  " coefficients (paper " + std::to_string(coeffs[deg - 1]) + ")");
  }
}

void claim_a2(const Data& d, Check& c) {
  if (!have_table4(d, c)) return;
  const int paper[5] = {320, 1760, 7320, 31136, 122464};
  const size_t cv = d.table4->col("vertices");
  for (int i = 0; i < 5; ++i) {
    const int row = table4_row(d, c, kGrid[i]);
    if (row < 0) continue;
    const double v = d.table4->number(row, cv);
    c.require(v == paper[i], "n = " + std::to_string(kGrid[i]) + ": " +
                                 std::to_string(static_cast<long long>(v)) + " vertices (paper " +
                                 std::to_string(paper[i]) + ")");
  }
}

// Unit of the last printed digit of a paper value printed with `digits` significant digits.
double last_digit_unit(double paper, int digits) {
  return std::pow(10.0, std::floor(std::log10(paper)) - (digits - 1));
}

// Our value rounded to the paper's last printed digit (3 significant digits) is within one unit
// of that digit of the paper's value.
bool within_last_digit(double ours, double paper) {
  const double unit = last_digit_unit(paper, 3);
  const double rounded = std::round(ours / unit) * unit;
  return std::abs(rounded - paper) <= 1.0001 * unit;
}

void claim_a3(const Data& d, Check& c) {
  if (!have_table4(d, c)) return;
  const double l2[5] = {3.60e-3, 1.12e-3, 2.59e-4, 6.71e-5, 1.65e-5};
  const double linf[5] = {9.30e-3, 3.47e-3, 9.03e-4, 2.25e-4, 5.70e-5};
  const size_t crms = d.table4->col("rms_error"), cmax = d.table4->col("max_error");
  std::vector<std::string> rates2, ratesinf;
  double prev2 = std::nan(""), previnf = std::nan("");
  for (int i = 0; i < 5; ++i) {
    const int row = table4_row(d, c, kGrid[i]);
    if (row < 0) {
      prev2 = previnf = std::nan("");
      continue;
    }
    const double r = d.table4->number(row, crms), m = d.table4->number(row, cmax);
    c.require(within_last_digit(r, l2[i]) && within_last_digit(m, linf[i]),
              "n = " + std::to_string(kGrid[i]) + ": L2 " + e3(r) + " (paper " + e2(l2[i]) +
                  "), Linf " + e3(m) + " (paper " + e2(linf[i]) + ")");
    if (i > 0 && std::isfinite(prev2)) {
      rates2.push_back(f2(std::log2(prev2 / r)));
      ratesinf.push_back(f2(std::log2(previnf / m)));
    }
    prev2 = r;
    previnf = m;
  }
  c.info("consecutive rates (log2 of the error ratio): L2 " + join(rates2, ", ") +
         " (paper 1.69, 2.11, 1.95, 2.03); Linf " + join(ratesinf, ", ") +
         " (paper 1.42, 1.94, 2.00, 1.98)");
}

void claim_a4(const Data& d, Check& c) {
  if (!have_table4(d, c)) return;
  const double paper[5] = {0.11, 0.048, 0.023, 0.011, 0.0057};
  const size_t ch = d.table4->col("mean_edge_length");
  for (int i = 0; i < 5; ++i) {
    const int row = table4_row(d, c, kGrid[i]);
    if (row < 0) continue;
    const double h = d.table4->number(row, ch), ratio = h / paper[i];
    c.require(std::abs(ratio - 2.0) <= 0.05,
              "n = " + std::to_string(kGrid[i]) + ": true mean edge length " + g3(h) +
                  " / paper column " + g3(paper[i]) + " = " + f2(ratio) + " (band 2.00 +- 0.05)");
    // Context, not part of the band: the column has 2 significant digits, so its rounding
    // alone moves the ratio by up to 0.5 unit / value (4.5% at 0.011).
    const double unit = last_digit_unit(paper[i], 2);
    c.info("n = " + std::to_string(kGrid[i]) + ": half the mean edge length " + g3(0.5 * h) +
           " rounds to " + g3(std::round(0.5 * h / unit) * unit) +
           " at the paper's 2 digits "
           "(paper " +
           g3(paper[i]) + "; rounding of the column alone allows the ratio 2 +- " +
           f2(2.0 * 0.5 * unit / paper[i]) + ")");
  }
}

// Errors below this are roundoff (e.g. principal directions on a perfectly symmetric mesh, ~1e-16)
// and are treated as equal by the A5 comparison.
constexpr double kRoundoffError = 1e-12;

void claim_a5(const Data& d, Check& c) {
  using Key = std::tuple<std::string, std::string, int, std::string, std::string, std::string,
                         std::string, std::string, std::string>;
  std::map<Key, const ErrorRow*> lhf;
  for (const auto& r : d.rows()) {
    const std::string m = upper(r.method);
    if (m.rfind("LHF-", 0) == 0)
      lhf[{r.experiment, r.family, r.level, m.substr(4), r.rings, r.noise, r.vertex_set, r.quantity,
           r.norm}] = &r;
  }
  std::map<std::string, std::pair<double, int>> per_family;  // family -> (max diff, pairs)
  double worst = -1.0;
  std::string worst_where;
  int pairs = 0;
  for (const auto& r : d.rows()) {
    const std::string m = upper(r.method);
    if (m.rfind("LOP-", 0) != 0) continue;
    auto it = lhf.find({r.experiment, r.family, r.level, m.substr(4), r.rings, r.noise,
                        r.vertex_set, r.quantity, r.norm});
    if (it == lhf.end()) continue;
    const double a = r.error, b = it->second->error;
    double diff = 0.0;
    if (std::isnan(a) && std::isnan(b))
      diff = 0.0;
    else if (!std::isfinite(a) || !std::isfinite(b))
      diff = kInf;
    else if (std::max(std::abs(a), std::abs(b)) < kRoundoffError)
      diff = 0.0;  // both errors are roundoff: their ratio carries no information
    else if (a != b)
      diff = std::abs(a - b) / std::max(std::abs(a), std::abs(b));
    ++pairs;
    auto& pf = per_family[r.family];
    pf.first = std::max(pf.first, diff);
    ++pf.second;
    if (diff > worst) {
      worst = diff;
      worst_where = r.experiment + " " + r.family + " level " + std::to_string(r.level) + " " +
                    r.method + " " + r.quantity + " " + r.norm + " (" + e2(a) + " vs " + e2(b) +
                    ")";
    }
  }
  if (pairs == 0) {
    c.missing("no LOP-d / LHF-d row pairs with the same ring in the errors CSVs");
    return;
  }
  c.info(
      "aggregate check on the error norms of the CSVs (the per-vertex identity of normals and "
      "curvatures is checked by the unit tests)");
  for (const auto& [family, pf] : per_family)
    c.require(pf.first <= 1e-8, family + ": max relative difference " + e2(pf.first) + " over " +
                                    std::to_string(pf.second) + " row pairs (band <= 1e-8)");
  c.info("largest difference at " + worst_where);
}

// ---- B: noise-free torus, degree 2 ------------------------------------------------------------

const Series* torus2(const Data& d, Check& c, const std::string& family, const std::string& m,
                     const std::string& q, const std::string& norm) {
  return d.find(c, query("fig03-05", family, m, q, norm, "none", torus_ring(m)));
}

void claim_b1(const Data& d, Check& c) {
  for (const auto& fam : kTori)
    for (const auto& m : kDeg2Others)
      for (const char* norm : {"L2", "Linf"})
        if (const Series* s = torus2(d, c, fam, m, "normal", norm))
          c.require(s->rate() >= 1.6 && s->rate() <= 2.6, rate_line(*s, "in [1.6, 2.6]"));
}

void claim_b2(const Data& d, Check& c) {
  for (const auto& fam : kTori)
    for (const auto& m : kDeg2Others) {
      if (const Series* s = torus2(d, c, fam, m, "H", "Linf"))
        c.require(s->rate() >= 0.6 && s->rate() <= 1.5, rate_line(*s, "in [0.6, 1.5]"));
      if (const Series* s = torus2(d, c, fam, m, "H", "L2"))
        c.require(s->rate() >= 1.4 && s->rate() <= 2.4, rate_line(*s, "in [1.4, 2.4]"));
    }
}

// Sign of a - b with ties (relative difference <= 1e-6, e.g. LHF = LOP) as 0.
int order_sign(double a, double b) {
  if (std::abs(a - b) <= 1e-6 * std::max(std::abs(a), std::abs(b))) return 0;
  return a < b ? -1 : 1;
}

void claim_b3(const Data& d, Check& c) {
  for (const auto& fam : kTori) {
    std::map<std::string, std::vector<const Series*>> by_q;  // quantity -> LHF, LOP, LSCM
    for (const char* q : {"H", "K", "d1"})
      for (const auto& m : kDeg2Others) {
        const Series* s = torus2(d, c, fam, m, q, "L2");
        if (s && std::string(q) != "H")
          c.require(s->rate() >= 0.9 && s->rate() <= 2.4, rate_line(*s, "in [0.9, 2.4]"));
        by_q[q].push_back(s);
      }
    // Ordering of the methods by L2 error at the finest common level, compared with H's.
    auto ordering = [&](const std::string& q, bool& ok_out) {
      const auto& ss = by_q[q];
      ok_out = std::all_of(ss.begin(), ss.end(), [](const Series* s) { return s != nullptr; });
      std::vector<int> signs;
      if (!ok_out) return signs;
      int level = std::min({ss[0]->last().level, ss[1]->last().level, ss[2]->last().level});
      std::vector<double> e;
      for (const auto* s : ss) {
        const Point* p = s->at(level);
        if (!p) {
          ok_out = false;
          return signs;
        }
        e.push_back(p->e);
      }
      for (int i = 0; i < 3; ++i)
        for (int j = i + 1; j < 3; ++j) signs.push_back(order_sign(e[i], e[j]));
      return signs;
    };
    auto order_text = [&](const std::string& q) {
      const auto& ss = by_q[q];
      int level = std::min({ss[0]->last().level, ss[1]->last().level, ss[2]->last().level});
      std::vector<std::pair<double, std::string>> v;
      for (const auto* s : ss)
        v.push_back({s->at(level)->e, s->method + " " + e2(s->at(level)->e)});
      std::stable_sort(v.begin(), v.end(),
                       [](const auto& a, const auto& b) { return a.first < b.first; });
      std::vector<std::string> parts;
      for (const auto& x : v) parts.push_back(x.second);
      return q + " L2 at level " + std::to_string(level) + ": " + join(parts, " <= ");
    };
    bool ok_h = false;
    const auto sh = ordering("H", ok_h);
    for (const char* q : {"K", "d1"}) {
      bool ok_q = false;
      const auto sq = ordering(q, ok_q);
      if (!ok_h || !ok_q) {
        auto present = [&](const std::string& qq) {
          return std::all_of(by_q[qq].begin(), by_q[qq].end(),
                             [](const Series* x) { return x != nullptr; });
        };
        // A missing series is already recorded; otherwise the finest levels differ.
        if (present("H") && present(q))
          c.missing(fam + " " + q + " and H L2: the methods have no finest level in common");
        continue;
      }
      c.require(sq == sh, fam + " method ordering (ties within 1e-6 relative): " + order_text(q) +
                              " vs " + order_text("H"));
    }
  }
}

void claim_b4(const Data& d, Check& c) {
  for (const char* q : {"normal", "H"}) {
    const Series* xu = torus2(d, c, kWell, "Xu-2", q, "L2");
    const Series* lhf = torus2(d, c, kWell, "LHF-2", q, "L2");
    if (xu && lhf)
      require_three_of_four(
          c, error_ratios(*xu, *lhf), [](double r) { return r < 1.0; },
          std::string(kWell) + " " + q + " L2 " + xu->method + " / " + lhf->method, "< 1");
  }
  for (const char* q : {"normal", "H"}) {
    const Series* xu = torus2(d, c, kWell, "Xu-2", q, "Linf");
    const Series* lhf = torus2(d, c, kWell, "LHF-2", q, "Linf");
    if (!xu || !lhf) continue;
    const auto r = error_ratios(*xu, *lhf);
    if (r.empty()) {
      c.missing(std::string(kWell) + " " + q + " Linf: no level in common");
      continue;
    }
    c.require(r.back().value >= 2.0, std::string(kWell) + " " + q + " Linf " + xu->method + " / " +
                                         lhf->method + " at the finest level " +
                                         std::to_string(r.back().level) + " = " +
                                         f2(r.back().value) + " (>= 2); all " + levels_text(r));
  }
}

void claim_b5(const Data& d, Check& c) {
  const std::pair<const char*, const char*> measures[] = {
      {"H", "L2"}, {"H", "Linf"}, {"normal", "Linf"}};
  for (const auto& [q, norm] : measures) {
    const Series* xu = torus2(d, c, kPoor, "Xu-2", q, norm);
    if (!xu) continue;
    require_failure(c, *xu);
    if (const Series* lhf = torus2(d, c, kPoor, "LHF-2", q, norm))
      c.info(std::string(q) + " " + norm + ": rate(" + lhf->method + ") - rate(" + xu->method +
             ") = " + f2(lhf->rate()) + " - " + f2(xu->rate()) + " = " +
             f2(lhf->rate() - xu->rate()) + " (the weaker minimum asks >= 0.8)");
  }
}

void claim_b6(const Data& d, Check& c) {
  for (const auto& fam : kTori)
    for (const char* q : {"normal", "H"}) {
      const Series* lhf = torus2(d, c, fam, "LHF-2", q, "L2");
      for (const char* m : {"LOP-2", "LSCM-2"}) {
        const Series* s = torus2(d, c, fam, m, q, "L2");
        if (!s || !lhf) continue;
        require_every_level(
            c, error_ratios(*s, *lhf), [](double r) { return r <= 1.5 && r >= 1.0 / 1.5; },
            fam + " " + q + " L2 " + s->method + " / " + lhf->method, "within a factor 1.5");
      }
    }
}

// ---- C: noise-free torus, degrees 3 and 4 -----------------------------------------------------

const Series* torus34(const Data& d, Check& c, const std::string& family, const std::string& m,
                      const std::string& q) {
  return d.find(c, query("fig06-07", family, m, q, "L2", "none", torus_ring(m)));
}

void claim_c1(const Data& d, Check& c) {
  int holds = 0, total = 0;
  bool ratio_ok = true;
  for (const auto& fam : kTori)
    for (const char* q : {"normal", "H", "K", "d1"}) {
      const Series* lscm = torus34(d, c, fam, "LSCM-3", q);
      const Series* lhf = torus34(d, c, fam, "LHF-3", q);
      if (!lscm || !lhf) continue;
      const auto r = error_ratios(*lscm, *lhf);
      for (const auto& x : r) {
        ++total;
        if (x.value <= 1.0) {
          ++holds;
          ratio_ok = ratio_ok && x.value >= 0.5;
        }
      }
      c.info(fam + " " + q + " L2 " + lscm->method + " / " + lhf->method + " at " + levels_text(r));
    }
  if (total == 0) return;
  c.require(2 * holds > total && ratio_ok,
            "LSCM-3 <= LHF-3 in " + std::to_string(holds) + " of " + std::to_string(total) +
                " (mesh type, quantity, level) combinations (need a majority); ratio in [0.5, "
                "1.0] wherever it holds: " +
                (ratio_ok ? "yes" : "no"));
}

void claim_c2(const Data& d, Check& c) {
  for (const auto& fam : kTori)
    for (const char* q : {"normal", "H", "K"}) {
      const Series* lscm = torus34(d, c, fam, "LSCM-4", q);
      const Series* lhf = torus34(d, c, fam, "LHF-4", q);
      if (!lscm || !lhf) continue;
      const auto r = error_ratios(*lscm, *lhf);
      if (r.empty()) {
        c.missing(fam + " " + q + ": no level in common");
        continue;
      }
      c.require(r.back().value >= 2.0, fam + " " + q + " L2 " + lscm->method + " / " + lhf->method +
                                           " at the finest level " +
                                           std::to_string(r.back().level) + " = " +
                                           f2(r.back().value) + " (>= 2); all " + levels_text(r));
    }
}

void claim_c3(const Data& d, Check& c) {
  for (const auto& fam : kTori)
    for (const char* q : {"normal", "H", "K"})
      if (const Series* s = torus34(d, c, fam, "LHF-4", q)) {
        const double need = std::string(q) == "normal" ? 4.6 : 3.6;
        c.require(s->rate() >= need, rate_line(*s, ">= " + f2(need)));
      }
}

void claim_c4(const Data& d, Check& c) {
  if (const Series* s = torus34(d, c, kWell, "LSCM-4", "normal"))
    c.require(s->rate() <= 3.5, rate_line(*s, "<= 3.50"));
  if (const Series* s = torus34(d, c, kWell, "LSCM-4", "H"))
    c.require(s->rate() <= 2.5, rate_line(*s, "<= 2.50"));
  for (const char* q : {"H", "K"})
    if (const Series* s = torus34(d, c, kPoor, "LSCM-4", q)) require_failure(c, *s);
  // Not part of the band: the same map solved by OpenNL conjugate gradients (tolerance 1e-6),
  // CGAL's LSCM solver without Eigen and most likely the paper's. Reported when it was run.
  for (const auto& fam : kTori)
    for (const char* q : {"normal", "H", "K"}) {
      Check scratch;  // a missing series is not a missing piece of this claim
      if (const Series* s = torus34(d, scratch, fam, "LSCM-CG-4", q)) {
        const auto why = failure_reasons(*s);
        c.info(rate_line(*s, "(conjugate-gradient LSCM map, not judged)") +
               (why.empty() ? "; converges" : "; fails to converge"));
      }
    }
}

void claim_c5(const Data& d, Check& c) {
  for (const auto& fam : kTori)
    for (const char* q : {"normal", "H", "K"}) {
      const Series* lhf3 = torus34(d, c, fam, "LHF-3", q);
      const Series* lscm3 = torus34(d, c, fam, "LSCM-3", q);
      if (lhf3 && lscm3) {
        const double diff = lscm3->rate() - lhf3->rate();
        c.require(std::abs(diff) <= 0.7,
                  fam + " " + q + " L2: rate(LSCM-3) - rate(LHF-3) = " + f2(lscm3->rate()) + " - " +
                      f2(lhf3->rate()) + " = " + f2(diff) + " (|.| <= 0.7)");
      }
      const Series* lhf4 = torus34(d, c, fam, "LHF-4", q);
      const Series* lscm4 = torus34(d, c, fam, "LSCM-4", q);
      if (lhf4 && lscm4) {
        const double gap = lhf4->rate() - lscm4->rate();
        c.require(gap >= 1.0, fam + " " + q +
                                  " L2: rate(LHF-4) - rate(LSCM-4) = " + f2(lhf4->rate()) + " - " +
                                  f2(lscm4->rate()) + " = " + f2(gap) + " (>= 1.0)");
      }
    }
}

// ---- D: noise-free open surface ---------------------------------------------------------------

const Series* bump(const Data& d, Check& c, const std::string& family, const std::string& m,
                   const std::string& q, const std::string& norm) {
  return d.find(c, query(degree_of(m) == 2 ? "fig09-10" : "fig11-12", family, m, q, norm));
}

void claim_d1(const Data& d, Check& c) {
  const std::pair<const char*, const char*> measures[] = {
      {"normal", "L2"}, {"normal", "Linf"}, {"H", "L2"}, {"K", "L2"}};
  for (const auto& fam : kBumps)
    for (const auto& [q, norm] : measures) {
      std::vector<const Series*> ss;
      for (const auto& m : kDeg2Others)
        if (const Series* s = bump(d, c, fam, m, q, norm)) ss.push_back(s);
      if (ss.size() != kDeg2Others.size()) continue;
      require_every_level(
          c, spreads(ss), [](double r) { return r <= 1.5; },
          fam + " " + q + " " + norm + " max/min of " + join(methods_of(ss), ", "), "<= 1.5");
    }
}

void claim_d2(const Data& d, Check& c) {
  for (const auto& m : kDeg2Others)
    for (const auto& fam : kBumps) {
      const Series* b = bump(d, c, fam, m, "H", "L2");
      for (const auto& tor : kTori) {
        const Series* t = torus2(d, c, tor, m, "H", "L2");
        if (!b || !t) continue;
        c.require(b->rate() <= t->rate() - 0.2, m + " H L2: rate on " + fam + " " + f2(b->rate()) +
                                                    " <= rate on " + tor + " " + f2(t->rate()) +
                                                    " - 0.2; bump " + b->detail());
      }
    }
}

void claim_d3(const Data& d, Check& c) {
  for (const auto& fam : kBumps)
    for (const char* q : {"H", "K"})
      if (const Series* s = bump(d, c, fam, "Xu-2", q, "L2")) require_failure(c, *s);
}

void claim_d4(const Data& d, Check& c) {
  const std::pair<const char*, const char*> measures[] = {
      {"normal", "L2"}, {"normal", "Linf"}, {"H", "L2"}, {"K", "L2"}};
  for (const auto& fam : kBumps)
    for (int deg : {3, 4})
      for (const auto& [q, norm] : measures) {
        const std::string dd = std::to_string(deg);
        const Series* lhf = bump(d, c, fam, "LHF-" + dd, q, norm);
        const Series* lscm = bump(d, c, fam, "LSCM-" + dd, q, norm);
        if (!lhf || !lscm) continue;
        require_three_of_four(
            c, error_ratios(*lhf, *lscm), [](double r) { return r < 1.0; },
            fam + " " + q + " " + norm + " " + lhf->method + " / " + lscm->method, "< 1");
      }
}

void claim_d5(const Data& d, Check& c) {
  for (const auto& fam : kBumps) {
    std::vector<std::string> parts;
    bool any = false, complete = true;
    for (const char* q : {"normal", "H"}) {
      const Series* lhf = bump(d, c, fam, "LHF-4", q, "L2");
      const Series* lscm = bump(d, c, fam, "LSCM-4", q, "L2");
      if (!lhf || !lscm) {
        complete = false;
        continue;
      }
      const double gap = lhf->rate() - lscm->rate();
      any = any || gap >= 1.0;
      parts.push_back(std::string(q) + " L2 " + f2(lhf->rate()) + " - " + f2(lscm->rate()) + " = " +
                      f2(gap));
    }
    if (complete)
      c.require(any, fam + ": rate(LHF-4) - rate(LSCM-4): " + join(parts, "; ") +
                         " (>= 1.0 for normals or H)");
  }
}

void claim_d6(const Data& d, Check& c) {
  for (const auto& fam : kBumps)
    for (int deg : {2, 3, 4}) {
      const std::string m = "LHF-" + std::to_string(deg);
      for (const char* q : {"normal", "H", "K"}) {
        const Series* s =
            d.find(c, query("fig13-14", fam, m, q, "L2", "none", 0.0, "boundary-ring"));
        const Series* all = bump(d, c, fam, m, q, "L2");
        if (!s) continue;
        const bool normal = std::string(q) == "normal";
        const double lo = normal ? deg - 0.5 : deg - 1.5, hi = normal ? deg + 0.7 : deg - 0.3;
        c.require(s->rate() >= lo && s->rate() <= hi,
                  "boundary-ring " + rate_line(*s, "in [" + f2(lo) + ", " + f2(hi) + "]"));
        if (all)
          c.require(s->rate() <= all->rate() + 0.2,
                    fam + " " + m + " " + q + " L2: boundary-ring rate " + f2(s->rate()) +
                        " <= all-vertex rate " + f2(all->rate()) + " + 0.2");
      }
    }
}

// ---- E: noisy data ----------------------------------------------------------------------------

const Series* noisy_torus(const Data& d, Check& c, const std::string& m, const std::string& q,
                          const std::string& norm, const std::string& experiment = "fig15-16") {
  const double ring = experiment == "fig15-16" ? noisy_torus_ring(m) : 0.0;
  return d.find(c, query(experiment, kNoisyTorus, m, q, norm, "isosurface", ring));
}

void claim_e1(const Data& d, Check& c) {
  for (const char* q : {"H", "K"}) {
    const Series* xu = noisy_torus(d, c, "Xu-2", q, "L2");
    std::vector<const Series*> others;
    for (const auto& m : kDeg2Others)
      if (const Series* s = noisy_torus(d, c, m, q, "L2")) others.push_back(s);
    if (!xu || others.size() != kDeg2Others.size()) continue;
    const auto r = ratios_to_min(*xu, others);
    if (r.empty()) {
      c.missing(std::string(q) + ": no level in common");
      continue;
    }
    c.require(r.back().value >= 20.0, std::string(kNoisyTorus) + " " + q + " L2 " + xu->method +
                                          " / min(" + join(methods_of(others), ", ") +
                                          ") at the finest level " +
                                          std::to_string(r.back().level) + " = " +
                                          f2(r.back().value) + " (>= 20); all " + levels_text(r));
  }
}

void claim_e2(const Data& d, Check& c) {
  for (const auto& m : kDeg2Others) {
    const Series* l2 = noisy_torus(d, c, m, "normal", "L2");
    const Series* linf = noisy_torus(d, c, m, "normal", "Linf");
    if (l2) c.require(l2->rate() >= 1.6 && l2->rate() <= 2.6, rate_line(*l2, "in [1.6, 2.6]"));
    if (l2 && linf)
      c.require(linf->rate() < l2->rate() && linf->rate() < 1.9,
                rate_line(*linf, "< L2 rate " + f2(l2->rate()) + " and < 1.9"));
  }
}

void claim_e3(const Data& d, Check& c) {
  for (const auto& m : kDeg2Others)
    for (const char* q : {"H", "K"})
      if (const Series* s = noisy_torus(d, c, m, q, "L2"))
        c.require(s->rate() >= 0.6 && s->rate() <= 1.5, rate_line(*s, "in [0.6, 1.5]"));
}

void claim_e4(const Data& d, Check& c) {
  for (const char* q : {"H", "K", "normal"}) {
    const bool weak = std::string(q) == "normal";
    Check scratch;  // the weak normal claim does not decide the verdict
    Check& cc = weak ? scratch : c;
    const Series* lhf2 = noisy_torus(d, cc, "LHF-2", q, "L2", "fig17-18");
    for (const char* m : {"LHF-3", "LHF-4"}) {
      const Series* s = noisy_torus(d, cc, m, q, "L2", "fig17-18");
      if (!s || !lhf2) continue;
      const auto r = error_ratios(*s, *lhf2);
      if (r.empty()) {
        cc.missing(std::string(q) + ": no level in common");
        continue;
      }
      const std::string text = std::string(kNoisyTorus) + " " + q + " L2 " + s->method + " / " +
                               lhf2->method + " at the finest level " +
                               std::to_string(r.back().level) + " = " + f2(r.back().value) +
                               " (> 1); all " + levels_text(r);
      if (weak)
        c.info("weak claim, not in the verdict: " + text +
               (r.back().value > 1.0 ? " holds" : " does not hold"));
      else
        c.require(r.back().value > 1.0, text);
    }
  }
}

const Series* bump_noise(const Data& d, Check& c, const std::string& fam, const std::string& m,
                         const std::string& q, const std::string& norm, int order) {
  return d.find(c, query(order == 3 ? "fig19-21" : "fig20-22", fam, m, q, norm,
                         "h^" + std::to_string(order)));
}

const std::vector<std::string> kDeg2All = {"Xu-2", "LHF-2", "LOP-2", "LSCM-2"};

void claim_e5(const Data& d, Check& c) {
  for (const auto& fam : kBumps)
    for (const auto& m : kDeg2All)
      for (const char* norm : {"L2", "Linf"}) {
        const Series* s3 = bump_noise(d, c, fam, m, "normal", norm, 3);
        const Series* s2 = bump_noise(d, c, fam, m, "normal", norm, 2);
        if (!s3 || !s2) continue;
        const std::string what = fam + " " + s3->method + " normal " + norm;
        require_every_level(
            c, error_ratios(*s2, *s3), [](double r) { return r <= 1.5 && r >= 1.0 / 1.5; },
            what + " h^2 / h^3", "within a factor 1.5");
        c.require(std::abs(s2->rate() - s3->rate()) <= 0.3,
                  what + ": rates h^3 " + f2(s3->rate()) + ", h^2 " + f2(s2->rate()) +
                      " differ by " + f2(std::abs(s2->rate() - s3->rate())) + " (<= 0.3)");
      }
}

void claim_e6(const Data& d, Check& c) {
  for (int order : {3, 2}) {
    const Series* xu = bump_noise(d, c, kBump48, "Xu-2", "normal", "L2", order);
    std::vector<const Series*> others;
    for (const auto& m : kDeg2Others)
      if (const Series* s = bump_noise(d, c, kBump48, m, "normal", "L2", order))
        others.push_back(s);
    if (!xu || others.size() != kDeg2Others.size()) continue;
    require_three_of_four(
        c, ratios_to_min(*xu, others), [](double r) { return r <= 1.0; },
        std::string(kBump48) + " h^" + std::to_string(order) + " normal L2 " + xu->method +
            " / min(" + join(methods_of(others), ", ") + ")",
        "<= 1", [](double r) { return r >= 0.5; }, ">= 0.5 (better by a factor <= 2)");
  }
}

void claim_e7(const Data& d, Check& c) {
  for (int order : {3, 2})
    for (const auto& fam : kBumps)
      for (const char* q : {"H", "K"})
        if (const Series* s = bump_noise(d, c, fam, "Xu-2", q, "L2", order))
          require_failure(c, *s, "h^" + std::to_string(order) + " ");
}

void claim_e8(const Data& d, Check& c) {
  for (const auto& fam : kBumps)
    for (const auto& m : kDeg2Others)
      for (const char* q : {"H", "K"})
        if (const Series* s = bump_noise(d, c, fam, m, q, "L2", 3))
          c.require(s->rate() > 1.0, "h^3 " + rate_line(*s, "> 1.0"));
}

void claim_e9(const Data& d, Check& c) {
  int pairs = 0, below = 0;
  for (const auto& fam : kBumps)
    for (const auto& m : kDeg2Others) {
      const Series* h = bump_noise(d, c, fam, m, "H", "L2", 2);
      const Series* k = bump_noise(d, c, fam, m, "K", "L2", 2);
      if (!h || !k) continue;
      ++pairs;
      const bool ok = h->rate() < 1.0 && k->rate() < 1.0;
      below += ok;
      c.info("h^2 " + fam + " " + h->method + ": H L2 rate " + f2(h->rate()) + ", K L2 rate " +
             f2(k->rate()) + (ok ? " (both < 1.0)" : " (not both < 1.0)"));
    }
  if (pairs > 0)
    c.require(2 * below > pairs, "H and K L2 rates < 1.0 for " + std::to_string(below) + " of " +
                                     std::to_string(pairs) +
                                     " (method, mesh) pairs (need a majority)");
}

// ---- F: efficiency ----------------------------------------------------------------------------

const std::vector<std::string> kTable5Methods = {"Xu-2",  "LOP-2",  "LHF-2",  "LHF-3",
                                                 "LHF-4", "LSCM-2", "LSCM-3", "LSCM-4"};

// t_a / t_b at the common levels.
std::vector<LevelValue> time_ratios(const TimingSeries& a, const TimingSeries& b) {
  std::vector<LevelValue> out;
  for (const auto& [level, e] : a)
    if (auto it = b.find(level); it != b.end())
      out.push_back({level, e.seconds / it->second.seconds});
  return out;
}

void require_time_ratios(const Data& d, Check& c, const std::string& a, const std::string& b,
                         const std::function<bool(double)>& pred, const std::string& cond) {
  const TimingSeries* ta = d.timing(c, a);
  const TimingSeries* tb = d.timing(c, b);
  if (!ta || !tb) return;
  require_every_level(c, time_ratios(*ta, *tb), pred, "time " + a + " / " + b, cond);
}

void require_time_ratios(const Data& d, Check& c, const std::string& a, const std::string& b,
                         double lo, double hi) {
  require_time_ratios(
      d, c, a, b, [lo, hi](double r) { return r >= lo && r <= hi; },
      hi == kInf ? ">= " + f2(lo) : "in [" + f2(lo) + ", " + f2(hi) + "]");
}

void claim_f1(const Data& d, Check& c) {
  std::map<std::string, const TimingSeries*> t;
  for (const auto& m : kTable5Methods) t[m] = d.timing(c, m);
  const TimingSeries* lhf = t["LHF-2"];
  if (!lhf) return;
  for (const auto& [level, e] : *lhf) {
    double best = kInf;
    std::string best_m;
    for (const auto& [m, s] : t) {
      if (m == "LHF-2" || !s) continue;
      if (auto it = s->find(level); it != s->end() && it->second.seconds < best) {
        best = it->second.seconds;
        best_m = m;
      }
    }
    if (best_m.empty()) continue;
    c.require(e.seconds < best, "level " + std::to_string(level) + ": LHF-2 " + g3(e.seconds) +
                                    " s, fastest other " + best_m + " " + g3(best) + " s (ratio " +
                                    f2(best / e.seconds) + ")");
  }
}

void claim_f2(const Data& d, Check& c) {
  require_time_ratios(d, c, "LOP-2", "LHF-2", 1.1, 3.0);
}

void claim_f3(const Data& d, Check& c) {
  require_time_ratios(d, c, "LHF-3", "LHF-2", 1.4, 3.5);
  require_time_ratios(d, c, "LHF-4", "LHF-3", 1.4, 3.5);
}

void claim_f4(const Data& d, Check& c) {
  require_time_ratios(d, c, "Xu-2", "LHF-2", 2.5, 12.0);
  require_time_ratios(
      d, c, "Xu-2", "LOP-2", [](double r) { return r > 1.0; }, "> 1");
}

void claim_f5(const Data& d, Check& c) {
  for (int deg : {2, 3, 4})
    require_time_ratios(d, c, "LSCM-" + std::to_string(deg), "LHF-" + std::to_string(deg), 5.0,
                        kInf);
  const TimingSeries* lscm = d.timing(c, "LSCM-2");
  const TimingSeries* xu = d.timing(c, "Xu-2");
  if (lscm && xu)
    c.info("time LSCM-2 / Xu-2 at " + levels_text(time_ratios(*lscm, *xu)) +
           " (paper 6-7; the paper attributes part of LSCM's cost to CGAL overhead)");
}

void claim_f6(const Data& d, Check& c) {
  for (const auto& m : kTable5Methods) {
    const TimingSeries* t = d.timing(c, m);
    if (!t) continue;
    if (t->size() < 2) {
      c.missing(m + ": fewer than two mesh levels timed");
      continue;
    }
    std::vector<LevelValue> per_vertex;
    double lo = kInf, hi = 0.0;
    for (const auto& [level, e] : *t) {
      const double pv = e.seconds / e.verts;
      per_vertex.push_back({level, pv * 1e6});
      lo = std::min(lo, pv);
      hi = std::max(hi, pv);
    }
    c.require(hi / lo < 1.3, m + ": microseconds per vertex " + levels_text(per_vertex) +
                                 "; max/min " + f2(hi / lo) + " (< 1.30)");
  }
}

void claim_f7(const Data& d, Check& c) {
  if (!d.timing(c, "LHF-2")) return;
  std::vector<std::string> svd, qr;
  for (const auto& m : d.timing_methods()) {
    if (m.find("SVD") != std::string::npos)
      svd.push_back(m);
    else if (m.find("QR") != std::string::npos)
      qr.push_back(m);
  }
  if (svd.empty()) {
    c.missing("table5_timing.csv has no QR-vs-SVD rows (a method label containing SVD)");
    return;
  }
  const std::string base = qr.empty() ? "LHF-2" : qr.front();
  for (const auto& s : svd) require_time_ratios(d, c, s, base, 2.5, 10.0);
}

void claim_f8(const Data& d, Check& c) {
  const TimingSeries* t = d.timing(c, "LHF-2");
  if (!t) return;
  c.info("informational band (2008 hardware: 439k and 448k triangles/s)");
  for (const auto& [level, e] : *t) {
    const double tps = e.tris / e.seconds;
    char buf[64];
    std::snprintf(buf, sizeof buf, "%.0f triangles in %.3g s = %.0fk", e.tris, e.seconds,
                  tps / 1e3);
    c.require(tps >= 450e3,
              "level " + std::to_string(level) + ": LHF-2 " + buf + " triangles/s (>= 450k)");
  }
}

void claim_f9(const Data& d, Check& c) {
  require_time_ratios(d, c, "JET-2", "LHF-2", 5.0, kInf);
}

// ---- claim table ------------------------------------------------------------------------------

struct ClaimDef {
  const char* id;
  const char* title;
  const char* statement;
  const char* band;
  void (*evaluate)(const Data&, Check&);  ///< nullptr for a conjunction (G)
  std::vector<const char*> cites;
};

const std::vector<ClaimDef>& claim_defs() {
  static const std::vector<ClaimDef> defs = {
      {"A1",
       "Half-ring sizes [Table 2]",
       "On a regular valence-6 mesh, the (d+1)/2-rings of an interior vertex hold 7, 13, 19, 31, "
       "37, 55 points (centre included) for d = 1..6. The numbers of coefficients are 3, 6, 10, "
       "15, 21, 28.",
       "exact",
       claim_a1,
       {}},
      {"A2",
       "Isosurface vertex counts [Table 4]",
       "SDF of the torus (R = 1, r = 0.3) on linspace(-1.5,1.5,n)^3 with n = 16, 32, 64, 128, 256 "
       "gives 320, 1760, 7320, 31136, 122464 vertices.",
       "exact",
       claim_a2,
       {}},
      {"A3",
       "Isosurface position errors [Table 4]",
       "Distance of the marching-cubes vertices to the torus: L2 = 3.60e-3, 1.12e-3, 2.59e-4, "
       "6.71e-5, 1.65e-5 and Linf = 9.30e-3, 3.47e-3, 9.03e-4, 2.25e-4, 5.70e-5 for n = 16..256. "
       "The isosurface is \"second-order accurate\".",
       "each value within +-1 in the last printed digit (our value rounded to the paper's 3 "
       "significant digits)",
       claim_a3,
       {}},
      {"A4",
       "Table 4 \"average edge length\" is half the mean edge length",
       "Table 4's \"average edge length\" (0.11, 0.048, 0.023, 0.011, 0.0057) equals half the true "
       "mean edge length of such a mesh. This is a finding about the paper's bookkeeping, not a "
       "claim of the paper.",
       "true mean edge length / paper column = 2.00 +- 0.05 at every n",
       claim_a4,
       {}},
      {"A5",
       "LOP = LHF",
       "With identical neighbourhoods, weights and safeguard, LOP-d and LHF-d give the same "
       "normals and curvatures (\"LHF and LOP deliver nearly identical results\").",
       "max relative difference <= 1e-8 on every mesh; here an aggregate check over the error "
       "norms of every LOP-d/LHF-d row pair of the CSVs (the per-vertex check is in the unit "
       "tests)",
       claim_a5,
       {}},
      {"B1",
       "Degree-2 normals converge quadratically on the noise-free torus",
       "LHF-2, LOP-2 and LSCM-2: normals converge about quadratically in both L2 and Linf, on both "
       "mesh types (well-shaped and poor-shaped torus).",
       "rate in [1.6, 2.6] (normal L2 and Linf; torus-jittered and torus-iso-projected; rings "
       "1.5)",
       claim_b1,
       {}},
      {"B2",
       "Degree-2 mean curvature: linear in Linf, super-convergent in L2",
       "LHF-2, LOP-2 and LSCM-2: mean curvature converges about linearly in Linf and nearly "
       "quadratically in L2 (super-convergence). Both mesh types.",
       "H Linf rate in [0.6, 1.5]; H L2 rate in [1.4, 2.4]; both torus mesh types",
       claim_b2,
       {}},
      {"B3",
       "Gaussian curvature and principal directions behave like H",
       "Gaussian curvature (L2) and principal directions (L2) behave \"qualitatively similar to "
       "mean curvature\".",
       "K and d1 L2 rates in [0.9, 2.4] for LHF-2, LOP-2, LSCM-2; the ordering of these methods "
       "by L2 error at the finest level is the same for K and d1 as for H (ties within 1e-6 "
       "relative)",
       claim_b3,
       {}},
      {"B4",
       "Xu-2 on well-shaped meshes: better in L2, substantially worse in Linf",
       "Xu-2 on well-shaped meshes: better than the others in L2 but substantially worse in Linf.",
       "torus-jittered: L2 error of Xu-2 < that of LHF-2 at >= 3 of 4 levels (normals and H); "
       "Linf error of Xu-2 >= 2x that of LHF-2 at the finest level (normals and H)",
       claim_b4,
       {}},
      {"B5",
       "Xu-2 fails to converge on poor-shaped meshes",
       "Xu-2 on poor-shaped (isosurface, projected) meshes fails to converge.",
       "the \"failed to converge\" criterion (rate <= 0.5, or e_last >= 0.7 e_first, or "
       "non-monotone with no net decrease) for H L2, H Linf and normal Linf on "
       "torus-iso-projected; the weaker minimum (Xu-2's rates >= 0.8 below LHF-2's) is reported",
       claim_b5,
       {}},
      {"B6",
       "LSCM-2 and LOP-2 close to LHF-2",
       "LHF-2 and LOP-2 are nearly identical (see A5). LSCM-2 is close to them at degree 2.",
       "LOP-2 and LSCM-2 within a factor 1.5 of LHF-2 at every level (normals and H, L2), both "
       "torus mesh types",
       claim_b6,
       {}},
      {"C1",
       "LSCM-3 slightly more accurate than LHF-3",
       "LSCM-3 is slightly more accurate than LHF-3 \"in most cases\".",
       "err(LSCM-3) <= err(LHF-3) for the majority of (mesh type, quantity, level) combinations "
       "(normal, H, K, d1 L2; both torus mesh types); the ratio is within [0.5, 1.0] where it "
       "holds",
       claim_c1,
       {}},
      {"C2",
       "LHF-4 substantially outperforms LSCM-4",
       "LHF-4 substantially outperforms LSCM-4 in almost all cases.",
       "err(LSCM-4)/err(LHF-4) >= 2 at the finest level, for normals, H and K (L2), on both "
       "torus mesh types",
       claim_c2,
       {}},
      {"C3",
       "LHF-4 nearly an order higher than theory",
       "LHF-4 rates are nearly an order higher than theory, in all cases (statistical "
       "cancellation).",
       "L2 rate for normals >= 4.6 (theory 4); for H and K >= 3.6 (theory 3); both torus mesh "
       "types",
       claim_c3,
       {}},
      {"C4",
       "LSCM-4 an order below theory; fails on poor-shaped meshes",
       "LSCM-4 converges nearly an order below theory on well-shaped meshes. It fails to converge "
       "on poor-shaped meshes.",
       "torus-jittered: normals L2 rate <= 3.5, H L2 rate <= 2.5; torus-iso-projected: the "
       "failure criterion for H and K (L2)",
       claim_c4,
       {}},
      {"C5",
       "LSCM sufficient for cubic, insufficient for quartic fitting",
       "LSCM is \"sufficiently smooth for cubic fitting but insufficient for higher degrees\" "
       "(implied by C1-C4).",
       "|rate(LSCM-3) - rate(LHF-3)| <= 0.7 and rate(LHF-4) - rate(LSCM-4) >= 1.0, for normals, "
       "H and K (L2), both torus mesh types",
       claim_c5,
       {}},
      {"D1",
       "Degree 2 on the bump: LHF-2, LOP-2, LSCM-2 very similar",
       "Degree 2: LHF-2, LOP-2 and LSCM-2 deliver very similar results.",
       "within a factor 1.5 of each other at every level (normal L2 and Linf, H L2, K L2; "
       "bump-irregular and bump-48)",
       claim_d1,
       {}},
      {"D2",
       "Bump H L2 rates lower than on the torus",
       "Degree 2: the L2 convergence rates of mean curvature are lower than on the torus (loss of "
       "cancellation at the boundary).",
       "bump H L2 rate <= torus H L2 rate - 0.2 for the same method (LHF-2, LOP-2, LSCM-2; each "
       "bump mesh against each torus mesh type); expect about 1.0-1.6",
       claim_d2,
       {}},
      {"D3",
       "Xu-2 curvatures fail to converge on the bump",
       "Xu-2 curvatures (H and K) fail to converge on both mesh types, because the stencils have "
       "too few points.",
       "the failure criterion for H and K in L2 (interior vertices), bump-irregular and bump-48",
       claim_d3,
       {}},
      {"D4",
       "LHF more accurate than LSCM at degrees 3 and 4 on the bump",
       "Degrees 3 and 4: LHF is consistently more accurate than LSCM for both d = 3 and d = 4.",
       "err(LHF-d) < err(LSCM-d) at >= 3 of 4 levels, for normals (L2 and Linf), H and K (L2), "
       "d = 3, 4, on both bump meshes",
       claim_d4,
       {}},
      {"D5",
       "LSCM-4 converges substantially slower than LHF-4 on the bump",
       "LSCM-4 converges substantially slower than LHF-4.",
       "rate(LHF-4) - rate(LSCM-4) >= 1.0 for normals or H (L2), on each bump mesh",
       claim_d5,
       {}},
      {"D6",
       "Boundary vertices: rates close to theory",
       "Boundary vertices plus their 1-ring neighbours (LHF, LSCM): rates are somewhat lower than "
       "for interior vertices but \"very close to the theoretical analysis\".",
       "LHF-d (d = 2, 3, 4), boundary-ring L2 rates: normals in [d - 0.5, d + 0.7]; H and K in "
       "[d - 1.5, d - 1 + 0.7]; each <= the corresponding all-vertex rate + 0.2; both bump meshes",
       claim_d6,
       {}},
      {"E1",
       "Noisy torus: Xu-2 errors nearly two orders larger",
       "Xu-2 has the largest errors, \"nearly two orders of magnitude larger\" than the others.",
       "err(Xu-2)/min(err of LHF-2, LOP-2, LSCM-2) >= 20 at the finest level, for H and K (L2)",
       claim_e1,
       {}},
      {"E2",
       "Noisy torus: normals second order in L2, slower in Linf",
       "LHF-2, LOP-2 and LSCM-2 normals: L2 about second order; Linf slower than second order.",
       "normal L2 rate in [1.6, 2.6]; Linf rate < L2 rate and < 1.9",
       claim_e2,
       {}},
      {"E3",
       "Noisy torus: H and K about first order",
       "LHF-2, LOP-2 and LSCM-2: L2 errors of H and K converge at about first order.",
       "H and K L2 rates in [0.6, 1.5]",
       claim_e3,
       {}},
      {"E4",
       "Noisy torus: cubic and quartic fits worse than quadratic",
       "Cubic and quartic fits are worse than quadratic on the noisy torus, because a degree-d "
       "fit needs O(h^(d+1)) input.",
       "at the finest level, err(LHF-3) > err(LHF-2) and err(LHF-4) > err(LHF-2) for H and K "
       "(L2); the normals (L2, weak claim) are reported but do not decide",
       claim_e4,
       {}},
      {"E5",
       "Bump with noise: normals identical for O(h^3) and O(h^2)",
       "Normals: each method behaves nearly identically for O(h^3) and O(h^2) perturbations.",
       "per method (Xu-2, LHF-2, LOP-2, LSCM-2) and bump mesh, the normal errors (L2 and Linf) of "
       "the two noise orders are within a factor 1.5 at every level, and the rates differ by <= "
       "0.3",
       claim_e5,
       {}},
      {"E6",
       "Bump with noise: Xu-2 normals slightly better on the 4-8 mesh",
       "Xu-2 normals are slightly better than the others on the 4-8 mesh (weak claim).",
       "bump-48, h^3 and h^2: err(Xu-2) <= min(err of LHF-2, LOP-2, LSCM-2) at >= 3 of 4 levels "
       "(normal L2), by a factor <= 2",
       claim_e6,
       {}},
      {"E7",
       "Bump with noise: Xu-2 curvatures fail to converge",
       "Xu-2 curvatures fail to converge (both perturbation orders).",
       "the failure criterion, H and K L2, h^3 and h^2, both bump meshes",
       claim_e7,
       {}},
      {"E8",
       "Bump with O(h^3) noise: curvatures faster than linear",
       "Others (LHF-2, LOP-2, LSCM-2), O(h^3) noise: curvatures converge faster than linearly.",
       "H and K L2 rate > 1.0, both bump meshes",
       claim_e8,
       {}},
      {"E9",
       "Bump with O(h^2) noise: curvatures generally lower than linear",
       "Others (LHF-2, LOP-2, LSCM-2), O(h^2) noise: curvatures converge \"generally lower than "
       "linear\".",
       "H and K L2 rates both < 1.0 for a majority of the (method, mesh) pairs",
       claim_e9,
       {}},
      {"F1",
       "LHF is the fastest method",
       "LHF is the fastest method.",
       "LHF-2 is the smallest time in every row (single-threaded, torus-structured levels; the "
       "eight Table 5 methods)",
       claim_f1,
       {}},
      {"F2",
       "LOP slightly slower than LHF",
       "LOP is slightly slower than LHF (3 right-hand sides, heavier formulas); paper ratio "
       "LOP-2/LHF-2 about 1.7.",
       "time LOP-2/LHF-2 in [1.1, 3.0] at every level",
       claim_f2,
       {}},
      {"F3",
       "The cost roughly doubles per extra degree",
       "The cost roughly doubles per extra degree for LHF (paper: LHF-3/LHF-2 about 2.1-2.2, "
       "LHF-4/LHF-3 about 2.2).",
       "each ratio in [1.4, 3.5] at every level",
       claim_f3,
       {}},
      {"F4",
       "Xu-2 second most expensive",
       "Xu-2 is the second most expensive despite 1-rings, because of SVD (paper: Xu-2/LHF-2 "
       "about 5.2-5.7, Xu-2/LOP-2 about 3.2).",
       "time Xu-2/LHF-2 in [2.5, 12] and Xu-2 > LOP-2, at every level",
       claim_f4,
       {}},
      {"F5",
       "LSCM about an order of magnitude more expensive",
       "LSCM is about an order of magnitude more expensive than the others (paper: LSCM-2/LHF-2 "
       "about 33-36, LSCM-3/LHF-3 about 28, LSCM-4/LHF-4 about 24, LSCM-2/Xu-2 about 6-7).",
       "time LSCM-d/LHF-d >= 5 for d = 2, 3, 4 at every level (CGAL-based: expect >= 10)",
       claim_f5,
       {}},
      {"F6",
       "The cost is linear in mesh size",
       "The cost is linear in mesh size (paper: time ratios between consecutive meshes about "
       "3.8-4.2 for vertex ratios about 3.9-4.0).",
       "per-vertex time varies by < 30% (max/min < 1.3) across the meshes, for every method",
       claim_f6,
       {}},
      {"F7",
       "QR with safeguard about 4-5x faster than SVD",
       "QR with safeguard is about 4-5x faster than SVD (\"roughly a factor of five\"): the same "
       "LHF-2 system solved by safeguarded Householder QR versus a truncated SVD.",
       "speed-up time(SVD)/time(QR) in [2.5, 10] at every level",
       claim_f7,
       {}},
      {"F8",
       "LHF-2 throughput about 450k triangles/s",
       "The throughput of LHF-2 is about 450k triangles/s on 2008 hardware.",
       ">= 450k triangles/s on current hardware at every level (informational only)",
       claim_f8,
       {}},
      {"F9",
       "LHF-2 more than 16x faster than CGAL Jet_fitting_3",
       "LHF-2 is more than 16x faster than CGAL Jet_fitting_3 at degree 2.",
       "time Jet-2/LHF-2 >= 5 at every level, measured in the same run",
       claim_f9,
       {}},
      {"G1",
       "Robust polynomial fits converge for exact or O(h^3) data",
       "Polynomial fits with a robust solver converge for exact or O(h^3) data (B1-B2, D, E8). "
       "Convergence is not guaranteed, but curvatures remain meaningful (often about first "
       "order), for O(h^2) data (E3, E9).",
       "conjunction of B1, B2, D1-D6, E8, E3, E9",
       nullptr,
       {"B1", "B2", "D1", "D2", "D3", "D4", "D5", "D6", "E8", "E3", "E9"}},
      {"G2",
       "LSCM good for d <= 3 but not d = 4; LHF and LOP reach high-order rates",
       "Approximate conformal parameterization (LSCM) is good for d <= 3 but not for d = 4; LHF "
       "and LOP reach high-order rates (C2-C5, D4-D5).",
       "conjunction of C2, C3, C4, C5, D4, D5",
       nullptr,
       {"C2", "C3", "C4", "C5", "D4", "D5"}},
      {"G3",
       "The choice of solver matters for accuracy and speed",
       "The choice of solver matters for accuracy and speed: Xu/SVD failures (B5, D3, E7); F4, "
       "F7.",
       "conjunction of B5, D3, E7, F4, F7",
       nullptr,
       {"B5", "D3", "E7", "F4", "F7"}},
      {"G4",
       "LOP with safeguard (= LHF) gives the best combination",
       "LOP with the normal-angle safeguard (= LHF) gives the best combination of simplicity, "
       "accuracy, efficiency and robustness (A5, B1-B2, D1, F1-F2).",
       "conjunction of A5, B1, B2, D1, F1, F2",
       nullptr,
       {"A5", "B1", "B2", "D1", "F1", "F2"}},
  };
  return defs;
}

const ClaimDef* find_def(const std::string& id) {
  for (const auto& d : claim_defs())
    if (id == d.id) return &d;
  return nullptr;
}

std::string escape_cell(const std::string& s) {
  std::string out;
  for (char ch : s) {
    if (ch == '|')
      out += "\\|";
    else if (ch == '\n')
      out += ' ';
    else
      out += ch;
  }
  return out;
}

}  // namespace

std::vector<ClaimResult> evaluate_claims(const std::string& results_dir) {
  const Data data(results_dir);
  std::vector<ClaimResult> out;
  for (const auto& def : claim_defs()) {
    ClaimResult r;
    r.id = def.id;
    r.statement = def.statement;
    r.band = def.band;
    if (def.evaluate) {
      Check c;
      def.evaluate(data, c);
      r.verdict = c.verdict();
      r.evidence = c.evidence();
    } else {
      // Conjunction: not reproduced if any cited claim is not reproduced; reproduced if every
      // cited claim is; otherwise (some cited claims lack data) not applicable.
      int rep = 0, na = 0;
      std::vector<std::string> lines;
      for (const char* id : def.cites) {
        const auto it =
            std::find_if(out.begin(), out.end(), [&](const ClaimResult& x) { return x.id == id; });
        const Verdict v = it == out.end() ? Verdict::not_applicable : it->verdict;
        rep += v == Verdict::reproduced;
        na += v == Verdict::not_applicable;
        lines.push_back(std::string(v == Verdict::reproduced       ? "[ok] "
                                    : v == Verdict::not_applicable ? "[missing] "
                                                                   : "[FAIL] ") +
                        id + ": " + to_string(v));
      }
      const int n = static_cast<int>(def.cites.size());
      const int failed = n - rep - na;
      r.verdict = failed > 0 ? Verdict::not_reproduced
                  : rep == n ? Verdict::reproduced
                             : Verdict::not_applicable;
      if (failed == 0 && na > 0 && rep > 0)
        lines.push_back("[info] partially evaluated: " + std::to_string(rep) + " of " +
                        std::to_string(n) + " cited claims reproduced, the rest lack data");
      r.evidence = join(lines, "\n");
    }
    out.push_back(std::move(r));
  }
  return out;
}

std::string claims_markdown(const std::vector<ClaimResult>& results,
                            const std::string& header_line) {
  int rep = 0, notrep = 0, na = 0;
  for (const auto& r : results) {
    rep += r.verdict == Verdict::reproduced;
    notrep += r.verdict == Verdict::not_reproduced;
    na += r.verdict == Verdict::not_applicable;
  }
  std::ostringstream md;
  md << "# Paper claims: reproduction check\n\n"
     << header_line << "\n\n"
     << "Checks the claims of Wang, Jiao et al., CAGD 2009 listed in PAPER_CLAIMS.md against "
        "the CSVs in this folder (harness/claims.cpp). Each claim has a numeric band fixed in "
        "advance. A claim outside its band is reported as *not reproduced*, and the methods are "
        "not tuned to fit it. A claim whose data is missing, or whose run used a different "
        "setup, is *not applicable*. Rates are log(e_first/e_last)/log(h_first/h_last) over the "
        "levels present, with the measured mean edge length h; \"levels 1-4: a, b, c, d\" "
        "lists a value per mesh level. "
        "Evidence lines are tagged [ok], [FAIL], [missing] or [info].\n\n"
     << "**Summary:** " << rep << " reproduced, " << notrep << " not reproduced, " << na
     << " not applicable (" << results.size() << " claims).\n\n"
     << "| claim | verdict | subject |\n|---|---|---|\n";
  for (const auto& r : results) {
    const ClaimDef* def = find_def(r.id);
    md << "| " << r.id << " | " << to_string(r.verdict) << " | "
       << escape_cell(def ? def->title : r.statement) << " |\n";
  }
  md << "\n";
  for (const auto& r : results) {
    const ClaimDef* def = find_def(r.id);
    md << "## " << r.id << ". " << (def ? def->title : "") << "\n\n"
       << "**Verdict: " << to_string(r.verdict) << "**\n\n"
       << "- Paper: " << r.statement << "\n"
       << "- Band: " << r.band << "\n\n"
       << "Evidence:\n\n";
    std::istringstream lines(r.evidence);
    std::string line;
    bool any = false;
    while (std::getline(lines, line)) {
      md << "- " << line << "\n";
      any = true;
    }
    if (!any) md << "- (none)\n";
    md << "\n";
  }
  return md.str();
}

}  // namespace curvbench
