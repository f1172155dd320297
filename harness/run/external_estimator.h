// Outside estimators as experiment methods: `method external name=N command="... {mesh} {out}"`.
//
// For each case the runner writes the mesh to a temporary PLY ({mesh}: positions and faces only,
// no exact quantities), runs the command through /bin/sh in the current folder with a time
// limit, and reads {out}, an estimate CSV in the format of `curvbench score` (score.h). {mesh}
// and {out} are replaced by single-quoted paths in a fresh temporary folder, removed afterwards.
#pragma once

#include <string>
#include <utility>
#include <vector>

#include "core/errors.h"
#include "harness/model/metrics.h"
#include "mesh/mesh.h"
#include "methods/estimator.h"

namespace curvbench {

/// An outside estimator failed: non-zero exit, killed by a signal, over its time limit, or its
/// output is missing or malformed. what() is one line naming the case and the reason (with the
/// last lines of the command's stderr).
class ExternalEstimatorError : public InputError {
 public:
  using InputError::InputError;
};

/// The exit code by which an outside estimator says it cannot run here (a missing library or
/// interpreter), as automake's SKIP: the runner skips the method instead of failing the run.
inline constexpr int kExternalSkipExitCode = 77;

/// The command exited with kExternalSkipExitCode. reason() is the last line of its stderr (or a
/// fixed text when it wrote none).
class ExternalEstimatorUnavailable : public ExternalEstimatorError {
 public:
  ExternalEstimatorUnavailable(const std::string& what, std::string reason)
      : ExternalEstimatorError(what), reason_(std::move(reason)) {}
  const std::string& reason() const { return reason_; }

 private:
  std::string reason_;
};

struct ExternalRun {
  std::string command;         ///< with {mesh} and {out}
  double timeout_seconds = 0;  ///< <= 0: kDefaultExternalTimeout
  std::string case_name;       ///< e.g. "field-estimators bump-irregular L3 myest", for errors
};

/// Time limit of one run of an outside estimator when the experiment gives none.
inline constexpr double kDefaultExternalTimeout = 600.0;

struct ExternalResult {
  std::vector<VertexEstimate> estimates;  ///< one per vertex; quantities not given are NaN
  std::vector<Quantity> quantities;       ///< the quantities the command wrote
  double seconds = 0.0;                   ///< wall time of the command
};

/// Runs the command on the mesh and reads its estimates. Throws ExternalEstimatorUnavailable
/// when it exits with kExternalSkipExitCode, ExternalEstimatorError for any other failure.
ExternalResult run_external_estimator(const Mesh& mesh, const ExternalRun& run);

/// The words of the command that name existing regular files (relative to the current folder),
/// e.g. the script; the case store keys on their contents.
std::vector<std::string> files_named_in(const std::string& command);

}  // namespace curvbench
