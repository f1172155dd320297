// REPORT.md section "Sweeps at a fixed mesh": the experiments marked `sweep radius` or
// `sweep noise` (experiment.h), from their errors CSVs in the results folder.
//
// Radius sweeps (one mesh level, methods expanded over a list of radii, `method lhf-2
// rings=1,1.5,...`, labelled "LHF-2 rings=1.5"; fixed 1-ring methods without a suffix):
//   - one plot per (family, noise, quantity) of the L2 error against the radius in units of h
//     (the option its registry line's neighbourhood size names: rings or the ball factor C), one
//     curve per method, the fixed methods as horizontal lines, each curve's best radius circled:
//     plots/<experiment>_<family>_<noise>_<quantity>.{png,svg};
//   - a table per (family, noise) of each method's best radius and its error, per quantity
//     ("rings 4 (largest)" when the best is the largest radius swept);
//   - <results>/best_radius.csv (provenance header): one row per (experiment, family, level,
//     noise, method, quantity, norm) with the best radius, the label of its case (to join the
//     timings CSVs) and its error.
// Noise sweeps (one mesh level, mesh lines expanded over noise-sigma= and outliers=): one plot
// per (family, quantity, noise model) of the L2 error against sigma/h (log-log), one curve per
// method, and a table of the errors under outliers.
#pragma once

#include <limits>
#include <string>
#include <vector>

#include "harness/model/experiment.h"
#include "harness/model/results_table.h"
#include "harness/report/model.h"
#include "harness/report/report.h"

namespace curvbench {

/// One method's best radius on one mesh, noise, quantity and norm.
struct BestRadius {
  std::string experiment, family;
  int level = 0, vertices = 0;
  double h = 0.0;
  std::string noise;
  NoiseLevel noise_level;  ///< the noise's model and sigma/h
  std::string method;      ///< "LHF-2"
  std::string parameter;   ///< "rings", "ball-factor", or "" (fixed: one radius)
  double radius = std::numeric_limits<double>::quiet_NaN();  ///< NaN when fixed
  std::string label;                                         ///< the best case's method label
  std::string quantity, norm;
  double error = 0.0;
  int radii = 0;  ///< radii tried
  /// The smallest and largest radius swept (NaN when fixed): a best radius at the largest says
  /// the error may fall further beyond the sweep.
  double lowest = std::numeric_limits<double>::quiet_NaN();
  double highest = std::numeric_limits<double>::quiet_NaN();
};

/// The best radius (smallest finite error; a tie goes to the smaller radius) of each method per
/// (experiment, family, level, noise, quantity, norm), in first-seen order of the rows. A method
/// with a single row (a fixed 1-ring method) is reported with its error and radius NaN.
std::vector<BestRadius> best_radii(const std::vector<ErrorRow>& rows);

/// The radius of b in words: "1-ring" (fixed), "rings 2", "C = 4", with " (largest)" when it is
/// the largest of more than one radius swept.
std::string radius_text(const BestRadius& b);

/// Writes the best-radius CSV (provenance comment, header, rows) atomically:
/// experiment,family,level,vertices,h,noise,sigma_over_h,method,parameter,best_radius,label,
/// quantity,norm,error,radii,lowest_radius,highest_radius
void write_best_radius_csv(const std::string& path, const std::vector<BestRadius>& rows);

/// Fills the section "Sweeps at a fixed mesh" (`out`'s title and blocks; nothing when no sweep
/// experiment has results): per experiment a heading, per (family, noise) the tables with their
/// numbers and the plots as series (rendered to PNG and SVG with options.plots), and writes
/// <results>/best_radius.csv from the radius sweeps; after them, under a heading of the
/// section's level, the blocks of recommendations_section() (harness/report/recommend.h), and
/// <results>/recommendations.csv. Returns false if options.stop asked to stop while plotting;
/// `missing_plots` counts plots gnuplot could not render.
bool sweeps_section(const std::vector<Experiment>& experiments, const ReportOptions& options,
                    int& missing_plots, report::Section& out);

}  // namespace curvbench
