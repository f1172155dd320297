// Where the safeguard's condition test fires (harness/run/safeguard_fires.h).
#include "harness/run/safeguard_fires.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include "core/atomic_file.h"

namespace curvbench {
namespace {

// bump-48 level 1 at degree 4: the test cuts some stencils (boundary ones, on four grid lines)
// while every |R_jj| passes; the irregular bump has none (docs/claims.md, "The safeguard on
// near-degenerate stencils").
TEST(SafeguardFires, CutsFourGridLineStencilsOfTheFourEightMeshOnly) {
  const auto rows =
      safeguard_fires({{"bump-48", {1}, {"lhf-4"}}, {"bump-irregular", {1}, {"lhf-4"}}});
  int cut48 = 0, irregular = 0;
  for (const SafeguardFire& f : rows) {
    EXPECT_EQ(f.level, 1);
    EXPECT_EQ(f.method, "LHF-4");
    if (f.family == "bump-irregular") {
      ++irregular;
      EXPECT_EQ(f.vertex, -1);  // looked at, nothing cut
      continue;
    }
    ASSERT_EQ(f.family, "bump-48");
    ASSERT_GE(f.vertex, 0);
    ++cut48;
    EXPECT_EQ(f.vertices, 289);
    EXPECT_LT(f.rank, f.column_rank);
    EXPECT_EQ(f.column_rank, 15);  // every |R_jj| passes
    EXPECT_GT(f.condition, 1e3);   // sqrt(k) ||R^-1||_F >= ||R_k^-1||_F > 1 / tol
    // Without the test the estimate keeps the first stencil at degree 4.
    EXPECT_EQ(f.degree_rjj_only, 4);
    EXPECT_GE(f.ring, f.ring_rjj_only);
  }
  EXPECT_GT(cut48, 0);
  EXPECT_EQ(irregular, 1);

  // The CSV reads back.
  const std::string path =
      (std::filesystem::temp_directory_path() / "curvbench_safeguard_fires.csv").string();
  write_file_atomic(path, safeguard_fires_csv(rows));
  const auto back = read_safeguard_fires_csv(path);
  std::filesystem::remove(path);
  ASSERT_EQ(back.size(), rows.size());
  for (size_t i = 0; i < rows.size(); ++i) {
    EXPECT_EQ(back[i].family, rows[i].family);
    EXPECT_EQ(back[i].vertex, rows[i].vertex);
    EXPECT_EQ(back[i].x, rows[i].x);
    EXPECT_EQ(back[i].boundary, rows[i].boundary);
    EXPECT_EQ(back[i].rank, rows[i].rank);
    EXPECT_NEAR(back[i].condition, rows[i].condition, 1e-5 * rows[i].condition);
    EXPECT_EQ(back[i].ring_rjj_only, rows[i].ring_rjj_only);
  }
}

}  // namespace
}  // namespace curvbench
