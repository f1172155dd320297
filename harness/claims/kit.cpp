#include "harness/claims/kit.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <map>
#include <set>
#include <sstream>
#include <tuple>

#include "harness/model/metrics.h"
#include "mesh/io.h"
#include "methods/estimator.h"

namespace curvbench {

bool Band::holds(double x) const {
  switch (kind) {
    case Kind::in:
    case Kind::within_factor:
      return x >= lo && x <= hi;
    case Kind::at_least:
      return x >= lo;
    case Kind::above:
      return x > lo;
    case Kind::at_most:
      return x <= hi;
    case Kind::below:
      return x < hi;
  }
  return false;
}

namespace {
std::string band_number(double x, int decimals) {
  char buf[48];
  if (decimals < 0)
    std::snprintf(buf, sizeof buf, "%g", x);
  else
    std::snprintf(buf, sizeof buf, "%.*f", decimals, x);
  std::string out = buf;
  // 1e-08 -> 1e-8
  for (const char* z : {"e-0", "e+0"})
    if (const size_t at = out.find(z); at != std::string::npos) out.erase(at + 2, 1);
  return out;
}
}  // namespace

std::string Band::text(int digits) const {
  switch (kind) {
    case Kind::in:
      return "in [" + band_number(lo, digits) + ", " + band_number(hi, digits) + "]";
    case Kind::at_least:
      return ">= " + band_number(lo, digits);
    case Kind::above:
      return "> " + band_number(lo, digits);
    case Kind::at_most:
      return "<= " + band_number(hi, digits);
    case Kind::below:
      return "< " + band_number(hi, digits);
    case Kind::within_factor:
      return "within a factor " + band_number(hi, digits);
  }
  return "?";
}

namespace claims {

namespace fs = std::filesystem;

namespace {

std::string non_finite(double x) {
  if (std::isnan(x)) return "nan";
  return x > 0 ? "inf" : "-inf";
}

}  // namespace

std::string f2(double x) {
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

std::string num(double x) {
  return band_number(x, -1);
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

void Check::require(bool pass, const std::string& text) {
  lines_.push_back((pass ? "[ok] " : "[FAIL] ") + text);
  ++(pass ? passed_ : failed_);
}
void Check::info(const std::string& text) {
  lines_.push_back("[info] " + text);
}
void Check::missing(const std::string& text) {
  const std::string line = "[missing] " + text;
  if (std::find(lines_.begin(), lines_.end(), line) == lines_.end()) lines_.push_back(line);
  ++missing_;
}
Verdict Check::verdict() const {
  if (missing_ > 0) return Verdict::not_applicable;
  if (failed_ > 0) return Verdict::not_reproduced;
  return passed_ > 0 ? Verdict::reproduced : Verdict::not_applicable;
}
std::string Check::evidence() const {
  return join(lines_, "\n");
}

// ---- series -----------------------------------------------------------------------------------

double Series::rate(RateFormula formula) const {
  return formula == RateFormula::measured_h ? rate_h() : rate_halving();
}
double Series::rate_h() const {
  return convergence_rate(first().e, last().e, first().h, last().h);
}
double Series::rate_halving() const {
  return level_halving_rate(first().e, last().e, first().level, last().level);
}
std::vector<double> Series::pair_rates(RateFormula formula) const {
  std::vector<double> out;
  for (size_t i = 1; i < points.size(); ++i) {
    const Point &a = points[i - 1], &b = points[i];
    out.push_back(formula == RateFormula::measured_h
                      ? convergence_rate(a.e, b.e, a.h, b.h)
                      : level_halving_rate(a.e, b.e, a.level, b.level));
  }
  return out;
}
const Point* Series::at(int level) const {
  for (const auto& p : points)
    if (p.level == level) return &p;
  return nullptr;
}

bool is_xu(const std::string& method) {
  return upper(method).rfind("XU", 0) == 0;
}

static bool ring_equals(const std::string& label, double ring) {
  try {
    return std::abs(std::stod(label) - ring) < 1e-9;
  } catch (const std::exception&) {
    return false;
  }
}

Query query(const std::string& experiment, const std::string& family, const std::string& method,
            const std::string& quantity, const std::string& norm, const std::string& noise,
            double ring, const std::string& vertex_set) {
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

int degree_of(const std::string& method) {
  return method.back() - '0';
}

double torus_ring(const std::string& method) {
  if (is_xu(method)) return 1.0;
  return 0.5 * (degree_of(method) + 1);
}
double noisy_torus_ring(const std::string& method) {
  return is_xu(method) ? 1.0 : torus_ring(method) + 0.5;
}

// ---- all inputs -------------------------------------------------------------------------------

namespace {
std::optional<CsvTable> read_table(const std::string& path) {
  if (!fs::exists(path)) return std::nullopt;
  return read_csv_table(path);
}
}  // namespace

namespace {

// The error rows of every errors CSV in `dir` (none if it is not a folder).
std::vector<ErrorRow> error_rows_in(const std::string& dir) {
  std::vector<ErrorRow> out;
  std::error_code ec;
  if (dir.empty() || !fs::is_directory(dir, ec)) return out;
  std::vector<fs::path> csvs;
  for (const auto& entry : fs::directory_iterator(dir))
    if (entry.is_regular_file() && entry.path().extension() == ".csv") csvs.push_back(entry.path());
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
    out.insert(out.end(), rows.begin(), rows.end());
  }
  return out;
}

}  // namespace

namespace {

// The (experiment, family, method, rings, noise, vertex set, quantity, norm) series of the rows,
// each sorted by level (a later row of a level replaces an earlier one).
std::vector<Series> build_series(const std::vector<ErrorRow>& rows) {
  std::vector<Series> series;
  using Key = std::tuple<std::string, std::string, std::string, std::string, std::string,
                         std::string, std::string, std::string>;
  std::map<Key, size_t> index;
  for (const auto& r : rows) {
    const Key k{r.experiment, r.family,     upper(r.method), r.rings,
                r.noise,      r.vertex_set, r.quantity,      r.norm};
    auto [it, inserted] = index.try_emplace(k, series.size());
    if (inserted)
      series.push_back({r.experiment,
                        r.family,
                        r.method,
                        r.rings,
                        r.noise,
                        r.vertex_set,
                        r.quantity,
                        r.norm,
                        {}});
    auto& pts = series[it->second].points;
    pts.erase(
        std::remove_if(pts.begin(), pts.end(), [&](const Point& p) { return p.level == r.level; }),
        pts.end());
    pts.push_back({r.level, r.h, r.error});
  }
  for (auto& s : series)
    std::sort(s.points.begin(), s.points.end(),
              [](const Point& a, const Point& b) { return a.level < b.level; });
  return series;
}

// The single-threaded timings of table5_timing.csv `t` on its timing family (set in `family`).
void build_timing(const CsvTable& t, std::map<std::string, TimingSeries>& timing,
                  std::string& family) {
  const size_t cm = t.col("mesh"), cl = t.col("level"), cv = t.col("verts"), ct = t.col("tris"),
               cme = t.col("method"), cth = t.col("threads"), cs = t.col("seconds");
  family = "torus-structured";
  for (size_t i = 0; i < t.rows.size(); ++i)
    if (t.text(i, cm) == "torus-unstructured") family = "torus-unstructured";
  for (size_t i = 0; i < t.rows.size(); ++i) {
    if (t.text(i, cm) != family || t.number(i, cth) != 1.0) continue;
    auto& e = timing[upper(t.text(i, cme))][static_cast<int>(t.number(i, cl))];
    const double s = t.number(i, cs);
    if (s < e.seconds) {
      e.seconds = s;
      e.verts = t.number(i, cv);
      e.tris = t.number(i, ct);
    }
  }
}

}  // namespace

Data::Data(const std::string& dir, const std::string& overlay) : csv_(read(dir, overlay)) {}

std::shared_ptr<const Data::Csv> Data::read(const std::string& dir, const std::string& overlay) {
  auto csv = std::make_shared<Csv>();
  csv->dir = dir;
  std::error_code ec;
  if (!fs::is_directory(dir, ec)) return csv;
  csv->rows = error_rows_in(dir);
  const std::vector<ErrorRow> replaced = error_rows_in(overlay);
  std::set<std::pair<std::string, std::string>> runs;  // (experiment, family)
  for (const ErrorRow& r : replaced) runs.insert({r.experiment, r.family});
  std::erase_if(csv->rows, [&](const ErrorRow& r) {
    return runs.count({r.experiment, r.family}) > 0;
  });
  csv->rows.insert(csv->rows.end(), replaced.begin(), replaced.end());
  csv->series = build_series(csv->rows);
  csv->table2 = read_table(dir + "/table2.csv");
  csv->table4 = read_table(dir + "/table4.csv");
  csv->table5 = read_table(dir + "/table5_timing.csv");
  if (csv->table5) build_timing(*csv->table5, csv->timing, csv->timing_family);
  return csv;
}

Data Data::with_rate_formula(RateFormula formula) const {
  Data out = *this;
  out.rate_formula_ = formula;
  return out;
}

Data Data::with_substitute(const std::string& name, const std::string& by) const {
  Data out = *this;
  if (by.empty() || by == name)
    out.substitutes_.erase(name);
  else
    out.substitutes_[name] = by;
  return out;
}

Data Data::in_folder(const std::string& dir) const {
  Data out = *this;
  out.csv_ = read(dir, "");
  return out;
}

const std::string& Data::family(const std::string& name) const {
  const auto it = substitutes_.find(name);
  return it == substitutes_.end() ? name : it->second;
}

std::vector<std::string> Data::tori() const {
  return {family(kWell), kPoor};
}

std::vector<std::string> Data::bumps() const {
  return {family(kBumpIrr), kBump48};
}

const Series* Data::find(Check& chk, const Query& q) const {
  const std::string vset =
      !q.vertex_set.empty()
          ? q.vertex_set
          : (scores_interior_only(q.method) && q.family.rfind("bump", 0) == 0 ? "interior" : "all");
  const std::string what = q.method + " " + q.quantity + " " + q.norm + " on " + q.family +
                           " (noise " + q.noise + ", vertex set " + vset + ")";
  std::vector<const Series*> cand;
  for (const auto& s : csv_->series)
    if (s.family == q.family && upper(s.method) == upper(q.method) && s.quantity == q.quantity &&
        s.norm == q.norm && s.noise == q.noise && s.vertex_set == vset)
      cand.push_back(&s);
  if (cand.empty()) {
    for (const auto& s : csv_->series)
      if (s.family == q.family && upper(s.method) == upper(q.method) && s.quantity == q.quantity &&
          s.norm == q.norm && s.noise == q.noise) {
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

const TimingSeries* Data::timing(Check& chk, const std::string& method) const {
  if (!csv_->table5) {
    chk.missing("table5_timing.csv not present: run make bench");
    return nullptr;
  }
  auto it = csv_->timing.find(upper(method));
  if (it == csv_->timing.end()) {
    chk.missing("table5_timing.csv has no single-threaded " + timing_family() + " rows for " +
                method);
    return nullptr;
  }
  return &it->second;
}
std::vector<std::string> Data::timing_methods() const {
  std::vector<std::string> out;
  for (const auto& [m, s] : csv_->timing) out.push_back(m);
  return out;
}

// ---- comparison helpers -----------------------------------------------------------------------

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

void require_every_level(Check& c, const std::vector<LevelValue>& v, const Band& band,
                         const std::string& what) {
  if (v.empty()) {
    c.missing(what + ": no level in common");
    return;
  }
  bool ok = true;
  for (const auto& x : v) ok = ok && band.holds(x.value);
  c.require(ok, what + " at " + levels_text(v) + " (" + band.text() + " at every level)");
}

void require_most_levels(Check& c, const std::vector<LevelValue>& v, const Band& band,
                         const std::string& what, const std::optional<Band>& extra,
                         const std::string& extra_text) {
  if (v.empty()) {
    c.missing(what + ": no level in common");
    return;
  }
  int count = 0;
  bool extra_ok = true;
  for (const auto& x : v)
    if (band.holds(x.value)) {
      ++count;
      extra_ok = extra_ok && (!extra || extra->holds(x.value));
    }
  const int n = static_cast<int>(v.size());
  const int need = (3 * n + 3) / 4;
  c.require(count >= need && extra_ok,
            what + " at " + levels_text(v) + " (" + band.text() + " at " + std::to_string(count) +
                " of " + std::to_string(n) + " levels, need " + std::to_string(need) + ")" +
                (extra ? "; where it holds, " + extra->text() + extra_text + ": " +
                             (extra_ok ? "yes" : "no")
                       : ""));
}

void require_finest(Check& c, const std::vector<LevelValue>& v, const Band& band,
                    const std::string& what) {
  c.require(band.holds(v.back().value),
            what + " at the finest level " + std::to_string(v.back().level) + " = " +
                f2(v.back().value) + " (" + band.text() + "); all " + levels_text(v));
}

std::string rate_line(const Data& d, const Series& s, const std::string& cond) {
  const bool h = d.rate_formula() == RateFormula::measured_h;
  return s.label() + ": " + (h ? "rate " : "level-halving rate ") + f2(d.rate(s)) + " " + cond +
         (h ? " (level-halving rate " + f2(s.rate_halving()) + ")"
            : " (measured-h rate " + f2(s.rate_h()) + ")") +
         "; " + s.detail();
}

void require_rate(const Data& d, Check& c, const Series& s, const Band& band,
                  const std::string& prefix) {
  c.require(band.holds(d.rate(s)), prefix + rate_line(d, s, band.text()));
}

// "failed to converge" (docs/claims.md, conventions): rate <= 0.5, or e_last >= 0.7 e_first, or
// non-monotone with no net decrease; a non-finite last error also counts.
std::vector<std::string> failure_reasons(const Data& d, const Series& s) {
  const double e1 = s.first().e, en = s.last().e, r = d.rate(s);
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

void require_failure(const Data& d, Check& c, const Series& s, const std::string& prefix) {
  const auto why = failure_reasons(d, s);
  if (!why.empty()) {
    c.require(true,
              prefix + s.label() + " fails to converge (" + join(why, ", ") + "); " + s.detail());
  } else {
    c.require(false, prefix + s.label() + " converges (rate " + f2(d.rate(s)) +
                         " > 0.5, e_last/e_first " + f2(s.last().e / s.first().e) + " < 0.7); " +
                         s.detail());
  }
}

// ---- timing ------------------------------------------------------------------------------------

std::vector<LevelValue> time_ratios(const TimingSeries& a, const TimingSeries& b) {
  std::vector<LevelValue> out;
  for (const auto& [level, e] : a)
    if (auto it = b.find(level); it != b.end())
      out.push_back({level, e.seconds / it->second.seconds});
  return out;
}

void require_time_ratio(const Data& d, Check& c, const std::string& a, const std::string& b,
                        const Band& band) {
  const TimingSeries* ta = d.timing(c, a);
  const TimingSeries* tb = d.timing(c, b);
  if (!ta || !tb) return;
  require_every_level(c, time_ratios(*ta, *tb), band, "time " + a + " / " + b);
}

}  // namespace claims
}  // namespace curvbench
