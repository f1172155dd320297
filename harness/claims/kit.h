// Internal to the claims registry (harness/claims*.cpp): the inputs a claim reads (Data: error
// series, Tables 2/4 CSVs, timings), the evidence accumulator (Check), the registry entry
// (ClaimEntry) and the check kinds the entries share:
//   require_rate          a series' rate in a Band
//   require_failure       the "failed to converge" criterion (docs/claims.md, conventions)
//   require_every_level   a per-level ratio of two series in a Band at every common level
//   require_most_levels   ... at >= 3/4 of the common levels
//   require_finest        ... at the finest common level
//   require_time_ratio    a time ratio of two methods (table5_timing.csv) at every level
//   all_of (ClaimEntry)   a conjunction of other claims
// Each prints the Band's own text into the evidence line, so a band is written once per entry.
#pragma once

#include <functional>
#include <limits>
#include <map>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "harness/claims/claims.h"
#include "harness/model/results_table.h"

namespace curvbench::claims {

inline constexpr double kInf = std::numeric_limits<double>::infinity();

// ---- formatting -------------------------------------------------------------------------------

std::string f2(double x);   ///< rates and ratios, %.2f
std::string e2(double x);   ///< errors, %.2e
std::string e3(double x);   ///< Table 4 values, %.3e (one digit more than the paper prints)
std::string g3(double x);   ///< seconds, ring sizes, %.3g
std::string num(double x);  ///< band constants in prose, %g
std::string upper(std::string s);
std::string join(const std::vector<std::string>& parts, const std::string& sep);

// ---- evidence accumulator ---------------------------------------------------------------------

/// Collects one line per check. Verdict: any missing input -> not applicable; else any failed
/// check -> not reproduced; else reproduced (not applicable if nothing was checked).
class Check {
 public:
  void require(bool pass, const std::string& text);
  void info(const std::string& text);
  void missing(const std::string& text);
  Verdict verdict() const;
  std::string evidence() const;
  /// The lines so far, tagged ("[ok] ...", "[FAIL] ...", "[missing] ...", "[info] ...").
  const std::vector<std::string>& lines() const { return lines_; }

 private:
  std::vector<std::string> lines_;
  int passed_ = 0, failed_ = 0, missing_ = 0;
};

// ---- error series -----------------------------------------------------------------------------

/// A rate formula: ours (measured mean edge length) or the paper's level-halving rate
/// (1/(L-1)) log2(e_1/e_L). evaluate_claims evaluates every claim with each (Data::rate_formula)
/// and flags a claim whose verdict differs.
enum class RateFormula { measured_h, level_halving };

struct Point {
  int level = 0;
  double h = 0.0;
  double e = 0.0;
};

/// One (experiment, family, method, rings, noise, vertex set, quantity, norm) series.
struct Series {
  std::string experiment, family, method, rings, noise, vertex_set, quantity, norm;
  std::vector<Point> points;  // increasing level, >= 1

  const Point& first() const { return points.front(); }
  const Point& last() const { return points.back(); }
  /// The rate of `formula` over the first and last level present.
  double rate(RateFormula formula) const;
  /// log(e_first/e_last)/log(h_first/h_last), measured mean edge length (as compute_rates).
  double rate_h() const;
  /// log2(e_first/e_last)/(level_last - level_first), the paper's formula.
  double rate_halving() const;
  /// The rate of `formula` between each pair of consecutive levels present, finest last.
  std::vector<double> pair_rates(RateFormula formula) const;
  const Point* at(int level) const;
  std::string label() const { return family + " " + method + " " + quantity + " " + norm; }
  /// "errors at levels 1-4: a, b, c, d; level-to-level rates r12, r23, r34"
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

Query query(const std::string& experiment, const std::string& family, const std::string& method,
            const std::string& quantity, const std::string& norm, const std::string& noise = "none",
            double ring = 0.0, const std::string& vertex_set = "");

bool is_xu(const std::string& method);
/// Degree of a label "XXX-d".
int degree_of(const std::string& method);
/// Rings of the §5.1 (noise-free torus) and §5.3 (noisy torus) setups.
double torus_ring(const std::string& method);
double noisy_torus_ring(const std::string& method);

// ---- timing (table5_timing.csv) --------------------------------------------------------------

struct TimingEntry {
  double seconds = kInf;  ///< minimum over repeated rows
  double verts = 0.0, tris = 0.0;
};
using TimingSeries = std::map<int, TimingEntry>;  // level -> entry

// ---- all inputs -------------------------------------------------------------------------------

/// The inputs every check receives: the CSVs of a results folder, read once and shared by the
/// copies, and the context the checks read them under, set where the Data is built
/// (evaluate_claims: each rate formula, a reading's family swap, the mesh-shape diagnostic of a
/// miss). A copy with another context (with_rate_formula, with_substitute) shares the CSVs.
class Data {
 public:
  /// The CSVs of `dir`; with `overlay`, an (experiment, mesh family) that has rows in the overlay
  /// folder's CSVs takes those instead of dir's (a reading's run, readings.h). Rates over the
  /// measured h, no family substituted.
  explicit Data(const std::string& dir, const std::string& overlay = "");

