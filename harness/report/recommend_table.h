// The recommendations table read back (results/recommendations.csv, written by
// write_recommendations_csv in harness/report/recommend.h) and the advice `curvbench recommend`,
// `curvbench estimate --method auto` and Python's estimate(method="auto") give from it and the
// advice cases beside it (advice_cases.csv, harness/report/advice.h): per quantity the estimator
// and radius learned from the swept meshes nearest in the mesh's features, with what
// cross-validation measured there (or, without advice cases, the row that matches the mesh's
// quality class and noise), and the `curvbench estimate` command line that runs them.
//
// The default table is a file found from where the code runs, not from the working folder:
// `make install` puts results/recommendations.csv into PREFIX/share/curvbench/, and a build
// tree's program reads the source tree's results/ (recommendations_search_paths()); `--results
// DIR` reads DIR/recommendations.csv instead. (Not compiled in: the executable's bytes name the
// code of a dirty tree in the case store, harness/run/case_store.h, and a table compiled in would
// change them at every `make experiments`.)
#pragma once

#include <limits>
#include <optional>
#include <string>
#include <vector>

#include "curvbench/estimator_options.h"
#include "harness/model/estimator_choice.h"
#include "harness/model/mesh_features.h"
#include "harness/model/noise_estimate.h"
#include "harness/report/advice.h"
#include "harness/report/recommend.h"
#include "mesh/creases.h"
#include "mesh/mesh.h"

