// The long-format result rows of the experiments, and their CSV files.
//
// errors CSV (one per experiment, results/<name>.csv), one row per
//   (mesh family, level, method, vertex set, quantity, norm):
//   experiment,surface,family,level,vertices,h,method,degree,rings,noise,vertex_set,quantity,
//   norm,error,counted,excluded,degree_reduced,failed
// rates CSV (results/rates.csv), one row per (experiment, family, method, quantity, norm):
//   experiment,family,method,degree,rings,noise,vertex_set,quantity,norm,levels,h_first,h_last,
//   e_first,e_last,rate,pairwise_rates
// timings CSV (one per experiment, results/timings/<name>.csv), one row per case:
//   experiment,family,level,vertices,method,seconds,us_per_vertex
//   the wall time of the case's estimation (ErrorRow::seconds). Unlike the errors CSV it is not
//   reproducible byte for byte: it is measured when a case is computed, and kept with the case
//   in the case store, so a rerun that reuses a case writes its stored time again.
// skipped CSV (results/skipped.csv, only when some method was skipped), one row per
//   (experiment, method) an outside estimator skipped (runner.h): experiment,method,cases,reason
//   (commas in the reason written as semicolons)
// Numbers are written with %.17g so a CSV read back gives the same doubles.
#pragma once

#include <limits>
#include <string>
#include <vector>

#include "core/atomic_file.h"
#include "meshgen/noise.h"

namespace curvbench {

struct ErrorRow {
  std::string experiment;
  std::string surface;
  std::string family;
  int level = 0;
  int vertices = 0;
  double h = 0.0;      ///< measured mean edge length
  std::string method;  ///< label, e.g. "LHF-2"
  int degree = 0;
  std::string rings;  ///< ring requested, e.g. "1.5" (adaptive growth may enlarge it)
  std::string noise;  ///< "none", "isosurface" (intrinsic O(h^2)), "h^3", "h^2"
  std::string vertex_set;
  std::string quantity;  ///< normal, H, K, k1, k2, d1
  std::string norm;      ///< L2, Linf
  double error = 0.0;
  int counted = 0;         ///< vertices in the error
  int excluded = 0;        ///< vertices of the set skipped (estimate excluded)
  int degree_reduced = 0;  ///< vertices of the mesh with status degree_reduced
  int failed = 0;          ///< vertices of the mesh with status failed
  /// Wall time of the case's estimation (estimate_mesh, or an outside estimator's command), in
  /// seconds; NaN when unknown. Not a column of the errors CSV (timings vary from run to run,
  /// the errors CSV does not): kept in the case store and written to the timings CSV.
  double seconds = std::numeric_limits<double>::quiet_NaN();

