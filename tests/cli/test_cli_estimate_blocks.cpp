// Streaming output: `curvbench estimate` estimates and writes a block of
// vertices at a time. The CSV and PLY bytes are the same for any --block and --threads, and equal
// to the whole-vector path of the C++ API and Python (estimate_oriented without blocks, then the
// whole-array writers); the parallel CSV formatting and the block PLY writer equal their one-piece
// forms.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <limits>
#include <random>
#include <string>
#include <vector>

#include "core/errors.h"
#include "harness/model/estimate_columns.h"
#include "mesh/io.h"
#include "methods/estimate_oriented.h"
#include "methods/estimator.h"
#include "tests/cli/cli_runner.h"

namespace curvbench {
namespace {

using testing::fresh_dir;
using testing::run_cli;
using testing::slurp;
namespace fs = std::filesystem;

TEST(CliEstimateBlocks, SameBytesForAnyBlockAndThreadsAndAsTheWholeVector) {
  const fs::path dir = fresh_dir("cli_estimate_blocks");
  // A mesh with a boundary and irregular valences.
  const fs::path mesh = dir / "mesh.off";
  ASSERT_EQ(run_cli("mesh --family bump-irregular --level 1 --output " + mesh.string()).exit_code,
            0);
  for (const std::string ext : {"csv", "ply"}) {
    std::string reference;
    for (const auto& [block, threads] : {std::pair{65536, 1}, std::pair{1, 1}, std::pair{7, 2},
                                         std::pair{100, 3}, std::pair{1000000, 2}}) {
      const fs::path out = dir / ("out." + ext);
      const auto r =
          run_cli("estimate " + mesh.string() + " --method lhf-2 --block " + std::to_string(block) +
                  " --threads " + std::to_string(threads) + " --output " + out.string());
      ASSERT_EQ(r.exit_code, 0) << r.output;
      const std::string bytes = slurp(out);
      ASSERT_FALSE(bytes.empty());
      if (reference.empty())
        reference = bytes;
      else
        EXPECT_EQ(bytes, reference) << ext << " block " << block << " threads " << threads;
    }
    // The whole-vector path (C++ API, Python) written by the whole-array writers.
    EstimatorOptions options;
    options.threads = 2;
    const auto est = make_estimator("lhf-2", options);
    OrientedEstimate whole = estimate_oriented(read_mesh(mesh.string()), *est);
    const fs::path out = dir / ("whole." + ext);
    if (ext == "csv")
      write_estimate_csv_atomic(out.string(), whole.estimates, {});
    else
      write_mesh(out.string(), whole.orientation.mesh, estimate_ply_properties(whole.estimates));
    EXPECT_EQ(slurp(out), reference) << ext;
  }
  // --color needs every vertex first (one block), and still gives the same bytes on 1 or 2
  // threads.
  const fs::path c1 = dir / "c1.ply", c2 = dir / "c2.ply";
  ASSERT_EQ(run_cli("estimate " + mesh.string() +
                    " --method lhf-2 --color H --threads 1 --block 5" + " --output " + c1.string())
                .exit_code,
            0);
  ASSERT_EQ(run_cli("estimate " + mesh.string() +
                    " --method lhf-2 --color H --threads 2 --output " + c2.string())
                .exit_code,
            0);
  EXPECT_EQ(slurp(c1), slurp(c2));
  EXPECT_EQ(run_cli("estimate " + mesh.string() + " --method lhf-2 --block 0 --output " +
                    (dir / "x.csv").string())
                .exit_code,
            2);
  fs::remove_all(dir);
}

// Made-up estimates with NaN, infinities, subnormals, negative zero and every status, in rows
// enough for several formatting chunks.
std::vector<VertexEstimate> odd_estimates(int n) {
  std::mt19937 rng(3);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  const double specials[] = {std::numeric_limits<double>::quiet_NaN(),
                             std::numeric_limits<double>::infinity(),
                             -std::numeric_limits<double>::denorm_min(),
                             -0.0,
                             1e300,
                             0.1};
  std::vector<VertexEstimate> e(static_cast<size_t>(n));
  for (int v = 0; v < n; ++v) {
    VertexEstimate& x = e[static_cast<size_t>(v)];
    x.normal = Vec3(u(rng), u(rng), specials[v % 6]);
    x.k1 = u(rng) * 1e5;
    x.k2 = std::ldexp(u(rng), v % 2000 - 1000);
    x.H = x.K = u(rng);
    x.d1 = Vec3(u(rng), 0.5, specials[(v / 6) % 6]);
    x.d2 = Vec3(1, 2, 3);
    x.degree = v % 5;
    x.points = v % 40;
    x.ring = 1.5;
    x.status = static_cast<VertexStatus>(v % 6);
  }
  return e;
}

TEST(EstimateCsvRows, SameBytesForAnyThreadsAndBlocks) {
  const std::vector<VertexEstimate> e = odd_estimates(20011);
  std::vector<int> source(e.size());
  for (size_t v = 0; v < source.size(); ++v) source[v] = static_cast<int>(3 * v + 1);
  for (const bool with_source : {false, true}) {
    const std::span<const int> s =
        with_source ? std::span<const int>(source) : std::span<const int>();
    std::string one;
    append_estimate_csv_rows(one, 0, e, s, 1);
    EXPECT_NE(one.find(",nan,"), std::string::npos);
    EXPECT_NE(one.find("inf"), std::string::npos);
    for (const int threads : {2, 3, 7}) {
      std::string many;
      append_estimate_csv_rows(many, 0, e, s, threads);
      EXPECT_EQ(many, one) << threads;
    }
    std::string blocks;
    for (size_t first = 0; first < e.size(); first += 4999)
      append_estimate_csv_rows(
          blocks, static_cast<int>(first),
          std::span(e).subspan(first, std::min<size_t>(4999, e.size() - first)), s, 2);
    EXPECT_EQ(blocks, one);
  }
}

// The writer formats and writes each block on a background thread while the caller fills the
// next one: the caller's buffer may change as soon as write() returns, the blocks keep their
// order, and a writer destroyed with a block in flight leaves no file.
TEST(EstimateCsvWriter, BlocksInFlightKeepTheirOrderAndAreCopies) {
  const fs::path dir = fresh_dir("estimate_csv_writer");
  const std::vector<VertexEstimate> e = odd_estimates(30011);
  std::string expected = estimate_csv_header() + "\n";
  append_estimate_csv_rows(expected, 0, e, {}, 1);
  const std::string path = (dir / "blocks.csv").string();
  {
    EstimateCsvWriter writer(path, {}, 2);
    std::vector<VertexEstimate> buffer;
    for (size_t first = 0; first < e.size(); first += 7000) {
      buffer.assign(e.begin() + static_cast<std::ptrdiff_t>(first),
                    e.begin() + static_cast<std::ptrdiff_t>(std::min(first + 7000, e.size())));
      writer.write(static_cast<int>(first), buffer);
      std::fill(buffer.begin(), buffer.end(), VertexEstimate{});  // reused at once
    }
    EXPECT_FALSE(fs::exists(path));
    writer.commit();
  }
  EXPECT_EQ(slurp(path), expected);
  // One block of several 8192-row pieces, each written while the next is formatted.
  for (const int threads : {1, 2}) {
    EstimateCsvWriter writer(path, {}, threads);
    writer.write(0, e);
    writer.commit();
    EXPECT_EQ(slurp(path), expected) << threads;
  }
  {
    EstimateCsvWriter writer((dir / "inflight.csv").string(), {}, 1);
    writer.write(0, e);
  }
  EXPECT_FALSE(fs::exists(dir / "inflight.csv"));
  EXPECT_EQ(std::distance(fs::directory_iterator(dir), fs::directory_iterator()), 1);
  fs::remove_all(dir);
}

// --columns: the CSV, PLY and .npy of the asked columns are the same bytes for any --block and
// --threads; the CSV's columns are the default CSV's columns, value for value, and the .npy holds
// the very doubles the CSV's shortest round-trip text reads back to.
TEST(CliEstimateColumns, SameBytesForAnyBlockAndThreadsAndTheSameValues) {
  const fs::path dir = fresh_dir("cli_estimate_columns");
  const fs::path mesh = dir / "mesh.off";
  ASSERT_EQ(run_cli("mesh --family bump-irregular --level 1 --output " + mesh.string()).exit_code,
            0);
  const std::string columns = "K,H,status,degree,nz";
  std::string reference[3];
  const std::string exts[3] = {"csv", "ply", "npy"};
  for (int x = 0; x < 3; ++x)
    for (const auto& [block, threads] : {std::pair{65536, 1}, std::pair{7, 2}, std::pair{100, 3}}) {
      const fs::path out = dir / ("out." + exts[x]);
      const auto r = run_cli("estimate " + mesh.string() + " --method lhf-2 --columns " + columns +
                             " --block " + std::to_string(block) + " --threads " +
                             std::to_string(threads) + " --output " + out.string());
      ASSERT_EQ(r.exit_code, 0) << r.output;
      const std::string bytes = slurp(out);
      ASSERT_FALSE(bytes.empty());
      if (reference[x].empty())
        reference[x] = bytes;
      else
        EXPECT_EQ(bytes, reference[x]) << exts[x] << " block " << block << " threads " << threads;
    }
  // The full CSV, split into fields.
  const fs::path full = dir / "full.csv";
  ASSERT_EQ(
      run_cli("estimate " + mesh.string() + " --method lhf-2 --output " + full.string()).exit_code,
      0);
  const auto fields = [](const std::string& text) {
    std::vector<std::vector<std::string>> rows;
    std::size_t at = 0;
    while (at < text.size()) {
      const std::size_t end = text.find('\n', at);
      std::vector<std::string> row;
      std::size_t f = at;
      for (;;) {
        const std::size_t comma = std::min(text.find(',', f), end);
        row.push_back(text.substr(f, comma - f));
        if (comma == end) break;
        f = comma + 1;
      }
      rows.push_back(row);
      at = end + 1;
    }
    return rows;
  };
  const auto all = fields(slurp(full));
  const auto some = fields(reference[0]);
  ASSERT_EQ(all.size(), some.size());
  ASSERT_EQ(some[0], (std::vector<std::string>{"vertex", "K", "H", "status", "degree", "nz"}));
  std::vector<std::size_t> at;  // the asked columns' places in the full CSV
  for (const std::string& name : some[0])
    at.push_back(
        static_cast<std::size_t>(std::find(all[0].begin(), all[0].end(), name) - all[0].begin()));
  for (std::size_t r = 0; r < all.size(); ++r)
    for (std::size_t c = 0; c < at.size(); ++c) ASSERT_EQ(some[r][c], all[r][at[c]]) << r;
  // The .npy: its header, then one packed record per vertex: vertex int32, K, H float64, status,
  // degree int32, nz float64.
  const std::string& npy = reference[2];
  ASSERT_GE(npy.size(), 10u);
  EXPECT_EQ(npy.substr(0, 8), std::string("\x93NUMPY\x01\x00", 8));
  const std::size_t header = 10 + static_cast<unsigned char>(npy[8]) +
                             256 * static_cast<std::size_t>(static_cast<unsigned char>(npy[9]));
  EXPECT_EQ(header % 64, 0u);
  EXPECT_NE(npy.find("'descr': [('vertex', '<i4'), ('K', '<f8'), ('H', '<f8'), ('status', "
                     "'<i4'), ('degree', '<i4'), ('nz', '<f8')]"),
            std::string::npos);
  const std::size_t rows = all.size() - 1;
  EXPECT_NE(npy.find("'shape': (" + std::to_string(rows) + ",)"), std::string::npos);
  constexpr std::size_t kRecord = 4 + 8 + 8 + 4 + 4 + 8;
  ASSERT_EQ(npy.size(), header + rows * kRecord);
  for (std::size_t r = 0; r < rows; ++r) {
    const char* p = npy.data() + header + r * kRecord;
    std::int32_t vertex, status, degree;
    double K, H, nz;
    std::memcpy(&vertex, p, 4);
    std::memcpy(&K, p + 4, 8);
    std::memcpy(&H, p + 12, 8);
    std::memcpy(&status, p + 20, 4);
    std::memcpy(&degree, p + 24, 4);
    std::memcpy(&nz, p + 28, 8);
    const auto& row = some[r + 1];
    EXPECT_EQ(std::to_string(vertex), row[0]);
    EXPECT_EQ(K, std::stod(row[1])) << r;  // the CSV text reads back to the exact double
    EXPECT_EQ(H, std::stod(row[2])) << r;
    EXPECT_EQ(to_string(static_cast<VertexStatus>(status)), row[3]);
    EXPECT_EQ(std::to_string(degree), row[4]);
    EXPECT_EQ(nz, std::stod(row[5])) << r;
  }
  // Unknown or repeated names: usage errors, no file.
  for (const std::string bad : {"H,X", "H,H", "H,"}) {
    const fs::path out = dir / "bad.csv";
    EXPECT_EQ(run_cli("estimate " + mesh.string() + " --method lhf-2 --columns '" + bad +
                      "' --output " + out.string())
                  .exit_code,
              2)
        << bad;
    EXPECT_FALSE(fs::exists(out)) << bad;
  }
  fs::remove_all(dir);
}

TEST(PlyWriterBlocks, SameBytesAsWritePly) {
  const fs::path dir = fresh_dir("ply_writer_blocks");
  VertexMatrix V(5, 3);
  V << 0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0, 1, 1, 1, 1;
  FaceMatrix F(4, 3);
  F << 0, 1, 2, 0, 1, 3, 1, 2, 4, 0, 2, 3;
  const Mesh mesh(V, F);
  const std::vector<VertexProperty> props = {{"a", {0.5, -1, 2, 1e-300, 7}, false},
                                             {"b", {1, 2, 3, -4, 5}, true}};
  write_ply((dir / "whole.ply").string(), mesh, props, {"one comment"});
  PlyWriter w((dir / "blocks.ply").string(), mesh, {{"a", false}, {"b", true}}, {"one comment"});
  const double rows[] = {0.5, 1, -1, 2, 2, 3, 1e-300, -4, 7, 5};
  w.write_vertices(0, 2, rows);
  w.write_vertices(2, 1, rows + 4);
  w.write_vertices(3, 2, rows + 6);
  w.commit();
  EXPECT_EQ(slurp(dir / "blocks.ply"), slurp(dir / "whole.ply"));
  // Out of order, or a non-integer for an int property: refused, and no file left behind.
  {
    PlyWriter bad((dir / "bad.ply").string(), mesh, {{"b", true}});
    const double x[] = {1.5};
    EXPECT_THROW(bad.write_vertices(0, 1, x), UsageError);
    EXPECT_THROW(bad.write_vertices(3, 1, x), std::logic_error);
  }
  EXPECT_FALSE(fs::exists(dir / "bad.ply"));
  fs::remove_all(dir);
}

}  // namespace
}  // namespace curvbench