  /// The same CSVs with every rate of `formula`.
  Data with_rate_formula(RateFormula formula) const;
  /// The same CSVs with `by`'s rows read where a check names `family` (none: `by` empty or
  /// `family` itself).
  Data with_substitute(const std::string& family, const std::string& by) const;
  /// The CSVs of another folder (a subfolder of results: deep/, readings/) under this context.
  Data in_folder(const std::string& dir) const;

  RateFormula rate_formula() const { return rate_formula_; }
  /// The rate of s under rate_formula() (Series::rate).
  double rate(const Series& s) const { return s.rate(rate_formula_); }
  std::vector<double> pair_rates(const Series& s) const { return s.pair_rates(rate_formula_); }
  /// The family the checks read for `family` (kWell, kBumpIrr): itself, unless substituted (a
  /// reading's swap, readings.h; the mesh-shape diagnostic of a miss, the "Why" line of
  /// CLAIMS.md).
  const std::string& family(const std::string& family) const;
  /// {family(kWell), kPoor}.
  std::vector<std::string> tori() const;
  /// {family(kBumpIrr), kBump48}.
  std::vector<std::string> bumps() const;

  const std::vector<ErrorRow>& rows() const { return csv_->rows; }
  /// The series matching q, or nullptr after recording why in chk.
  const Series* find(Check& chk, const Query& q) const;
  /// Single-threaded timings of a method label on the timing family (timing_family()), or nullptr
  /// after recording why.
  const TimingSeries* timing(Check& chk, const std::string& method) const;
  /// Method labels (upper case) of the timing table.
  std::vector<std::string> timing_methods() const;
  /// The mesh family of the timings used: torus-unstructured (the paper's well-shaped meshes),
  /// or torus-structured if the timing table has no torus-unstructured rows (an older make bench).
  const std::string& timing_family() const { return csv_->timing_family; }

  const std::optional<CsvTable>& table2() const { return csv_->table2; }
  const std::optional<CsvTable>& table4() const { return csv_->table4; }
  const std::optional<CsvTable>& table5() const { return csv_->table5; }

  /// The results folder read (the base, not the overlay): where the diagnostics that are not
  /// error CSVs of this folder are looked for (results/deep/, results/readings/, the firing CSV
  /// of the safeguard).
  const std::string& dir() const { return csv_->dir; }

 private:
  struct Csv {
    std::vector<ErrorRow> rows;
    std::vector<Series> series;
    std::map<std::string, TimingSeries> timing;
    std::string timing_family;
    std::optional<CsvTable> table2, table4, table5;
    std::string dir;
  };
  static std::shared_ptr<const Csv> read(const std::string& dir, const std::string& overlay);