  // Typed columns, not written to the CSV: what `method` and `noise` say, as values. The runner
  // sets them from the experiment; reading a CSV sets them from the text, once
  // (split_radius_label, parse_noise_label), so no reader of rows parses a label.
  /// The label without its swept radius ("LHF-2" of "LHF-2 rings=1.5"); the whole label else.
  std::string method_base;
  /// The radius option the case swept (radius_option(): "rings", "ball-factor"), "" when its
  /// label names none, and its value (NaN then).
  std::string radius_parameter;
  double radius = std::numeric_limits<double>::quiet_NaN();
  NoiseLevel noise_level;  ///< the noise's model and sigma/h (meshgen/noise.h)
};

/// A method label split at the radius an experiment's method line swept: "LHF-2 rings=1.5" ->
/// {"LHF-2", "rings", 1.5}, "ICC ball-factor=4" -> {"ICC", "ball-factor", 4}. A label without a
/// "<radius option>=<number>" suffix (radius_option() of any NeighbourhoodSize) is its own
/// method with parameter "" and radius NaN.
struct RadiusLabel {
  std::string method;
  std::string parameter;
  double radius = std::numeric_limits<double>::quiet_NaN();
};
RadiusLabel split_radius_label(const std::string& label);

/// Sets a row's typed columns from its `method` and `noise` text (split_radius_label,
/// parse_noise_label): what reading an errors CSV does to every row.
void type_columns(ErrorRow& row);

struct RateRow {
  std::string experiment, family, method;
  int degree = 0;
  std::string rings, noise, vertex_set, quantity, norm;
  std::string levels;  ///< e.g. "1-4"
  double h_first = 0, h_last = 0, e_first = 0, e_last = 0, rate = 0;
  std::vector<double> pairwise;
};

/// Writes rows as CSV (provenance comment + header + rows) atomically (write_file_atomic).
void write_error_csv(const std::string& path, const std::vector<ErrorRow>& rows);
void write_rate_csv(const std::string& path, const std::vector<RateRow>& rows);

/// The text of an errors CSV: `comment` (one or more '#' lines, without the final newline),
/// the header, then the rows. write_error_csv uses provenance_comment() as the comment.
std::string error_csv_text(const std::vector<ErrorRow>& rows, const std::string& comment);

/// One row of a timings CSV.
struct TimingRow {
  std::string experiment, family, method;
  int level = 0;
  int vertices = 0;
  double seconds = 0.0;
};

/// Writes the timings CSV of an experiment's rows (one row per case: the first row of each
/// (family, level, method)) atomically.
void write_timing_csv(const std::string& path, const std::vector<ErrorRow>& rows);
/// Reads a timings CSV. Throws InputError naming file and line.
std::vector<TimingRow> read_timing_csv(const std::string& path);

/// An outside estimator that said it cannot run here (exit code kExternalSkipExitCode,
/// external_estimator.h), with the cases of one experiment it skipped.
struct SkippedMethod {
  std::string experiment;
  std::string method;  ///< the label (name=)
  int cases = 0;       ///< cases of the experiment skipped
  std::string reason;  ///< the last line of its stderr
};

/// Writes the skipped CSV atomically; with no rows, removes the file instead.
void write_skipped_csv(const std::string& path, const std::vector<SkippedMethod>& rows);
/// Reads a skipped CSV; a missing file has no rows. Throws InputError naming file and line.
std::vector<SkippedMethod> read_skipped_csv(const std::string& path);

/// Reads an errors CSV written by write_error_csv. Throws InputError naming file and line.
std::vector<ErrorRow> read_error_csv(const std::string& path);
/// The same from the file's text; `name` names it in error messages.
std::vector<ErrorRow> parse_error_csv(const std::string& text, const std::string& name);

/// Groups rows by (experiment, family, method, rings, noise, vertex_set, quantity, norm) and
/// computes the average rate over the first and last level, plus the pairwise rates.
std::vector<RateRow> compute_rates(const std::vector<ErrorRow>& rows);

/// A CSV file with a header row, as curvbench writes them: lines starting with '#' (the
/// provenance comment) and empty lines are skipped, fields are split at commas.
struct CsvTable {
  std::string path;
  std::vector<std::string> header;
  std::vector<std::vector<std::string>> rows;  ///< each has header.size() fields
  std::vector<int> lines;                      ///< file line of each row, for messages

  /// Index of a header column; throws InputError naming the file if it is missing.
  size_t col(const std::string& name) const;
  const std::string& text(size_t row, size_t c) const { return rows[row][c]; }
  /// The field as a number ("nan"/"inf" allowed); throws InputError "<path>:<line>: ...".
  double number(size_t row, size_t c) const;
  /// The field as an int; throws InputError "<path>:<line>: ...".
  int integer(size_t row, size_t c) const;
};

/// Reads a CsvTable. Throws InputError if the file cannot be opened, has no header, or a row
/// has a different number of fields than the header ("<path>:<line>: expected N fields, got M").
CsvTable read_csv_table(const std::string& path);
/// The same from the file's text; `name` names it in error messages.
CsvTable parse_csv_table(const std::string& text, const std::string& name);

// write_file_atomic and temp_path (the atomic writer for every output): core/atomic_file.h.

/// Removes the temporary files "<name>.tmp.<pid>" under `directory` (recursively) left behind
/// by a process that no longer runs (e.g. killed with SIGKILL while writing); files of running
/// processes are kept. Returns the number removed; a missing directory removes nothing.
int remove_stale_temp_files(const std::string& directory);

/// x as "1.23e-04" (two decimals, for error tables), or `not_finite` when x is not finite.
std::string scientific(double x, const char* not_finite = "n/a");

/// x as "1.98" (two decimals, for rates and ratios), or "n/a" when x is not finite.
std::string two_decimals(double x);

/// "%.17g" with "nan"/"inf" spelled out.
std::string format_double(double x);

}  // namespace curvbench
