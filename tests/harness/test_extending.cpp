// The recipes of docs/extending.md, done once: a test-only estimator and a test-only mesh family
// added through the same tables as the built-in ones (register_estimator, register_mesh_family),
// then used by an experiment file (`method toy-normal`, `method all-operators`, `mesh
// toy-sphere`), the runner, the case key and the report's captions, with no other edit.
#include <gtest/gtest.h>

#include <memory>
#include <string>
#include <vector>

#include "core/errors.h"
#include "harness/model/experiment.h"
#include "harness/run/runner.h"
#include "meshgen/generate.h"
#include "methods/estimator.h"
#include "surfaces/sphere.h"
#include "tests/methods/method_test_util.h"

namespace curvbench {
namespace {

// A degree-free operator that reports the area-weighted vertex normal and nothing else.
class ToyNormalEstimator final : public Estimator {
 public:
  using Estimator::Estimator;
  std::string name() const override { return "toy-normal"; }
  bool takes_degree() const override { return false; }
  ComputedQuantities computes() const override { return {true, false, false, false, false}; }
  std::unique_ptr<Workspace> make_workspace(const Mesh&) const override {
    return std::make_unique<Workspace>();
  }
  void estimate(const MeshContext& ctx, int v, Workspace&, VertexEstimate& out) const override {
    out = VertexEstimate{};
    out.normal = ctx.approx_normals.row(v).transpose().normalized();
    out.points = static_cast<int>(ctx.mesh.vertex_faces(v).size());
    out.status = VertexStatus::ok;
  }
};

int toy_normals_built = 0;  // calls of make_toy_normal

std::unique_ptr<Estimator> make_toy_normal(EstimatorOptions options) {
  ++toy_normals_built;
  return std::make_unique<ToyNormalEstimator>(options);
}

// The unit icosphere of `level` subdivisions, its vertices on the exact sphere.
GeneratedMesh toy_sphere(const MeshSpec& spec) {
  GeneratedMesh g;
  g.mesh = testing::icosphere(spec.level, 1.0);
  g.exact_points = g.mesh.vertices();
  g.surface = make_sphere(1.0);
  g.family = spec.family;
  g.level = spec.level;
  g.description = "icosphere, " + std::to_string(spec.level) + " subdivisions";
  return g;
}

void register_toys() {
  static const bool once = [] {
    register_estimator({"toy-normal", 0, 0, {}, 0.1, "test only: the area-weighted normal"},
                       &make_toy_normal);
    register_mesh_family(
        {"toy-sphere", 4, "unit icosphere (test only)", "not in the paper", "none"}, &toy_sphere);
    return true;
  }();
  (void)once;
}

TEST(Extending, AToyEstimatorAndFamilyRunThroughTheExperimentPath) {
  register_toys();
  const Experiment e = parse_experiment_text(
      "mesh toy-sphere levels=2,3\nmethod toy-normal label=\"TOY first\"\n"
      "method lhf-2\nmethod all-operators vertex-normals=angle\n"
      "panel toy-n \"Toy. Normals.\" normal L2\n",
      "toy.exp");
  // all-operators now includes the toy operator, after the built-in ones (the line of its own
  // needs a label: both would report as TOY-NORMAL).
  size_t operators = 0;  // the registry's discrete operators, the toy included
  for (const MethodInfo& m : method_table())
    operators += !m.is_fit() && m.group == MethodGroup::discrete;
  ASSERT_GE(operators, 2u);
  ASSERT_EQ(e.methods.size(), 2u + operators);
  EXPECT_EQ(e.methods.back().spec, "toy-normal");
  EXPECT_EQ(e.methods.back().options.vertex_normals, VertexNormals::angle);
  RunOptions o;
  o.threads = 1;
  const RunSummary run = run_experiments({e}, o);
  const size_t methods = e.methods.size();
  ASSERT_EQ(run.rows.size(), 2u * methods);  // one normal L2 row per level and method
  for (const ErrorRow& r : run.rows) {
    EXPECT_EQ(r.family, "toy-sphere");
    EXPECT_EQ(r.noise, "none");  // the family's noise label
    EXPECT_EQ(r.failed, 0) << r.method;
  }
  // The toy's normal error converges, about first order on the icosphere (0.45x per halving).
  const ErrorRow& coarse = run.rows[0];
  const ErrorRow& fine = run.rows[methods];
  ASSERT_EQ(coarse.method, "TOY first");
  ASSERT_EQ(fine.method, "TOY first");
  EXPECT_EQ(run.rows[methods - 1].method, "TOY-NORMAL");
  EXPECT_GT(coarse.error, 0.0);
  EXPECT_LT(fine.error, 0.6 * coarse.error);
  // The tables know them.
  EXPECT_EQ(mesh_family("toy-sphere").caption, "unit icosphere (test only)");
  EXPECT_EQ(method_labels(2, 2).back(), "toy-normal");
}

// run_case builds a case's estimator once (its degree and radius come from the registry, not
// from a first estimator built to ask), also under the noisy reading and radius scaling.
TEST(Extending, RunCaseBuildsTheEstimatorOnce) {
  register_toys();
  const std::vector<Experiment> experiments = {
      parse_experiment_text("mesh toy-sphere levels=2\nnoisy yes\nradius-scaling alpha=0.5 c=0.44\n"
                            "method toy-normal\npanel toy-n \"Toy. Normals.\" normal L2\n",
                            "toy-once.exp")};
  const std::vector<RunCase> cases = expand_cases(experiments);
  ASSERT_EQ(cases.size(), 1u);
  // 4^2 x the registry line's cost 0.1 x a degree-free method's factor 0.5, nothing built
  EXPECT_DOUBLE_EQ(case_cost(cases[0]), 16.0 * 0.1 * 0.5);
  MeshCache cache;
  toy_normals_built = 0;
  EXPECT_EQ(run_case(cases[0], cache, 1).size(), 1u);
  EXPECT_EQ(toy_normals_built, 1);
}

TEST(Extending, RegistrationErrors) {
  register_toys();
  EXPECT_THROW(register_estimator({"toy-normal", 0, 0, {}, 1.0, ""}, &make_toy_normal), UsageError);
  EXPECT_THROW(register_estimator({"Toy2", 0, 0, {}, 1.0, ""}, &make_toy_normal), UsageError);
  EXPECT_THROW(register_estimator({"toy3", 0, 2, {}, 1.0, ""}, &make_toy_normal), UsageError);
  EXPECT_THROW(register_estimator({"external", 0, 0, {}, 1.0, ""}, &make_toy_normal), UsageError);
  EXPECT_THROW(register_estimator({"toy four", 0, 0, {}, 1.0, ""}, &make_toy_normal), UsageError);
  EXPECT_THROW(register_mesh_family({"toy-sphere", 1, "", "", "none"}, &toy_sphere), UsageError);
  // An option of the fits given to the toy operator is refused as for any operator.
  EstimatorOptions fit_only;
  fit_only.qr_tolerance = 1e-6;
  EXPECT_THROW(make_estimator("toy-normal", fit_only), UsageError);
  EXPECT_THROW(make_estimator("toy-normal-2", EstimatorOptions{}), UsageError);
}

}  // namespace
}  // namespace curvbench
