// The paper's checkable claims (docs/claims.md, A1-G4) evaluated against the result CSVs, and
// results/CLAIMS.md. The claims form one registry: each claim is one entry (wording, named bands,
// check) in the file of its paper section, harness/claims/exact.cpp (A: tables and identities),
// claims_section5_1.cpp (B, C), claims_section5_2.cpp (D), claims_section5_3.cpp (E),
// claims_section5_4.cpp (F) and claims_section6.cpp (G: conjunctions); harness/claims/kit.h has
// the check kinds they share.
//
// Inputs (all in results_dir, all optional; a claim whose data is missing is "not applicable"):
//   *.csv with the errors header   errors rows (results_table.h ErrorRow), any experiment name;
//                                  series are looked up by configuration (mesh family, noise,
//                                  vertex set, method label case-insensitively, quantity, norm)
//   table2.csv                     degree,coefficients,ring,points_with_centre,paper_points
//   table4.csv                     grid_points,vertices,mean_edge_length,paper_edge_length,
//                                  rms_error,max_error
//   table5_timing.csv              mesh,level,verts,tris,method,degree,threads,seconds,
//                                  tris_per_second (single-threaded rows, threads == 1, on the
//                                  torus-unstructured meshes, or torus-structured in a table
//                                  from before that family, are used; the minimum over repeated
//                                  rows). F7 compares a method label containing "SVD" with one
//                                  containing "QR" (or LHF-2 if there is none), e.g. "LHF-2-SVD"
//                                  vs "LHF-2-QR"; F9 compares "Jet-2" with "LHF-2".
//
// Rates are log(e_first/e_last)/log(h_first/h_last) over the levels present (as compute_rates),
// "finest level" is the largest level present in both series compared, and "at >= 3 of 4 levels"
// means at >= 3/4 of the common levels. The "failed to converge" criterion (docs/claims.md
// conventions): rate <= 0.5, or e_last >= 0.7 e_first, or non-monotone with no net decrease; a
// non-finite last error also counts as a failure.
#pragma once

#include <string>
#include <vector>

#include "harness/model/family_substitute.h"

namespace curvbench {

enum class Verdict { reproduced, not_reproduced, not_applicable };

/// An acceptance band of a claim: a condition on one number (a rate, a ratio, a rate gap) that
/// prints its own text ("in [1.6, 2.6]", ">= 2", "within a factor 1.5"). The registry entry
/// holds each band once; its band prose, its check and the tests read the same value.
struct Band {
  enum class Kind { in, at_least, above, at_most, below, within_factor };
  Kind kind = Kind::in;
  double lo = 0.0, hi = 0.0;  ///< bounds (at_least/above: lo; at_most/below/within_factor: hi)
  int decimals = -1;          ///< digits after the point in text(); -1 = shortest (%g)

  static Band in(double lo, double hi, int decimals = -1) { return {Kind::in, lo, hi, decimals}; }
  static Band at_least(double x, int decimals = -1) { return {Kind::at_least, x, 0, decimals}; }
  static Band above(double x, int decimals = -1) { return {Kind::above, x, 0, decimals}; }
  static Band at_most(double x, int decimals = -1) { return {Kind::at_most, 0, x, decimals}; }
  static Band below(double x, int decimals = -1) { return {Kind::below, 0, x, decimals}; }
  /// x in [1/f, f].
  static Band within_factor(double f) { return {Kind::within_factor, 1.0 / f, f, -1}; }

