// Advice from mesh features (docs/advice.md): the radius sweeps' errors per swept mesh, noise
// level, quantity and case, with the measured features of each swept mesh
// (harness/model/mesh_features.h); the choice for a mesh learned from the swept meshes nearest in
// feature space; and its leave-one-family-out cross-validation, which `make experiments` ships
// (advice_cross_validation.csv, REPORT.md, the site) and `curvbench recommend` quotes.
//
// The choice, per quantity (normals, and the mean curvature H; a curvature error grows like
// sigma/h^2, a normal error like sigma/h, so the two may differ):
//   1. the kAdviceNeighbours swept meshes nearest to the mesh, by the Euclidean distance of the
//      feature coordinates (feature_coordinate()), each divided by its standard deviation over
//      the swept meshes (at least kFeatureScaleFloor);
//   2. on each of them, the noise level nearest to the mesh's in the quantity's unit: for normals
//      sigma/h, for H the relative curvature noise (sigma/h) x size_over_h = sigma size / h^2;
//      compared as logarithms, a level below the floor (kNormalNoiseFloor, kCurvatureNoiseFloor)
//      counting as the floor, so that light noise is never rounded to none;
//   3. the case (method and radius) whose error is nearest to the best on those meshes: the
//      least mean of log(error / the mesh's best error) over the neighbours (a case missing or
//      not finite on one of them is not a candidate; a tie goes to the first in the rows' order).
#pragma once

#include <functional>
#include <limits>
#include <optional>
#include <string>
#include <vector>

#include "harness/model/measured_advice.h"
#include "harness/model/mesh_features.h"
#include "harness/model/results_table.h"
#include "harness/report/model.h"
#include "meshgen/generate.h"

