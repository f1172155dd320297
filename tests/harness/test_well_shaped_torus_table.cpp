// The section of the well-shaped torus meshes (harness/report/well_shaped_torus_table.h) from its CSV:
// the words, one row per family and level with the counts against the paper's, and the numbers
// in the cells.
#include "harness/report/well_shaped_torus_table.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <string>
#include <variant>

#include "harness/report/model.h"
#include "tests/cli/cli_runner.h"

namespace curvbench {
namespace {

namespace fs = std::filesystem;

TEST(WellShapedTorusTable, SectionFromTheCsv) {
  const fs::path dir = testing::fresh_dir("well_shaped_torus_table");
  const fs::path csv = dir / "torus_unstructured.csv";
  std::ofstream(csv) << "# provenance\n"
                        "family,level,vertices,paper_vertices,faces,mean_edge_length,"
                        "min_angle_deg,max_angle_deg,valence_histogram\n"
                        "torus-unstructured,1,1343,1338,2686,0.10186554,30.03246,117.12078,"
                        "4:22 5:281 6:753\n";
  const report::Section s = well_shaped_torus_section(csv.string());
  EXPECT_EQ(s.id, "well-shaped-torus");
  const std::string md = report::to_markdown(s);
  EXPECT_NE(md.find("## Well-shaped torus meshes (the paper's Table 5 meshes)"), std::string::npos);
  EXPECT_NE(md.find("`torus-unstructured-minval5`: the same meshes"), std::string::npos);
  // 1343 against the paper's 1338: +0.4%.
  EXPECT_NE(md.find("| `torus-unstructured` | 1 | 1343 / 1338 (+0.4%) | 2686 | 0.1019 | "
                    "30.0 - 117.1 | 4:22 5:281 6:753 |"),
            std::string::npos)
      << md;
  const auto* tab = std::get_if<report::Table>(&s.blocks.back());
  ASSERT_NE(tab, nullptr);
  ASSERT_EQ(tab->rows.size(), 1u);
  EXPECT_EQ(tab->rows[0][2].value, 1343);
  EXPECT_EQ(tab->rows[0][3].value, 2686);
  EXPECT_DOUBLE_EQ(tab->rows[0][4].value, 0.10186554);
  EXPECT_DOUBLE_EQ(tab->rows[0][5].value, 30.03246);

  // No CSV: an empty section.
  const report::Section none = well_shaped_torus_section((dir / "missing.csv").string());
  EXPECT_TRUE(none.title.empty());
  EXPECT_TRUE(none.blocks.empty());
  fs::remove_all(dir);
}

}  // namespace
}  // namespace curvbench
