// The paper's unstated choices as named readings (docs/claims.md, "Readings"): ONE table. Each
// reading names the paper's words, the choice curvbench adopts and the alternatives considered;
// each choice says how it changes an experiment (experiment.h: the mesh levels, the noise model,
// the noisy-data rings, ...). `curvbench run` runs the experiments of the adopted choice into
// results/ and, for each alternative, the experiments it changes into
// results/readings/<reading>=<choice>/; CLAIMS.md evaluates every claim under each alternative
// as well (claims.h evaluate_claims with an overlay folder) and prints the sensitivity table.
#pragma once

#include <functional>
#include <string>
#include <vector>

#include "harness/model/experiment.h"
#include "harness/model/family_substitute.h"

namespace curvbench {

struct ReadingChoice {
  std::string name;         ///< "32-256": the folder's and the table's name of the choice
  std::string description;  ///< one line: what the choice does
  /// Changes an experiment to this choice; returns whether anything changed (the adopted
  /// choice is the experiment files' own and changes nothing).
  std::function<bool(Experiment&)> apply;
  /// The family the claims read in place of another under this choice (none by default).
  FamilySubstitute substitute;
};

struct Reading {
  std::string id;                      ///< "iso-levels"
  std::string title;                   ///< "Which isosurface meshes"
  std::string paper;                   ///< where the paper is silent or ambiguous, with its section
  std::vector<ReadingChoice> choices;  ///< the adopted one first
};

/// Every reading, in docs/claims.md's order.
const std::vector<Reading>& readings();

/// The experiments that `choice` changes, changed (those it leaves alone are not returned); a
/// changed experiment keeps only the mesh lines the choice changes when it changes some lines
/// only (its other families' rows are the adopted run's).
std::vector<Experiment> apply_reading(const std::vector<Experiment>& experiments,
                                      const ReadingChoice& choice);

/// "results/readings/iso-levels=16-128": the folder of a choice's CSVs under `output`.
std::string reading_folder(const std::string& output, const Reading& reading,
                           const ReadingChoice& choice);

}  // namespace curvbench
