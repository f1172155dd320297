// Experiment files: parsing, error messages, the shipped definitions, results CSV round trip.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <map>
#include <set>
#include <sstream>
#include <string>

#include "core/errors.h"
#include "harness/model/experiment.h"
#include "harness/model/results_table.h"
#include "harness/run/case_store.h"
#include "harness/run/runner.h"
#include "meshgen/generate.h"
#include "methods/estimator.h"
#include "tests/cli/cli_runner.h"

namespace curvbench {
namespace {

TEST(Experiment, ParsesEveryKey) {
  const Experiment e = parse_experiment_text(
      "# comment line\n"
      "title    \"A demo, with commas\"\n"
      "section  5.3\n"
      "report   paper\n"
      "noise    order=2 seed=77\n"
      "noisy    yes\n"
      "vertex-set interior\n"
      "mesh     bump-48 levels=1,2,3\n"
      "method   lhf-2 rings=2.5\n"
      "method   xu-2 vertex-set=all\n"
      "method   lhf-4 centre=no qr-tol=1e-8 safeguard=no adaptive=no weight-power=0.5 "
      "label=\"LHF-4 ablated\"\n"
      "panel    p1 \"Caption one.\" normal Linf\n",
      "demo.exp");
  EXPECT_EQ(e.name, "demo");
  EXPECT_EQ(e.title, "A demo, with commas");
  EXPECT_EQ(e.section, "5.3");
  EXPECT_EQ(e.report, ReportSection::paper);
  EXPECT_EQ(parse_experiment_text("mesh bump-48 levels=1\nmethod lhf-2\npanel p c H L2\n", "x.exp")
                .report,
            ReportSection::extra);  // the default
  EXPECT_EQ(e.noise_order, 2);
  EXPECT_EQ(e.noise_seed, 77u);
  EXPECT_TRUE(e.noisy);
  EXPECT_EQ(e.vertex_set, VertexSet::interior);
  ASSERT_EQ(e.meshes.size(), 1u);
  EXPECT_EQ(e.meshes[0].levels, (std::vector<int>{1, 2, 3}));
  ASSERT_EQ(e.methods.size(), 3u);
  const ExperimentMethod& ab = e.methods[2];
  EXPECT_EQ(ab.label, "LHF-4 ablated");
  EXPECT_FALSE(ab.options.include_centre);
  EXPECT_DOUBLE_EQ(ab.options.qr_tolerance, 1e-8);
  EXPECT_FALSE(ab.options.normal_safeguard);
  EXPECT_FALSE(ab.options.adaptive);
  EXPECT_DOUBLE_EQ(ab.options.weight_power, 0.5);
  EXPECT_TRUE(e.methods[0].options.include_centre);  // defaults are EstimatorOptions' defaults
  EXPECT_DOUBLE_EQ(e.methods[0].options.qr_tolerance, EstimatorOptions{}.qr_tolerance);
  EXPECT_DOUBLE_EQ(e.methods[0].options.rings, 2.5);
  EXPECT_FALSE(e.methods[0].has_vertex_set);
  EXPECT_TRUE(e.methods[1].has_vertex_set);
  EXPECT_EQ(e.methods[1].vertex_set, VertexSet::all);
  ASSERT_EQ(e.panels.size(), 1u);
  EXPECT_EQ(e.panels[0].caption, "Caption one.");
  EXPECT_EQ(e.panels[0].quantity, Quantity::normal);
  EXPECT_EQ(e.panels[0].norm, Norm::Linf);
}

TEST(Experiment, ErrorsNameFileAndLine) {
  const std::string base = "mesh bump-48 levels=1\nmethod lhf-2\npanel p c H L2\n";
  auto expect_error = [](const std::string& text, const std::string& needle) {
    try {
      parse_experiment_text(text, "bad.exp");
      ADD_FAILURE() << "expected InputError for: " << text;
    } catch (const InputError& err) {
      EXPECT_NE(std::string(err.what()).find(needle), std::string::npos) << err.what();
    }
  };
  expect_error(base + "colour red\n", "bad.exp:4: unknown key 'colour'");
  expect_error(base + "panel q c curvature L2\n", "bad.exp:4: unknown quantity");
  expect_error(base + "panel q c H angle-rms\n", "bad.exp:4: norm angle-rms measures normals");
  expect_error(base + "panel q c normal rectified\n", "bad.exp:4: norm rectified measures H");
  expect_error(base + "noise order=5\n",
               "bad.exp:4: noise order 5 out of range (valid: 0 = none, 1..4)");
  expect_error(base + "mesh bump-48 levels=1,x\n", "bad.exp:4: 'x' is not an integer");
  expect_error(base + "title \"open\n", "bad.exp:4: unterminated quote");
  expect_error(base + "method lhf-2 label=\"a,b\"\n", "bad.exp:4: a label must be");
  expect_error(base + "method lhf-2 centre=maybe\n", "bad.exp:4: centre: expected yes or no");
  expect_error(
      base + "report figures\n",
      "bad.exp:4: report 'figures' is not one of paper, field, hard, sweeps, points, extra");
  expect_error(base + "sweep radius\n", "bad.exp: a 'sweep' line and 'report sweeps' go together");
  expect_error(base + "report sweeps\n", "bad.exp: a 'sweep' line and 'report sweeps' go together");
  // One name per experiment: the file's; a name line is refused, the name must suit a CSV.
  expect_error("name x\n" + base,
               "bad.exp:1: no 'name' line: the experiment's name is its file name ('bad')");
  try {
    parse_experiment_text(base, "dir/a,b.exp");
    ADD_FAILURE() << "a comma in the file name";
  } catch (const InputError& err) {
    EXPECT_NE(std::string(err.what()).find("dir/a,b.exp: the file name 'a,b' is the experiment's"),
              std::string::npos)
        << err.what();
  }
  EXPECT_EQ(parse_experiment_text(base, "experiments/sweeps/sweep-radius-a1_2.exp").name,
            "sweep-radius-a1_2");
  expect_error("method lhf-2\npanel p c H L2\n", "no 'mesh' line");
  // Two methods under one label would share every table row: a label= of its own is asked for.
  expect_error(base + "method lhf-2 centre=no\n",
               "bad.exp: methods 1 (lhf-2) and 2 (lhf-2) both report as 'LHF-2'");
  expect_error(base + "method lhf-4\nmethod lhf-2 label=LHF-4\n", "both report as 'LHF-4'");
  EXPECT_NO_THROW(
      parse_experiment_text(base + "method lhf-2 centre=no label=\"LHF-2 interp\"\n", "good.exp"));
  EXPECT_NO_THROW(  // another vertex set: rows apart
      parse_experiment_text(base + "method lhf-2 vertex-set=interior\n", "good.exp"));
  EXPECT_THROW(parse_experiment("/nonexistent/x.exp"), InputError);
}

// The options of single methods: parsed onto the method line, and checked there against the
// method (make_estimator) so that a misplaced or bad option names the file and line.
TEST(Experiment, SingleMethodOptions) {
  const std::string head = "mesh bump-48 levels=1\npanel p c H L2\n";
  const Experiment e =
      parse_experiment_text(head +
                                "method meyer vertex-normals=angle\n"
                                "method quadric quadric-constant=yes\n"
                                "method normal-cycle ball-factor=2.5 label=\"NC ball\"\n"
                                "method normal-cycle\n",
                            "opts.exp");
  ASSERT_EQ(e.methods.size(), 4u);
  EXPECT_EQ(e.methods[0].options.vertex_normals, VertexNormals::angle);
  EXPECT_TRUE(e.methods[1].options.quadric_constant);
  EXPECT_DOUBLE_EQ(e.methods[2].options.ball_factor, 2.5);
  EXPECT_EQ(e.methods[3].options.vertex_normals, VertexNormals::method_default);  // the defaults
  EXPECT_FALSE(e.methods[3].options.quadric_constant);
  EXPECT_EQ(e.methods[3].options.ball_factor, 0.0);
  const auto expect_error = [&](const std::string& line, const std::string& needle) {
    try {
      parse_experiment_text(head + line, "bad.exp");
      ADD_FAILURE() << "expected InputError for: " << line;
    } catch (const InputError& err) {
      EXPECT_NE(std::string(err.what()).find(needle), std::string::npos) << err.what();
    }
  };
  expect_error("method lhf-2 vertex-normals=area\n",
               "bad.exp:3: vertex-normals applies to the discrete operators only");
  expect_error("method meyer vertex-normals=cot\n",
               "bad.exp:3: vertex-normals: unknown value 'cot'");
  expect_error("method meyer quadric-constant=yes\n",
               "bad.exp:3: quadric-constant applies to method 'quadric' only");
  expect_error("method quadric quadric-constant=maybe\n",
               "bad.exp:3: quadric-constant: expected yes or no");
  // (the ball-sized methods the message lists are the registry's: test_vertex_normals.cpp)
  expect_error("method taubin ball-factor=1\n",
               "only (the methods sized by a ball), not to 'taubin'");
  expect_error("method normal-cycle ball-factor=-1\n", "bad.exp:3: ball-factor -1: out of range");
  expect_error("method lhf-2 rings=0.5\n", "bad.exp:3: fit: ring 0.5 is not supported");
}

// `method M key=v1,v2,...`: one method per value, labelled "<label> key=value".
TEST(Experiment, MethodOptionListExpands) {
  const std::string head = "mesh bump-48 levels=1\npanel p c H L2\n";
  const Experiment e = parse_experiment_text(head +
                                                 "method lhf-2 rings=1,1.5,2\n"
                                                 "method icc ball-factor=1,4 label=B\n"
                                                 "method meyer\n",
                                             "list.exp");
  ASSERT_EQ(e.methods.size(), 6u);
  EXPECT_EQ(e.methods[0].label, "LHF-2 rings=1");
  EXPECT_EQ(e.methods[1].label, "LHF-2 rings=1.5");
  EXPECT_DOUBLE_EQ(e.methods[1].options.rings, 1.5);
  EXPECT_EQ(e.methods[2].label, "LHF-2 rings=2");
  EXPECT_EQ(e.methods[3].label, "B ball-factor=1");
  EXPECT_DOUBLE_EQ(e.methods[4].options.ball_factor, 4.0);
  EXPECT_EQ(e.methods[4].label, "B ball-factor=4");
  EXPECT_EQ(e.methods[5].label, "");
  const auto expect_error = [&](const std::string& line, const std::string& needle) {
    try {
      parse_experiment_text(head + line, "bad.exp");
      ADD_FAILURE() << "expected InputError for: " << line;
    } catch (const InputError& err) {
      EXPECT_NE(std::string(err.what()).find(needle), std::string::npos) << err.what();
    }
  };
  expect_error("method lhf-2 rings=1,2 qr-tol=1e-3,1e-8\n",
               "bad.exp:3: only one option of a method line may list values");
  expect_error("method lhf-2 rings=1,,2\n", "bad.exp:3: empty value in the list '1,,2'");
  expect_error("method lhf-2 rings=1,0.5\n", "bad.exp:3: fit: ring 0.5 is not supported");
}

// Mesh lines with their own noise: one mesh per listed sigma/h or outlier fraction (sigma 0: the
// noise-free mesh, listed once), the model on each; bad values name the option and value.
TEST(Experiment, MeshNoiseVariants) {
  const std::string head = "method meyer\npanel p c H L2\n";
  const Experiment e = parse_experiment_text(
      head +
          "noise seed=5\n"
          "mesh torus-structured levels=1 noise-sigma=0,0.03 noise-model=tangential "
          "noise-alpha=uniform-centred\n"
          "mesh torus-structured levels=1 noise-sigma=0,0.1\n"
          "mesh torus-structured levels=1 outliers=0.01\n",
      "noise.exp");
  EXPECT_EQ(e.noise_order, 0);
  EXPECT_EQ(e.noise_seed, 5u);
  ASSERT_EQ(e.meshes.size(), 4u);
  EXPECT_FALSE(e.meshes[0].has_noise_model);
  EXPECT_EQ(e.noise_order_of(e.meshes[0]), 0);
  EXPECT_EQ(e.noise_order_of(e.meshes[1]), 1);
  EXPECT_EQ(e.noise_model_of(e.meshes[1]).direction, NoiseDirection::tangential);
  EXPECT_EQ(e.noise_model_of(e.meshes[1]).distribution, NoiseDistribution::uniform_centred);
  EXPECT_DOUBLE_EQ(e.noise_model_of(e.meshes[1]).scale, 0.03);
  EXPECT_EQ(e.noise_model_of(e.meshes[2]).direction, NoiseDirection::normal);
  EXPECT_DOUBLE_EQ(e.noise_model_of(e.meshes[2]).scale, 0.1);
  EXPECT_DOUBLE_EQ(e.noise_model_of(e.meshes[3]).outlier_fraction, 0.01);
  const std::string base = "mesh bump-48 levels=1\nmethod lhf-2\npanel p c H L2\n";
  const auto expect_error = [&](const std::string& line, const std::string& needle) {
    try {
      parse_experiment_text(base + line, "bad.exp");
      ADD_FAILURE() << "expected InputError for: " << line;
    } catch (const InputError& err) {
      EXPECT_NE(std::string(err.what()).find(needle), std::string::npos) << err.what();
    }
  };
  expect_error("mesh bump-48 levels=1 noise-sigma=0.1,-0.01\n",
               "bad.exp:4: noise-sigma=-0.01 must be finite and >= 0");
  expect_error("mesh bump-48 levels=1 outliers=1.5\n", "bad.exp:4: outliers=1.5 is outside [0, 1]");
  expect_error("mesh bump-48 levels=1 outliers=-0.1\n",
               "bad.exp:4: outliers=-0.1 is outside [0, 1]");
  expect_error("mesh bump-48 levels=1 noise-sigma=0.1 noise-model=radial\n",
               "bad.exp:4: noise model 'radial' is not one of normal, isotropic, tangential");
  expect_error("mesh bump-48 levels=1 noise-model=isotropic\n",
               "bad.exp:4: noise-model and noise-alpha need noise-sigma=S,...");
  expect_error("noise outliers=2\n", "bad.exp:4: noise outliers=2 is outside (0, 1]");
  expect_error("noise order=2 scale=-1\n", "bad.exp:4: noise scale=-1 must be finite and >= 0");
  expect_error("radius-scaling alpha=0 c=1\n",
               "bad.exp:4: radius-scaling alpha=0 c=1: needs c > 0 and 0 < alpha <= 1");
  expect_error("radius-scaling alpha=-0.5 c=1\n", "bad.exp:4: radius-scaling alpha=-0.5 c=1");
  expect_error("sweep size\n", "bad.exp:4: sweep 'size' is not one of radius, noise");
}

// The noise of each mesh line reaches the rows' noise column and the case ids (no collision
// between meshes of one family with different noise).
TEST(Experiment, MeshNoiseReachesRowsAndCaseIds) {
  const Experiment e = parse_experiment_text(
      "method meyer\npanel p c H L2\nnoise seed=3\n"
      "mesh torus-structured levels=1 noise-sigma=0,0.03\n"
      "mesh torus-structured levels=1 noise-sigma=0.03 noise-model=tangential "
      "noise-alpha=uniform-centred\n"
      "mesh torus-structured levels=1 noise-sigma=0.03 noise-model=isotropic\n"
      "mesh torus-structured levels=1 outliers=0.01\n",
      "nz.exp");
  RunOptions o;
  o.threads = 1;
  const RunSummary run = run_experiments({e}, o);
  ASSERT_EQ(run.rows.size(), 5u);
  const std::vector<std::string> labels{"none", "normal gauss 0.03h", "tangential uniform 0.03h",
                                        "isotropic gauss 0.03h", "outliers 1%"};
  std::set<double> errors;
  for (size_t i = 0; i < labels.size(); ++i) {
    EXPECT_EQ(run.rows[i].noise, labels[i]);
    errors.insert(run.rows[i].error);
  }
  EXPECT_EQ(errors.size(), labels.size());  // five different meshes
  std::set<std::string> ids;
  const std::vector<Experiment> experiments{e};
  for (const RunCase& c : expand_cases(experiments))
    EXPECT_TRUE(ids.insert(case_id(c)).second) << case_id(c);
}

// The runner hands the options of single methods to the estimator: each variant's errors differ
// from its method's default on the same mesh.
TEST(Experiment, SingleMethodOptionsReachTheRunner) {
  const Experiment e = parse_experiment_text(
      "mesh torus-structured levels=1\npanel p c H L2\n"
      "method normal-cycle\nmethod normal-cycle ball-factor=2 label=NC-ball\n"
      "method quadric\nmethod quadric quadric-constant=yes label=Q6\n"
      "method meyer\nmethod meyer vertex-normals=angle label=Meyer-angle\n",
      "opts.exp");
  RunOptions o;
  o.threads = 1;
  const RunSummary run = run_experiments({e}, o);
  ASSERT_EQ(run.rows.size(), 6u);
  for (size_t i = 0; i < 6; i += 2) {
    EXPECT_NE(run.rows[i].method, run.rows[i + 1].method);
    EXPECT_NE(run.rows[i].error, run.rows[i + 1].error) << run.rows[i + 1].method;
  }
}

// Every shipped experiment parses, names valid families, levels and methods, and has a unique
// name and unique panel ids.
TEST(Experiment, ShippedDefinitionsAreValid) {
  const auto files = list_experiment_files(std::string(CURVBENCH_SOURCE_DIR) + "/experiments");
  ASSERT_GE(files.size(), 9u);
  std::set<std::string> names, panels;
  const auto families = mesh_families();
  for (const auto& f : files) {
    const Experiment e = parse_experiment(f);
    EXPECT_TRUE(names.insert(e.name).second) << "duplicate experiment " << e.name;
    for (const auto& m : e.meshes) {
      EXPECT_NE(std::find(families.begin(), families.end(), m.family), families.end())
          << f << ": family " << m.family;
      for (int l : m.levels) {
        EXPECT_GE(l, 1);
        EXPECT_LE(l, max_mesh_level(m.family)) << f;
      }
    }
    for (const auto& m : e.methods) {
      if (!m.is_external()) {
        EXPECT_NO_THROW(make_estimator(m.spec, {})) << m.spec;
        continue;
      }
      // An outside estimator runs a script of the repository (from its root).
      std::istringstream words(m.command);
      int scripts = 0;
      for (std::string w; words >> w;)
        if (w.rfind("experiments/", 0) == 0) {
          ++scripts;
          EXPECT_TRUE(std::filesystem::is_regular_file(std::string(CURVBENCH_SOURCE_DIR) + "/" + w))
              << f << ": " << w;
        }
      EXPECT_GE(scripts, 1) << f << ": " << m.command;
    }
    for (const auto& p : e.panels) EXPECT_TRUE(panels.insert(p.id).second) << p.id;
  }
}

// The full sweeps (experiments/sweeps/, run --full) parse; one named like a top-level experiment
// (its trimmed version) is a sweep of the same kind with the same panels.
TEST(Experiment, ShippedFullSweepsMatchTheirTrimmedVersions) {
  const std::string dir = std::string(CURVBENCH_SOURCE_DIR) + "/experiments";
  std::map<std::string, Experiment> top;
  for (const auto& f : list_experiment_files(dir)) {
    Experiment e = parse_experiment(f);
    top.emplace(e.name, std::move(e));
  }
  int replaced = 0;
  for (const auto& f : list_experiment_files(dir, true)) {
    if (f.find("/sweeps/") == std::string::npos) continue;
    const Experiment e = parse_experiment(f);
    const auto it = top.find(e.name);
    if (it == top.end()) continue;
    ++replaced;
    // A sweep at a fixed mesh, or the radius-scaling study at the same radius c h^alpha.
    EXPECT_TRUE(!e.sweep.empty() || e.radius_c > 0.0) << f;
    EXPECT_EQ(e.sweep, it->second.sweep) << f;
    EXPECT_EQ(e.radius_alpha, it->second.radius_alpha) << f;
    EXPECT_EQ(e.radius_c, it->second.radius_c) << f;
    ASSERT_EQ(e.panels.size(), it->second.panels.size()) << f;
    for (size_t i = 0; i < e.panels.size(); ++i) EXPECT_EQ(e.panels[i].id, it->second.panels[i].id);
  }
  EXPECT_EQ(replaced, 6);  // sweep-radius, sweep-noise, sweep-radius-a{1_3,1_2,2_3,1}
}

TEST(ResultsTable, CsvRoundTripAndRates) {
  std::vector<ErrorRow> rows;
  for (int level = 1; level <= 4; ++level) {
    ErrorRow r;
    r.experiment = "demo";
    r.surface = "torus";
    r.family = "torus-structured";
    r.level = level;
    r.vertices = 1000 << (2 * level);
    r.h = 0.1 / (1 << (level - 1)) * (1.0 + 0.01 * level);
    r.method = "LHF-2";
    r.degree = 2;
    r.rings = "1.5";
    r.noise = "none";
    r.vertex_set = "all";
    r.quantity = "normal";
    r.norm = "L2";
    r.error = 0.3 * std::pow(r.h, 2.0);
    rows.push_back(r);
  }
  rows.back().failed = 3;
  const auto dir = testing::fresh_dir("results_csv");
  const std::string path = (dir / "demo.csv").string();
  write_error_csv(path, rows);
  const auto back = read_error_csv(path);
  ASSERT_EQ(back.size(), rows.size());
  for (size_t i = 0; i < rows.size(); ++i) {
    EXPECT_EQ(back[i].h, rows[i].h);  // %.17g round-trips exactly
    EXPECT_EQ(back[i].error, rows[i].error);
    EXPECT_EQ(back[i].vertices, rows[i].vertices);
  }
  EXPECT_EQ(back.back().failed, 3);
  const auto rates = compute_rates(back);
  ASSERT_EQ(rates.size(), 1u);
  EXPECT_NEAR(rates[0].rate, 2.0, 1e-12);
  EXPECT_EQ(rates[0].levels, "1-4");
  ASSERT_EQ(rates[0].pairwise.size(), 3u);
  for (double p : rates[0].pairwise) EXPECT_NEAR(p, 2.0, 1e-12);
  // A damaged file is refused with its line number.
  write_file_atomic((dir / "bad.csv").string(),
                    "experiment,surface,family,level,vertices,h,method,degree,rings,noise,"
                    "vertex_set,quantity,norm,error,counted,excluded,degree_reduced,failed\n"
                    "demo,torus,f,1,10,0.1,LHF-2,2,1.5,none,all,normal,L2,abc,1,0,0,0\n");
  try {
    read_error_csv((dir / "bad.csv").string());
    FAIL();
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("bad.csv:2"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace curvbench

namespace curvbench {
namespace {

// REPORT.md names each shipped experiment's file by its path in the repository, subfolder
// included (the diagnostics were named as if they were top-level files).
TEST(Experiment, SourceNamesArePathsInTheRepository) {
  const std::string root = std::string(CURVBENCH_SOURCE_DIR) + "/";
  int diagnostics = 0;
  for (const auto& f : list_experiment_files(root + "experiments", true)) {
    const Experiment e = parse_experiment(f);
    const std::string name = experiment_source_name(e);
    EXPECT_TRUE(std::filesystem::is_regular_file(root + name)) << f << " -> " << name;
    diagnostics += name.rfind("experiments/diagnostics/", 0) == 0;
  }
  EXPECT_GE(diagnostics, 6);
}

}  // namespace
}  // namespace curvbench
