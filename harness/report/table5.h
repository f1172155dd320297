// The paper's Table 5 (timing, §5.4) and the measurements around it, as one section of the
// report model (report/model.h), from the CSVs that `make bench` writes (tools/bench.sh):
//
//   results/table5_timing.csv   mesh,level,verts,tris,method,degree,threads,seconds,
//                               tris_per_second: levels 1-4 of the well-shaped torus, every
//                               estimator on 1 thread, LHF-2 on 2, and bench_solvers' QR and SVD
//                               rows; its comment line "# machine: ..." names CPU, compiler and
//                               build (bench/bench_estimators.cpp)
//   results/table5_scaling.csv  the same columns: LHF-2 on torus-structured levels 5-6
//   results/limits.csv          stage,measured_seconds,bound_seconds,bound_kind,ratio,notes: each
//                               stage against the hardware's bound (bench/bench_limits.cpp)
//   results/end_to_end.csv      threads,read_s,orientation_s,fit_s,write_s,wall_s,peak_rss_mb:
//                               `curvbench estimate` on 1.44 million vertices (tools/bench.sh)
//
// Subtables: our times with the paper's beside (harness/model/paper_tables.h), throughput, time
// ratios (ours and the paper's), safeguarded QR against SVD, scaling and threads, end to end.
// A missing file leaves its subtables out; without table5_timing.csv the section says to run
// `make bench`.
#pragma once

#include <string>

#include "harness/report/model.h"

namespace curvbench {

/// The section "Table 5: timing" (id "table5") from the CSVs in results_dir. Throws InputError
/// naming the file for a malformed CSV.
report::Section table5_section(const std::string& results_dir);

}  // namespace curvbench
