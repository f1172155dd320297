#include "harness/estimate_columns.h"

#include <omp.h>
#include <charconv>
#include <cmath>

#include <algorithm>
#include <cstring>
#include <memory>
#include <vector>

#include "core/errors.h"
#include "core/huge_pages.h"
#include "harness/results_table.h"

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

// Appends the shortest text that reads back to exactly x (std::to_chars), "nan" for NaN; at most
// 24 characters.
char* put_double(char* p, double x) {
  if (std::isnan(x)) return std::copy_n("nan", 3, p);
  return std::to_chars(p, p + 32, x).ptr;
}

// The longest row: an index, 13 doubles, 2 integers and a status word, with separators.
constexpr std::size_t kMaxRow = 12 + 16 * 25 + 20 + 2;

// Formats the rows of estimates[begin, end) at `p`; returns the end.
char* format_rows(char* p, int first, std::span<const VertexEstimate> estimates,
                  std::span<const int> source, std::size_t begin, std::size_t end) {
  for (std::size_t i = begin; i < end; ++i) {
    const VertexEstimate& e = estimates[i];
    const std::size_t v = static_cast<std::size_t>(first) + i;
    p = std::to_chars(p, p + 24, source.empty() ? v : static_cast<std::size_t>(source[v])).ptr;
    for (const EstimateColumn& c : kColumns) {
      if (!c.in_csv) continue;
      *p++ = ',';
      if (is_status(c)) {
        const char* word = to_string(e.status);
        p = std::copy(word, word + std::strlen(word), p);
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

// Formats the rows into `scratch` (room for kMaxRow bytes per row; not zero-filled), packed, and
// returns their length: the block is cut into chunks formatted in parallel, each into its own
// slice, then moved together in order.
std::size_t format_csv_block(char* scratch, int first, std::span<const VertexEstimate> estimates,
                             std::span<const int> source, int threads) {
  const std::size_t n = estimates.size();
  if (threads < 1) threads = omp_get_max_threads();
  const std::size_t chunks =
      std::max<std::size_t>(1, std::min<std::size_t>(static_cast<std::size_t>(threads), n / 4096));
  std::vector<std::size_t> ends(chunks);
  const auto bound = [&](std::size_t c) { return n * c / chunks; };
#pragma omp parallel for num_threads(static_cast <int>(chunks)) schedule(static, 1)
  for (std::size_t c = 0; c < chunks; ++c) {
    char* start = scratch + bound(c) * kMaxRow;
    ends[c] = static_cast<std::size_t>(
        format_rows(start, first, estimates, source, bound(c), bound(c + 1)) - start);
  }
  std::size_t at = ends[0];
  for (std::size_t c = 1; c < chunks; ++c) {
    std::memmove(scratch + at, scratch + bound(c) * kMaxRow, ends[c]);
    at += ends[c];
  }
  return at;
}

}  // namespace

std::span<const EstimateColumn> estimate_columns() {
  return kColumns;
}

std::string estimate_csv_header() {
  std::string h = "vertex";
  for (const EstimateColumn& c : kColumns)
    if (c.in_csv) h += std::string(",") + c.name;
  return h;
}

void append_estimate_csv_rows(std::string& out, int first,
                              std::span<const VertexEstimate> estimates,
                              std::span<const int> source, int threads) {
  const std::unique_ptr<char[]> scratch(new char[estimates.size() * kMaxRow + 1]);
  out.append(scratch.get(), format_csv_block(scratch.get(), first, estimates, source, threads));
}

EstimateCsvWriter::EstimateCsvWriter(const std::string& path, std::span<const int> source,
                                     int threads)
    : file_(path), source_(source), threads_(threads) {
  file_.append(estimate_csv_header() + "\n");
}

EstimateCsvWriter::~EstimateCsvWriter() {
  if (in_flight_.valid()) in_flight_.wait();
}

void EstimateCsvWriter::wait_in_flight() {
  if (in_flight_.valid()) in_flight_.get();
}

void EstimateCsvWriter::write(int first, std::span<const VertexEstimate> estimates) {
  wait_in_flight();
  // The copy and the two formatting buffers (28 MB each for a block of 65536) on huge pages:
  // one first-touch fault per 2 MiB instead of per 4 KiB (core/huge_pages.h).
  reserve_huge(block_, estimates.size());
  block_.assign(estimates.begin(), estimates.end());
  in_flight_ = std::async(std::launch::async, [this, first] {
    const std::size_t room = block_.size() * kMaxRow + 1;
    if (scratch_.size() < room) {
      scratch_.reserve(room);
      advise_huge_pages(scratch_.data(), room);
      scratch_.resize(room);
    }
    const std::size_t bytes = format_csv_block(scratch_.data(), first, block_, source_, threads_);
    // Written by a thread of its own while this one formats the next block; the buffer of the
    // block before comes back for it.
    scratch_ = file_.append_in_background(std::move(scratch_), bytes);
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

std::vector<PlyWriter::Property> estimate_ply_types() {
  std::vector<PlyWriter::Property> types;
  for (const EstimateColumn& c : kColumns)
    if (c.in_ply) types.push_back({c.name, c.integer});
  return types;
}

void estimate_ply_row(const VertexEstimate& e, double* row) {
  for (const EstimateColumn& c : kColumns)
    if (c.in_ply) *row++ = c.value(e);
}

}  // namespace curvbench
