// Differential test of the mesh readers against CGAL's (tests/mesh/cgal_oracle.h): every corpus
// file our reader accepts, CGAL's reader accepts too, with the same soup; plus files written by
// write_off / write_ply, whose layouts (full-precision OFF, binary PLY with extra properties) are
// the ones curvbench itself produces.
#include <unistd.h>

#include <gtest/gtest.h>

#include <filesystem>
#include <string>

#include "core/text.h"
#include "mesh/io.h"
#include "tests/cli/cli_runner.h"
#include "tests/mesh/cgal_oracle.h"

namespace curvbench {
namespace {

namespace fs = std::filesystem;

using testing::slurp;

TEST(MeshIoOracle, CorpusFilesWeAcceptCgalReadsToTheSameSoup) {
  const fs::path corpus = fs::path(CURVBENCH_SOURCE_DIR) / "tests" / "corpus";
  int accepted = 0, refused = 0;
  for (const char* folder : {"off", "obj", "ply", "regressions"}) {
    for (const auto& entry : fs::directory_iterator(corpus / folder)) {
      const std::string format = lower_extension(entry.path().string());
      bool ok = false;
      EXPECT_EQ(oracle::differential(format, slurp(entry.path()), &ok), "") << entry.path();
      ++(ok ? accepted : refused);
    }
  }
  // The corpus holds both kinds; refused files are not given to CGAL (see cgal_oracle.h).
  EXPECT_GE(accepted, 25);
  EXPECT_GE(refused, 20);
}

TEST(MeshIoOracle, FilesWrittenByCurvbenchReadTheSameInCgal) {
  VertexMatrix V(5, 3);
  V << 0.1, 1.0 / 3.0, -0.0, 1.0, -2.5e17, 4.9406564584124654e-324, -1e-300, 2.0 / 3.0, 7.0,
      123456.789, 0.2, 1.4142135623730951, 0.5, 0.5, 0.5;
  FaceMatrix F(6, 3);
  F << 0, 2, 1, 0, 1, 3, 0, 3, 2, 1, 2, 4, 2, 3, 4, 3, 1, 4;
  const Mesh mesh(V, F);
  const fs::path dir =
      fs::temp_directory_path() / ("curvbench_oracle_" + std::to_string(::getpid()));
  fs::create_directories(dir);
  const std::vector<VertexProperty> props = {{"k1", {1, 2, 3, 4, 5}, false},
                                             {"status", {0, 1, 0, 2, 0}, true}};
  write_off((dir / "m.off").string(), mesh, {"a comment"});
  write_ply((dir / "plain.ply").string(), mesh);
  write_ply((dir / "props.ply").string(), mesh, props, {"c"});
  for (const char* name : {"m.off", "plain.ply", "props.ply"}) {
    const fs::path p = dir / name;
    bool ok = false;
    EXPECT_EQ(oracle::differential(lower_extension(p.string()), slurp(p), &ok), "") << name;
    EXPECT_TRUE(ok) << name;
  }
  fs::remove_all(dir);
}

}  // namespace
}  // namespace curvbench
