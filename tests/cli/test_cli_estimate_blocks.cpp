// Streaming output: `curvbench estimate` estimates and writes a block of
// vertices at a time. The CSV and PLY bytes are the same for any --block and --threads, and equal
// to the whole-vector path of the C++ API and Python (estimate_oriented without blocks, then the
// whole-array writers); the parallel CSV formatting and the block PLY writer equal their one-piece
// forms.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <limits>
#include <random>
#include <string>
#include <vector>

#include "core/errors.h"
#include "harness/estimate_columns.h"
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
  {
    EstimateCsvWriter writer((dir / "inflight.csv").string(), {}, 1);
    writer.write(0, e);
  }
  EXPECT_FALSE(fs::exists(dir / "inflight.csv"));
  EXPECT_EQ(std::distance(fs::directory_iterator(dir), fs::directory_iterator()), 1);
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
