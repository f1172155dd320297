// The long-format result rows of the experiments, and their CSV files.
//
// errors CSV (one per experiment, results/<name>.csv), one row per
//   (mesh family, level, method, vertex set, quantity, norm):
//   experiment,surface,family,level,vertices,h,method,degree,rings,noise,vertex_set,quantity,
//   norm,error,counted,excluded,degree_reduced,failed
// rates CSV (results/rates.csv), one row per (experiment, family, method, quantity, norm):
//   experiment,family,method,degree,rings,noise,vertex_set,quantity,norm,levels,h_first,h_last,
//   e_first,e_last,rate,pairwise_rates
// Numbers are written with %.17g so a CSV read back gives the same doubles.
#pragma once

#include <string>
#include <vector>

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
};

struct RateRow {
  std::string experiment, family, method;
  int degree = 0;
  std::string rings, noise, vertex_set, quantity, norm;
  std::string levels;  ///< e.g. "1-4"
  double h_first = 0, h_last = 0, e_first = 0, e_last = 0, rate = 0;
  std::vector<double> pairwise;
};

/// Writes rows as CSV (header + rows) atomically (temporary file + rename).
void write_error_csv(const std::string& path, const std::vector<ErrorRow>& rows);
void write_rate_csv(const std::string& path, const std::vector<RateRow>& rows);

/// Reads an errors CSV written by write_error_csv. Throws InputError naming file and line.
std::vector<ErrorRow> read_error_csv(const std::string& path);

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

/// Writes `content` to `path` atomically (temporary file in the same folder + rename).
void write_file_atomic(const std::string& path, const std::string& content);

/// "%.17g" with "nan"/"inf" spelled out.
std::string format_double(double x);

}  // namespace curvbench
