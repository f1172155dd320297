// Scoring outside estimates (harness/model/score.h, `curvbench score`): the errors of a `curvbench
// estimate` CSV equal the runner's for the same case; the exact values score zero; NaN rows are
// counted as failed and left out; every bad input exits 2 with one line naming row and column.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <functional>
#include <regex>
#include <sstream>
#include <string>
#include <vector>

#include "harness/run/runner.h"
#include "harness/model/score.h"
#include "tests/cli/cli_runner.h"

namespace curvbench {
namespace {

using testing::fresh_dir;
using testing::run_cli;
namespace fs = std::filesystem;

// A CSV with the exact values of the mesh (vertex order reversed, as a reader must not care);
// `edit(v, row)` may change a row's cells before it is written.
void write_exact_csv(const fs::path& p, const ExactMesh& m,
                     const std::function<void(int, std::vector<std::string>&)>& edit = {}) {
  std::ofstream out(p);
  out << "vertex,nx,ny,nz,H,K,k1,k2,d1x,d1y,d1z,comment\n";
  char buf[40];
  auto num = [&](double x) {
    std::snprintf(buf, sizeof buf, "%.17g", x);
    return std::string(buf);
  };
  for (int v = static_cast<int>(m.exact.size()) - 1; v >= 0; --v) {
    const SurfacePoint& s = m.exact[v];
    std::vector<std::string> row = {std::to_string(v), num(s.normal.x()), num(s.normal.y()),
                                    num(s.normal.z()), num(s.H),          num(s.K),
                                    num(s.k1),         num(s.k2),         num(s.d1.x()),
                                    num(s.d1.y()),     num(s.d1.z()),     "free text"};
    if (edit) edit(v, row);
    for (size_t i = 0; i < row.size(); ++i) out << (i ? "," : "") << row[i];
    out << "\n";
  }
}

class Score : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    dir_ = new fs::path(fresh_dir("score"));
    mesh_ = new fs::path(*dir_ / "bump.ply");
    ASSERT_EQ(
        run_cli("mesh --family bump-irregular --level 2 --output " + mesh_->string()).exit_code, 0);
  }
  static void TearDownTestSuite() {
    fs::remove_all(*dir_);
    delete mesh_;
    delete dir_;
  }
  static fs::path* dir_;
  static fs::path* mesh_;
};
fs::path* Score::dir_ = nullptr;
fs::path* Score::mesh_ = nullptr;

TEST_F(Score, EstimateCsvScoresAsTheRunnerScoresTheSameCase) {
  const fs::path est = *dir_ / "lhf2.csv";
  ASSERT_EQ(run_cli("estimate " + mesh_->string() + " --method lhf-2 --threads 1 --output " +
                    est.string())
                .exit_code,
            0);
  const ScoreResult got = score_files(mesh_->string(), est.string(), VertexSet::interior);
  ASSERT_EQ(got.scores.size(), 6u);  // normal, H, K, k1, k2, d1

  // The runner on the same family, level and method, one panel per quantity and norm.
  Experiment e;
  e.name = "score-check";
  e.meshes = {{"bump-irregular", {2}}};
  e.methods = {ExperimentMethod{}};
  e.methods[0].spec = "lhf-2";
  e.vertex_set = VertexSet::interior;
  for (const QuantityScore& s : got.scores)
    for (Norm n : {Norm::L2, Norm::Linf}) e.panels.push_back({"p", "p", s.quantity, n});
  MeshCache cache;
  const auto rows = run_case({&e, &e.meshes[0], 2, &e.methods[0]}, cache, 1);
  ASSERT_EQ(rows.size(), 12u);
  for (size_t i = 0; i < got.scores.size(); ++i) {
    const QuantityScore& s = got.scores[i];
    const ErrorRow& l2 = rows[2 * i];
    const ErrorRow& linf = rows[2 * i + 1];
    ASSERT_EQ(l2.quantity, to_string(s.quantity));
    EXPECT_DOUBLE_EQ(s.l2.value, l2.error) << l2.quantity;
    EXPECT_DOUBLE_EQ(s.linf.value, linf.error) << l2.quantity;
    EXPECT_EQ(s.l2.vertices, l2.counted) << l2.quantity;
    EXPECT_GT(s.l2.value, 1e-4) << l2.quantity;  // a real, non-zero error
  }
  EXPECT_EQ(got.vertices_in_set, rows[0].counted);
}

