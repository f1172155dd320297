// The report's Table 5 (harness/report/table5.h) from the CSVs of `make bench`: our times with
// the paper's beside, the ratios with the paper's, QR against SVD, scaling over the levels of
// both timing files, the end-to-end rows, the machine line; every number in its cell.
#include "harness/report/table5.h"

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <string>
#include <variant>
#include <vector>

#include "tests/cli/cli_runner.h"

namespace curvbench {
namespace {

namespace fs = std::filesystem;

const char* kHeader = "mesh,level,verts,tris,method,degree,threads,seconds,tris_per_second\n";

// The table of a section with this id.
const report::Table* table_of(const report::Section& s, const std::string& id) {
  for (const report::Block& b : s.blocks)
    if (const auto* t = std::get_if<report::Table>(&b); t && t->id == id) return t;
  return nullptr;
}

// The row of a table whose first cell reads `first`.
const std::vector<report::Cell>* row_headed_by(const report::Table& t, const std::string& first) {
  for (const auto& r : t.rows)
    if (!r.empty() && r[0].text == first) return &r;
  return nullptr;
}

TEST(ReportTable5, EverySubtableFromTheCsvs) {
  const fs::path dir = testing::fresh_dir("report_table5");
  std::ofstream(dir / "table5_timing.csv")
      << "# curvbench test\n# machine: Test CPU, nproc 2. Compiler: GCC 12. Build: Release\n"
      << kHeader
      << "torus-unstructured,1,1343,2686,LHF-2,2,1,0.001,2.686e6\n"
         "torus-unstructured,1,1343,2686,LHF-2,2,2,0.0005,5.372e6\n"
         "torus-unstructured,1,1343,2686,LOP-2,2,1,0.002,1.343e6\n"
         "torus-unstructured,1,1343,2686,Meyer,0,1,0.0005,5.372e6\n"
         "torus-unstructured,1,1343,2686,LHF-2 scalar,2,1,0.003,0.895e6\n"
         "torus-unstructured,1,1343,2686,LHF-2 QR,2,1,0.0004,6.7e6\n"
         "torus-unstructured,1,1343,2686,LHF-2 SVD (Jacobi),2,1,0.0024,1.1e6\n";
  std::ofstream(dir / "table5_scaling.csv")
      << kHeader << "torus-structured,5,360448,720896,LHF-2,2,1,0.18,4e6\n";
  std::ofstream(dir / "end_to_end.csv")
      << "# test\nthreads,read_s,orientation_s,fit_s,write_s,wall_s,peak_rss_mb\n"
         "1,0.219,0.136,0.847,0.572,1.78,267\n";
  std::ofstream(dir / "limits.csv")
      << "# test\nstage,measured_seconds,bound_seconds,bound_kind,ratio,notes\n"
         "orientation,0.030,0.015,one pass over the edges,2,consistent mesh\n";
  const report::Section s = table5_section(dir.string());
  EXPECT_EQ(s.id, "table5");
  const std::string md = report::to_markdown(s);
  EXPECT_NE(md.find("Machine: Test CPU, nproc 2. Compiler: GCC 12. Build: Release."),
            std::string::npos)
      << md;

  // Our times, the paper's in parentheses (Table 5, level 1: LHF-2 0.0061 s, 1338 vertices).
  const report::Table* times = table_of(s, "table5-times");
  ASSERT_NE(times, nullptr);
  EXPECT_EQ(times->columns[5], "LHF-2");
  ASSERT_EQ(times->rows.size(), 4u);
  EXPECT_EQ(times->rows[0][1].text, "1343 (1338)");
  EXPECT_EQ(times->rows[0][1].value, 1343);
  EXPECT_EQ(times->rows[0][5].text, "0.001 (0.0061)");
  EXPECT_DOUBLE_EQ(times->rows[0][5].value, 0.001);
  EXPECT_EQ(times->rows[1][5].text, "- (0.023)");  // level 2 not measured
  // Throughput: 2686 triangles in 1 ms; the 2-thread column.
  const report::Table* tp = table_of(s, "table5-throughput");
  ASSERT_NE(tp, nullptr);
  EXPECT_EQ(tp->rows[0][3].text, "2686");
  EXPECT_EQ(tp->rows[0].back().text, "5372");
  // Ratios, ours (paper): LOP-2 / LHF-2 = 2 (paper 0.011 / 0.0061 = 1.80).
  const report::Table* ratios = table_of(s, "table5-ratios");
  ASSERT_NE(ratios, nullptr);
  const auto* lop = row_headed_by(*ratios, "LOP-2 / LHF-2");
  ASSERT_NE(lop, nullptr);
  EXPECT_EQ((*lop)[1].text, "2.00 (1.80)");
  EXPECT_DOUBLE_EQ((*lop)[1].value, 2.0);
  // The rows the paper has not, from the CSV in its order, each against the reference of its
  // degree (a degree-free one against LHF-2) or, a bench variant, against its method; the
  // solver rows are not methods.
  const std::vector<std::string> extra(times->columns.begin() + 11, times->columns.end());
  EXPECT_EQ(extra, (std::vector<std::string>{"Meyer", "LHF-2 scalar"}));
  const auto* meyer = row_headed_by(*ratios, "Meyer / LHF-2");
  ASSERT_NE(meyer, nullptr);
  EXPECT_EQ((*meyer)[1].text, "0.50");
  const auto* scalar = row_headed_by(*ratios, "LHF-2 scalar / LHF-2");
  ASSERT_NE(scalar, nullptr);
  EXPECT_EQ((*scalar)[1].text, "3.00");
  // QR against SVD: 6x.
  const report::Table* solvers = table_of(s, "table5-solvers");
  ASSERT_NE(solvers, nullptr);
  EXPECT_EQ(solvers->columns.back(), "LHF-2 SVD (Jacobi) / QR");
  EXPECT_DOUBLE_EQ(solvers->rows[0].back().value, 6.0);
  // Scaling: levels 1 (table5_timing.csv) and 5 (table5_scaling.csv); 745 and 499 ns/vertex.
  const report::Table* scaling = table_of(s, "table5-scaling");
  ASSERT_NE(scaling, nullptr);
  ASSERT_EQ(scaling->rows.size(), 2u);
  EXPECT_EQ(scaling->rows[0][3].text, "745");
  EXPECT_EQ(scaling->rows[0][6].text, "2.00");  // speed-up on 2 threads
  EXPECT_EQ(scaling->rows[1][0].text, "5");
  EXPECT_EQ(scaling->rows[1][4].text, "-");
  EXPECT_NE(md.find("Per-vertex time, 1 thread: max/min = 1.49"), std::string::npos) << md;
  // End to end: the stages and the wall time as m:ss.
  const report::Table* e2e = table_of(s, "table5-end-to-end");
  ASSERT_NE(e2e, nullptr);
  ASSERT_EQ(e2e->rows.size(), 1u);
  EXPECT_EQ(e2e->rows[0][3].text, "0.847");
  EXPECT_EQ(e2e->rows[0][5].text, "0:01.78");
  EXPECT_DOUBLE_EQ(e2e->rows[0][5].value, 1.78);
  EXPECT_EQ(e2e->rows[0][6].value, 267);

  // The limits table: each stage against its bound.
  const report::Table* limits = table_of(s, "limits");
  ASSERT_NE(limits, nullptr);
  ASSERT_EQ(limits->rows.size(), 1u);
  EXPECT_EQ(limits->rows[0][0].text, "orientation");
  EXPECT_DOUBLE_EQ(limits->rows[0][1].value, 0.030);
  EXPECT_DOUBLE_EQ(limits->rows[0][4].value, 2.0);

  // Without the optional files their subtables are left out; without the timings, a sentence.
  fs::remove(dir / "end_to_end.csv");
  EXPECT_EQ(table_of(table5_section(dir.string()), "table5-end-to-end"), nullptr);
  fs::remove(dir / "table5_timing.csv");
  const std::string none = report::to_markdown(table5_section(dir.string()));
  EXPECT_NE(none.find("Not measured yet: run `make bench`."), std::string::npos) << none;
  fs::remove_all(dir);
}

}  // namespace
}  // namespace curvbench
