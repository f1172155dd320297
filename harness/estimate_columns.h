// The per-vertex output columns of `curvbench estimate`: one table that drives the CSV header,
// the CSV rows and the PLY vertex properties (and the Python module's arrays are named alike).
//
//   CSV  vertex,nx,ny,nz,k1,k2,H,K,d1x,d1y,d1z,d2x,d2y,d2z,degree,points,status
//        numbers as the shortest text that reads back to the exact double (std::to_chars),
//        "nan" for NaN, the status as a word (ok, degree_reduced, failed, excluded)
//   PLY  nx,ny,nz,k1,k2,H,K,d1x,d1y,d1z,d2x,d2y,d2z,degree,points,ring,status
//        status as its integer code 0..3
#pragma once

#include <span>
#include <string>
#include <vector>

#include "mesh/io.h"
#include "methods/estimator.h"

namespace curvbench {

/// One output column of a vertex estimate.
struct EstimateColumn {
  const char* name;
  double (*value)(const VertexEstimate&);  ///< the column's value (status: its integer code)
  bool integer;                            ///< degree, points, status
  bool in_csv;
  bool in_ply;
};

/// Every column, in output order (the CSV's leading "vertex" column is not in the table).
std::span<const EstimateColumn> estimate_columns();

/// The CSV header line (without newline): "vertex," then the CSV columns.
std::string estimate_csv_header();

/// Writes the estimates as CSV to `path` (not atomic; see write_estimate_csv_atomic). Errors
/// throw InputError naming `shown` (the user's output file). `source`: the file index of each
/// vertex for the "vertex" column (empty: the identity).
void write_estimate_csv(const std::string& path, const std::string& shown,
                        std::span<const VertexEstimate> estimates, std::span<const int> source);

/// The same, streamed to temp_path(path) and renamed into place (no partial file on failure).
void write_estimate_csv_atomic(const std::string& path, std::span<const VertexEstimate> estimates,
                               std::span<const int> source);

/// The PLY vertex properties of the estimates (write_mesh's `properties`).
std::vector<VertexProperty> estimate_ply_properties(std::span<const VertexEstimate> estimates);

}  // namespace curvbench
