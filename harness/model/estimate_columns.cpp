#include "harness/model/estimate_columns.h"

#include <omp.h>
#include <charconv>
#include <cmath>

#include <algorithm>
#include <array>
#include <cstring>
#include <memory>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "core/errors.h"
#include "core/huge_pages.h"
#include "harness/model/results_table.h"
#include "harness/model/shortest_double.h"

namespace curvbench {

namespace {

using E = VertexEstimate;

// clang-format off
constexpr EstimateColumn kColumns[] = {
    {"nx",     [](const E& e) { return e.normal.x(); }, false, true, true},
    {"ny",     [](const E& e) { return e.normal.y(); }, false, true, true},
    {"nz",     [](const E& e) { return e.normal.z(); }, false, true, true},
    {"k1",     [](const E& e) { return e.k1; },         false, true, true},
    {"k2",     [](const E& e) { return e.k2; },         false, true, true},
    {"H",      [](const E& e) { return e.H; },          false, true, true},
    {"K",      [](const E& e) { return e.K; },          false, true, true},
    {"d1x",    [](const E& e) { return e.d1.x(); },     false, true, true},
    {"d1y",    [](const E& e) { return e.d1.y(); },     false, true, true},
    {"d1z",    [](const E& e) { return e.d1.z(); },     false, true, true},
    {"d2x",    [](const E& e) { return e.d2.x(); },     false, true, true},
    {"d2y",    [](const E& e) { return e.d2.y(); },     false, true, true},
    {"d2z",    [](const E& e) { return e.d2.z(); },     false, true, true},
    {"degree", [](const E& e) { return static_cast<double>(e.degree); }, true, true, true},
    {"points", [](const E& e) { return static_cast<double>(e.points); }, true, true, true},
    {"ring",   [](const E& e) { return e.ring; },       false, false, true},
    {"status", [](const E& e) { return static_cast<double>(static_cast<int>(e.status)); },
               true, true, true},
};
// clang-format on

bool is_status(const EstimateColumn& c) {
  return std::string_view(c.name) == "status";
}

// Appends the shortest text that reads back to exactly x (std::to_chars's bytes, written by
// harness/model/shortest_double.h), "nan" for NaN; at most 24 characters.
char* put_double(char* p, double x) {
  if (std::isnan(x)) return std::copy_n("nan", 3, p);
  return write_shortest(p, x);
}

// The status words, measured once.
std::string_view status_word(VertexStatus s) {
  static const auto words = [] {
    std::array<std::string_view, kVertexStatusCount> w;
    for (int i = 0; i < kVertexStatusCount; ++i)
      w[static_cast<std::size_t>(i)] = to_string(static_cast<VertexStatus>(i));
    return w;
  }();
  return words[static_cast<std::size_t>(s)];
}

// The longest row of these columns: the index (at most 24 characters), each column with its
// comma (a double in at most 24 characters, an int in 11, the longest status word), the newline.
std::size_t max_row(std::span<const int> columns) {
  std::size_t row = 24 + 1;
  for (const int k : columns) {
    const EstimateColumn& c = kColumns[k];
    if (is_status(c)) {
      std::size_t longest = 0;
      for (int i = 0; i < kVertexStatusCount; ++i)
        longest = std::max(longest, status_word(static_cast<VertexStatus>(i)).size());
      row += 1 + longest;
    } else {
      row += c.integer ? 12 : 25;
    }
  }
  return row;
}

// The chunks a block of n rows is formatted in, on `threads` threads (< 1: the OpenMP default).
std::size_t csv_chunks(std::size_t n, int threads) {
  if (threads < 1) threads = omp_get_max_threads();
  return std::max<std::size_t>(1,
                               std::min<std::size_t>(static_cast<std::size_t>(threads), n / 1024));
}

// The bytes format_csv_block needs for n rows: each chunk its rows at their longest and the room
// its last number's writer may use past its end (harness/model/shortest_double.h).
std::size_t csv_room(std::size_t n, std::span<const int> columns, int threads) {
  return n * max_row(columns) + csv_chunks(n, threads) * kShortestRoom + 1;
}

// Rows formatted at a time by the writer per formatting thread: its two buffers stay at about
// 3 MB per thread whatever the block.
constexpr std::size_t kRowsPerWrite = 8192;

// The CSV columns when none are asked for (--columns).
std::vector<int> default_columns(bool csv) {
  std::vector<int> out;
  for (std::size_t i = 0; i < std::size(kColumns); ++i)
    if (csv ? kColumns[i].in_csv : kColumns[i].in_ply) out.push_back(static_cast<int>(i));
  return out;
}

// Formats the rows of estimates[begin, end) at `p`; returns the end.
char* format_rows(char* p, int first, std::span<const VertexEstimate> estimates,
                  std::span<const int> source, std::span<const int> columns, std::size_t begin,
                  std::size_t end) {
  for (std::size_t i = begin; i < end; ++i) {
    const VertexEstimate& e = estimates[i];
    const std::size_t v = static_cast<std::size_t>(first) + i;
    p = std::to_chars(p, p + 24, source.empty() ? v : static_cast<std::size_t>(source[v])).ptr;
    for (const int k : columns) {
      const EstimateColumn& c = kColumns[k];
      *p++ = ',';
      if (is_status(c)) {
        const std::string_view word = status_word(e.status);
        p = std::copy(word.begin(), word.end(), p);
      } else if (c.integer) {
        p = std::to_chars(p, p + 12, static_cast<int>(c.value(e))).ptr;
      } else {
        p = put_double(p, c.value(e));
      }
    }
    *p++ = '\n';
  }
  return p;
}

// Formats the rows into `scratch` (csv_room bytes; not zero-filled), packed, and returns their
// length: the block is cut into chunks formatted in parallel, each into its own slice, then moved
// together in order.
std::size_t format_csv_block(char* scratch, int first, std::span<const VertexEstimate> estimates,
                             std::span<const int> source, std::span<const int> columns,
                             int threads) {
  const std::size_t n = estimates.size();
  const std::size_t chunks = csv_chunks(n, threads);
  const std::size_t row = max_row(columns);
  if (chunks == 1)
    return static_cast<std::size_t>(format_rows(scratch, first, estimates, source, columns, 0, n) -
                                    scratch);
  std::vector<std::size_t> ends(chunks);
  const auto bound = [&](std::size_t c) { return n * c / chunks; };
  const auto offset = [&](std::size_t c) { return bound(c) * row + c * kShortestRoom; };
#pragma omp parallel for num_threads(static_cast <int>(chunks)) schedule(static, 1)
  for (std::size_t c = 0; c < chunks; ++c) {
    char* start = scratch + offset(c);
    ends[c] = static_cast<std::size_t>(
        format_rows(start, first, estimates, source, columns, bound(c), bound(c + 1)) - start);
  }
  std::size_t at = ends[0];
  for (std::size_t c = 1; c < chunks; ++c) {
    std::memmove(scratch + at, scratch + offset(c), ends[c]);
    at += ends[c];
  }
  return at;
}

}  // namespace

std::span<const EstimateColumn> estimate_columns() {
  return kColumns;
}

std::vector<int> estimate_csv_columns() {
  return default_columns(true);
}

std::vector<int> estimate_ply_columns() {
  return default_columns(false);
}

std::vector<int> parse_estimate_columns(const std::string& list) {
  std::string names;
  for (const EstimateColumn& c : kColumns) names += std::string(names.empty() ? "" : ", ") + c.name;
  std::vector<int> out;
  std::size_t at = 0;
  for (;;) {
    const std::size_t comma = std::min(list.find(',', at), list.size());
    const std::string name = list.substr(at, comma - at);
    const auto* c = std::find_if(std::begin(kColumns), std::end(kColumns),
                                 [&](const EstimateColumn& x) { return name == x.name; });
    if (c == std::end(kColumns))
      throw UsageError("--columns: unknown column '" + name + "' (columns: " + names + ")");
    const int k = static_cast<int>(c - std::begin(kColumns));
    if (std::find(out.begin(), out.end(), k) != out.end())
      throw UsageError("--columns: column '" + name + "' given twice");
    out.push_back(k);
    if (comma == list.size()) return out;
    at = comma + 1;
  }
}

std::string estimate_csv_header(std::span<const int> columns) {
  const std::vector<int> all = columns.empty() ? estimate_csv_columns() : std::vector<int>();
  if (columns.empty()) columns = all;
  std::string h = "vertex";
  for (const int k : columns) h += std::string(",") + kColumns[k].name;
  return h;
}

void append_estimate_csv_rows(std::string& out, int first,
                              std::span<const VertexEstimate> estimates,
                              std::span<const int> source, int threads,
                              std::span<const int> columns) {
  const std::vector<int> all = columns.empty() ? estimate_csv_columns() : std::vector<int>();
  if (columns.empty()) columns = all;
  const std::unique_ptr<char[]> scratch(new char[csv_room(estimates.size(), columns, threads)]);
  out.append(scratch.get(),
             format_csv_block(scratch.get(), first, estimates, source, columns, threads));
}

EstimateCsvWriter::EstimateCsvWriter(const std::string& path, std::span<const int> source,
                                     int threads, std::vector<int> columns)
    : file_(path),
      source_(source),
      threads_(threads),
      columns_(columns.empty() ? estimate_csv_columns() : std::move(columns)) {
  file_.append(estimate_csv_header(columns_) + "\n");
}

EstimateCsvWriter::~EstimateCsvWriter() {
  if (in_flight_.valid()) in_flight_.wait();
}

void EstimateCsvWriter::wait_in_flight() {
  if (in_flight_.valid()) in_flight_.get();
}

void EstimateCsvWriter::write(int first, std::span<const VertexEstimate> estimates) {
  wait_in_flight();
  reserve_huge(block_, estimates.size());
  block_.assign(estimates.begin(), estimates.end());
  in_flight_ = std::async(std::launch::async, [this, first] {
    // A piece of rows at a time, each piece written by a thread of its own while this one
    // formats the next; the buffer of the piece before comes back for it.
    // On several threads, a piece of kRowsPerWrite rows per thread: one parallel region (a
    // fork and a join of the team) per piece is paid per thread's share, not per 8192 rows.
    const std::size_t piece =
        kRowsPerWrite * static_cast<std::size_t>(threads_ < 1 ? omp_get_max_threads() : threads_);
    for (std::size_t i0 = 0; i0 < block_.size(); i0 += piece) {
      const std::size_t rows = std::min(piece, block_.size() - i0);
      const std::size_t room = csv_room(rows, columns_, threads_);
      if (scratch_.size() < room) scratch_.resize(room);
      const std::size_t bytes =
          format_csv_block(scratch_.data(), first + static_cast<int>(i0),
                           std::span(block_).subspan(i0, rows), source_, columns_, threads_);
      scratch_ = file_.append_in_background(std::move(scratch_), bytes);
    }
  });
}

void EstimateCsvWriter::commit() {
  wait_in_flight();
  file_.commit();
}

void write_estimate_csv_atomic(const std::string& path, std::span<const VertexEstimate> estimates,
                               std::span<const int> source, int threads) {
  EstimateCsvWriter writer(path, source, threads);
  writer.write(0, estimates);
  writer.commit();
}

std::vector<VertexProperty> estimate_ply_properties(std::span<const VertexEstimate> estimates) {
  std::vector<VertexProperty> props;
  for (const EstimateColumn& c : kColumns) {
    if (!c.in_ply) continue;
    VertexProperty p{c.name, std::vector<double>(estimates.size()), c.integer};
    for (size_t v = 0; v < estimates.size(); ++v) p.values[v] = c.value(estimates[v]);
    props.push_back(std::move(p));
  }
  return props;
}

std::vector<PlyWriter::Property> estimate_ply_types(std::span<const int> columns) {
  const std::vector<int> all = columns.empty() ? estimate_ply_columns() : std::vector<int>();
  if (columns.empty()) columns = all;
  std::vector<PlyWriter::Property> types;
  for (const int k : columns) types.push_back({kColumns[k].name, kColumns[k].integer});
  return types;
}

void estimate_ply_row(const VertexEstimate& e, double* row, std::span<const int> columns) {
  if (columns.empty()) {
    for (const EstimateColumn& c : kColumns)
      if (c.in_ply) *row++ = c.value(e);
    return;
  }
  for (const int k : columns) *row++ = kColumns[k].value(e);
}

}  // namespace curvbench
