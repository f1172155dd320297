// The per-vertex output columns of `curvbench estimate`: one table that drives the CSV header,
// the CSV rows and the PLY vertex properties (and the Python module's arrays are named alike).
//
//   CSV  vertex,nx,ny,nz,k1,k2,H,K,d1x,d1y,d1z,d2x,d2y,d2z,degree,points,status
//        numbers as the shortest text that reads back to the exact double (std::to_chars),
//        "nan" for NaN, the status as a word (ok, degree_reduced, failed, excluded, disk_cut,
//        sign_undetermined, partial, reprojected)
//   PLY  nx,ny,nz,k1,k2,H,K,d1x,d1y,d1z,d2x,d2y,d2z,degree,points,ring,status
//        status as its integer code 0..7
// Both are written block by block as the estimates come (EstimateCsvWriter, PlyWriter with
// estimate_ply_types / estimate_ply_row), or at once from a whole vector (the same bytes).
#pragma once

#include <future>
#include <memory>
#include <span>
#include <string>
#include <vector>

#include "core/atomic_file.h"
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

/// A selection of columns: indices into estimate_columns(), in output order. An empty
/// selection everywhere below means the format's own columns (in_csv, in_ply).
std::vector<int> estimate_csv_columns();
std::vector<int> estimate_ply_columns();

/// `--columns`: a comma-separated list of column names (e.g. "H,K"), kept in the given order.
/// Throws UsageError for an unknown name (the message lists the names) or a name given twice.
std::vector<int> parse_estimate_columns(const std::string& list);

/// The CSV header line (without newline): "vertex," then the columns.
std::string estimate_csv_header(std::span<const int> columns = {});

/// Appends the CSV rows of the estimates of vertices first, first + 1, ... to `out`: the block is
/// cut into `threads` chunks (< 1: the OpenMP default) formatted in parallel and joined in order,
/// so the bytes do not depend on the thread count. `source`: the file index of every vertex of the
/// mesh for the "vertex" column (empty: the identity).
void append_estimate_csv_rows(std::string& out, int first,
                              std::span<const VertexEstimate> estimates,
                              std::span<const int> source, int threads = 1,
                              std::span<const int> columns = {});

/// The estimate CSV written block by block (the header first), through the project's atomic
/// file writer: a failure leaves no file. `source` as above; it must outlive the writer.
/// A pipeline of three stages, each on a thread of its own: the caller estimates block k + 1
/// while block k is formatted 8192 rows per thread at a time (16 numbers per vertex cost more
/// than a fast fit), each piece written while the next is formatted
/// (AtomicFile::append_in_background), so the text held stays at two pieces (2 x about 3 MB per
/// formatting thread) whatever the block. write() copies the block
/// and returns; one block is being formatted at a time, and the next write() or commit() waits
/// for it and reports its error.
class EstimateCsvWriter {
 public:
  EstimateCsvWriter(const std::string& path, std::span<const int> source, int threads = 1,
                    std::vector<int> columns = {});
  EstimateCsvWriter(const EstimateCsvWriter&) = delete;
  EstimateCsvWriter& operator=(const EstimateCsvWriter&) = delete;
  /// Waits for the block in flight (its error no longer matters); uncommitted, no file is left.
  ~EstimateCsvWriter();
  /// Appends the rows of vertices [first, first + estimates.size()).
  void write(int first, std::span<const VertexEstimate> estimates);
  /// Waits for the last block, closes the file and renames it into place.
  void commit();

 private:
  void wait_in_flight();

  AtomicFile file_;
  std::span<const int> source_;
  int threads_;
  std::vector<int> columns_;
  std::vector<VertexEstimate> block_;  ///< the block in flight (a copy)
  std::string scratch_;                ///< a piece of its formatted rows (two buffers take turns)
  std::future<void> in_flight_;
};

/// Writes the whole CSV at once (EstimateCsvWriter with one block).
void write_estimate_csv_atomic(const std::string& path, std::span<const VertexEstimate> estimates,
                               std::span<const int> source, int threads = 1);

/// The PLY vertex properties of the estimates (write_mesh's `properties`).
std::vector<VertexProperty> estimate_ply_properties(std::span<const VertexEstimate> estimates);

/// Names and types of the same properties (or of `columns`), for PlyWriter, and one vertex's
/// values in that order (estimate_ply_types(columns).size() of them written to `row`).
std::vector<PlyWriter::Property> estimate_ply_types(std::span<const int> columns = {});
void estimate_ply_row(const VertexEstimate& e, double* row, std::span<const int> columns = {});

}  // namespace curvbench