  bool holds(double x) const;
  std::string text() const { return text(decimals); }
  std::string text(int digits_after_point) const;
};

/// "reproduced", "not reproduced", "not applicable".
const char* to_string(Verdict v);

/// What one finding of a Why line establishes (docs/claims.md, "Why lines"). Only the first two
/// kinds may be called a cause; the line says which kind each finding is.
enum class CauseKind {
  /// With it removed (another reading, a vertex subset, a finer level, another solver) the
  /// claim's own check is reproduced.
  cause_removed_passes,
  /// A measured mechanism predicts the size of the miss.
  mechanism_predicts,
  /// Where the miss is (which quantities, vertices, levels), not why.
  localised,
  /// A diagnostic that was run and neither removes nor explains the miss.
  tried,
};
bool is_cause(CauseKind kind);

struct WhyFinding {
  CauseKind kind = CauseKind::tried;
  std::string text;  ///< what was measured, with its numbers; never says "cause" itself
};

/// The Why line of `findings`: the causes (each with its kind), then what was localised and what
/// was tried; "No cause found." first when no finding is a cause.
std::string why_text(const std::vector<WhyFinding>& findings);

struct ClaimResult {
  std::string id;         ///< "A1" ... "G4"
  std::string statement;  ///< the paper's wording (docs/claims.md)
  std::string band;       ///< the acceptance band
  Verdict verdict = Verdict::not_applicable;
  std::string evidence;  ///< one line per check, '\n'-separated, with the deciding numbers
  /// The verdict when every rate is the paper's level-halving rate (1/(L-1)) log2(e_1/e_L)
  /// instead of ours over the measured mean edge length; the checks of that evaluation whose
  /// outcome differs from `evidence` are in halving_evidence (empty if the verdicts agree).
  Verdict halving_verdict = Verdict::not_applicable;
  std::string halving_evidence;
  /// For a claim not reproduced: what its diagnostics establish (the rate formula, the mesh
  /// shape: the same check on the jittered and structured tori, the experiments named by the
  /// registry entry), each finding with its kind, and the line why_text makes of them (without
  /// the readings, which claims_markdown adds). Empty otherwise.
  std::vector<WhyFinding> why_findings;
  std::string why;
  /// A re-read band (claims/kit.h ClaimEntry::original_band): the band fixed in advance, the
  /// reason for the re-reading and the verdict and evidence under the original band.
  std::string original_band, reread_reason;
  Verdict original_verdict = Verdict::not_applicable;
  std::string original_evidence;
};

/// The band named `name` of claim `id` in the registry (e.g. ("B1", "rate")); throws
/// std::out_of_range if there is none. The tests build their synthetic data from these values.
Band claim_band(const std::string& id, const std::string& name);

/// Evaluates claims A1-G4 of docs/claims.md from the CSVs in results_dir (see above), in order.
/// With `overlay`, an experiment with rows in that folder's CSVs is read from there (a reading's
/// run, readings.h); with `substitute` (a reading's family swap, e.g. torus-unstructured by
/// torus-unstructured-minval5), the checks read the substitute's rows for that family. Throws
/// InputError if a CSV it reads is malformed.
std::vector<ClaimResult> evaluate_claims(const std::string& results_dir,
                                         const std::string& overlay = "",
                                         const FamilySubstitute& substitute = {});

/// Every claim under one alternative reading (readings.h): the reading, the choice and what it
/// does, and the results in registry order.
struct ReadingResults {
  std::string reading, choice, description;
  std::vector<ClaimResult> results;
};

/// The claims under each alternative reading whose folder (readings.h reading_folder) holds
/// CSVs, in the readings table's order.
std::vector<ReadingResults> evaluate_readings(const std::string& results_dir);

/// One choice of a reading (readings.h), or of the rate formula ("rate-formula": "measured-h",
/// the adopted one, or "level-halving", the paper's).
struct ReadingPick {
  std::string reading, choice;
  bool operator==(const ReadingPick&) const = default;
};

/// Two claims that no one consistent choice of readings reproduces together, each reproduced
/// under some choice; `why` names the choices each needs, e.g. "E5 needs noise-alpha =
/// uniform-0.1 or gaussian-0.1; E9 needs noise-alpha = gaussian-0.033".
struct IncompatiblePair {
  std::string a, b, why;
  /// false when a choice that picks two alternatives touching one of the claims (never run
  /// together, so its verdict is undetermined) might still reproduce both: a joint run would
  /// decide the pair.
  bool decided = true;
};

/// The summary counts of CLAIMS.md, for the report, the site and README's headline.
struct ClaimCounts {
  int total = 0;
  /// Reproduced under the bands fixed in advance, the adopted readings and our rate formula.
  int fixed_bands = 0;
  /// The same with the re-read bands (ClaimResult::original_band); `reread` lists those claims.
  int reread_bands = 0;
  std::vector<std::string> reread;
  /// Under the re-read bands and the adopted readings.
  int not_reproduced = 0, not_applicable = 0;
  /// The largest number reproduced (re-read bands) under one consistent choice: one choice per
  /// reading that has alternatives in the results, and one rate formula. `best_choice` lists the
  /// picks that differ from the adopted ones (empty: the adopted choice is best); gained and lost
  /// are the claims whose verdict that choice changes against the adopted one. A claim touched
  /// by two of the picked alternatives at once was never run under both together: it is not
  /// counted and is listed in `undetermined`.
  int best = 0;
  std::vector<ReadingPick> best_choice;
  std::vector<std::string> best_gained, best_lost, undetermined;
  int choices_searched = 0;  ///< the number of consistent choices compared
  std::vector<IncompatiblePair> incompatible;
};

/// The counts over `results` (adopted readings) and the alternatives' results
/// (evaluate_readings). A claim's verdict under a choice is that of the one picked alternative
/// whose evidence differs from the adopted one (with the picked rate formula); a conjunction's
/// (G) is recomputed from its cited claims under the same choice.
ClaimCounts claim_counts(const std::vector<ClaimResult>& results,
                         const std::vector<ReadingResults>& alternatives);

/// The summary line and the counts behind it, as CLAIMS.md, REPORT.md and the site show them.
std::string claim_counts_markdown(const ClaimCounts& counts);

/// Markdown: title, header_line (build info and date), a count per verdict, a summary table,
/// the readings' sensitivity table (if any alternatives), then one section "## <id>. ..." per
/// claim with the wording, band, verdict, its verdict under each alternative reading that
/// changes its evidence, and the evidence.
std::string claims_markdown(const std::vector<ClaimResult>& results, const std::string& header_line,
                            const std::vector<ReadingResults>& alternatives = {});

}  // namespace curvbench
