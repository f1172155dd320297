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

/// Writes `content` to `path` atomically (temporary file in the same folder + rename).
void write_file_atomic(const std::string& path, const std::string& content);

/// "%.17g" with "nan"/"inf" spelled out.
std::string format_double(double x);

}  // namespace curvbench
