// tools/realmeshes_report.py (make realmeshes): the worst-vertex diagnostics on a mesh with one
// known bad vertex, estimated by the real CLI.
#include <gtest/gtest.h>

#include <filesystem>
#include <string>

#include "mesh/io.h"
#include "meshgen/torus_structured.h"
#include "tests/cli/cli_runner.h"

namespace curvbench {
namespace {

namespace fs = std::filesystem;
using testing::fresh_dir;
using testing::run_cli;
using testing::slurp;

// Column c (0 = vertex) of a markdown table row that starts after its leading "| ".
std::string column(const std::string& row, int c) {
  size_t p = 0;
  for (int k = 0; k < c; ++k) p = row.find('|', p) + 1;
  return row.substr(p, row.find('|', p) - p);
}

// The report of tools/realmeshes_report.py on `mesh` estimated by LHF-4 (the reference) and
// LSCM-2 through the real CLI; `table_row` gets the worst-vertex row of `vertex` ("" if absent)
// and `first_row` the first one.
std::string report(const std::string& name, const Mesh& mesh, int vertex, std::string* first_row,
                   std::string* table_row) {
  const fs::path dir = fresh_dir("realmeshes_report_" + name);
  fs::create_directories(dir / "data" / "meshes");
  const fs::path off = dir / "data" / "meshes" / (name + ".off");
  write_mesh(off.string(), mesh, {}, {});
  EXPECT_EQ(run_cli("info " + off.string() + " > " + (dir / (name + ".info")).string()).exit_code,
            0);
  for (const char* method : {"lhf-4", "lscm-2"}) {
    const std::string base = (dir / (name + "." + method)).string();
    const auto r = run_cli("estimate " + off.string() + " --method " + method + " --output " +
                           base + ".csv 2> " + base + ".log");
    EXPECT_EQ(r.exit_code, 0) << r.output;
  }
  const std::string cmd = std::string("/usr/bin/python3 ") + CURVBENCH_SOURCE_DIR +
                          "/tools/realmeshes_report.py " + dir.string() + " " +
                          (dir / "R.md").string() + " --meshes " + name +
                          " --methods lhf-4 lscm-2 --worst 3";
  EXPECT_EQ(std::system(cmd.c_str()), 0);
  const std::string md = slurp(dir / "R.md");
  fs::remove_all(dir);
  const size_t table = md.find("| vertex | d | method |");
  if (table == std::string::npos) return md;
  const size_t row = md.find("\n| ", md.find("|---:|", table));
  *first_row = md.substr(row + 3, md.find('\n', row + 1) - row - 3);
  const std::string key = "\n| " + std::to_string(vertex) + " |";
  const size_t mine = md.find(key, table);
  const size_t end = md.find("\n\n", row);
  *table_row = mine < end ? md.substr(mine + 3, md.find('\n', mine + 1) - mine - 3) : "";
  return md;
}

TEST(RealMeshesReport, WorstVertexIsTheKnownBadOne) {
  if (!fs::exists("/usr/bin/python3")) GTEST_SKIP() << "no /usr/bin/python3";
  // A torus with vertex 100 pushed 0.9 of the way to its neighbour 101: needle and cap triangles
  // around it, an edge of a tenth of its length, and a curvature spike the methods disagree on.
  const Mesh t = torus_structured(1).mesh;
  VertexMatrix V = t.vertices();
  const int bad = 100;
  V.row(bad) += 0.9 * (V.row(bad + 1) - V.row(bad));
  std::string first, row;
  const std::string md = report("bad", Mesh(V, t.faces()), bad, &first, &row);
  ASSERT_FALSE(first.empty()) << md;
  // The first row of the worst-vertex table: vertex 100 or one of its neighbours, with the needle
  // (smallest angle < 10 degrees) in its star.
  const int vertex = std::stoi(first);
  EXPECT_TRUE(vertex == bad || (V.row(vertex) - V.row(bad)).norm() < 3 * t.mean_edge_length())
      << first;
  EXPECT_LT(std::stod(column(first, 5)), 10.0) << first;
  // Vertex 100 is in the table with its short edge (0.1 of a torus edge; column 10), and no fold
  // (column 9): its triangles are squeezed, not flipped.
  ASSERT_FALSE(row.empty()) << md;
  EXPECT_LT(std::stod(column(row, 10)), 0.2) << row;
  EXPECT_LT(std::stod(column(row, 9)), 90.0) << row;
  EXPECT_NE(md.find("| LSCM-2 |"), std::string::npos);
}

TEST(RealMeshesReport, FoldColumnFindsFlippedTriangles) {
  if (!fs::exists("/usr/bin/python3")) GTEST_SKIP() << "no /usr/bin/python3";
  // Vertex 100 pushed past its neighbour 101 (1.7 of the way): the triangles between them turn
  // over, so two faces sharing an edge there have nearly opposite normals (a fold near 180 deg).
  const Mesh t = torus_structured(1).mesh;
  VertexMatrix V = t.vertices();
  const int bad = 100;
  V.row(bad) += 1.7 * (V.row(bad + 1) - V.row(bad));
  std::string first, row;
  const std::string md = report("fold", Mesh(V, t.faces()), bad, &first, &row);
  ASSERT_FALSE(first.empty()) << md;
  EXPECT_GT(std::stod(column(first, 9)), 150.0) << first;
  // The whole-mesh line counts the folded vertices: some, and not most.
  const std::string tag = "with a fold > 90 deg in their two-ring: ";
  const size_t p = md.find(tag);
  ASSERT_NE(p, std::string::npos) << md;
  const int folded = std::stoi(md.substr(p + tag.size()));
  EXPECT_GT(folded, 0);
  EXPECT_LT(folded, 50);
  // The clean torus has no fold at all.
  std::string clean_first, clean_row;
  const std::string clean = report("clean", t, bad, &clean_first, &clean_row);
  EXPECT_NE(clean.find(tag + "0 "), std::string::npos) << clean;
}

}  // namespace
}  // namespace curvbench
