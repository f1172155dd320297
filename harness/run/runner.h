// Runs experiments: generates each mesh level, runs each method, scores it against the exact
// surface, and returns the long-format error rows (results_table.h). With a case store
// (case_store.h) every finished case is kept on disk, and a later run reuses the cases whose
// inputs and code version are unchanged; a stop request is honoured between cases.
#pragma once

#include <functional>
#include <map>
#include <memory>
#include <string>
#include <tuple>
#include <utility>
#include <vector>

#include "harness/model/error_causes.h"
#include "harness/model/experiment.h"
#include "harness/model/results_table.h"
#include "mesh/neighbourhood_table.h"
#include "meshgen/generated_mesh.h"

namespace curvbench {

/// A generated mesh with its exact quantities per vertex, shared between experiments.
struct ScoredMesh {
  GeneratedMesh generated;
  std::vector<SurfacePoint> exact;  ///< surface->evaluate(exact_points.row(i))
  /// The starting neighbourhoods of generated.mesh, gathered once per spec and shared by every
  /// method and degree run on it (bit-identical results; mesh/neighbourhood_table.h).
  std::unique_ptr<NeighbourhoodCache> neighbourhoods;
  /// The per-vertex inputs of the errors by cause (error_causes.h), made by run_case on the
  /// first case of the mesh that needs them and shared by the others (the runner is sequential).
  mutable std::unique_ptr<VertexCauses> causes;
};

/// Generated meshes keyed by (family, level, noise order, seed, noise model, mesh options);
/// generated on first use.
class MeshCache {
 public:
  const ScoredMesh& get(const MeshSpec& spec);
  const ScoredMesh& get(const std::string& family, int level, int noise_order, std::uint64_t seed,
                        const NoiseModel& model = {}, const MeshShape& shape = {});

 private:
  std::map<std::tuple<std::string, int, int, std::uint64_t, NoiseModel, MeshShape>,
           std::unique_ptr<ScoredMesh>>
      meshes_;
};

/// One unit of work: one method on one mesh level.
struct RunCase {
  const Experiment* experiment = nullptr;
  const ExperimentMesh* mesh = nullptr;
  int level = 0;
  const ExperimentMethod* method = nullptr;
};

struct RunProgress {
  int done = 0;   ///< cases finished (computed or reused)
  int total = 0;  ///< cases in the run
  const RunCase* current = nullptr;
  bool reused = false;   ///< the current case's rows came from the store
  bool skipped = false;  ///< the current case's outside estimator cannot run here (no rows)
  double case_seconds = 0.0;
  double elapsed_seconds = 0.0;
  double eta_seconds = 0.0;  ///< estimate from the work (4^level) of the cases left to compute
  int vertices = 0;
};

struct RunOptions {
  int threads = 0;                                   ///< 0 = OpenMP default
  std::function<void(const RunProgress&)> progress;  ///< called after each case
  /// One line ("[run] skipped method ..."), without newline.
  std::function<void(const std::string&)> message;
  /// Called with an experiment's rows as soon as its last case is done (e.g. to write its CSV).
  std::function<void(const Experiment&, const std::vector<ErrorRow>&)> experiment_done;
  /// Called with an experiment's errors by cause (error_causes.h) right after experiment_done.
  std::function<void(const Experiment&, const std::vector<CauseRow>&)> causes_done;
  /// Folder of the case store (case_store.h); empty = no store, every case is computed.
  std::string store_dir;
  /// Commands of outside estimators already known not to run here (RunSummary::unavailable of
  /// an earlier run of the same process, e.g. the adopted readings' before an alternative's),
  /// with the reason: their cases are skipped without a try and without a second message.
  std::map<std::string, std::string> unavailable;
  bool force = false;  ///< recompute every case even if stored (the store is rewritten)
  /// Polled after each case; true = stop there (the finished cases are stored).
  std::function<bool()> stop;
  /// Run only shard `shard` (1-based) of `shard_count` (shard_cases). A sharded run stores its
  /// cases but calls no experiment_done and prunes nothing (the other shards' cases are not its).
  int shard = 1;
  int shard_count = 1;
};

struct RunSummary {
  std::vector<ErrorRow> rows;                  ///< rows of the finished cases, in case order
  std::vector<CauseRow> cause_rows;            ///< their errors by cause, in case order
  int total = 0;                               ///< cases in the run
  int reused = 0;                              ///< finished cases taken from the store
  int computed = 0;                            ///< finished cases computed in this run
  int skipped = 0;                             ///< cases of outside estimators that cannot run here
  std::vector<SkippedMethod> skipped_methods;  ///< per (experiment, method), first-seen order
  /// Commands of outside estimators that cannot run here, with the reason (those of
  /// RunOptions::unavailable included).
  std::map<std::string, std::string> unavailable;
  bool interrupted = false;  ///< stopped before the last case
};

/// Expands the experiments into cases (experiment order, then mesh, level, method).
std::vector<RunCase> expand_cases(const std::vector<Experiment>& experiments);

/// The (quantity, norm) pairs of the experiment's panels, in first-seen order: the rows of a case.
std::vector<std::pair<Quantity, Norm>> panel_measures(const Experiment& e);

/// Runs one case and returns its rows: every panel's (quantity, norm) on the case's vertex set,
/// each with the wall time of the estimation (ErrorRow::seconds). A `method external` runs its
/// command (external_estimator.h) and throws ExternalEstimatorError if it fails. With `causes`,
/// also the errors by cause (error_causes.h) at the mesh's finest level (none at other levels,
/// or when the method does not give H).
std::vector<ErrorRow> run_case(const RunCase& c, MeshCache& cache, int threads,
                               std::vector<CauseRow>* causes = nullptr);

/// radius-scaling (experiment.h): sets the neighbourhood parameter of `method` (a name or label
/// method_info() knows) in `opt` to the radius e.radius_c h^e.radius_alpha, i.e.
/// n = c h^(alpha - 1) edge lengths, as its registry line declares its size (NeighbourhoodSize):
/// rings n rounded to half rings (>= 1) for half_rings, to whole rings (>= 1) for whole_rings,
/// ball-factor n for ball_factor; a fixed method is left alone.
void scale_radius(const Experiment& e, const std::string& method, double h, EstimatorOptions& opt);

/// Expected relative cost of a case for balancing shards: 4^level (the vertex count grows about
/// 4x per level) times the method's relative cost per vertex (LHF-2 = 1; from the Table 5
/// timings of `make bench`, rounded; methods not in that table count 1).
double case_cost(const RunCase& c);

/// Indices (increasing) of the cases of shard k (1-based) of n: a deterministic partition
/// balanced by case_cost (largest first, each to the least loaded shard, ties to the lower
/// index). Throws UsageError unless 1 <= k <= n.
std::vector<size_t> shard_cases(const std::vector<RunCase>& cases, int k, int n);

/// Runs all cases of the experiments (taking the unchanged ones from the store, if any),
/// reporting progress, until done or options.stop() says to stop. An outside estimator whose
/// command exits with kExternalSkipExitCode is unavailable for the rest of the run: that case
/// and every later case with the same command are skipped (not run, not stored, no rows; one
/// options.message line the first time) and listed in RunSummary::skipped_methods, so that a
/// later run where it can run computes them.
RunSummary run_experiments(const std::vector<Experiment>& experiments, const RunOptions& options);

}  // namespace curvbench
