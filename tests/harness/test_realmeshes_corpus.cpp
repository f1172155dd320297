// tools/realmeshes.sh with CORPUS=all and tools/realmeshes_corpus.py on a tiny corpus, with the
// real CLI: a faceless OFF file and a point file are point sets (run with the point-set methods,
// listed in the point-set table), a mesh is run with the mesh methods, a 2-D point file is
// refused with one line.
#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>

#include "mesh/io.h"
#include "meshgen/torus_structured.h"
#include "tests/cli/cli_runner.h"

namespace curvbench {
namespace {

namespace fs = std::filesystem;
using testing::fresh_dir;
using testing::slurp;
using testing::write_text;

// The lines of `md` that start with `prefix`, joined.
std::string lines_starting(const std::string& md, const std::string& prefix) {
  std::string out;
  for (size_t p = 0; (p = md.find("\n" + prefix, p)) != std::string::npos; ++p)
    out += md.substr(p + 1, md.find('\n', p + 1) - p);
  return out;
}

TEST(RealmeshesCorpus, FacelessFilesRunAsPointSets) {
  const fs::path work = fresh_dir("realmeshes_corpus");
  const fs::path data = work / "data";
  // A mesh, a faceless OFF (points of the same torus), a point file, a 2-D point file.
  const Mesh torus = torus_structured(1).mesh;
  fs::create_directories(data / "meshes");
  write_mesh((data / "meshes" / "torus.off").string(), torus);
  std::string off = "OFF\n" + std::to_string(torus.num_vertices()) + " 0 0\n", xyz;
  for (int v = 0; v < torus.num_vertices(); ++v) {
    const Vec3 p = torus.position(v);
    const std::string line =
        std::to_string(p.x()) + " " + std::to_string(p.y()) + " " + std::to_string(p.z()) + "\n";
    off += line;
    xyz += line;
  }
  write_text(data / "points" / "faceless.off", off);
  write_text(data / "points" / "torus.xyz", xyz);
  write_text(data / "points" / "flat.xyz", "0 0\n1 0\n0 1\n");
  std::ofstream(work / ".data-all").put('\n');  // the extraction is done

  const std::string cmd =
      "WORK=" + work.string() + " CORPUS=all CORPUS_REPORT=" + (work / "R.md").string() +
      " CORPUS_METHODS='lhf meyer' bash " + CURVBENCH_SOURCE_DIR + "/tools/realmeshes.sh " +
      CURVBENCH_BINARY_DIR + " > " + (work / "log").string() + " 2>&1";
  ASSERT_EQ(std::system(cmd.c_str()), 0) << slurp(work / "log");
  const fs::path runs = work / "corpus" / "runs";
  // The point sets ran the point-set methods (meyer is not one), the mesh the mesh methods.
  for (const char* f : {"points/faceless.off", "points/torus.xyz"}) {
    SCOPED_TRACE(f);
    for (const char* m : {"lhf", "lop", "jet", "apss", "surface-variation"})
      EXPECT_TRUE(fs::exists(runs / f / (std::string(m) + ".rc"))) << m;
    EXPECT_FALSE(fs::exists(runs / f / "meyer.rc"));
  }
  EXPECT_TRUE(fs::exists(runs / "meshes/torus.off" / "meyer.rc"));
  EXPECT_FALSE(fs::exists(runs / "meshes/torus.off" / "apss.rc"));

  const std::string md = slurp(work / "R.md");
  const size_t table = md.find("### Point sets");
  ASSERT_NE(table, std::string::npos) << md;
  const std::string rows = lines_starting(md.substr(table), "| `");
  const std::string n = std::to_string(torus.num_vertices());
  EXPECT_NE(rows.find("| `points/faceless.off` | " + n + " | LHF-2 | " + n + " |"),
            std::string::npos)
      << rows;
  EXPECT_NE(rows.find("| `points/torus.xyz` | " + n + " | APSS | " + n + " |"), std::string::npos)
      << rows;
  EXPECT_NE(rows.find("| `points/flat.xyz` |  | lhf | refused |"), std::string::npos) << rows;
  EXPECT_EQ(rows.find("meshes/torus.off"), std::string::npos) << rows;
  // The refusal is listed with its one line.
  EXPECT_NE(md.find("- `points/flat.xyz`: line 1: a point has 2 numbers"), std::string::npos) << md;
  EXPECT_NE(md.find("(17 estimate runs in all): 1 mesh with 2 methods, 1 clean and 0 other; 3 "
                    "point sets with 5 methods."),
            std::string::npos)
      << md;
  fs::remove_all(work);
}

}  // namespace
}  // namespace curvbench
