// Runs experiments: generates each mesh level, runs each method, scores it against the exact
// surface, and returns the long-format error rows (results_table.h).
#pragma once

#include <functional>
#include <map>
#include <memory>
#include <string>
#include <tuple>
#include <vector>

#include "harness/experiment.h"
#include "harness/results_table.h"
#include "meshgen/generated_mesh.h"

namespace curvbench {

/// A generated mesh with its exact quantities per vertex, shared between experiments.
struct ScoredMesh {
  GeneratedMesh generated;
  std::vector<SurfacePoint> exact;  ///< surface->evaluate(exact_points.row(i))
};

/// Generated meshes keyed by (family, level, noise order, seed); generated on first use.
class MeshCache {
 public:
  const ScoredMesh& get(const std::string& family, int level, int noise_order, std::uint64_t seed);

 private:
  std::map<std::tuple<std::string, int, int, std::uint64_t>, std::unique_ptr<ScoredMesh>> meshes_;
};

/// One unit of work: one method on one mesh level.
struct RunCase {
  const Experiment* experiment = nullptr;
  const ExperimentMesh* mesh = nullptr;
  int level = 0;
  const ExperimentMethod* method = nullptr;
};

struct RunProgress {
  int done = 0;   ///< cases finished
  int total = 0;  ///< cases in the run
  const RunCase* current = nullptr;
  double case_seconds = 0.0;
  double elapsed_seconds = 0.0;
  double eta_seconds = 0.0;  ///< estimate from vertices processed so far
  int vertices = 0;
};

struct RunOptions {
  int threads = 0;                                   ///< 0 = OpenMP default
  std::function<void(const RunProgress&)> progress;  ///< called after each case
  /// Called with an experiment's rows as soon as its last case is done (e.g. to write its CSV).
  std::function<void(const Experiment&, const std::vector<ErrorRow>&)> experiment_done;
};

/// Expands the experiments into cases (experiment order, then mesh, level, method).
std::vector<RunCase> expand_cases(const std::vector<Experiment>& experiments);

/// Runs one case and returns its rows: every panel's (quantity, norm) on the case's vertex set.
std::vector<ErrorRow> run_case(const RunCase& c, MeshCache& cache, int threads);

/// Runs all cases of the experiments, reporting progress; rows in case order.
std::vector<ErrorRow> run_experiments(const std::vector<Experiment>& experiments,
                                      const RunOptions& options);

}  // namespace curvbench
