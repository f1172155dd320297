// The per-case result store of `curvbench run`: every case (experiment, mesh family, level,
// method with its options) keeps its error rows in a small file of its own, stamped with a hash
// of everything that determines them, so that a run that was interrupted, crashed or killed
// redoes only the cases that are missing or stale.
//
//   <store>/<experiment>/<family>_L<level>_<method>_<8 hex>.csv   (<family>: the mesh line's
//     label, with its mesh options: torus-anisotropic-A16)
//     line 1   "# curvbench case: inputs <16 hex> content <16 hex>"
//     line 2   "# " + case_inputs(c) + ";code=" + code version   (for people; not parsed)
//     line 3   "# estimate-seconds <s>": the case's estimation time when it was computed; a
//              reused case keeps it (ErrorRow::seconds), so reruns report the same times
//     then     the errors CSV of results_table.h (header + this case's rows)
//     then     at the finest level of the mesh, if the method gave H: the line "# errors by
//              cause" and the errors-by-cause CSV of error_causes.h (header + rows)
//
//   <family> is followed by the mesh line's own noise label when it has one (the sweeps:
//   "torus-unstructured_normal_gauss_0.03h"), since such meshes share their family;
//   <method> is the method's label or spec with characters outside [A-Za-z0-9.+-] replaced by
//   '_'; the 8 hex digits are a hash of the method's options, so that variants of one method
//   (ablations) get separate files.
//   inputs  = fnv1a64(case_inputs(c) + code version): the file is stale when it differs.
//   content = fnv1a64(everything after line 1): the file is corrupt when it differs.
// Stale, corrupt and unreadable files are recomputed (and overwritten); files are written with
// write_file_atomic, so a killed run leaves either the whole file or none.
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "core/hash.h"
#include "harness/model/error_causes.h"
#include "harness/model/experiment.h"
#include "harness/model/results_table.h"
#include "harness/run/runner.h"

namespace curvbench {

/// 16 lower-case hex digits.
std::string hex64(std::uint64_t x);

/// The code version the store keys on: build_info(); for a build of uncommitted sources (git
/// describe ends in "-dirty") also the hash of the running executable (/proc/self/exe), so that
/// every development rebuild is a new version. Computed once per process.
const std::string& code_version();

/// One line naming every input that determines the rows of case c, except the code version:
/// experiment name, mesh family and the mesh options it takes (given or default: ";aspect=4"),
/// level, noise order and seed, noisy flag, vertex sets, method spec, label and every estimator
/// option, the (quantity, norm) pairs of the panels, and at the mesh's finest level that the
/// errors by cause are kept (error_causes.h). Titles,
/// captions and the thread count do not change the rows and are not included.
std::string case_inputs(const RunCase& c);

/// The stable id of case c, "<experiment>/<family>_L<level>_<method>_<8 hex>": its file in the
/// store without ".csv" (`curvbench run --list-cases` prints these).
std::string case_id(const RunCase& c);

/// fnv1a64(case_inputs(c) + code version).
std::uint64_t case_hash(const RunCase& c, const std::string& version);

class CaseStore {
 public:
  /// A store in `directory` (created on the first save) for code version `version`.
  explicit CaseStore(std::string directory, std::string version = code_version());

  const std::string& directory() const { return directory_; }

  /// The file of case c (whether it exists or not).
  std::string path(const RunCase& c) const;

  /// The stored rows of case c, or nothing if the file is missing, stale or corrupt; its errors
  /// by cause into `causes` if given.
  std::optional<std::vector<ErrorRow>> load(const RunCase& c,
                                            std::vector<CauseRow>* causes = nullptr) const;

  /// Stores the rows (and errors by cause) of case c atomically (replacing a previous file).
  void save(const RunCase& c, const std::vector<ErrorRow>& rows,
            const std::vector<CauseRow>& causes = {}) const;

  /// Records that case c was skipped (an outside estimator that cannot run here, exit 77) with
  /// its reason, so that --report-only of a sharded study knows it; save() of the case removes
  /// the record. The runner does not reuse a record: it asks the outside estimator again.
  void save_skipped(const RunCase& c, const std::string& reason) const;

  /// The reason recorded by save_skipped for case c, or nothing (none, stale or corrupt).
  std::optional<std::string> load_skipped(const RunCase& c) const;

  /// Removes the files in the folders of the experiments of `cases` that belong to none of
  /// `cases` (cases since removed or changed); returns how many.
  int prune(const std::vector<RunCase>& cases) const;

 private:
  std::string directory_;
  std::string version_;
};

}  // namespace curvbench