TEST_F(Score, ExactValuesScoreZeroAndNanRowsCountAsFailed) {
  const ExactMesh m = read_exact_mesh(mesh_->string());
  ASSERT_TRUE(m.has_directions);
  const int n = m.mesh.num_vertices();
  const fs::path exact = *dir_ / "exact.csv";
  write_exact_csv(exact, m);
  const ScoreResult zero = score_files(mesh_->string(), exact.string(), VertexSet::all);
  ASSERT_EQ(zero.scores.size(), 6u);
  for (const QuantityScore& s : zero.scores) {
    EXPECT_EQ(s.l2.value, 0.0) << to_string(s.quantity);
    EXPECT_EQ(s.linf.value, 0.0) << to_string(s.quantity);
    EXPECT_EQ(s.l2.excluded, 0);
  }

  // Vertex 7: H is NaN; vertex 8: H off by 1 (relative L2 of that one error). The NaN row is
  // counted as failed and left out of the sums; a NaN averaged in would make the error NaN.
  const fs::path mixed = *dir_ / "mixed.csv";
  write_exact_csv(mixed, m, [&](int v, std::vector<std::string>& row) {
    if (v == 7) row[4] = "nan";
    if (v == 8) row[4] = std::to_string(m.exact[8].H + 1.0);
  });
  const ScoreResult r = score_files(mesh_->string(), mixed.string(), VertexSet::all);
  const QuantityScore& h = r.scores[1];
  ASSERT_EQ(h.quantity, Quantity::H);
  EXPECT_EQ(h.l2.excluded, 1);
  EXPECT_EQ(h.l2.vertices, n - 1);
  double den = 0.0;
  for (int v = 0; v < n; ++v)
    if (v != 7) den += m.exact[v].H * m.exact[v].H;
  EXPECT_NEAR(h.l2.value, 1.0 / std::sqrt(den), 1e-6 / std::sqrt(den));
  EXPECT_EQ(r.scores[0].l2.excluded, 0);  // the other quantities of vertex 7 still count
  EXPECT_EQ(r.scores[0].l2.value, 0.0);
}

TEST_F(Score, SubsetOfColumnsScoresOnlyThoseQuantities) {
  const fs::path p = *dir_ / "only_k.csv";
  {
    const ExactMesh m = read_exact_mesh(mesh_->string());
    std::ofstream out(p);
    out.precision(17);
    out << "K,vertex\n";
    for (int v = 0; v < m.mesh.num_vertices(); ++v) out << 2 * m.exact[v].K << "," << v << "\n";
  }
  const auto r = run_cli("score " + mesh_->string() + " --estimates " + p.string() + " --json");
  ASSERT_EQ(r.exit_code, 0) << r.output;
  EXPECT_NE(r.output.find("\"quantity\": \"K\", \"L2\": 1, \"Linf\": 1,"), std::string::npos)
      << r.output;
  EXPECT_EQ(r.output.find("\"normal\""), std::string::npos) << r.output;
  const auto text = run_cli("score " + mesh_->string() + " --estimates " + p.string() +
                            " --vertex-set boundary-ring");
  ASSERT_EQ(text.exit_code, 0) << text.output;
  EXPECT_TRUE(
      std::regex_search(text.output, std::regex(R"(vertex set boundary-ring: \d+ vertices)")))
      << text.output;
}