namespace curvbench {

/// The quantities the advice chooses for (ErrorRow::quantity), in order, and their words.
const std::vector<std::string>& advice_quantities();
std::string advice_quantity_words(const std::string& quantity);
inline constexpr const char* kAdviceNorm = "L2";
inline constexpr int kAdviceNeighbours = 3;
inline constexpr double kFeatureScaleFloor = 0.05;
/// sigma/h below which noise counts as this floor for normals; for H the floor is in the unit
/// sigma size / h^2 (the same floor on a mesh of size_over_h 10, the swept meshes' scale).
inline constexpr double kNormalNoiseFloor = 0.0005;
inline constexpr double kCurvatureNoiseFloor = 0.005;
/// The goal the cross-validation is scored against (issue 40): within kRegretGoal of the best in
/// at least kRegretGoalShare of the held-out cases, and never worse than kRegretLimit.
inline constexpr double kRegretGoal = 2.0;
inline constexpr double kRegretGoalShare = 0.9;
inline constexpr double kRegretLimit = 4.0;

/// sigma/h of normal Gaussian noise (no noise is 0), NaN for any other noise model: the noise
/// the advice learns from.
double normal_noise_sigma(const NoiseLevel& noise);

/// One case of a swept mesh at one noise level: a row of advice_cases.csv.
struct AdviceCase {
  std::string experiment, family;  ///< family: the results' label (torus-anisotropic-A4)
  int level = 0, vertices = 0;
  double h = 0.0;
  MeshFeatures features;  ///< of the noise-free mesh
  double sigma_over_h = 0.0;
  std::string quantity;  ///< "normal", "H"
  std::string label;     ///< the case ("LHF-4 rings=2")
  double error = std::numeric_limits<double>::quiet_NaN();
};

struct AdviceTable {
  std::string name;        ///< the file's path
  std::string provenance;  ///< its first comment line, without "# "
  std::vector<AdviceCase> cases;
};

/// The cases from the radius sweeps' rows (normal Gaussian noise or none, the quantities of
/// advice_quantities() in kAdviceNorm); `features_of(family label, level)` gives a swept mesh's
/// features. Order: the rows'. No timings: the file is the same bytes at every run.
using FeaturesOf = std::function<MeshFeatures(const std::string& family_label, int level)>;
std::vector<AdviceCase> advice_cases(const std::vector<ErrorRow>& rows,
                                     const FeaturesOf& features_of);

/// Writes advice_cases.csv (provenance comment, header, one line per case) atomically.
void write_advice_cases_csv(const std::string& path, const std::vector<AdviceCase>& cases);
/// Parses it; throws InputError "<name>[:<line>]: <problem>" for a missing column, a field that
/// is not a number, a quantity not in advice_quantities(), or no case at all.
AdviceTable parse_advice_cases_csv(const std::string& text, const std::string& name);
/// DIR/advice_cases.csv; throws InputError "<file>: not found" or as the parser.
AdviceTable read_advice_cases_csv(const std::string& results_dir);

/// A swept mesh the choice read, with the noise level it read there.
struct AdviceNeighbour {
  std::string experiment, family;
  int level = 0;
  double distance = 0.0;
  double sigma_over_h = 0.0;  ///< the level read (nearest in the quantity's unit)
  std::string best_label;     ///< the best case there
  double best_error = std::numeric_limits<double>::quiet_NaN();
  double error = std::numeric_limits<double>::quiet_NaN();  ///< of the chosen case there
};

struct AdvicePick {
  std::string quantity;
  bool found = false;  ///< false: no swept mesh (left) has this quantity
  std::string label;   ///< the chosen case
  double mean_log_regret = 0.0;
  std::vector<AdviceNeighbour> neighbours;  ///< nearest first
};

/// The choice for a mesh of `features` at noise `sigma_over_h` (file comment), from the cases of
/// every family but `exclude_family` ("" excludes none).
AdvicePick pick_advice(const std::vector<AdviceCase>& cases, const MeshFeatures& features,
                       double sigma_over_h, const std::string& quantity,
                       const std::string& exclude_family = "");

/// A feature of a mesh outside the range of the swept meshes' values.
struct FeatureOutOfRange {
  std::string name, words;
  double value = 0.0, lowest = 0.0, highest = 0.0;
};
/// The features of `features` below the swept meshes' lowest or above their highest value (the
/// range widened by kFeatureScaleFloor on each side in the feature's coordinate).
std::vector<FeatureOutOfRange> features_out_of_range(const std::vector<AdviceCase>& cases,
                                                     const MeshFeatures& features);

/// One held-out case of the leave-one-family-out cross-validation.
struct CrossValidationRow {
  std::string family;
  int level = 0;
  double sigma_over_h = 0.0;
  std::string quantity;
  std::string advised;  ///< the case chosen without the family
  double advised_error = std::numeric_limits<double>::quiet_NaN();
  std::string best;  ///< the best case on the family
  double best_error = std::numeric_limits<double>::quiet_NaN();
  double regret = std::numeric_limits<double>::quiet_NaN();  ///< advised / best error
  std::string neighbours;  ///< the families the choice read, nearest first ("a; b; c")
};

/// For each swept mesh (family, level) and noise level and quantity, in the cases' order: the
/// choice learned from the other families at the mesh's own features and noise, followed on the
/// mesh and scored by its regret. A case the choice names that the mesh lacks scores NaN.
std::vector<CrossValidationRow> cross_validate(const std::vector<AdviceCase>& cases);

/// A regret as the report and `recommend` print it: "1.43"; 1000 or more (a best error at
/// round-off, an exact method) as "5.1e+12"; "n/a" when not finite.
std::string regret_text(double regret);

struct RegretSummary {
  int cases = 0;  ///< with a finite regret
  double median = std::numeric_limits<double>::quiet_NaN();
  double worst = std::numeric_limits<double>::quiet_NaN();
  double within_goal = std::numeric_limits<double>::quiet_NaN();  ///< share <= kRegretGoal
  bool meets_goal() const;
};
/// Over the rows of `quantity` (all noise levels when sigma_over_h is NaN, else that level; all
/// families when `family` is empty).
RegretSummary summarize_regret(const std::vector<CrossValidationRow>& rows,
                               const std::string& quantity,
                               double sigma_over_h = std::numeric_limits<double>::quiet_NaN(),
                               const std::string& family = "");

/// Writes advice_cross_validation.csv (provenance comment, header, rows) atomically.
void write_cross_validation_csv(const std::string& path,
                                const std::vector<CrossValidationRow>& rows);
/// Reads it back; throws InputError as read_csv_table does.
std::vector<CrossValidationRow> read_cross_validation_csv(const std::string& path);

/// A swept mesh at one noise level, generated as its sweep generated it.
struct SweptNoisyMesh {
  std::string family;  ///< the results' label
  int level = 0;
  double sigma_over_h = 0.0;  ///< the true noise
  MeshSpec spec;
};

/// One case of the advice measured on a swept mesh (harness/model/measured_advice.h): a row of
/// advice_measured.csv. `error` is the case's true L2 error there (the sweep's, from the advice
/// cases); `chosen` marks the least prediction.
struct MeasuredAdviceRow {
  std::string family;
  int level = 0;
  double sigma_over_h = 0.0;            ///< true
  double estimated_sigma_over_h = 0.0;  ///< estimate_noise(): what the measurement perturbs with
  std::string quantity, label;
  static constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
  double noise_part = kNaN, bias_part = kNaN, predicted = kNaN, error = kNaN;
  bool chosen = false;
};

/// Measures the advice on each mesh, at its estimated noise, with the cases the sweep ran on it
/// (in the cases' order) as candidates; `progress` (may be empty) is called before each mesh.
std::vector<MeasuredAdviceRow> measure_swept_advice(
    const std::vector<SweptNoisyMesh>& meshes, const std::vector<AdviceCase>& cases,
    const std::function<void(const SweptNoisyMesh&, size_t index)>& progress = {});
/// Per mesh, noise level and quantity: the chosen case scored by its regret (advised over best
/// true error among the measured cases); neighbours "measured on the mesh".
std::vector<CrossValidationRow> measured_regrets(const std::vector<MeasuredAdviceRow>& rows);
/// Writes advice_measured.csv (provenance comment, header, rows) atomically.
void write_measured_advice_csv(const std::string& path, const std::vector<MeasuredAdviceRow>& rows);
/// Reads it back; throws InputError as read_csv_table does.
std::vector<MeasuredAdviceRow> read_measured_advice_csv(const std::string& path);

/// The section "Advice on meshes it never saw" (id "advice-cross-validation"): what was held
/// out, the summary per quantity and noise level (median, worst, share within 2x, the goal) and
/// the table per family and noise level.
/// With `measured` (measured_regrets()), the advice measured on the mesh beside it: its summary
/// and its H choice and regret per family and noise level.
report::Section cross_validation_section(const std::vector<CrossValidationRow>& rows,
                                         const std::vector<CrossValidationRow>& measured = {});
/// The section from a results folder's advice_cross_validation.csv and, when present,
/// advice_measured.csv; nullopt without the first.
std::optional<report::Section> cross_validation_section_of(const std::string& results_dir);

}  // namespace curvbench
