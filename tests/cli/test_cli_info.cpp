// `curvbench --version`, `--help`, `info`, and the exit-code contract (0 ok, 2 bad input/usage).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <fstream>

#include "mesh/io.h"
#include "tests/cli/cli_runner.h"
#include "tests/mesh/crease_test_meshes.h"

namespace curvbench {
namespace {

using testing::fresh_dir;
using testing::run_cli;

TEST(Cli, VersionAndHelp) {
  auto r = run_cli("--version");
  EXPECT_EQ(r.exit_code, 0);
  EXPECT_NE(r.output.find("curvbench 0."), std::string::npos) << r.output;
  r = run_cli("--help");
  EXPECT_EQ(r.exit_code, 0);
  EXPECT_NE(r.output.find("info"), std::string::npos);
  r = run_cli("info --help");
  EXPECT_EQ(r.exit_code, 0);
  EXPECT_NE(r.output.find("MESH"), std::string::npos);
  EXPECT_NE(r.output.find("--skip-invalid"), std::string::npos);
}

TEST(Cli, BadUsageExits2) {
  EXPECT_EQ(run_cli("").exit_code, 2);
  EXPECT_EQ(run_cli("no-such-command").exit_code, 2);
  EXPECT_EQ(run_cli("info").exit_code, 2);  // missing MESH
}

TEST(Cli, InfoOnOctahedron) {
  const auto dir = fresh_dir("info_octa");
  const auto path = dir / "octa.off";
  std::ofstream(path) << "OFF\n6 8 0\n1 0 0\n-1 0 0\n0 1 0\n0 -1 0\n0 0 1\n0 0 -1\n"
                         "3 0 2 4\n3 2 1 4\n3 1 3 4\n3 3 0 4\n3 2 0 5\n3 1 2 5\n3 3 1 5\n3 0 3 5\n";
  const auto r = run_cli("info " + path.string());
  ASSERT_EQ(r.exit_code, 0) << r.output;
  EXPECT_NE(r.output.find("vertices:              6"), std::string::npos) << r.output;
  EXPECT_NE(r.output.find("faces:                 8"), std::string::npos);
  EXPECT_NE(r.output.find("edges:                 12"), std::string::npos);
  EXPECT_NE(r.output.find("boundary vertices:     0"), std::string::npos);
  EXPECT_NE(r.output.find("euler characteristic:  2"), std::string::npos);
  EXPECT_NE(r.output.find("mean edge length:      1.41421"), std::string::npos);
  EXPECT_NE(r.output.find("orientation:           consistent"), std::string::npos);
  EXPECT_NE(r.output.find("outward normals"), std::string::npos);
  // Defect counts (mesh/mesh_checks.h): all zero on a clean closed mesh, one component.
  for (const char* line :
       {"polygons triangulated: 0\n", "faces dropped:         0\n", "boundary loops:        0\n",
        "non-manifold vertices: 0\n", "zero-area faces:       0\n", "duplicate vertices:    0\n",
        "duplicate faces:       0\n", "components:            1\n"})
    EXPECT_NE(r.output.find(line), std::string::npos) << line;
  EXPECT_EQ(r.output.find("warning"), std::string::npos) << r.output;
}

// Sharp edges and the noise estimate (mesh/creases.h, harness/model/noise_estimate.h): the 12
// edges of n = 8 segments of a meshed cube, its 12 (n - 1) + 8 crease vertices, and a noise
// estimate of 0 from the face centres; no crease above 95 degrees, and then the fits across the
// edges read as noise.
TEST(Cli, InfoReportsCreasesAndNoise) {
  const auto dir = fresh_dir("info_creases");
  const std::string path = (dir / "cube.off").string();
  write_mesh(path, crease_test::meshed_cube(8).mesh);
  auto r = run_cli("info " + path);
  ASSERT_EQ(r.exit_code, 0) << r.output;
  EXPECT_NE(r.output.find("sharp edges:           96 (face normals more than 60 degrees apart)\n"),
            std::string::npos)
      << r.output;
  EXPECT_NE(r.output.find("crease vertices:       92\n"), std::string::npos) << r.output;
  EXPECT_NE(r.output.find("noise estimate:        sigma/h = 0, sigma/h^2 = 0 (from 6 vertices; 92 "
                          "crease vertices and 288 next to one left out)"),
            std::string::npos)
      << r.output;
  r = run_cli("info " + path + " --crease-angle 95");
  ASSERT_EQ(r.exit_code, 0) << r.output;
  EXPECT_NE(r.output.find("sharp edges:           0 (face normals more than 95 degrees apart)"),
            std::string::npos)
      << r.output;
  EXPECT_EQ(r.output.find("sigma/h = 0,"), std::string::npos) << r.output;
  for (const char* bad : {"0", "180", "-5", "nan"}) {
    r = run_cli("info " + path + " --crease-angle " + bad);
    EXPECT_EQ(r.exit_code, 2) << bad;
    EXPECT_NE(r.output.find("--crease-angle"), std::string::npos) << r.output;
  }
}

// Too few vertices for a fit: the octahedron's 12 edges (70.5 degrees) are all sharp.
TEST(Cli, InfoOnOctahedronHasNoNoiseEstimate) {
  const auto dir = fresh_dir("info_octa_noise");
  const auto path = dir / "octa.off";
  std::ofstream(path) << "OFF\n6 8 0\n1 0 0\n-1 0 0\n0 1 0\n0 -1 0\n0 0 1\n0 0 -1\n"
                         "3 0 2 4\n3 2 1 4\n3 1 3 4\n3 3 0 4\n3 2 0 5\n3 1 2 5\n3 3 1 5\n3 0 3 5\n";
  const auto r = run_cli("info " + path.string());
  ASSERT_EQ(r.exit_code, 0) << r.output;
  EXPECT_NE(r.output.find("sharp edges:           12 "), std::string::npos) << r.output;
  EXPECT_NE(r.output.find("crease vertices:       6\n"), std::string::npos) << r.output;
  EXPECT_NE(r.output.find("noise estimate:        none (cannot estimate the noise"),
            std::string::npos)
      << r.output;
}

TEST(Cli, InfoReportsBoundaryAndQuads) {
  const auto dir = fresh_dir("info_quad");
  const auto path = dir / "quads.obj";
  std::ofstream(path)
      << "v 0 0 0\nv 1 0 0\nv 2 0 0\nv 0 1 0\nv 1 1 0\nv 2 1 0\nf 1 2 5 4\nf 2 3 6 5\n";
  const auto r = run_cli("info " + path.string());
  ASSERT_EQ(r.exit_code, 0) << r.output;
  EXPECT_NE(r.output.find("faces:                 4 (2 polygons fan-triangulated)"),
            std::string::npos)
      << r.output;
  EXPECT_NE(r.output.find("boundary vertices:     6"), std::string::npos);
  EXPECT_NE(r.output.find("euler characteristic:  1"), std::string::npos);
}

TEST(Cli, BadInputExits2WithOneLineNamingTheFile) {
  const auto dir = fresh_dir("info_bad");
  auto r = run_cli("info " + (dir / "missing.off").string());
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.output.find("missing.off"), std::string::npos) << r.output;
  EXPECT_EQ(std::count(r.output.begin(), r.output.end(), '\n'), 1) << r.output;