namespace curvbench {

/// One row of a recommendations CSV. The fields of a "not swept" row past `swept` are empty.
struct RecommendationRow {
  std::string quality;
  double sigma_over_h = 0.0;
  bool swept = false;
  std::string experiment, family;  ///< the sweep and the mesh that stands for the quality class
  int level = 0, vertices = 0;
  double h = 0.0;
  std::string noise, quantity, norm;  ///< "normal gauss 0.01h", "H", "L2"
  int cases = 0;
  std::string best_label;  ///< the most accurate case ("LHF-4 rings=2")
  double best_error = std::numeric_limits<double>::quiet_NaN();
  double best_seconds = std::numeric_limits<double>::quiet_NaN();
  std::string cheapest_label;  ///< the fastest case within 2x of it ("" when none was timed)
  double cheapest_error = std::numeric_limits<double>::quiet_NaN();
  double cheapest_seconds = std::numeric_limits<double>::quiet_NaN();
  int line = 0;                     ///< line of the file
  std::vector<std::string> fields;  ///< the row as written, one field per header column
};

struct RecommendationTable {
  std::string name;        ///< the file's path
  std::string provenance;  ///< the file's first comment line, without "# " ("" when none)
  std::vector<std::string> header;
  std::vector<RecommendationRow> rows;  ///< one per quality class and noise level, file order
};

/// Parses a recommendations CSV; `name` names it in messages. Throws InputError
/// "<name>[:<line>]: <problem>" for a table that is empty, lacks a column, has a row of another
/// field count (a truncated file), a quality class or noise level the table does not have, a
/// cell twice or missing, a field that is not a number, or a swept row whose best case names no
/// estimator `curvbench estimate` can run (estimator_choice).
RecommendationTable parse_recommendations_csv(const std::string& text, const std::string& name);
/// DIR/recommendations.csv; throws InputError "<file>: not found" or as parse_recommendations_csv.
RecommendationTable read_recommendations_csv(const std::string& results_dir);
/// Where the default table is looked for, in order: P/share/curvbench/recommendations.csv for P
/// the parent of the folder of the file running this code (the curvbench executable,
/// libcurvbench.so or the Python module), then of the two folders above it (so that bin/, lib/
/// and lib/python3.X/site-packages/ all find PREFIX/share/curvbench), then
/// results/recommendations.csv of the source tree this code was built from.
std::vector<std::string> recommendations_search_paths();
/// The first of recommendations_search_paths() that exists ("" when none does).
std::string default_recommendations_path();
/// The table at default_recommendations_path(); throws InputError naming the places looked in
/// when there is none, or as parse_recommendations_csv.
RecommendationTable default_recommendations();
/// The first line of a recommendations CSV when it is a comment, without "# " (the provenance:
/// "curvbench 0.1.0 (git 747a679) GNU 12.2.0 Release, generated ..."); "" otherwise.
std::string recommendations_provenance(const std::string& path);

/// The advice cases (advice_cases.csv) in the folder of the recommendations table `table_path`
/// (written by the same `make experiments`); none when that folder has no such file (a table of
/// an older curvbench). Throws InputError as parse_advice_cases_csv.
std::optional<AdviceTable> advice_cases_beside(const std::string& table_path);

/// The advice of the mesh features for one quantity (harness/report/advice.h).
struct QuantityAdvice {
  AdvicePick pick;
  EstimatorChoice choice;  ///< the pick's case as an estimator (when pick.found)
  /// The cross-validation's regrets (advised over best error, each learned without its family)
  /// on the swept meshes the pick read, at the noise levels it read there.
  RegretSummary validated;
  double lowest_regret = std::numeric_limits<double>::quiet_NaN();
  /// The pick's error on those meshes (lowest, highest).
  double lowest_error = std::numeric_limits<double>::quiet_NaN();
  double highest_error = std::numeric_limits<double>::quiet_NaN();
};

/// The advice measured on the mesh itself (`curvbench recommend --measure`,
/// harness/model/measured_advice.h), over the advice cases' estimators.
struct MeasuredRecommendation {
  MeasuredAdvice advice;
  std::vector<EstimatorChoice> candidates;  ///< in the advice cases' order
  /// What the same measurement advised on the swept meshes against their exact answers
  /// (advice_measured.csv beside the table), per quantity in measured_quantities() order; no
  /// cases when that file is absent.
  std::vector<RegretSummary> validated;
};

/// The advice for a mesh: its class, its noise (given, or estimated when `noise` is NaN), the
/// table's row for them and, when that row was swept, the estimator it recommends.
struct Advice {
  MeshClass mesh_class;
  double sigma_over_h = 0.0;
  bool noise_estimated = false;
  double noise_level = 0.0;  ///< nearest_noise_level(sigma_over_h)
  RecommendationRow row;
  bool has_choice = false;  ///< false when the row is "not swept"
  EstimatorChoice choice;   ///< the row's most accurate case
  /// The choice's case, what it was ranked by and the error measured: the class row's best, or
  /// with the advice from mesh features the curvature's pick and its error on the nearest swept
  /// mesh (experiment, family, level: that mesh's).
  std::string label, quantity, norm;
  double error = std::numeric_limits<double>::quiet_NaN();
  std::string experiment, family;
  int level = 0;
  std::string table;                ///< the table's name
  std::string provenance;           ///< the table's provenance
  std::vector<std::string> header;  ///< the table's header (for the row's CSV and JSON)
  int vertices = 0;                 ///< of the mesh
  double h = 0.0;                   ///< its mean edge length
  /// sigma/h^2 = sigma_over_h / h (1/length): the noise in the unit of the curvature error it
  /// causes (harness/model/noise_estimate.h); small sigma/h can be large here on a fine mesh.
  double sigma_over_h2 = 0.0;
  double crease_angle = kDefaultCreaseAngle;  ///< degrees (mesh/creases.h)
  int sharp_edges = 0;                        ///< at crease_angle
  int crease_vertices = 0;             ///< on a sharp edge: no smooth-surface curvature there
  std::vector<int> crease_vertex_ids;  ///< those vertices, increasing
  /// Left out of the noise estimate (when estimated; harness/model/noise_estimate.h, which may
  /// take its creases at a larger angle on a noisy mesh): crease vertices, and the vertices with
  /// a crease vertex in their fit.
  int noise_crease_vertices = 0;
  int noise_near_crease_vertices = 0;
  /// The advice from mesh features, given advice cases: the mesh's features, a choice per
  /// quantity (advice_quantities() order), and the features outside the swept meshes' range.
  /// With it, `choice` is the mean curvature's choice (has_choice when it found one), not the
  /// class row's.
  bool has_feature_advice = false;
  std::string advice_table;  ///< the advice cases' file
  MeshFeatures features;
  std::vector<QuantityAdvice> quantities;
  std::vector<FeatureOutOfRange> out_of_range;
  /// Measured on the mesh (measure_on_mesh): then `choice` is its curvature's choice.
  bool has_measured = false;
  MeasuredRecommendation measured;
  /// Whether the normals' and the curvature's choices differ.
  bool choices_differ() const;
};
/// Throws InputError as classify_mesh and estimate_noise do, UsageError for a negative or
/// non-finite `noise`. Creases are those of detect_creases at its default angle. Without
/// `cases`, the advice is the class row's alone.
Advice advise(const Mesh& mesh, double noise, const RecommendationTable& table,
              const AdviceTable* cases = nullptr);

/// Adds the advice measured on `mesh` at the advice's noise (given or estimated) over the
/// estimators of `cases`, with `threads` threads (0: all cores); the mesh is oriented first
/// (closed parts outward). Its curvature's choice becomes the advice's `choice` (family and
/// level cleared: no swept mesh stands behind it). The crease vertices (crease_vertex_ids) are
/// left out of its error predictions. Throws InputError without `cases` ("measure:
/// no advice_cases.csv beside <table>"), for cases naming no estimator, for a quantity no case
/// gives a finite value of, and as orient_mesh and measure_advice do.
void measure_on_mesh(Advice& advice, const Mesh& mesh, const AdviceTable* cases, int threads = 0);

/// Whether `method` is "auto" (case-insensitive): the estimator and radius of the advice.
bool is_auto_method(const std::string& method);
/// The options of method "auto": the choice's, with the run options of `given` (threads,
/// kernel). Throws UsageError naming an option of role "result" given away from its default (the
/// choice is the whole estimator), spelled as a flag (--rings) or, with `python_keywords`, as
/// Python's keyword (ball_factor).
EstimatorOptions auto_options(const EstimatorChoice& choice, const EstimatorOptions& given,
                              bool python_keywords);

/// A word of a shell command, quoted with '...' when it holds anything but
/// [A-Za-z0-9_./:=+,@%-] (empty: '').
std::string shell_quote(const std::string& word);
/// Where the printed command writes: the mesh's path with its extension replaced by
/// ".curvatures.csv" ("meshes/bunny.off" -> "meshes/bunny.curvatures.csv").
std::string advice_output_path(const std::string& mesh_path);
/// `program estimate MESH --method M [--rings R | --ball-factor C] [--skip-invalid] --output OUT`,
/// every word shell-quoted.
std::string estimate_command(const std::string& program, const std::string& mesh_path,
                             const EstimatorChoice& choice, bool skip_invalid,
                             const std::string& output);

/// The human text of `curvbench recommend` (see docs/cli.md): mesh, class and why, noise and
/// why, estimator and radius, the error the sweep measured and on which mesh, the faster case
/// within 2x, the table, and `command` (empty: none, e.g. a row not swept).
std::string advice_text(const Advice& a, const std::string& mesh_path, const std::string& command);
/// The same as one JSON object (NaN as null; "row": the table's fields by column, as strings).
std::string advice_json(const Advice& a, const std::string& mesh_path, const std::string& command);
/// The table's header and the advice's row, as two CSV lines.
std::string advice_csv(const Advice& a);

}  // namespace curvbench
