// The advice measured on the mesh (harness/model/measured_advice.h): its noise part is the
// linear response to the mesh's noise, its bias part is within the reference's own error of the
// true bias, it is deterministic, and it refuses what it cannot measure.
#include <gtest/gtest.h>

#include <unistd.h>

#include <cmath>
#include <filesystem>
#include <variant>
#include <vector>

#include "core/errors.h"
#include "harness/model/measured_advice.h"
#include "harness/report/advice.h"
#include "mesh/mesh.h"
#include "meshgen/generate.h"
#include "methods/estimator.h"
#include "tests/mesh/crease_test_meshes.h"

namespace curvbench {
namespace {

std::vector<EstimatorChoice> measured_candidates(const std::vector<std::string>& labels) {
  std::vector<EstimatorChoice> out;
  for (const std::string& l : labels) out.push_back(estimator_choice(l));
  return out;
}

GeneratedMesh measured_torus(double sigma_over_h, int level = 1) {
  MeshSpec spec;
  spec.family = "torus-unstructured";
  spec.level = level;
  if (sigma_over_h > 0.0) {
    spec.noise_order = 1;
    spec.noise_model.scale = sigma_over_h;
  }
  return generate_mesh(spec);
}

// The relative L2 error in H of `label` on the generated mesh, against its exact answer.
double true_h_error(const GeneratedMesh& g, const std::string& label) {
  const EstimatorChoice c = estimator_choice(label);
  const std::vector<VertexEstimate> est =
      estimate_mesh(g.mesh, *make_estimator(c.method, c.options));
  double num = 0.0, den = 0.0;
  for (int v = 0; v < g.mesh.num_vertices(); ++v) {
    const double H = g.surface->evaluate(g.exact_points.row(v).transpose()).H;
    num += (est[v].H - H) * (est[v].H - H);
    den += H * H;
  }
  return std::sqrt(num / den);
}

const MeasuredCase& measured_case(const MeasuredAdvice& a, const std::string& quantity,
                                  const std::string& label) {
  for (const MeasuredQuantity& q : a.quantities)
    if (q.quantity == quantity)
      for (const MeasuredCase& c : q.cases)
        if (c.label == label) return c;
  throw std::runtime_error("no case " + label);
}

TEST(MeasuredAdvice, NoisePartIsTheLinearResponseToTheNoise) {
  // On a noise-free torus the measured noise part of a fit grows in proportion to sigma (a
  // fit's output is linear in small moves of its points): 4 times the noise, 4 times the noise
  // part.
  const GeneratedMesh g = measured_torus(0.0);
  const auto cands = measured_candidates({"LHF-2 rings=1", "LHF-2 rings=3", "Jet-2 rings=2"});
  MeasuredAdviceOptions o;
  o.sigma_over_h = 0.005;
  const MeasuredAdvice low = measure_advice(g.mesh, cands, o);
  o.sigma_over_h = 0.02;
  const MeasuredAdvice high = measure_advice(g.mesh, cands, o);
  for (const std::string q : {"normal", "H"})
    for (const EstimatorChoice& c : cands) {
      const double ratio =
          measured_case(high, q, c.label).noise_part / measured_case(low, q, c.label).noise_part;
      EXPECT_NEAR(ratio, 4.0, 0.4) << q << " " << c.label;
    }
  EXPECT_DOUBLE_EQ(low.perturbation_over_h, 0.005);
  EXPECT_DOUBLE_EQ(measure_advice(g.mesh, cands, MeasuredAdviceOptions{}).perturbation_over_h,
                   kMeasuredNoiseFloor);
  EXPECT_NEAR(low.h, g.mesh.mean_edge_length(), 0.0);
}

TEST(MeasuredAdvice, BiasPartIsTheTrueErrorWithinTheReferences) {
  // Noise-free: the bias part of c is ||b_c - b_r|| (less the floor perturbation's variance), so
  // by the triangle inequality it is within ||b_r|| (the reference's true error) of c's true
  // error, up to that variance (the noise part of both). Level 2: on level 1 the reference's
  // own error (4e-2) exceeds LHF-2's. The reference of a clean mesh is the ladder's first rung.
  const GeneratedMesh g = measured_torus(0.0, 2);
  const auto cands = measured_candidates({"LHF-2 rings=1", "LHF-2 rings=3", "ICC ball-factor=4"});
  const MeasuredAdvice a = measure_advice(g.mesh, cands, MeasuredAdviceOptions{});
  ASSERT_EQ(a.quantities.size(), 2u);
  EXPECT_EQ(a.quantities[1].reference, kMeasuredReferences[0]);
  const double reference_error = true_h_error(g, kMeasuredReferences[0]);
  const double reference_noise =
      measured_case(measure_advice(g.mesh, measured_candidates({kMeasuredReferences[0]}), {}), "H",
                    kMeasuredReferences[0])
          .noise_part;
  for (const EstimatorChoice& c : cands) {
    const MeasuredCase& m = measured_case(a, "H", c.label);
    const double truth = true_h_error(g, c.label);
    EXPECT_LE(std::fabs(m.bias_part - truth), reference_error + m.noise_part + reference_noise)
        << c.label << ": bias part " << m.bias_part << ", true error " << truth;
    EXPECT_GT(truth, 3.0 * reference_error) << c.label;  // the check says something
  }
}

TEST(MeasuredAdvice, ANoisyMeshTakesAWiderReference) {
  // sigma = 0.1 h: LHF-4 on 2 rings is mostly noise (H error 2.4), so the ladder moves to a
  // wider ring, which has the smaller true error.
  const GeneratedMesh g = measured_torus(0.1, 2);
  MeasuredAdviceOptions o;
  o.sigma_over_h = 0.1;
  const MeasuredAdvice a = measure_advice(g.mesh, measured_candidates({"LHF-2 rings=3"}), o);
  EXPECT_NE(a.quantities[1].reference, kMeasuredReferences[0]);
  EXPECT_LT(true_h_error(g, a.quantities[1].reference), true_h_error(g, kMeasuredReferences[0]));
}

TEST(MeasuredAdvice, OnANoisyMeshTheNoisePartOfAHighOrderFitIsItsError) {
  // sigma = 0.03 h: LHF-4 on 2 rings amplifies the noise by far more than its bias, so its true H
  // error is its noise part, to within the spread of one noise realisation against two.
  const GeneratedMesh g = measured_torus(0.03);
  MeasuredAdviceOptions o;
  o.sigma_over_h = 0.03;
  const MeasuredAdvice a = measure_advice(g.mesh, measured_candidates({"LHF-4 rings=2"}), o);
  const double truth = true_h_error(g, "LHF-4 rings=2");
  EXPECT_NEAR(measured_case(a, "H", "LHF-4 rings=2").noise_part / truth, 1.0, 0.25);
  EXPECT_NEAR(measured_case(a, "H", "LHF-4 rings=2").predicted / truth, 1.0, 0.25);
}

TEST(MeasuredAdvice, ChoosesTheLeastPredictionTheSameForAnyThreadCount) {
  const GeneratedMesh g = measured_torus(0.01);
  const auto cands = measured_candidates({"LHF-4 rings=2", "LHF-2 rings=3", "ICC ball-factor=2"});
  MeasuredAdviceOptions o;
  o.sigma_over_h = 0.01;
  o.threads = 1;
  const MeasuredAdvice one = measure_advice(g.mesh, cands, o);
  o.threads = 2;
  const MeasuredAdvice two = measure_advice(g.mesh, cands, o);
  ASSERT_EQ(one.quantities.size(), 2u);
  for (size_t q = 0; q < 2; ++q) {
    const MeasuredQuantity& m = one.quantities[q];
    ASSERT_GE(m.chosen, 0);
    for (const MeasuredCase& c : m.cases) EXPECT_GE(c.predicted, m.cases[m.chosen].predicted);
    for (size_t i = 0; i < m.cases.size(); ++i) {
      EXPECT_EQ(m.cases[i].predicted, two.quantities[q].cases[i].predicted);
      EXPECT_EQ(m.cases[i].noise_part, two.quantities[q].cases[i].noise_part);
    }
    EXPECT_EQ(m.chosen, two.quantities[q].chosen);
  }
}

TEST(MeasuredAdvice, CreaseVerticesAreLeftOut) {
  // The meshed cube (8 x 8 squares a face): its faces are planes, so away from the 12 edges
  // every case gives H = 0 and the cases disagree only about the crease vertices and the
  // vertices whose neighbourhoods reach them. Leaving the crease vertices out shrinks the bias
  // parts; leaving every vertex out leaves nothing to predict.
  const crease_test::CreasedMesh cube = crease_test::meshed_cube(8);
  const auto cands = measured_candidates({"LHF-2 rings=1", "ICC ball-factor=4"});
  MeasuredAdviceOptions o;
  const MeasuredAdvice all = measure_advice(cube.mesh, cands, o);
  o.left_out = cube.crease_vertices;
  const MeasuredAdvice smooth = measure_advice(cube.mesh, cands, o);
  for (const std::string q : {"normal", "H"})
    for (const EstimatorChoice& c : cands) {
      const double with = measured_case(all, q, c.label).bias_part;
      const double without = measured_case(smooth, q, c.label).bias_part;
      EXPECT_LT(without, with) << q << " " << c.label;
    }
  o.left_out.resize(static_cast<size_t>(cube.mesh.num_vertices()));
  for (int v = 0; v < cube.mesh.num_vertices(); ++v) o.left_out[static_cast<size_t>(v)] = v;
  const MeasuredAdvice none = measure_advice(cube.mesh, cands, o);
  for (const MeasuredQuantity& q : none.quantities) {
    EXPECT_EQ(q.chosen, -1) << q.quantity;
    EXPECT_EQ(q.reference, "") << q.quantity;
    for (const MeasuredCase& c : q.cases) EXPECT_TRUE(std::isinf(c.predicted)) << c.label;
  }
  o.left_out = {cube.mesh.num_vertices()};
  EXPECT_THROW(measure_advice(cube.mesh, cands, o), UsageError);
}

TEST(MeasuredAdvice, RefusesWhatItCannotMeasure) {
  const GeneratedMesh g = measured_torus(0.0);
  const auto cands = measured_candidates({"LHF-2 rings=1"});
  MeasuredAdviceOptions o;
  o.sigma_over_h = -0.01;
  EXPECT_THROW(measure_advice(g.mesh, cands, o), UsageError);
  o.sigma_over_h = std::nan("");
  EXPECT_THROW(measure_advice(g.mesh, cands, o), UsageError);
  o.sigma_over_h = 0.0;
  o.perturbations = 0;
  EXPECT_THROW(measure_advice(g.mesh, cands, o), UsageError);
  EXPECT_THROW(measure_advice(g.mesh, {}, MeasuredAdviceOptions{}), UsageError);
  VertexMatrix points(3, 3);
  points << 0, 0, 0, 1, 0, 0, 0, 1, 0;
  EXPECT_THROW(measure_advice(Mesh(points, FaceMatrix(0, 3), "points"), cands, {}), InputError);
}

MeasuredAdviceRow measured_row(const std::string& family, double sigma, const std::string& q,
                               const std::string& label, double error, bool chosen) {
  MeasuredAdviceRow r;
  r.family = family;
  r.level = 2;
  r.sigma_over_h = sigma;
  r.estimated_sigma_over_h = sigma * 1.1;
  r.quantity = q;
  r.label = label;
  r.noise_part = 0.5 * error;
  r.bias_part = 0.25 * error;
  r.predicted = 0.6 * error;
  r.error = error;
  r.chosen = chosen;
  return r;
}

// Two meshes: on a the H choice is the second of three (error 0.2 against the best 0.1: regret
// 2), the normals' the best (1); on b at sigma 0.01 the H choice is the best. The section shows
// the measured summary and the H choice per family beside the learned advice.
TEST(MeasuredAdvice, RegretsCsvAndSection) {
  const std::vector<MeasuredAdviceRow> rows{
      measured_row("a", 0.0, "normal", "LHF-2 rings=1", 0.01, true),
      measured_row("a", 0.0, "normal", "LHF-4 rings=2", 0.03, false),
      measured_row("a", 0.0, "H", "LHF-2 rings=1", 0.1, false),
      measured_row("a", 0.0, "H", "LHF-4 rings=2", 0.2, true),
      measured_row("a", 0.0, "H", "ICC ball-factor=2", 0.4, false),
      measured_row("b", 0.01, "H", "LHF-2 rings=1", 0.3, true),
      measured_row("b", 0.01, "H", "ICC ball-factor=2", 0.5, false)};
  const std::vector<CrossValidationRow> regrets = measured_regrets(rows);
  ASSERT_EQ(regrets.size(), 3u);
  EXPECT_EQ(regrets[0].quantity, "normal");
  EXPECT_EQ(regrets[0].regret, 1.0);
  EXPECT_EQ(regrets[1].advised, "LHF-4 rings=2");
  EXPECT_EQ(regrets[1].best, "LHF-2 rings=1");
  EXPECT_NEAR(regrets[1].regret, 2.0, 1e-15);
  EXPECT_EQ(regrets[2].family, "b");
  EXPECT_EQ(regrets[2].regret, 1.0);
  const RegretSummary h = summarize_regret(regrets, "H");
  EXPECT_EQ(h.cases, 2);
  EXPECT_NEAR(h.worst, 2.0, 1e-15);
  EXPECT_EQ(h.within_goal, 1.0);

  namespace fs = std::filesystem;
  const fs::path dir = fs::temp_directory_path() / ("cb_measured_" + std::to_string(::getpid()));
  fs::create_directories(dir);
  write_measured_advice_csv((dir / "advice_measured.csv").string(), rows);
  const std::vector<MeasuredAdviceRow> back =
      read_measured_advice_csv((dir / "advice_measured.csv").string());
  // The results folder's section: none without the learned advice's CSV; with it, the measured
  // summary only where advice_measured.csv is.
  CrossValidationRow learned_row = regrets[1];
  learned_row.neighbours = "b";
  EXPECT_FALSE(cross_validation_section_of(dir.string()).has_value());
  write_cross_validation_csv((dir / "advice_cross_validation.csv").string(), {learned_row});
  const auto has_measured_table = [](const report::Section& sec) {
    for (const report::Block& b : sec.blocks)
      if (const auto* t = std::get_if<report::Table>(&b))
        if (t->id == "advice-measured-summary") return true;
    return false;
  };
  ASSERT_TRUE(cross_validation_section_of(dir.string()).has_value());
  EXPECT_TRUE(has_measured_table(*cross_validation_section_of(dir.string())));
  fs::remove(dir / "advice_measured.csv");
  EXPECT_FALSE(has_measured_table(*cross_validation_section_of(dir.string())));
  fs::remove_all(dir);
  ASSERT_EQ(back.size(), rows.size());
  for (size_t i = 0; i < rows.size(); ++i) {
    EXPECT_EQ(back[i].family, rows[i].family);
    EXPECT_EQ(back[i].level, rows[i].level);
    EXPECT_EQ(back[i].sigma_over_h, rows[i].sigma_over_h);
    EXPECT_EQ(back[i].estimated_sigma_over_h, rows[i].estimated_sigma_over_h);
    EXPECT_EQ(back[i].quantity, rows[i].quantity);
    EXPECT_EQ(back[i].label, rows[i].label);
    EXPECT_EQ(back[i].noise_part, rows[i].noise_part);
    EXPECT_EQ(back[i].bias_part, rows[i].bias_part);
    EXPECT_EQ(back[i].predicted, rows[i].predicted);
    EXPECT_EQ(back[i].error, rows[i].error);
    EXPECT_EQ(back[i].chosen, rows[i].chosen);
  }

  CrossValidationRow learned = regrets[1];
  learned.neighbours = "b";
  const report::Section both = cross_validation_section({learned}, regrets);
  const report::Table* summary = nullptr;
  const report::Table* per_family = nullptr;
  for (const report::Block& b : both.blocks)
    if (const auto* t = std::get_if<report::Table>(&b)) {
      if (t->id == "advice-measured-summary") summary = t;
      if (t->id == "advice-regret-table") per_family = t;
    }
  ASSERT_NE(summary, nullptr);
  ASSERT_NE(per_family, nullptr);
  EXPECT_EQ(summary->columns.size(), summary->rows.front().size());
  EXPECT_EQ(per_family->columns.back(), "regret");
  EXPECT_EQ(per_family->columns[per_family->columns.size() - 2], "H: measured");
  EXPECT_EQ(per_family->rows.front().size(), per_family->columns.size());
  // Family a at sigma 0: the measured H choice and its regret 2.
  EXPECT_EQ(per_family->rows.front()[per_family->columns.size() - 2].text, "`LHF-4 rings=2`");
  EXPECT_NEAR(per_family->rows.front().back().value, 2.0, 1e-15);
  // The measured summary has its own levels: b's 0.01 too, though no learned row has it.
  bool level_of_b = false;
  for (const auto& row : summary->rows) level_of_b |= row[1].text == "0.01";
  EXPECT_TRUE(level_of_b);
}

}  // namespace
}  // namespace curvbench