  const auto unknown = dir / "mesh.abc";  // not a format curvbench reads
  std::ofstream(unknown) << "1 2 3\n";
  r = run_cli("info " + unknown.string());
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.output.find("mesh.abc"), std::string::npos) << r.output;

  const auto range = dir / "range.off";
  std::ofstream(range) << "OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 7\n";
  r = run_cli("info " + range.string());
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.output.find("range.off"), std::string::npos) << r.output;
  EXPECT_EQ(std::count(r.output.begin(), r.output.end(), '\n'), 1) << r.output;
}

}  // namespace
}  // namespace curvbench

namespace curvbench {
namespace {

// What the estimators will not handle, from the mesh alone: `info` lists it, and `estimate`
// counts its failed, excluded and partial vertices by it (mesh/mesh_checks.h VertexDefect). An
// octahedron (six vertices, too few for a quadratic's 6 coefficients and a centre: the quadric
// gives the normal only, status partial) beside a larger component.
TEST(Cli, InfoListsAndEstimateCountsTheCausesOfFailedVertices) {
  const auto dir = testing::fresh_dir("info_causes");
  const auto path = dir / "two.off";
  std::ofstream out(path);
  // A flat 5 x 5 grid of squares (36 vertices, 20 on the boundary), then the octahedron (6
  // vertices) beside it.
  out << "OFF\n42 58 0\n";
  for (int j = 0; j <= 5; ++j)
    for (int i = 0; i <= 5; ++i) out << i << " " << j << " 0\n";
  out << "11 0 0\n9 0 0\n10 1 0\n10 -1 0\n10 0 1\n10 0 -1\n";
  for (int j = 0; j < 5; ++j)
    for (int i = 0; i < 5; ++i) {
      const int a = 6 * j + i;
      out << "3 " << a << " " << a + 1 << " " << a + 7 << "\n3 " << a << " " << a + 7 << " "
          << a + 6 << "\n";
    }
  for (const char* f : {"3 36 38 40\n", "3 38 37 40\n", "3 37 39 40\n", "3 39 36 40\n",
                        "3 38 36 41\n", "3 37 38 41\n", "3 39 37 41\n", "3 36 39 41\n"})
    out << f;
  out.close();
  const auto r = testing::run_cli("info " + path.string());
  ASSERT_EQ(r.exit_code, 0) << r.output;
  const std::string& info = r.output;
  EXPECT_NE(info.find("hard for estimators:   isolated vertex 0, component of fewer than 7 "
                      "vertices 6, non-manifold neighbourhood 0, zero-area faces only 0, "
                      "boundary vertex 20 (vertices)"),
            std::string::npos)
      << info;
  const auto est = testing::run_cli("estimate " + path.string() + " --method quadric --output " +
                                    (dir / "q.csv").string());
  ASSERT_EQ(est.exit_code, 0) << est.output;
  EXPECT_NE(est.output.find("partial vertices by cause: component of fewer than 7 vertices 6"),
            std::string::npos)
      << est.output;
}

TEST(Cli, EstimateNamesTheMethodsOwnFailureWhereTheMeshShowsNoDefect) {
  // A hexagonal bipyramid (8 vertices, closed, manifold) whose top apex is folded down through
  // the equator to z = -0.6: the corrected area of the apex's 1-ring, with the interpolated
  // vertex normals, is negative, so ICC (which divides by it) fails there.
  const auto dir = testing::fresh_dir("own_failure");
  const auto path = dir / "folded.off";
  std::ofstream out(path);
  out << "OFF\n8 12 0\n";
  for (int i = 0; i < 6; ++i)
    out << std::cos(M_PI * i / 3) << " " << std::sin(M_PI * i / 3) << " 0\n";
  out << "0 0 -0.6\n0 0 -1\n";
  for (int i = 0; i < 6; ++i)
    out << "3 " << i << " " << (i + 1) % 6 << " 6\n3 " << (i + 1) % 6 << " " << i << " 7\n";
  out.close();
  const auto icc = testing::run_cli("estimate " + path.string() + " --method icc --output " +
                                    (dir / "icc.csv").string());
  ASSERT_EQ(icc.exit_code, 0) << icc.output;
  EXPECT_NE(icc.output.find("failed vertices by cause: no mesh defect (a corrected area measure "
                            "that is not positive) 1"),
            std::string::npos)
      << icc.output;
}

}  // namespace
}  // namespace curvbench
