// The report's files: results/REPORT.md (a summary of at most about 150 lines), the details in
// results/report/<section>.md, and the results site results/site/ (index.html and its pages),
// all rendered from one ReportContent (report.h) by the markdown and HTML renderers of
// report/model.h. The site opens from file:// with no network: its data is embedded as JSON,
// its script and styles are its own (compiled in), Chart.js is copied from Debian's
// libjs-chart.js.
//
//   site page          what it shows
//   index.html         the leaderboard (results/leaderboard.csv), sortable and filterable, with
//                      its state in the URL's hash
//   convergence.html   the experiments, each linking to exp-<name>.html (tables, log-log plots)
//   cost.html          error in H against microseconds per vertex, Pareto frontier drawn
//   paper.html         Tables 2, 4 and 5 beside the paper's, and every claim
//   real-meshes.html   results/REAL_MESHES.md and its pictures
//   advice.html        the recommendations with their `curvbench estimate` commands
//   studies.html       the field studies, radius scaling and sweeps sections
#pragma once

#include <string>
#include <vector>

#include "harness/model/experiment.h"
#include "harness/report/leaderboard.h"
#include "harness/report/report.h"

namespace curvbench {

/// A claim as the summary and the site show it (filled from the claims by the pipeline, which
/// sits above both).
struct ClaimView {
  std::string id, statement, band, verdict;  ///< verdict: "reproduced", "not reproduced", ...
  /// Where the band was re-read (docs/claims.md): the band fixed in advance and its verdict.
  std::string original_band, original_verdict;
  std::string halving_verdict;  ///< under the paper's rate formula
  std::string why;              ///< cause of a miss ("" when reproduced)
  /// The readings whose alternatives change its evidence: the reading, its adopted choice, and
  /// each alternative's verdict ("uniform-0.1", "reproduced").
  struct Reading {
    std::string id, adopted;
    std::vector<std::pair<std::string, std::string>> alternatives;
  };
  std::vector<Reading> readings;
  std::vector<std::string> experiments;  ///< experiments whose numbers decide it
};

/// The claims as the report shows them: the counts (claims.h claim_counts_markdown) and each claim.
struct ClaimsView {
  std::string counts_markdown;
  std::vector<ClaimView> claims;
};

struct ReportFiles {
  std::string results_dir = "results";
  std::string site_dir;  ///< "" = <results_dir>/site
  /// Where Chart.js is copied from (Debian's libjs-chart.js).
  std::string chart_js = "/usr/share/javascript/chart.js/chart.min.js";
  /// The command that reproduces the results, shown on every page.
  std::string command = "make experiments";
};

/// The summary: which estimator wins where, what of the paper holds, speed against CGAL's jet,
/// links to the details. Markdown, at most about 150 lines.
std::string summary_markdown(const ReportContent& content, const std::vector<LeaderRow>& board,
                             const ClaimsView& claims, const std::string& results_dir);

/// Writes REPORT.md and results/report/*.md (each atomically). Returns REPORT.md's path.
std::string write_markdown_report(const ReportContent& content, const std::vector<LeaderRow>& board,
                                  const ClaimsView& claims, const ReportFiles& files);

/// Writes the site into a temporary folder next to it, then renames it into place (nothing half
/// written is left). Throws InputError naming the file when an input is missing or unreadable
/// (Chart.js included). Returns the path of index.html.
std::string write_site(const std::vector<Experiment>& experiments, const ReportContent& content,
                       const std::vector<LeaderRow>& board, const ClaimsView& claims,
                       const ReportFiles& files);

}  // namespace curvbench