  std::shared_ptr<const Csv> csv_;
  RateFormula rate_formula_ = RateFormula::measured_h;
  std::map<std::string, std::string> substitutes_;  ///< family named -> family read
};

// ---- per-level values and the check kinds -----------------------------------------------------

struct LevelValue {
  int level = 0;
  double value = 0.0;
};

/// "levels 1-4: a, b, c, d" (or "levels 1,2,4: ..." if not contiguous).
std::string levels_text(const std::vector<int>& levels, const std::vector<std::string>& values);
std::string levels_text(const std::vector<LevelValue>& v);

/// a.e / b.e at the levels present in both.
std::vector<LevelValue> error_ratios(const Series& a, const Series& b);
/// a.e / min(others' e) at the levels present in all of them.
std::vector<LevelValue> ratios_to_min(const Series& a, const std::vector<const Series*>& others);
/// max(e) / min(e) over the series at the levels present in all of them.
std::vector<LevelValue> spreads(const std::vector<const Series*>& ss);
std::vector<std::string> methods_of(const std::vector<const Series*>& ss);

/// "<label>: rate <r> <cond> (level-halving rate <r'>); <detail>", the judged rate first (that of
/// d.rate_formula()) and the other formula's in brackets.
std::string rate_line(const Data& d, const Series& s, const std::string& cond);

/// The series' rate in the band: "[ok|FAIL] <prefix><label>: rate r <band>; errors ...".
void require_rate(const Data& d, Check& c, const Series& s, const Band& band,
                  const std::string& prefix = "");

/// "failed to converge" (rates of d.rate_formula()): the reasons; empty = converges.
std::vector<std::string> failure_reasons(const Data& d, const Series& s);
void require_failure(const Data& d, Check& c, const Series& s, const std::string& prefix = "");

/// Every level value in the band.
void require_every_level(Check& c, const std::vector<LevelValue>& v, const Band& band,
                         const std::string& what);
/// The band holds at >= 3/4 of the levels ("at >= 3 of 4 levels"); `extra`, described by
/// extra_text after its own band text, must hold wherever the band does.
void require_most_levels(Check& c, const std::vector<LevelValue>& v, const Band& band,
                         const std::string& what, const std::optional<Band>& extra = std::nullopt,
                         const std::string& extra_text = "");
/// The value at the finest common level in the band: "<what> at the finest level L = x (<band>);
/// all levels ...".
void require_finest(Check& c, const std::vector<LevelValue>& v, const Band& band,
                    const std::string& what);

/// t_a / t_b at the common levels.
std::vector<LevelValue> time_ratios(const TimingSeries& a, const TimingSeries& b);
/// time(a)/time(b) in the band at every timed level.
void require_time_ratio(const Data& d, Check& c, const std::string& a, const std::string& b,
                        const Band& band);

// ---- the registry entry -----------------------------------------------------------------------

/// One claim: its wording, its band prose (composed from `bands`), the named bands themselves,
/// and its check; a conjunction has no check and lists the claims it cites in all_of.
struct ClaimEntry {
  std::string id, title, statement, band;
  std::map<std::string, Band> bands;
  std::function<void(const Data&, Check&)> check;
  std::vector<std::string> all_of;
  /// The findings of the entry's diagnostics in the CSVs (e.g. another solver, a finer level),
  /// for the "Why" line when the claim is not reproduced, each with its kind (claims.h
  /// CauseKind: a cause only when the claim's check is reproduced with it removed, or when a
  /// measured mechanism predicts the size of the miss); empty when the diagnostics were not run.
  std::function<std::vector<WhyFinding>(const Data&)> why = nullptr;
  /// A band re-read (docs/claims.md, "Bands re-read"): the band fixed in advance, its check and
  /// why it misread the sentence (the paper's printed precision, a quantity it did not
  /// measure). CLAIMS.md gives the verdict under both; `band` and `check` are the re-read ones.
  std::string original_band = {};
  std::function<void(const Data&, Check&)> original_check = nullptr;
  std::string reread_reason = {};
};

/// One finding of `kind` (none if `text` is empty).
inline std::vector<WhyFinding> finding(CauseKind kind, std::string text) {
  if (text.empty()) return {};
  return {{kind, std::move(text)}};
}

// One function per paper section, each returning its entries in order.
std::vector<ClaimEntry> exact_claims();       // A1-A5  (claims_exact.cpp)
std::vector<ClaimEntry> section5_1_claims();  // B1-C5  (claims_section5_1.cpp)
std::vector<ClaimEntry> section5_2_claims();  // D1-D6  (claims_section5_2.cpp)
std::vector<ClaimEntry> section5_3_claims();  // E1-E9  (claims_section5_3.cpp)
std::vector<ClaimEntry> section5_4_claims();  // F1-F9  (claims_section5_4.cpp)
std::vector<ClaimEntry> section6_claims();    // G1-G4  (claims_section6.cpp)

// ---- mesh families of the claims --------------------------------------------------------------

// The well-shaped torus (the paper's unstructured GAMBIT meshes): the CGAL Delaunay-refined
// unstructured torus with the paper's vertex counts (docs/mesh_families.md). The structured and
// jittered tori are extra rows of the experiments, not used by the claims.
inline const std::string kWell = "torus-unstructured";
inline const std::string kPoor = "torus-iso-projected";
inline const std::string kNoisyTorus = "torus-iso";
inline const std::string kBumpIrr = "bump-irregular";
inline const std::string kBump48 = "bump-48";
// Data::family, tori() and bumps() give the families a check reads for these.
inline const std::vector<std::string> kDeg2Others = {"LHF-2", "LOP-2", "LSCM-2"};

}  // namespace curvbench::claims
