// tools/realmeshes_report.py (make realmeshes): the worst-vertex diagnostics on a mesh with one
// known bad vertex, estimated by the real CLI.
#include <gtest/gtest.h>

#include <filesystem>
#include <string>

#include "mesh/io.h"
#include "meshgen/torus_structured.h"
#include "tests/harness/cli_runner.h"

namespace curvbench {
namespace {

namespace fs = std::filesystem;
using testing::fresh_dir;
using testing::run_cli;
using testing::slurp;

TEST(RealMeshesReport, WorstVertexIsTheKnownBadOne) {
  if (!fs::exists("/usr/bin/python3")) GTEST_SKIP() << "no /usr/bin/python3";
  const fs::path dir = fresh_dir("realmeshes_report");
  fs::create_directories(dir / "data" / "meshes");
  // A torus with vertex 100 pushed almost onto the segment between two of its neighbours' far
  // side: needle and cap triangles around it, and a curvature spike the methods disagree on.
  const Mesh t = torus_structured(1).mesh;
  VertexMatrix V = t.vertices();
  const int bad = 100;
  V.row(bad) += 0.9 * (V.row(bad + 1) - V.row(bad));
  const fs::path off = dir / "data" / "meshes" / "bad.off";
  write_mesh(off.string(), Mesh(V, t.faces()), {}, {});
  ASSERT_EQ(run_cli("info " + off.string() + " > " + (dir / "bad.info").string()).exit_code, 0);
  for (const char* method : {"lhf-4", "lscm-2"}) {
    const std::string base = (dir / (std::string("bad.") + method)).string();
    const auto r = run_cli("estimate " + off.string() + " --method " + method + " --output " +
                           base + ".csv 2> " + base + ".log");
    ASSERT_EQ(r.exit_code, 0) << r.output;
  }
  const std::string cmd = std::string("/usr/bin/python3 ") + CURVBENCH_SOURCE_DIR +
                          "/tools/realmeshes_report.py " + dir.string() + " " +
                          (dir / "R.md").string() +
                          " --meshes bad --methods lhf-4 lscm-2 --worst 3";
  ASSERT_EQ(std::system(cmd.c_str()), 0);
  const std::string md = slurp(dir / "R.md");
  // The first row of the worst-vertex table: vertex 100 or one of its neighbours, with the needle
  // (smallest angle < 10 degrees) in its star.
  const size_t table = md.find("| vertex | d | method |");
  ASSERT_NE(table, std::string::npos) << md;
  const size_t row = md.find("\n| ", md.find("|---:|", table));
  ASSERT_NE(row, std::string::npos);
  const std::string first = md.substr(row + 3, md.find('\n', row + 1) - row - 3);
  const int vertex = std::stoi(first);
  EXPECT_TRUE(vertex == bad || (V.row(vertex) - V.row(bad)).norm() < 3 * t.mean_edge_length())
      << first;
  // Columns: vertex, d, method, H, H_ref, smallest angle, ...
  size_t p = 0;
  for (int c = 0; c < 5; ++c) p = first.find('|', p) + 1;
  EXPECT_LT(std::stod(first.substr(p)), 10.0) << first;
  EXPECT_NE(md.find("| LSCM-2 |"), std::string::npos);
  fs::remove_all(dir);
}

}  // namespace
}  // namespace curvbench
