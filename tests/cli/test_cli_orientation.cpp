// `curvbench estimate` orients the input first (mesh/orientation.h): a mesh and a copy
// with random faces flipped, or turned inside out, give byte-identical estimates, with a warning.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <random>
#include <string>
#include <utility>

#include "mesh/io.h"
#include "meshgen/torus_structured.h"
#include "tests/cli/cli_runner.h"

namespace curvbench {
namespace {

namespace fs = std::filesystem;
using testing::fresh_dir;
using testing::run_cli;
using testing::slurp;

TEST(CliOrientation, FlippedCopiesGiveIdenticalEstimates) {
  const fs::path dir = fresh_dir("cli_orientation");
  const Mesh torus = torus_structured(1, true, 3).mesh;
  FaceMatrix soup = torus.faces(), inside_out = torus.faces();
  std::mt19937 rng(11);
  int flipped = 0;
  for (int f = 0; f < soup.rows(); ++f) {
    if (rng() % 3 == 0) {
      std::swap(soup(f, 0), soup(f, 1));
      ++flipped;
    }
    std::swap(inside_out(f, 1), inside_out(f, 2));
  }
  write_mesh((dir / "torus.off").string(), torus, {}, {});
  write_mesh((dir / "soup.off").string(), Mesh(torus.vertices(), soup), {}, {});
  write_mesh((dir / "inside_out.off").string(), Mesh(torus.vertices(), inside_out), {}, {});
  for (const char* method : {"lhf-2", "lscm-fast-3", "xu", "jet-2"}) {
    std::string reference;
    for (const char* name : {"torus", "soup", "inside_out"}) {
      const fs::path out = dir / (std::string(name) + "_" + method + ".csv");
      const auto r = run_cli("estimate " + (dir / (std::string(name) + ".off")).string() +
                             " --method " + method + " --output " + out.string());
      ASSERT_EQ(r.exit_code, 0) << r.output;
      const std::string csv = slurp(out);
      if (reference.empty()) {
        reference = csv;
        EXPECT_EQ(r.output.find("reoriented"), std::string::npos) << r.output;
      } else {
        EXPECT_EQ(csv, reference) << name << " " << method;
        const int expected = std::string(name) == "soup" ? flipped : torus.num_faces();
        EXPECT_NE(r.output.find("warning: " + (dir / (std::string(name) + ".off")).string() +
                                ": reoriented " + std::to_string(expected) + " of " +
                                std::to_string(torus.num_faces()) + " faces"),
                  std::string::npos)
            << r.output;
      }
    }
  }
  fs::remove_all(dir);
}

TEST(CliOrientation, MoebiusStripSaysSignUndetermined) {
  const fs::path dir = fresh_dir("cli_moebius");
  const int nu = 40;
  VertexMatrix V(3 * nu, 3);
  for (int i = 0; i < nu; ++i)
    for (int j = 0; j < 3; ++j) {
      const double u = 2 * 3.141592653589793 * i / nu, t = 0.3 * (j - 1);
      V.row(3 * i + j) << (1 + t * std::cos(u / 2)) * std::cos(u),
          (1 + t * std::cos(u / 2)) * std::sin(u), t * std::sin(u / 2);
    }
  FaceMatrix F(4 * nu, 3);
  for (int i = 0, f = 0; i < nu; ++i)
    for (int j = 0; j < 2; ++j) {
      const int a = 3 * i + j, b = a + 1;
      const int c = i + 1 < nu ? 3 * (i + 1) + j : 2 - j, d = i + 1 < nu ? c + 1 : 1 - j;
      F.row(f++) << a, c, d;
      F.row(f++) << a, d, b;
    }
  write_mesh((dir / "moebius.off").string(), Mesh(V, F), {}, {});
  const auto r = run_cli("estimate " + (dir / "moebius.off").string() +
                         " --method lhf-2 --output " + (dir / "m.csv").string());
  ASSERT_EQ(r.exit_code, 0) << r.output;
  EXPECT_NE(r.output.find("120 vertices are on a non-orientable"), std::string::npos) << r.output;
  const std::string csv = slurp(dir / "m.csv");
  size_t rows = 0, undetermined = 0;
  for (size_t p = csv.find('\n'); p != std::string::npos && p + 1 < csv.size();
       p = csv.find('\n', p + 1)) {
    ++rows;
    const size_t end = csv.find('\n', p + 1);
    undetermined += csv.substr(p + 1, end - p - 1).ends_with(",sign_undetermined");
  }
  EXPECT_EQ(rows, 120u);
  EXPECT_EQ(undetermined, 120u);
  fs::remove_all(dir);
}

}  // namespace
}  // namespace curvbench
