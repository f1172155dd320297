// The errors-by-cause tables of an experiment's report section, read from
// results/errors_by_cause/<experiment>.csv (harness/model/error_causes.h writes it).
#pragma once

#include <string>

#include "harness/model/error_causes.h"
#include "harness/model/experiment.h"
#include "harness/report/model.h"

namespace curvbench {

/// Appends to an experiment's section `out` a heading and its words, then per mesh family of the
/// experiment a table of the errors by cause at the finest level (methods as rows, bins as
/// columns, the vertex count of each bin first; each cell with its number) from
/// <results_dir>/errors_by_cause/<experiment>.csv; nothing when that file is missing.
void cause_tables(const Experiment& e, const std::string& results_dir, report::Section& out);

}  // namespace curvbench
