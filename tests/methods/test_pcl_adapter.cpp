// The PCL adapter (experiments/examples/pcl_curvatures.cpp, run by pcl_curvatures.sh): where it is
// built (libpcl-dev), its columns on a sphere and a plane are what PCL's quantities are (oriented
// PCA normals, the surface variation in H, non-negative pc1 >= pc2 in k1, k2); where it is not,
// the script exits 77 with one line and these tests are skipped with that reason.
#include <gtest/gtest.h>
#include <sys/wait.h>

#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "mesh/io.h"
#include "tests/methods/method_test_util.h"

namespace curvbench {
namespace {

namespace fs = std::filesystem;
using testing::grid_mesh;
using testing::icosphere;

const std::string kAdapter = std::string(CURVBENCH_BINARY_DIR) + "/pcl_curvatures";
const std::string kScript =
    std::string(CURVBENCH_SOURCE_DIR) + "/experiments/examples/pcl_curvatures.sh";

struct Row {
  double n[3], k1, k2, H;
};

// Writes the mesh, runs the script on it, returns the rows (one per vertex) of its CSV.
std::vector<Row> run_adapter(const Mesh& m) {
  // One folder per test: ctest runs the tests of this file in parallel processes.
  const fs::path dir =
      fs::temp_directory_path() /
      ("curvbench_test_pcl_adapter_" +
       std::string(::testing::UnitTest::GetInstance()->current_test_info()->name()));
  fs::create_directories(dir);
  const std::string mesh = (dir / "mesh.ply").string(), out = (dir / "out.csv").string();
  write_mesh(mesh, m);
  const std::string cmd = "CURVBENCH_PCL_ADAPTER='" + kAdapter + "' sh '" + kScript + "' '" + mesh +
                          "' '" + out + "' 20";
  EXPECT_EQ(std::system(cmd.c_str()), 0) << cmd;
  std::ifstream in(out);
  std::string line;
  std::getline(in, line);
  EXPECT_EQ(line, "vertex,nx,ny,nz,k1,k2,H");
  std::vector<Row> rows;
  while (std::getline(in, line)) {
    for (char& c : line)
      if (c == ',') c = ' ';
    std::istringstream s(line);
    int v;
    Row r;
    s >> v >> r.n[0] >> r.n[1] >> r.n[2] >> r.k1 >> r.k2 >> r.H;
    EXPECT_EQ(v, static_cast<int>(rows.size()));
    rows.push_back(r);
  }
  fs::remove_all(dir);
  return rows;
}

TEST(PclAdapter, ScriptSkipsWithOneLineWhereNotBuilt) {
  const std::string cmd = "CURVBENCH_PCL_ADAPTER=/nonexistent/pcl_curvatures sh '" + kScript +
                          "' a.ply b.csv 2>/dev/null";
  const int status = std::system(cmd.c_str());
  ASSERT_TRUE(WIFEXITED(status));
  EXPECT_EQ(WEXITSTATUS(status), 77);
}

TEST(PclAdapter, SphereColumnsArePclsQuantities) {
  if (!fs::exists(kAdapter)) GTEST_SKIP() << "PCL adapter not built (no libpcl-dev)";
  const double r = 2.0;
  const Mesh m = icosphere(4, r);
  const auto rows = run_adapter(m);
  ASSERT_EQ(static_cast<int>(rows.size()), m.num_vertices());
  for (int v = 0; v < m.num_vertices(); ++v) {
    const Row& e = rows[static_cast<size_t>(v)];
    const Vec3 n(e.n[0], e.n[1], e.n[2]);
    EXPECT_GT(n.dot(m.position(v).normalized()), 0.999) << v;  // turned outward
    EXPECT_GT(e.H, 0.0) << v;                                  // surface variation: unsigned
    EXPECT_LT(e.H, 1.0 / 3.0) << v;
    EXPECT_GE(e.k1, e.k2) << v;  // pc1 >= pc2 >= 0: variances, not -1/r
    EXPECT_GE(e.k2, 0.0) << v;
    EXPECT_LT(e.k1, 0.1 / r) << v;  // far below 1/r
  }
}

TEST(PclAdapter, PlaneIsFlat) {
  if (!fs::exists(kAdapter)) GTEST_SKIP() << "PCL adapter not built (no libpcl-dev)";
  const Mesh m =
      grid_mesh(12, 0.1, false, 0.2, 4, [](double x, double y) { return Vec3(x, y, 0); });
  const auto rows = run_adapter(m);
  ASSERT_EQ(static_cast<int>(rows.size()), m.num_vertices());
  for (const Row& e : rows) {
    EXPECT_NEAR(std::abs(e.n[2]), 1.0, 1e-6);  // float precision (PCL's PointXYZ)
    EXPECT_GT(e.n[2], 0.0);                    // the faces' side (counter-clockwise: +z)
    EXPECT_LT(e.H, 1e-6);
    EXPECT_LT(e.k1, 1e-6);
  }
}

}  // namespace
}  // namespace curvbench
