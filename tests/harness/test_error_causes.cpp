// Errors by cause (error_causes.h): the valence, smallest-angle and sign-of-K bins of hand-made
// fans; each bin's error is the relative L2 error in H summed directly over its vertices; only
// the finest level of a mesh gets them; the CSV's columns and round trip; the case store keeps
// them; the REPORT.md table.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <numbers>
#include <string>
#include <variant>
#include <vector>

#include "harness/run/case_store.h"
#include "harness/model/error_causes.h"
#include "harness/report/causes.h"
#include "harness/report/model.h"
#include "harness/run/runner.h"
#include "mesh/io.h"
#include "mesh/mesh_checks.h"
#include "methods/estimator.h"
#include "tests/cli/cli_runner.h"
#include "tests/methods/small_mesh_util.h"

namespace curvbench {
namespace {

namespace fs = std::filesystem;

// A closed fan in the plane z = 0: vertex 0 at the origin, vertex i (1..n) on the unit circle at
// angles_deg[i - 1], triangles (0, i, i + 1) and (0, n, 1).
Mesh fan(const std::vector<double>& angles_deg) {
  std::vector<Vec3> P{Vec3::Zero()};
  for (double a : angles_deg) {
    const double t = a * std::numbers::pi / 180.0;
    P.emplace_back(std::cos(t), std::sin(t), 0.0);
  }
  std::vector<std::array<int, 3>> T;
  const int n = static_cast<int>(angles_deg.size());
  for (int i = 1; i <= n; ++i) T.push_back({0, i, i % n + 1});
  return testing::mesh_of(P, T, "fan");
}

// The bins as "cause/bin" -> vertices.
std::map<std::string, std::vector<int>> bins_of(const Mesh& mesh,
                                                const std::vector<SurfacePoint>& exact,
                                                const std::vector<int>& vertices) {
  const auto bins = cause_bin_vertices(vertex_causes(mesh, exact), exact, vertices);
  EXPECT_EQ(bins.size(), cause_bins().size());
  std::map<std::string, std::vector<int>> out;
  for (size_t b = 0; b < bins.size(); ++b)
    out[std::string(cause_bins()[b].cause) + "/" + cause_bins()[b].bin] = bins[b];
  return out;
}

std::vector<int> iota(int n) {
  std::vector<int> v(static_cast<size_t>(n));
  for (int i = 0; i < n; ++i) v[static_cast<size_t>(i)] = i;
  return v;
}

TEST(ErrorCauses, BinsOfAHandMadeFan) {
  // Apex angles 5, 25, 100, 70, 80, 80 degrees; each triangle's base angles (180 - apex) / 2.
  // Smallest angle around each vertex: centre 5, rim 5, 5, 25, 40, 50, 50.
  const Mesh m = fan({0, 5, 30, 130, 200, 280});
  const std::vector<double> angle = min_incident_angles(m);
  const double want[] = {5, 5, 5, 25, 40, 50, 50};
  ASSERT_EQ(angle.size(), 7u);
  for (size_t v = 0; v < 7; ++v) EXPECT_NEAR(angle[v], want[v], 1e-9) << v;

  // Exact K: the largest |K| is 2, so |K| <= 0.02 is "K~0" (the bound included).
  std::vector<SurfacePoint> exact(7);
  const double K[] = {2.0, -1.0, 0.005, -0.02, 0.0, 1.0, -2.0};
  for (size_t v = 0; v < 7; ++v) exact[v].K = K[v];

  auto b = bins_of(m, exact, iota(7));
  EXPECT_EQ(b["all/all"], iota(7));
  EXPECT_EQ(b["valence/<=4"], (std::vector<int>{1, 2, 3, 4, 5, 6}));  // the rim: valence 3
  EXPECT_EQ(b["valence/6"], std::vector<int>{0});
  EXPECT_TRUE(b["valence/5"].empty() && b["valence/7"].empty() && b["valence/>=8"].empty());
  EXPECT_EQ(b["min-angle/<10"], (std::vector<int>{0, 1, 2}));
  EXPECT_TRUE(b["min-angle/10-20"].empty());
  EXPECT_EQ(b["min-angle/20-30"], std::vector<int>{3});
  EXPECT_EQ(b["min-angle/30-45"], std::vector<int>{4});
  EXPECT_EQ(b["min-angle/>=45"], (std::vector<int>{5, 6}));
  EXPECT_EQ(b["K-sign/K>0"], (std::vector<int>{0, 5}));
  EXPECT_EQ(b["K-sign/K<0"], (std::vector<int>{1, 6}));
  EXPECT_EQ(b["K-sign/K~0"], (std::vector<int>{2, 3, 4}));

  // Only the given vertices are binned.
  b = bins_of(m, exact, {0, 3, 5});
  EXPECT_EQ(b["all/all"], (std::vector<int>{0, 3, 5}));
  EXPECT_EQ(b["valence/<=4"], (std::vector<int>{3, 5}));
  EXPECT_EQ(b["min-angle/<10"], std::vector<int>{0});
  EXPECT_EQ(b["K-sign/K~0"], std::vector<int>{3});

  // Centre valences 5, 7, 8 and 9 (regular fans: apex 360/n, smallest angle min(360/n, base);
  // n = 8 sits on the 45-degree edge and is left out of the angle check).
  const std::vector<int> n_of = {5, 7, 8, 9};
  const char* bin_of[] = {"valence/5", "valence/7", "valence/>=8", "valence/>=8"};
  const char* angle_bin_of[] = {">=45", ">=45", nullptr, "30-45"};
  for (size_t i = 0; i < n_of.size(); ++i) {
    std::vector<double> a;
    for (int k = 0; k < n_of[i]; ++k) a.push_back(360.0 * k / n_of[i]);
    const Mesh r = fan(a);
    const auto rb = bins_of(r, std::vector<SurfacePoint>(a.size() + 1), iota(r.num_vertices()));
    EXPECT_EQ(rb.at(bin_of[i]), std::vector<int>{0}) << n_of[i];
    if (angle_bin_of[i] != nullptr) {
      EXPECT_EQ(rb.at(std::string("min-angle/") + angle_bin_of[i]).size(), a.size() + 1) << n_of[i];
    }
    // K = 0 everywhere: every vertex is "K~0".
    EXPECT_EQ(rb.at("K-sign/K~0").size(), a.size() + 1);
  }

  // The cube with square centres: centres valence 4, corners 6.
  std::vector<bool> centre;
  const Mesh cube = testing::cube_with_square_centres(1, &centre);
  const auto cb = bins_of(cube, std::vector<SurfacePoint>(centre.size()), iota(14));
  EXPECT_EQ(cb.at("valence/<=4").size(), 6u);
  for (int v : cb.at("valence/<=4")) EXPECT_TRUE(centre[static_cast<size_t>(v)]) << v;
  EXPECT_EQ(cb.at("valence/6").size(), 8u);
}

// A small experiment: torus-unstructured levels 1-2, LHF-2 and Meyer, H and normals in L2.
Experiment causes_experiment() {
  Experiment e;
  e.name = "causes";
  e.title = "Causes test";
  e.section = "beyond";
  e.meshes = {{"torus-unstructured", {1, 2}}};
  ExperimentMethod lhf, meyer;
  lhf.spec = "lhf-2";
  meyer.spec = "meyer";
  e.methods = {lhf, meyer};
  e.panels = {{"c-h", "H.", Quantity::H, Norm::L2},
              {"c-n", "Normals.", Quantity::normal, Norm::L2}};
  return e;
}

TEST(ErrorCauses, EachBinIsTheErrorSummedDirectlyOverItsVerticesAtTheFinestLevelOnly) {
  const Experiment e = causes_experiment();
  MeshCache cache;
  std::vector<CauseRow> causes{CauseRow{}};
  run_case({&e, &e.meshes[0], 1, &e.methods[0]}, cache, 1, &causes);
  EXPECT_TRUE(causes.empty());  // level 1 is not the finest
  const std::vector<ErrorRow> rows =
      run_case({&e, &e.meshes[0], 2, &e.methods[0]}, cache, 1, &causes);
  ASSERT_EQ(causes.size(), cause_bins().size());

  const ScoredMesh& sm = cache.get("torus-unstructured", 2, 0, e.noise_seed);
  const Mesh& mesh = sm.generated.mesh;
  const auto est = estimate_mesh(mesh, *make_estimator("lhf-2", {}));
  const std::vector<int> valence = vertex_valences(mesh);
  const std::vector<double> angle = min_incident_angles(mesh);
  double kmax = 0.0;
  for (const auto& p : sm.exact) kmax = std::max(kmax, std::abs(p.K));
  // Each bin's predicate, written out.
  const auto in_bin = [&](const std::string& cause, const std::string& bin, int v) {
    const int val = valence[static_cast<size_t>(v)];
    const double a = angle[static_cast<size_t>(v)], K = sm.exact[static_cast<size_t>(v)].K;
    if (cause == "all") return true;
    if (cause == "valence")
      return bin == "<=4" ? val <= 4 : bin == ">=8" ? val >= 8 : val == std::stoi(bin);
    if (cause == "min-angle") {
      if (bin == "<10") return a < 10;
      if (bin == ">=45") return a >= 45;
      const auto dash = bin.find('-');
      return a >= std::stod(bin.substr(0, dash)) && a < std::stod(bin.substr(dash + 1));
    }
    if (bin == "K~0") return std::abs(K) <= kTinyGaussian * kmax;
    return std::abs(K) > kTinyGaussian * kmax && (bin == "K>0" ? K > 0 : K < 0);
  };
  std::map<std::string, int> per_cause;
  int nonempty = 0;
  for (const CauseRow& r : causes) {
    double num = 0, den = 0;
    int n = 0;
    for (int v = 0; v < mesh.num_vertices(); ++v)
      if (in_bin(r.cause, r.bin, v)) {
        const double err = est[static_cast<size_t>(v)].H - sm.exact[static_cast<size_t>(v)].H;
        num += err * err;
        den += sm.exact[static_cast<size_t>(v)].H * sm.exact[static_cast<size_t>(v)].H;
        ++n;
      }
    EXPECT_EQ(r.counted + r.excluded, n) << r.cause << " " << r.bin;
    per_cause[r.cause] += n;
    if (n == 0) {
      EXPECT_TRUE(std::isnan(r.error)) << r.bin;
      continue;
    }
    ++nonempty;
    EXPECT_NEAR(r.error, std::sqrt(num / den), 1e-12 * std::sqrt(num / den)) << r.bin;
    EXPECT_EQ(r.family, "torus-unstructured");
    EXPECT_EQ(r.level, 2);
    EXPECT_EQ(r.method, "LHF-2");
    EXPECT_EQ(r.quantity, "H");
    EXPECT_EQ(r.norm, "L2");
  }
  EXPECT_GE(nonempty, 8);
  // Each cause splits the vertex set; the "all" bin is the case's own error row.
  for (const char* c : {"all", "valence", "min-angle", "K-sign"})
    EXPECT_EQ(per_cause[c], mesh.num_vertices()) << c;
  ASSERT_EQ(rows.front().quantity, "H");
  EXPECT_EQ(causes.front().error, rows.front().error);
}

// A cell of the REPORT.md table: the error with three significant digits.
std::string cause_tables_cell(double e) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.2e", e);
  return buf;
}

TEST(ErrorCauses, CsvColumnsRoundTripAndTheCaseStoreKeepsThem) {
  const auto dir = testing::fresh_dir("error_causes_csv");
  const Experiment e = causes_experiment();
  const RunCase c{&e, &e.meshes[0], 2, &e.methods[1]};
  MeshCache cache;
  std::vector<CauseRow> causes;
  const auto rows = run_case(c, cache, 1, &causes);
  ASSERT_EQ(causes.size(), cause_bins().size());
  EXPECT_EQ(causes.front().method, "Meyer");
  const int all_count = causes.front().counted + causes.front().excluded;

  const std::string path = (dir / "errors_by_cause" / "causes.csv").string();
  write_cause_csv(path, causes);
  // For the REPORT.md table below: the same rows as a method scored over the interior.
  std::vector<CauseRow> with_interior = causes;
  for (CauseRow r : causes) {
    r.method = "Inner";
    r.vertex_set = "interior";
    r.error *= 2.0;
    with_interior.push_back(r);
  }
  const std::string report_dir = (dir / "report").string();
  write_cause_csv(report_dir + "/errors_by_cause/causes.csv", with_interior);
  const std::string text = read_file(path);
  EXPECT_EQ(text.rfind("# curvbench", 0), 0u) << text;  // the provenance line
  const std::string header =
      text.substr(text.find('\n') + 1, text.find('\n', text.find('\n') + 1) - text.find('\n') - 1);
  EXPECT_EQ(header,
            "experiment,surface,family,level,vertices,h,method,degree,noise,vertex_set,quantity,"
            "norm,cause,bin,error,counted,excluded");
  const auto back = read_cause_csv(path);
  EXPECT_EQ(cause_csv_text(back, "#"), cause_csv_text(causes, "#"));  // doubles bit for bit

  // The case store: saved with the case's rows, back with them.
  const CaseStore store((dir / "store").string(), "version-1");
  store.save(c, rows, causes);
  std::vector<CauseRow> loaded;
  const auto again = store.load(c, &loaded);
  ASSERT_TRUE(again.has_value());
  EXPECT_EQ(error_csv_text(*again, "#"), error_csv_text(rows, "#"));
  EXPECT_EQ(cause_csv_text(loaded, "#"), cause_csv_text(causes, "#"));
  // A case at a coarser level has none, and its file no "errors by cause" part.
  const RunCase coarse{&e, &e.meshes[0], 1, &e.methods[1]};
  const auto coarse_rows = run_case(coarse, cache, 1, &causes);
  EXPECT_TRUE(causes.empty());
  store.save(coarse, coarse_rows, causes);
  EXPECT_EQ(read_file(store.path(coarse)).find("# errors by cause"), std::string::npos);
  loaded = {CauseRow{}};
  ASSERT_TRUE(store.load(coarse, &loaded).has_value());
  EXPECT_TRUE(loaded.empty());
  // Whether a case keeps its causes is one of its inputs.
  EXPECT_NE(case_inputs(c).find(";causes=H/L2"), std::string::npos);
  EXPECT_EQ(case_inputs(coarse).find(";causes="), std::string::npos);

  // The REPORT.md table: the bins as columns, the counts, one row per method.
  report::Section section;
  cause_tables(e, report_dir, section);
  const std::string md = report::to_markdown(section);
  EXPECT_NE(md.find("### Errors by cause at the finest level"), std::string::npos) << md;
  EXPECT_NE(md.find("**`torus-unstructured`**, level 2"), std::string::npos) << md;
  EXPECT_NE(md.find("| method | all | val <=4 | val 5 | val 6 | val 7 | val >=8 | <10° |"),
            std::string::npos)
      << md;
  EXPECT_NE(md.find("| *vertices (all)* | " + std::to_string(all_count) + " |"), std::string::npos)
      << md;
  EXPECT_NE(md.find("| Meyer | " + cause_tables_cell(causes.front().error) + " |"),
            std::string::npos)
      << md;
  // A method scored over another vertex set (a tie goes to the first seen) names it.
  EXPECT_NE(md.find("| Inner (interior) | " + cause_tables_cell(2.0 * causes.front().error) + " |"),
            std::string::npos)
      << md;
  // The cells carry the numbers: the count of all vertices, Meyer's error over them.
  const auto* tab = std::get_if<report::Table>(&section.blocks.back());
  ASSERT_NE(tab, nullptr);
  EXPECT_EQ(tab->rows[0][1].value, all_count);
  EXPECT_EQ(tab->rows[1][0].text, "Meyer");
  EXPECT_EQ(tab->rows[1][1].value, causes.front().error);
  Experiment other = e;
  other.name = "missing";
  report::Section none;
  cause_tables(other, dir.string(), none);
  EXPECT_TRUE(none.blocks.empty());
}

}  // namespace
}  // namespace curvbench
