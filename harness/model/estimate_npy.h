// The estimates as a NumPy .npy file (`curvbench estimate --output OUT.npy`): a one-dimensional
// array of records, one per vertex, with a named field per column, so that Python reads it with
// numpy.load alone and picks columns by name (a["H"]):
//
//   format 1.0, dtype [('vertex', '<i4'), (column, '<f8' or '<i4'), ...], shape (n,), packed
//   vertex   the vertex index (with --skip-invalid: its index in the input file)
//   columns  those asked for (--columns, harness/model/estimate_columns.h), by default every column
//   of
//            the table (the PLY's: nx ... status, ring included); integer columns (degree,
//            points, status as its code 0..7) as int32, the others as float64
//
// Written block by block as the estimates come, through the atomic file writer: a failure
// leaves no file. The bytes do not depend on the block size or the thread count.
#pragma once

#include <span>
#include <string>
#include <vector>

#include "core/atomic_file.h"
#include "methods/estimator.h"

namespace curvbench {

class EstimateNpyWriter {
 public:
  /// `vertices`: the rows the file will hold (the header names the shape); `source` as for the
  /// CSV (empty: the identity; it must outlive the writer); `columns` as estimate_columns.h
  /// (empty: every column of the PLY's set).
  EstimateNpyWriter(const std::string& path, int vertices, std::span<const int> source,
                    std::vector<int> columns = {});
  EstimateNpyWriter(const EstimateNpyWriter&) = delete;
  EstimateNpyWriter& operator=(const EstimateNpyWriter&) = delete;

  /// Appends the records of vertices [first, first + estimates.size()), first = the vertices
  /// written so far.
  void write(int first, std::span<const VertexEstimate> estimates);
  /// Closes and renames into place (InputError if that fails); every row must be written.
  void commit();

  /// The .npy header (magic, version, length, the dictionary padded to 64 bytes).
  static std::string header(int vertices, std::span<const int> columns);

 private:
  AtomicFile file_;
  int vertices_;
  int written_ = 0;
  std::span<const int> source_;
  std::vector<int> columns_;
  std::size_t record_ = 0;  ///< bytes per vertex
  std::vector<char> buffer_;
};

}  // namespace curvbench
