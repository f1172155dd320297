// The leaderboard of the results site and of REPORT.md's summary: per estimator (method label
// as the experiments name it) and mesh class, its finest-level error, convergence rate and time
// per vertex, for every quantity and norm; written to results/leaderboard.csv.
//
// The mesh classes (mesh_classes(), one table): which series of which experiments stand for a
// class. A class with several meshes (e.g. the irregular and the 4-8 bump) shows the worst of
// them: the largest finest-level error and the smallest rate, so that a row never looks better
// than the estimator is on any mesh of its class. Rates are log(e1/eN)/log(h1/hN) over the first
// and last level with the measured mean edge length h (the report's "rate (h)"). A method scored
// on the interior vertices only (Xu-2 and the operators undefined at a boundary, paper §5.2)
// enters with its interior series, its mesh named "<family>(interior)".
//
// CSV columns: method,group,mesh_class,quantity,norm,error,rate,us_per_vertex,meshes,experiment,
//              finest_level
#pragma once

#include <string>
#include <vector>

#include "harness/model/experiment.h"
#include "harness/model/results_table.h"

namespace curvbench {

struct MeshClassRule {
  std::string id;     ///< "well-shaped", ...
  std::string title;  ///< column heading on the site
  /// Whether the rows of (the experiment's report section, family, noise, vertex set) belong to
  /// the class.
  bool (*member)(ReportSection experiment, const std::string& family, const std::string& noise,
                 const std::string& vertex_set);
};

/// The classes, in column order: well-shaped, isosurface, irregular/4-8, boundary ring,
/// noisy O(h^2), noisy O(h^3), hard meshes.
const std::vector<MeshClassRule>& mesh_classes();

/// Whether an experiment's rows feed the leaderboard: the paper's figures, the field studies and
/// the hard meshes (not the ablations, diagnostics and sweeps, whose labels are variants).
bool feeds_leaderboard(const Experiment& e);

struct LeaderRow {
  std::string method;      ///< "LHF-2"
  std::string group;       ///< to_string(MethodGroup)
  std::string mesh_class;  ///< MeshClassRule::id
  std::string quantity, norm;
  double error = 0.0;          ///< worst finest-level error over the class's meshes
  double rate = 0.0;           ///< smallest rate over them
  double us_per_vertex = 0.0;  ///< at the finest level of the largest mesh; NaN when not timed
  std::string meshes;          ///< the mesh labels, ' '-separated
  std::string experiment;      ///< the experiment of the worst error (its page holds the series)
  int finest_level = 0;
};

/// The rows from <results_dir>/<experiment>.csv and timings/<experiment>.csv, ordered by
/// method (first seen), class, quantity, norm. Missing CSVs contribute nothing.
std::vector<LeaderRow> leaderboard_rows(const std::vector<Experiment>& experiments,
                                        const std::string& results_dir);

void write_leaderboard_csv(const std::string& path, const std::vector<LeaderRow>& rows);
/// Reads it back; throws InputError naming the file on a missing column or a bad number.
std::vector<LeaderRow> read_leaderboard_csv(const std::string& path);

}  // namespace curvbench
