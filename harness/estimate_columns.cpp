#include "harness/estimate_columns.h"

#include <charconv>
#include <cmath>
#include <cstdio>
#include <filesystem>

#include "core/errors.h"
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

// Shortest text that reads back to exactly x (std::to_chars; about 10x faster than "%.17g").
void put_double(std::FILE* f, double x) {
  if (std::isnan(x)) {
    std::fputs("nan", f);
    return;
  }
  char buf[32];
  const auto r = std::to_chars(buf, buf + sizeof buf, x);
  std::fwrite(buf, 1, static_cast<size_t>(r.ptr - buf), f);
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

void write_estimate_csv(const std::string& path, const std::string& shown,
                        std::span<const VertexEstimate> estimates, std::span<const int> source) {
  std::FILE* f = std::fopen(path.c_str(), "w");
  if (f == nullptr) throw InputError(shown + ": cannot open for writing");
  std::fputs((estimate_csv_header() + "\n").c_str(), f);
  for (size_t v = 0; v < estimates.size(); ++v) {
    const VertexEstimate& e = estimates[v];
    std::fprintf(f, "%zu", source.empty() ? v : static_cast<size_t>(source[v]));
    for (const EstimateColumn& c : kColumns) {
      if (!c.in_csv) continue;
      std::fputc(',', f);
      if (is_status(c))
        std::fputs(to_string(e.status), f);
      else if (c.integer)
        std::fprintf(f, "%d", static_cast<int>(c.value(e)));
      else
        put_double(f, c.value(e));
    }
    std::fputc('\n', f);
  }
  const bool ok = std::ferror(f) == 0;
  if (std::fclose(f) != 0 || !ok) throw InputError(shown + ": write failed");
}

void write_estimate_csv_atomic(const std::string& path, std::span<const VertexEstimate> estimates,
                               std::span<const int> source) {
  const std::string tmp = temp_path(path);
  try {
    write_estimate_csv(tmp, path, estimates, source);
    std::error_code ec;
    std::filesystem::rename(tmp, path, ec);
    if (ec) throw InputError(path + ": cannot write (" + ec.message() + ")");
  } catch (...) {
    std::error_code ec;
    std::filesystem::remove(tmp, ec);
    throw;
  }
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

}  // namespace curvbench
