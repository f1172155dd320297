// The paper's checkable claims (shared/reference/PAPER_CLAIMS.md, A1-G4) evaluated against the
// result CSVs, and results/CLAIMS.md.
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
//                                  torus-structured meshes are used; the minimum over repeated
//                                  rows). F7 compares a method label containing "SVD" with one
//                                  containing "QR" (or LHF-2 if there is none), e.g. "LHF-2-SVD"
//                                  vs "LHF-2-QR"; F9 compares "Jet-2" with "LHF-2".
//
// Rates are log(e_first/e_last)/log(h_first/h_last) over the levels present (as compute_rates),
// "finest level" is the largest level present in both series compared, and "at >= 3 of 4 levels"
// means at >= 3/4 of the common levels. The "failed to converge" criterion (PAPER_CLAIMS
// conventions): rate <= 0.5, or e_last >= 0.7 e_first, or non-monotone with no net decrease; a
// non-finite last error also counts as a failure.
#pragma once

#include <string>
#include <vector>

namespace curvbench {

enum class Verdict { reproduced, not_reproduced, not_applicable };

/// "reproduced", "not reproduced", "not applicable".
const char* to_string(Verdict v);

struct ClaimResult {
  std::string id;         ///< "A1" ... "G4"
  std::string statement;  ///< the paper's wording (PAPER_CLAIMS)
  std::string band;       ///< the acceptance band
  Verdict verdict = Verdict::not_applicable;
  std::string evidence;  ///< one line per check, '\n'-separated, with the deciding numbers
};

/// Evaluates claims A1-G4 of PAPER_CLAIMS.md from the CSVs in results_dir (see above), in order.
/// Throws InputError if a CSV it reads is malformed.
std::vector<ClaimResult> evaluate_claims(const std::string& results_dir);

/// Markdown: title, header_line (build info and date), a count per verdict, a summary table,
/// then one section "## <id>. ..." per claim with the wording, band, verdict and evidence.
std::string claims_markdown(const std::vector<ClaimResult>& results,
                            const std::string& header_line);

}  // namespace curvbench