// Each bad file: exit 2 and one line with the expected words.
TEST_F(Score, BadInputsExitTwoNamingRowAndColumn) {
  const ExactMesh m = read_exact_mesh(mesh_->string());
  const int n = m.mesh.num_vertices();
  struct Case {
    const char* name;
    std::function<void(int, std::vector<std::string>&)> edit;
    std::string header;  // replaces the header when non-empty
    int drop_rows = 0;
    std::string expected;
  };
  const std::vector<Case> cases = {
      {"count", {}, "", 1, std::to_string(n - 1) + " rows for a mesh of " + std::to_string(n)},
      {"novertex", {}, "id,nx,ny,nz,H,K,k1,k2,d1x,d1y,d1z,comment", 0, "no 'vertex' column"},
      {"duplicate",
       [](int v, std::vector<std::string>& row) {
         if (v == 5) row[0] = "6";
       },
       "", 0, "row " + std::to_string(n - 5) + ", column 'vertex': vertex 6 appears twice"},
      {"range",
       [n](int v, std::vector<std::string>& row) {
         if (v == 0) row[0] = std::to_string(n);
       },
       "", 0, "column 'vertex': vertex " + std::to_string(n) + " out of range"},
      {"negative",
       [](int v, std::vector<std::string>& row) {
         if (v == 0) row[0] = "-1";
       },
       "", 0, "column 'vertex': vertex -1 out of range"},
      {"cell",
       [](int v, std::vector<std::string>& row) {
         if (v == 3) row[5] = "1.2.3";
       },
       "", 0, "row " + std::to_string(n - 3) + ", column 'K': '1.2.3' is not a number"},
      {"empty",
       [](int v, std::vector<std::string>& row) {
         if (v == 3) row[2] = "";
       },
       "", 0, "column 'ny': '' is not a number"},
      {"id",
       [](int v, std::vector<std::string>& row) {
         if (v == 2) row[0] = "2.5";
       },
       "", 0, "column 'vertex': '2.5' is not an integer"},
      {"triple",
       {},
       "vertex,nx,ny,nzz,H,K,k1,k2,d1x,d1y,d1z,comment",
       0,
       "columns nx,ny,nz must be given together"},
      {"nothing", {}, "vertex,a,b,c,d,e,f,g,h,i,j,comment", 0, "no estimate column"},
  };
  for (const Case& c : cases) {
    const fs::path p = *dir_ / (std::string(c.name) + ".csv");
    write_exact_csv(p, m, c.edit);
    if (!c.header.empty() || c.drop_rows > 0) {
      std::ifstream in(p);
      std::stringstream ss;
      ss << in.rdbuf();
      std::string text = ss.str();
      if (!c.header.empty()) text = c.header + text.substr(text.find('\n'));
      for (int k = 0; k < c.drop_rows; ++k) text.erase(text.rfind('\n', text.size() - 2) + 1);
      std::ofstream(p) << text;
    }
    const auto r = run_cli("score " + mesh_->string() + " --estimates " + p.string());
    EXPECT_EQ(r.exit_code, 2) << c.name << ": " << r.output;
    EXPECT_NE(r.output.find(c.expected), std::string::npos) << c.name << ": " << r.output;
    EXPECT_EQ(std::count(r.output.begin(), r.output.end(), '\n'), 1) << c.name << ": " << r.output;
  }
  // The row's file line is named too (header is line 1, row k is line k + 1).
  const auto r =
      run_cli("score " + mesh_->string() + " --estimates " + (*dir_ / "cell.csv").string());
  EXPECT_NE(r.output.find("cell.csv:" + std::to_string(n - 3 + 1) + ": row"), std::string::npos)
      << r.output;

  // A mesh without exact quantities, and a missing estimate file.
  const fs::path off = *dir_ / "plain.off";
  ASSERT_EQ(run_cli("mesh --family bump-irregular --level 1 --output " + off.string()).exit_code,
            0);
  auto bad = run_cli("score " + off.string() + " --estimates " + (*dir_ / "exact.csv").string());
  EXPECT_EQ(bad.exit_code, 2) << bad.output;
  EXPECT_NE(bad.output.find("written by `curvbench mesh`"), std::string::npos) << bad.output;
  bad = run_cli("score " + mesh_->string() + " --estimates " + (*dir_ / "missing.csv").string());
  EXPECT_EQ(bad.exit_code, 2) << bad.output;
  bad = run_cli("score " + mesh_->string() + " --estimates " + (*dir_ / "cell.csv").string() +
                " --vertex-set middle");
  EXPECT_EQ(bad.exit_code, 2) << bad.output;
}

}  // namespace
}  // namespace curvbench
