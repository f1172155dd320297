// The advice from mesh features and its cross-validation (harness/report/advice.h) on synthetic
// cases whose answers are known, and `recommend`'s per-quantity advice and coverage lines
// (harness/report/recommend_table.h) on generated meshes.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <string>
#include <vector>

#include <unistd.h>

#include "core/errors.h"
#include "harness/model/experiment.h"
#include "harness/report/advice.h"
#include "harness/report/recommend_table.h"
#include "mesh/io.h"
#include "meshgen/generate.h"

namespace curvbench {
namespace {

namespace fs = std::filesystem;

// A mesh whose features differ only in anisotropy (the other features 0, density 1).
MeshFeatures stretched(double anisotropy, double size_over_h = 10.0) {
  MeshFeatures f;
  f.anisotropy = anisotropy;
  f.size_over_h = size_over_h;
  return f;
}

void add(std::vector<AdviceCase>& cases, const std::string& family, const MeshFeatures& f,
         double sigma, const std::string& quantity, const std::string& label, double error) {
  AdviceCase c;
  c.experiment = "sweep";
  c.family = family;
  c.level = 2;
  c.vertices = 1000;
  c.h = 0.1;
  c.features = f;
  c.sigma_over_h = sigma;
  c.quantity = quantity;
  c.label = label;
  c.error = error;
  cases.push_back(c);
}

// Four meshes at anisotropy 1, 1.1, 4, 4.4: on the two near 1, "LHF-2 rings=1" is best and
// "ICC ball-factor=2" 3x worse; on the two near 4 the reverse.
std::vector<AdviceCase> two_clusters(const std::string& quantity = "H") {
  std::vector<AdviceCase> cases;
  const struct {
    const char* family;
    double anisotropy;
    bool fit_best;
  } meshes[] = {{"a", 1.0, true}, {"b", 1.1, true}, {"c", 4.0, false}, {"d", 4.4, false}};
  for (const auto& m : meshes) {
    add(cases, m.family, stretched(m.anisotropy), 0.0, quantity, "LHF-2 rings=1",
        m.fit_best ? 0.01 : 0.03);
    add(cases, m.family, stretched(m.anisotropy), 0.0, quantity, "ICC ball-factor=2",
        m.fit_best ? 0.03 : 0.01);
  }
  return cases;
}

TEST(Advice, NearestMeshesInFeatureSpace) {
  const std::vector<AdviceCase> cases = two_clusters();
  AdvicePick p = pick_advice(cases, stretched(1.05), 0.0, "H");
  ASSERT_TRUE(p.found);
  ASSERT_EQ(p.neighbours.size(), static_cast<size_t>(kAdviceNeighbours));
  // a and b are equally near (log 1.05 between log 1 and log 1.1 is nearer b: 0.0465 vs 0.0488).
  EXPECT_EQ(p.neighbours[0].family, "b");
  EXPECT_EQ(p.neighbours[1].family, "a");
  EXPECT_EQ(p.neighbours[2].family, "c");
  EXPECT_LT(p.neighbours[1].distance, p.neighbours[2].distance);
  // Two of three neighbours favour the fit: mean log regret log(3)/3 against 2 log(3)/3.
  EXPECT_EQ(p.label, "LHF-2 rings=1");
  EXPECT_NEAR(p.mean_log_regret, std::log(3.0) / 3.0, 1e-12);
  EXPECT_EQ(pick_advice(cases, stretched(4.2), 0.0, "H").label, "ICC ball-factor=2");
  // Leaving out family b: a, c, d are the neighbours, and the ball wins 2 to 1.
  p = pick_advice(cases, stretched(1.05), 0.0, "H", "b");
  EXPECT_EQ(p.neighbours[0].family, "a");
  EXPECT_EQ(p.label, "ICC ball-factor=2");
  // No case of the quantity: nothing found.
  EXPECT_FALSE(pick_advice(cases, stretched(1.0), 0.0, "normal").found);
}

// The normals' and the curvature's advice come from their own rows and may differ.
TEST(Advice, PerQuantityChoicesDiffer) {
  std::vector<AdviceCase> cases = two_clusters("H");
  for (AdviceCase c : two_clusters("normal")) {
    // For normals the ball is best everywhere.
    c.error = c.label == "ICC ball-factor=2" ? 0.001 : 0.002;
    cases.push_back(c);
  }
  const AdvicePick h = pick_advice(cases, stretched(1.0), 0.0, "H");
  const AdvicePick n = pick_advice(cases, stretched(1.0), 0.0, "normal");
  EXPECT_EQ(h.label, "LHF-2 rings=1");
  EXPECT_EQ(n.label, "ICC ball-factor=2");
}

// Noise levels 0, 0.001, 0.003, 0.01 on one swept mesh of size 10 h. Normals read sigma/h: 0.0004
// is below the floor (level 0), 0.004 reads 0.003, not none. The curvature reads sigma size /
// h^2: a mesh 4 times the size at sigma/h 0.001 has the curvature noise of 0.004 here, level
// 0.003.
TEST(Advice, NoiseLevelInTheQuantitysUnit) {
  std::vector<AdviceCase> cases;
  for (const std::string q : {"normal", "H"})
    for (double s : {0.0, 0.001, 0.003, 0.01}) add(cases, "a", stretched(1.0), s, q, "Meyer", 1.0);
  const auto level = [&](double sigma, const std::string& q, double size) {
    return pick_advice(cases, stretched(1.0, size), sigma, q).neighbours.at(0).sigma_over_h;
  };
  EXPECT_EQ(level(0.0, "normal", 10), 0.0);
  EXPECT_EQ(level(0.0004, "normal", 10), 0.0);
  EXPECT_EQ(level(0.004, "normal", 10), 0.003);
  EXPECT_EQ(level(0.001, "normal", 40), 0.001);
  EXPECT_EQ(level(0.001, "H", 10), 0.001);
  EXPECT_EQ(level(0.001, "H", 40), 0.003);
  EXPECT_EQ(level(0.0, "H", 40), 0.0);
}

// Leave one family out on the two clusters: a held out learns from b, c, d (two favour the
// ball): the ball, 3x its best; likewise b; c and d learn from a, b and the other of c, d: the
// fit, 3x. Every regret is 3: median 3, worst 3, none within 2x.
TEST(Advice, CrossValidationRegretOnKnownRows) {
  const std::vector<CrossValidationRow> rows = cross_validate(two_clusters());
  ASSERT_EQ(rows.size(), 4u);
  for (const CrossValidationRow& r : rows) {
    EXPECT_NEAR(r.regret, 3.0, 1e-12) << r.family;
    EXPECT_EQ(r.advised,
              r.family == "a" || r.family == "b" ? "ICC ball-factor=2" : "LHF-2 rings=1");
    EXPECT_EQ(r.best, r.family == "a" || r.family == "b" ? "LHF-2 rings=1" : "ICC ball-factor=2");
  }
  const RegretSummary s = summarize_regret(rows, "H");
  EXPECT_EQ(s.cases, 4);
  EXPECT_NEAR(s.median, 3.0, 1e-12);
  EXPECT_NEAR(s.worst, 3.0, 1e-12);
  EXPECT_EQ(s.within_goal, 0.0);
  EXPECT_FALSE(s.meets_goal());
  // With a fifth mesh near a, b, the held-out a, b learn from two fits and win.
  std::vector<AdviceCase> cases = two_clusters();
  add(cases, "e", stretched(1.2), 0.0, "H", "LHF-2 rings=1", 0.02);
  add(cases, "e", stretched(1.2), 0.0, "H", "ICC ball-factor=2", 0.05);
  const std::vector<CrossValidationRow> more = cross_validate(cases);
  const RegretSummary m = summarize_regret(more, "H");
  EXPECT_EQ(m.cases, 5);
  EXPECT_NEAR(summarize_regret(more, "H", 0.0, "a").worst, 1.0, 1e-12);
  EXPECT_NEAR(m.within_goal, 3.0 / 5.0, 1e-12);  // a, b, e at 1; c, d at 3
  EXPECT_NEAR(m.median, 1.0, 1e-12);
}

TEST(Advice, CsvRoundTrips) {
  const fs::path dir = fs::temp_directory_path() / ("cb_advice_" + std::to_string(::getpid()));
  fs::create_directories(dir);
  std::vector<AdviceCase> cases = two_clusters();
  cases[0].features.small_angle_share = 0.125;
  write_advice_cases_csv((dir / "advice_cases.csv").string(), cases);
  const AdviceTable t = read_advice_cases_csv(dir.string());
  ASSERT_EQ(t.cases.size(), cases.size());
  EXPECT_EQ(t.cases[0].features.small_angle_share, 0.125);
  EXPECT_EQ(t.cases[2].features.anisotropy, 1.1);
  EXPECT_EQ(t.cases[5].error, cases[5].error);
  EXPECT_FALSE(t.provenance.empty());
  const std::vector<CrossValidationRow> rows = cross_validate(cases);
  write_cross_validation_csv((dir / "cv.csv").string(), rows);
  const std::vector<CrossValidationRow> back = read_cross_validation_csv((dir / "cv.csv").string());
  ASSERT_EQ(back.size(), rows.size());
  EXPECT_EQ(back[2].regret, rows[2].regret);
  EXPECT_EQ(back[2].neighbours, rows[2].neighbours);
  EXPECT_THROW((void)parse_advice_cases_csv("experiment,family\n", "x.csv"), InputError);
  fs::remove_all(dir);
}

// A mesh outside the swept meshes' range is named by the feature out of range: here
// bump-density with D = 32 (density ratio 8.6) against cases whose densest mesh reads 1 or 2.
TEST(Advice, OutOfRangeFeatureIsNamed) {
  std::vector<AdviceCase> cases = two_clusters();
  cases[0].features.density_ratio = 2.0;
  MeshSpec spec;
  spec.family = "bump-density";
  spec.level = 1;
  spec.shape.density = 32.0;
  const MeshFeatures f = measure_mesh_features(generate_mesh(spec).mesh);
  const std::vector<FeatureOutOfRange> out = features_out_of_range(cases, f);
  bool density = false;
  for (const FeatureOutOfRange& o : out) {
    density = density || o.name == std::string("density_ratio");
    EXPECT_TRUE(o.value < o.lowest || o.value > o.highest) << o.name;
  }
  EXPECT_TRUE(density);
  EXPECT_TRUE(features_out_of_range(cases, stretched(1.05)).empty());
}

// `recommend` on a table with advice cases: per-quantity lines, the cross-validated range, and
// the coverage line naming the feature out of range.
TEST(Advice, RecommendTextSaysHowSureAndWhatIsOutOfRange) {
  std::vector<AdviceCase> cases = two_clusters("H");
  for (AdviceCase c : two_clusters("normal")) {
    c.error = c.label == "ICC ball-factor=2" ? 0.001 : 0.002;
    cases.push_back(c);
  }
  AdviceTable table{"cases.csv", "", cases};
  const RecommendationTable recs = default_recommendations();
  MeshSpec spec;
  spec.family = "torus-anisotropic";
  spec.level = 1;
  spec.shape.aspect = 16.0;  // anisotropy about 16, above the cases' 4.4
  const Advice a = advise(generate_mesh(spec).mesh, 0.0, recs, &table);
  ASSERT_TRUE(a.has_feature_advice);
  ASSERT_EQ(a.quantities.size(), 2u);
  EXPECT_EQ(a.quantities[1].pick.label, "ICC ball-factor=2");  // nearest c, d
  EXPECT_EQ(a.quantities[0].pick.label, "ICC ball-factor=2");
  EXPECT_FALSE(a.choices_differ());
  EXPECT_EQ(a.label, "ICC ball-factor=2");
  EXPECT_EQ(a.choice.method, "icc");
  // The cross-validation on the neighbours c, d, b: c and d at regret 3 (see above), b at 3.
  EXPECT_NEAR(a.quantities[1].validated.worst, 3.0, 1e-12);
  const std::string text = advice_text(a, "m.off", "");
  // The synthetic cases have no small or obtuse angles either: those are out of range too.
  const size_t coverage = text.find("coverage:   OUTSIDE what the sweeps cover: ");
  ASSERT_NE(coverage, std::string::npos) << text;
  const std::string line = text.substr(coverage, text.find('\n', coverage) - coverage);
  EXPECT_NE(line.find("; anisotropy 1"), std::string::npos) << line;
  EXPECT_NE(line.find("(swept meshes 1 to 4.4)"), std::string::npos) << line;
  EXPECT_NE(text.find("cross-validated"), std::string::npos) << text;
  EXPECT_NE(text.find("normals:    ICC"), std::string::npos) << text;
  EXPECT_NE(text.find("curvatures: ICC"), std::string::npos) << text;
  const std::string json = advice_json(a, "m.off", "");
  EXPECT_NE(json.find("{\"feature\": \"anisotropy\""), std::string::npos) << json;
}

// The trimmed radius sweep `make experiments` runs is what the advice learns from and is
// cross-validated on: it sweeps the families that stand for anisotropic, graded-density and
// lantern-like meshes besides the three classes', each at the light noise levels too.
TEST(Advice, TrimmedSweepCoversTheFamiliesAndLightNoise) {
  const Experiment e =
      parse_experiment(std::string(CURVBENCH_SOURCE_DIR) + "/experiments/sweep-radius.exp");
  for (const char* family :
       {"torus-unstructured", "torus-iso-projected", "bump-irregular", "torus-anisotropic",
        "bump-anisotropic", "bump-density", "lantern", "lantern-squeezed", "ellipsoid"})
    for (double sigma : {0.001, 0.003, 0.01, 0.1}) {
      bool found = false;
      for (const ExperimentMesh& m : e.meshes)
        found = found || (m.family == family && m.has_noise_model &&
                          std::fabs(m.noise_model.scale - sigma) < 1e-12);
      EXPECT_TRUE(found) << family << " at sigma/h " << sigma;
    }
}

}  // namespace
}  // namespace curvbench
