// The readings of the paper's unstated choices (harness/readings/readings.h): each alternative
// changes the experiments as documented (levels, noise model, noisy-data rings) and only those, the
// experiment files accept the options they set, and the runner honours them.
#include <gtest/gtest.h>

#include <string>

#include "core/errors.h"
#include "harness/model/experiment.h"
#include "harness/readings/readings.h"
#include "harness/run/runner.h"
#include "methods/estimator.h"

namespace curvbench {
namespace {

const ReadingChoice& choice(const std::string& reading, const std::string& name) {
  for (const Reading& r : readings())
    if (r.id == reading)
      for (const ReadingChoice& c : r.choices)
        if (c.name == name) return c;
  throw std::out_of_range(reading + "=" + name);
}

Experiment parse(const std::string& body, const std::string& section = "5") {
  return parse_experiment_text(
      "title t\nsection " + section + "\n" + body + "panel p \"p\" normal L2\n", "t.exp");
}

TEST(Readings, EveryReadingHasTheAdoptedChoiceFirstAndItChangesNothing) {
  ASSERT_FALSE(readings().empty());
  const Experiment e = parse(
      "noise order=3 seed=1\nnoisy yes\nmesh torus-iso levels=2,3,4,5\n"
      "method lhf-4\n");
  for (const Reading& r : readings()) {
    ASSERT_GE(r.choices.size(), 2u) << r.id;
    EXPECT_TRUE(apply_reading({e}, r.choices.front()).empty()) << r.id;
    for (size_t i = 1; i < r.choices.size(); ++i)
      EXPECT_EQ(reading_folder("results", r, r.choices[i]),
                "results/readings/" + r.id + "=" + r.choices[i].name);
  }
}

// noise-alpha's adopted choice, alpha = (0.1/3) N(0,1), is what the experiment files of the
// paper's controlled noise write; the alternative gaussian-0.1 changes them, and changes nothing
// that already draws alpha = 0.1 N(0,1).
TEST(Readings, NoiseAlphaAdoptedIsTheExperimentFilesModel) {
  const auto all = load_experiments(std::string(CURVBENCH_SOURCE_DIR) + "/experiments");
  const ReadingChoice& wide = choice("noise-alpha", "gaussian-0.1");
  EXPECT_EQ(choice("noise-alpha", "gaussian-0.033").name, readings()[2].choices[0].name);
  int seen = 0;
  for (const Experiment& e : all) {
    if (e.name != "fig19-21" && e.name != "fig20-22") continue;
    ++seen;
    EXPECT_EQ(e.noise_model.distribution, NoiseDistribution::gaussian) << e.name;
    EXPECT_EQ(e.noise_model.scale, 0.1 / 3) << e.name;
    const auto changed = apply_reading({e}, wide);
    ASSERT_EQ(changed.size(), 1u) << e.name;
    EXPECT_EQ(changed[0].noise_model.scale, 0.1) << e.name;
  }
  EXPECT_EQ(seen, 2);
  EXPECT_TRUE(
      apply_reading(
          {parse("noise order=2 seed=1 scale=0.1\nmesh bump-48 levels=1\nmethod lhf-2\n")}, wide)
          .empty());
}

TEST(Readings, IsoLevelsShiftTheIsosurfaceToriOnly) {
  const Experiment e = parse(
      "mesh torus-iso levels=2,3,4,5\nmesh torus-iso-projected "
      "levels=2,3,4,5\nmesh torus-unstructured levels=1,2,3,4\n"
      "method lhf-2\n");
  const auto changed = apply_reading({e}, choice("iso-levels", "16-128"));
  ASSERT_EQ(changed.size(), 1u);
  // Only the changed mesh lines are rerun (torus-unstructured's rows stay the adopted run's).
  ASSERT_EQ(changed[0].meshes.size(), 2u);
  EXPECT_EQ(changed[0].meshes[0].levels, (std::vector<int>{1, 2, 3, 4}));
  EXPECT_EQ(changed[0].meshes[1].levels, (std::vector<int>{1, 2, 3, 4}));
  EXPECT_EQ(changed[0].name, "t");  // same name: its rows replace the adopted ones in CLAIMS
  EXPECT_TRUE(apply_reading({parse("mesh bump-48 levels=1,2\nmethod lhf-2\n")},
                            choice("iso-levels", "16-128"))
                  .empty());
}

// A family-swapping reading: of an experiment with `family` and `other` mesh lines, it keeps the
// `family` line, renamed `by` with the same levels (the `other` rows stay the adopted run's), and
// tells the claims to read `by` for `family`.
void expect_family_swap(const ReadingChoice& c, const std::string& family, const std::string& other,
                        const std::string& by) {
  const auto changed = apply_reading(
      {parse("mesh " + family + " levels=1,2\nmesh " + other + " levels=2,3\nmethod lhf-4\n")}, c);
  ASSERT_EQ(changed.size(), 1u);
  ASSERT_EQ(changed[0].meshes.size(), 1u);
  EXPECT_EQ(changed[0].meshes[0].family, by);
  EXPECT_EQ(changed[0].meshes[0].levels, (std::vector<int>{1, 2}));
  EXPECT_EQ(c.substitute.family, family);
  EXPECT_EQ(c.substitute.by, by);
}

TEST(Readings, WellShapedTorusSwapsTheFamilyAndNamesItForTheClaims) {
  expect_family_swap(choice("well-shaped-torus", "min-valence-5"), "torus-unstructured",
                     "torus-iso-projected", "torus-unstructured-minval5");
}

TEST(Readings, IrregularBumpSwapsTheFamilyInThePapersExperimentsOnly) {
  const ReadingChoice& c = choice("irregular-bump", "delaunay-refined");
  expect_family_swap(c, "bump-irregular", "bump-48", "bump-unstructured");
  // A study beyond the paper keeps the adopted mesh.
  EXPECT_TRUE(
      apply_reading({parse("mesh bump-irregular levels=1\nmethod lhf-2\n", "beyond")}, c).empty());
}

TEST(Readings, SafeguardSetsEveryRingFitWithoutItsOwnSafeguard) {
  const Experiment e = parse(
      "mesh bump-48 levels=1\nmethod lhf-4\nmethod lop-2\nmethod lscm-3\nmethod xu-2\n"
      "method jet-2\nmethod meyer\nmethod lhf-2 qr-tol=1e-5 label=\"own\"\n"
      "method lhf-3 qr-condition=no label=\"own test\"\n");
  const EstimatorOptions defaults;
  EXPECT_EQ(defaults.qr_tolerance, 1e-3);
  EXPECT_TRUE(defaults.qr_condition);
  for (const char* name : {"1e-8", "rjj-only"}) {
    SCOPED_TRACE(name);
    const ReadingChoice& c = choice("safeguard", name);
    const auto changed = apply_reading({e}, c);
    ASSERT_EQ(changed.size(), 1u);
    const Experiment& x = changed[0];
    ASSERT_EQ(x.methods.size(), e.methods.size());
    EXPECT_EQ(x.meshes.size(), e.meshes.size());  // every mesh line: the methods change
    const bool loose = std::string(name) == "1e-8";
    // The three ring fits get the choice's safeguard: one of the two settings changes.
    for (size_t i = 0; i < 3; ++i) {
      EXPECT_EQ(x.methods[i].options.qr_tolerance, loose ? 1e-8 : 1e-3) << i;
      EXPECT_EQ(x.methods[i].options.qr_condition, loose) << i;
    }
    for (size_t i = 3; i < 6; ++i) {
      EXPECT_EQ(x.methods[i].options.qr_tolerance, defaults.qr_tolerance) << i;
      EXPECT_TRUE(x.methods[i].options.qr_condition) << i;
    }
    // A fit that sets its own tolerance or test keeps it.
    EXPECT_EQ(x.methods[6].options.qr_tolerance, 1e-5);
    EXPECT_TRUE(x.methods[6].options.qr_condition);
    EXPECT_EQ(x.methods[7].options.qr_tolerance, 1e-3);
    EXPECT_FALSE(x.methods[7].options.qr_condition);
    // Nothing to change: no ring fit, or a study beyond the paper.
    EXPECT_TRUE(apply_reading({parse("mesh bump-48 levels=1\nmethod meyer\n")}, c).empty());
    EXPECT_TRUE(
        apply_reading({parse("mesh bump-48 levels=1\nmethod lhf-2\n", "beyond")}, c).empty());
  }
}

TEST(Readings, NoisyRingsQuadraticOnlyGivesDegreesThreeAndFourTheirOwnRings) {
  const Experiment e = parse("noisy yes\nmesh torus-iso levels=2\nmethod lhf-2\nmethod lhf-4\n");
  const auto changed = apply_reading({e}, choice("noisy-rings", "quadratic"));
  ASSERT_EQ(changed.size(), 1u);
  EXPECT_TRUE(changed[0].noisy_quadratic_only);
  EXPECT_TRUE(changed[0].noisy_for_degree(2));
  EXPECT_FALSE(changed[0].noisy_for_degree(4));
  EXPECT_TRUE(e.noisy_for_degree(4));
  // An experiment of degree-2 fits only is left alone (nothing would change).
  EXPECT_TRUE(apply_reading({parse("noisy yes\nmesh torus-iso levels=2\nmethod lhf-2\n")},
                            choice("noisy-rings", "quadratic"))
                  .empty());
  // The runner's rings: LHF-4 at 2.5 + 0.5 under the adopted reading, 2.5 under this one.
  MeshCache cache;
  const auto ring_of = [&](const Experiment& x) {
    const RunCase c{&x, &x.meshes[0], 2, &x.methods[1]};
    return run_case(c, cache, 1).front().rings;
  };
  EXPECT_EQ(ring_of(e), "3");
  EXPECT_EQ(ring_of(changed[0]), "2.5");
}

TEST(Readings, NoiseAlphaSetsTheModelOfNoisyExperimentsOnly) {
  const Experiment e = parse("noise order=2 seed=5\nmesh bump-48 levels=1\nmethod lhf-2\n");
  const auto u = apply_reading({e}, choice("noise-alpha", "uniform-0.1"));
  ASSERT_EQ(u.size(), 1u);
  EXPECT_EQ(u[0].noise_model.distribution, NoiseDistribution::uniform);
  EXPECT_EQ(u[0].noise_model.scale, 0.1);
  // The adopted scale 0.1/3 (the experiment files write it) to 0.1.
  const Experiment adopted = parse(
      "noise order=2 seed=5 scale=0.03333333333333333\nmesh bump-48 levels=1\nmethod lhf-2\n");
  EXPECT_EQ(adopted.noise_model.scale, 0.1 / 3);
  const auto g = apply_reading({adopted}, choice("noise-alpha", "gaussian-0.1"));
  ASSERT_EQ(g.size(), 1u);
  EXPECT_EQ(g[0].noise_model.distribution, NoiseDistribution::gaussian);
  EXPECT_EQ(g[0].noise_model.scale, 0.1);
  EXPECT_TRUE(apply_reading({parse("mesh bump-48 levels=1\nmethod lhf-2\n")},
                            choice("noise-alpha", "uniform-0.1"))
                  .empty());
}

// noise-h=half-mean-edge: alpha (h/2)^k, i.e. alpha's scale over 2^k for each noisy mesh of the
// paper's sections (the mesh lines keep their order and the distribution the experiment sets);
// noise-free meshes and the studies beyond the paper are left alone.
TEST(Readings, NoiseHHalvesTheEdgeLengthOfTheControlledNoise) {
  const Experiment e = parse(
      "noise order=3 seed=5 alpha=uniform scale=0.1\nmesh bump-48 levels=1\n"
      "mesh bump-irregular levels=1 noise-order=2\nmesh bump-irregular levels=2 noise-order=0\n"
      "method lhf-2\n");
  const auto half = apply_reading({e}, choice("noise-h", "half-mean-edge"));
  ASSERT_EQ(half.size(), 1u);
  ASSERT_EQ(half[0].meshes.size(), 2u);  // the noise-free line keeps the adopted run's rows
  for (const auto& m : half[0].meshes) {
    const int k = half[0].noise_order_of(m);
    const NoiseModel model = half[0].noise_model_of(m);
    EXPECT_EQ(model.distribution, NoiseDistribution::uniform);
    EXPECT_DOUBLE_EQ(model.scale, k == 3 ? 0.1 / 8 : 0.1 / 4) << m.family;
    // The results' noise column (and so the claims' queries) stays "h^k".
    EXPECT_EQ(noise_label(k, model), "h^" + std::to_string(k));
  }
  EXPECT_EQ(half[0].noise_order_of(half[0].meshes[0]), 3);
  EXPECT_EQ(half[0].noise_order_of(half[0].meshes[1]), 2);
  EXPECT_TRUE(apply_reading({parse("mesh bump-48 levels=1\nmethod lhf-2\n")},
                            choice("noise-h", "half-mean-edge"))
                  .empty());
  EXPECT_TRUE(apply_reading(
                  {parse("noise order=2 seed=5\nmesh bump-48 levels=1\nmethod lhf-2\n", "beyond")},
                  choice("noise-h", "half-mean-edge"))
                  .empty());
}

// radius-scaling alpha=0.5 c=0.44: n = 0.44 h^(-1/2) edge lengths; at h = 0.0121 (n = 4.0) the
// fits take 4 rings, at h = 0.0484 (n = 2.0) 2, at h = 0.02 (n = 3.11) 3; the quadric whole
// rings, the normal cycle the ball factor itself, Meyer and Xu nothing.
TEST(RadiusScaling, EachMethodGetsItsOwnNeighbourhoodParameter) {
  const Experiment e = parse(
      "radius-scaling alpha=0.5 c=0.44\nmesh torus-iso levels=2\n"
      "method lhf-2\n");
  EXPECT_EQ(e.radius_alpha, 0.5);
  EXPECT_EQ(e.radius_c, 0.44);
  const auto rings_of = [&](const std::string& method, double h) {
    EstimatorOptions o;
    scale_radius(e, method, h, o);
    return std::make_pair(o.rings, o.ball_factor);
  };
  EXPECT_EQ(rings_of("lhf-2", 0.0121).first, 4.0);
  EXPECT_EQ(rings_of("lhf-4", 0.0484).first, 2.0);
  EXPECT_EQ(rings_of("jet-2", 0.02).first, 3.0);    // 3.11 -> 3
  EXPECT_EQ(rings_of("lhf-2", 0.03).first, 2.5);    // 2.54 -> 2.5
  EXPECT_EQ(rings_of("quadric", 0.03).first, 3.0);  // 2.54 -> 3
  EXPECT_EQ(rings_of("lhf-2", 1.0).first, 1.0);     // 0.44 -> at least 1
  EXPECT_NEAR(rings_of("normal-cycle", 0.0121).second, 4.0, 1e-12);
  EXPECT_NEAR(rings_of("icc", 0.0121).second, 4.0, 1e-12);
  EXPECT_EQ(rings_of("meyer", 0.0121), std::make_pair(0.0, 0.0));
  EXPECT_EQ(rings_of("xu-2", 0.0121), std::make_pair(0.0, 0.0));
  EXPECT_THROW(parse("radius-scaling alpha=0 c=1\nmesh bump-48 levels=1\nmethod lhf-2\n"),
               InputError);
  EXPECT_THROW(parse("radius-scaling alpha=0.5\nmesh bump-48 levels=1\nmethod lhf-2\n"),
               InputError);
}

// noise-order on a mesh line: that family's noise instead of the experiment's (the torus keeps
// its own isosurface errors, the bump gets alpha h^2), in the rows' noise column too.
TEST(MeshNoiseOrder, OverridesTheExperimentsNoiseForOneFamily) {
  const Experiment e = parse(
      "mesh torus-iso levels=2\nmesh bump-irregular levels=1 noise-order=2\n"
      "method lhf-2\n");
  EXPECT_EQ(e.noise_order_of(e.meshes[0]), 0);
  EXPECT_EQ(e.noise_order_of(e.meshes[1]), 2);
  MeshCache cache;
  EXPECT_EQ(run_case({&e, &e.meshes[0], 2, &e.methods[0]}, cache, 1).front().noise, "isosurface");
  EXPECT_EQ(run_case({&e, &e.meshes[1], 1, &e.methods[0]}, cache, 1).front().noise, "h^2");
  // The noise-alpha reading reaches an experiment whose noise is on a mesh line only.
  EXPECT_EQ(apply_reading({e}, choice("noise-alpha", "uniform-0.1")).size(), 1u);
  EXPECT_THROW(parse("mesh bump-48 levels=1 noise-order=5\nmethod lhf-2\n"), InputError);
}

TEST(Readings, ExperimentFilesTakeTheOptionsAndRefuseBadValues) {
  const Experiment e = parse(
      "noise order=3 seed=2 alpha=uniform scale=0.05\nnoisy yes rings=quadratic\n"
      "mesh bump-48 levels=1\nmethod lhf-2\n");
  EXPECT_EQ(e.noise_model.distribution, NoiseDistribution::uniform);
  EXPECT_EQ(e.noise_model.scale, 0.05);
  EXPECT_TRUE(e.noisy_quadratic_only);
  EXPECT_THROW(parse("noise order=3 alpha=laplace\nmesh bump-48 levels=1\nmethod lhf-2\n"),
               InputError);
  EXPECT_THROW(parse("noise order=3 scale=-1\nmesh bump-48 levels=1\nmethod lhf-2\n"), InputError);
  EXPECT_THROW(parse("noisy yes rings=cubic\nmesh bump-48 levels=1\nmethod lhf-2\n"), InputError);
}

}  // namespace
}  // namespace curvbench
