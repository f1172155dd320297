// Declarative experiment definitions (experiments/*.exp), read by `curvbench run`.
//
// A file is a list of lines `key value...`; `#` starts a comment; double quotes group words.
// The file name is the experiment's name, its unique id: experiments/fig03-05.exp writes
// results/fig03-05.csv (a `name` line is refused).
//
//   title       "Noise-free torus, degree 2"    one line
//   section     5.1                             paper section
//   mesh        torus-structured levels=1,2,3,4 [noise-order=K] [aspect=A] [density=D]
//               one line per mesh family (meshgen families); noise-order=K (0 = none, else an
//               order: meshgen/noise.h check_noise_order) overrides the experiment's noise
//               order for this family (e.g. noise on the bump only);
//               the mesh options of the family (meshgen/generate.h, mesh_option_table()) as
//               name=value. The results name the meshes by ExperimentMesh::label()
//               (torus-anisotropic-A16), so lines of one family with other options stay apart
//   mesh        torus-unstructured levels=3 noise-sigma=0,0.01,0.03 [noise-model=normal|isotropic|
//               tangential] [noise-alpha=gaussian|uniform-centred|uniform] [outliers=0.001,0.01]
//               the mesh line's own noise, one mesh per listed value (the sweeps at a fixed mesh):
//               sigma = noise-sigma * h (order 1, scale sigma/h; 0: no noise), or outliers with
//               fraction p; the noise column says the model ("normal gauss 0.03h", "outliers 1%");
//               a mesh listed twice counts once
//   noise       order=3 seed=11 [alpha=gaussian|uniform|uniform-centred] [scale=0.1]
//               [model=normal|isotropic|tangential] [outliers=P]
//               optional controlled noise alpha h^k (meshgen/noise.h; paper §5.3,
//               docs/algorithms.md §10.3): alpha = scale N(0,1), scale U[0,1) or scale
//               U[-sqrt3,sqrt3), along the normal (or isotropic, tangential; outliers: a fraction P
//               of the vertices moved by 3h); order 1..4 (check_noise_order); a line without order=
//               sets the seed (and model) of the mesh lines' own noise
//   sweep       radius | noise                  a study at a fixed mesh (harness/report/sweeps.h):
//               reported in its own REPORT.md section, not as convergence tables; no readings;
//               needs `report sweeps`
//   report      paper | field | hard | sweeps | extra   the part of REPORT.md and the site the
//               experiment belongs to (ReportSection; default extra)
//   noisy       yes [rings=all|quadratic]       input is noisy: default rings +0.5 (paper §5.3)
//               for the fits of every degree (all) or of degree 2 only (quadratic)
//   vertex-set  all                             all | interior | boundary-ring (default all)
//   radius-scaling alpha=0.5 c=0.44             optional: each method's neighbourhood radius is
//               c h^alpha in the mesh's units (h its mean edge length) at every level: rings
//               c h^(alpha-1) rounded to half rings (>= 1) for the fits, to whole rings for the
//               quadric, ball-factor c h^(alpha-1) for the normal cycle and ICC; the 1-ring methods
//               keep their 1-ring
//   method      lhf-2 [rings=2.5] [vertex-set=interior]  one line per method and degree
//               any estimator option of role "result" as name=value (rings, centre=no,
//               qr-tol=1e-8, vertex-normals=max, ball-factor=2, ...: the table of
//               include/curvbench/estimator_options.h), and label="LHF-2 interp" to tell
//               variants apart (two methods under one label and vertex set are an error).
//               One option may list values (rings=1,1.5,2): one method per
//               value, labelled "<label> <option>=<value>" (e.g. "LHF-2 rings=1.5")
//   method      all-operators [options]   every registered degree-free operator, one line each
//               external name=N command="prog {mesh} {out}" [timeout=SECONDS]
//               [description="..."]: an outside estimator (external_estimator.h), labelled N,
//               limited to SECONDS per case (default 600), described in REPORT.md by the
//               description; a command exiting 77 skips the method (runner.h)
//   panel       fig3-left "Fig. 3 (left). ..." normal L2  one table/plot per mesh family
//
// Methods that score interior vertices only (Estimator::scores_interior_only(): Xu-2, paper
// §5.2, and the operators that exclude boundary vertices, Meyer, Taubin, normal cycle) are scored
// over interior vertices on meshes with a boundary unless a vertex-set is given explicitly.
#pragma once

#include <cstdint>
#include <limits>
#include <string>
#include <vector>

#include "harness/model/metrics.h"
#include "meshgen/generate.h"
#include "meshgen/noise.h"
#include "methods/estimator.h"

namespace curvbench {

/// The method line that stands for every registered degree-free operator.
inline constexpr const char* kAllOperators = "all-operators";

struct ExperimentMesh {
  std::string family;
  std::vector<int> levels;
  int noise_order = -1;  ///< `noise-order=K` on the mesh line: this family's controlled noise
                         ///< order instead of the experiment's (0: none); -1: the experiment's
  MeshShape shape = {};  ///< the mesh options of the line (aspect=A, density=D)

  /// The results' family column, report tables, plot names and case ids: mesh_label().
  std::string label() const { return mesh_label(family, shape); }
  /// The mesh line's own noise model (noise-sigma=, outliers=; order 1), instead of the
  /// experiment's; the case ids of such a mesh name its noise (case_store.h).
  bool has_noise_model = false;
  NoiseModel noise_model = {};

  bool operator==(const ExperimentMesh& o) const {
    return family == o.family && levels == o.levels && noise_order == o.noise_order &&
           !(shape < o.shape) && !(o.shape < shape) && has_noise_model == o.has_noise_model &&
           !(noise_model < o.noise_model) && !(o.noise_model < noise_model);
  }
};

struct ExperimentMethod {
  std::string spec;   ///< e.g. "lhf-2" (accepted by make_estimator)
  std::string label;  ///< name in tables and plots; empty = the estimator's label ("LHF-2")
  bool has_vertex_set = false;
  VertexSet vertex_set = VertexSet::all;
  /// The estimator options the line sets (role "result" only; the experiment's `noisy` and the
  /// run's threads are added by the runner).
  EstimatorOptions options;
  // spec "external": an outside estimator (external_estimator.h); its name is the label.
  std::string command;           ///< command=".. {mesh} .. {out}"
  double timeout_seconds = 0.0;  ///< timeout=S (<= 0: kDefaultExternalTimeout)
  /// description="...": what it computes, one line in REPORT.md (not part of the case's key:
  /// it does not change the results)
  std::string description;
  /// A line expanded from a list of its radius option's values (`rings=1,1.5,2`,
  /// `ball-factor=2,4`): that option and this line's value, and its label without the
  /// " rings=1.5" suffix; parameter "" and radius NaN otherwise.
  std::string radius_parameter;
  double radius = std::numeric_limits<double>::quiet_NaN();
  std::string radius_base_label;

  bool is_external() const { return spec == "external"; }
};

struct ExperimentPanel {
  std::string id;
  std::string caption;
  Quantity quantity = Quantity::normal;
  Norm norm = Norm::L2;
};

/// The part of REPORT.md and the site an experiment belongs to (`report <keyword>`). Every
/// experiment but a sweep also gets its own section of tables and plots.
enum class ReportSection {
  paper,   ///< the paper's figures: first among the experiments' sections; the leaderboard
  field,   ///< the estimators in common use: the field studies, the leaderboard, the cost page
  hard,    ///< meshes that break estimators: its field study, the leaderboard's "hard meshes"
           ///< class (and no other), the cost page
  sweeps,  ///< a study at a fixed mesh (`sweep`): the sweeps section and the cost page only
  points,  ///< the point-cloud study: its section (report/point_clouds.h) and the studies page
  extra,   ///< ablations, diagnostics, the radius scaling: its own section only
};
/// "paper", "field", "hard", "sweeps", "points", "extra".
const char* to_string(ReportSection section);
/// The inverse of to_string; throws UsageError naming the keywords.
ReportSection parse_report_section(const std::string& keyword);

struct Experiment {
  std::string name;  ///< the file name's stem
  std::string title;
  std::string section;
  std::string source;  ///< file it was read from
  std::vector<ExperimentMesh> meshes;
  std::vector<ExperimentMethod> methods;
  std::vector<ExperimentPanel> panels;
  int noise_order = 0;  ///< 0 = no controlled noise
  std::uint64_t noise_seed = 1;
  NoiseModel noise_model = {};  ///< the distribution of alpha
  bool noisy = false;
  bool noisy_quadratic_only = false;  ///< `noisy yes rings=quadratic`: +0.5 ring for degree 2 only
  double radius_alpha = 0.0;          ///< radius-scaling: radius c h^alpha (c > 0 when set)
  double radius_c = 0.0;
  std::string sweep;  ///< `sweep radius|noise`: a study at a fixed mesh; empty otherwise
  ReportSection report = ReportSection::extra;  ///< `report <keyword>`

  /// The controlled noise order of a mesh line (its own, else the experiment's).
  int noise_order_of(const ExperimentMesh& m) const {
    return m.noise_order >= 0 ? m.noise_order : noise_order;
  }

  /// The noise model of a mesh line (its own, else the experiment's).
  const NoiseModel& noise_model_of(const ExperimentMesh& m) const {
    return m.has_noise_model ? m.noise_model : noise_model;
  }

  /// The mesh the runner generates for a mesh line at `level`: the one spec of it (the runner's
  /// cache and the advice measured on the swept meshes read it).
  MeshSpec mesh_spec(const ExperimentMesh& m, int level) const {
    MeshSpec spec;
    spec.family = m.family;
    spec.level = level;
    spec.noise_order = noise_order_of(m);
    spec.seed = noise_seed;
    spec.noise_model = noise_model_of(m);
    spec.shape = m.shape;
    return spec;
  }

  /// Whether a fit of this degree gets the noisy-data half ring.
  bool noisy_for_degree(int degree) const {
    return noisy && (!noisy_quadratic_only || degree <= 2);
  }
  VertexSet vertex_set = VertexSet::all;
};

/// Parses one experiment file. Throws InputError naming the file, line and problem.
Experiment parse_experiment(const std::string& path);

/// Parses experiment text (for tests); `source` names it in error messages and gives the name
/// (its stem: "x.exp" is experiment x).
Experiment parse_experiment_text(const std::string& text, const std::string& source);

/// The experiment files in a directory (*.exp), sorted by name (the file name's stem), then those
/// of its `diagnostics` subfolder (the diagnostic experiments behind CLAIMS.md's Why lines); with
/// `full`, then those of its `sweeps` subfolder (the full sweeps, `curvbench run --full`).
std::vector<std::string> list_experiment_files(const std::string& directory, bool full = false);

/// How REPORT.md names an experiment's file: "experiments/<file>", or "experiments/<sub>/<file>"
/// for a file of the subfolders list_experiment_files reads (diagnostics/, sweeps/).
std::string experiment_source_name(const Experiment& e);

/// Every experiment of the .exp files of `dir` (list_experiment_files); with `full`, the full
/// sweeps of <dir>/sweeps/ join, one named like an earlier experiment (the trimmed sweep of the
/// default run) replacing it.
std::vector<Experiment> load_experiments(const std::string& dir, bool full = false);

}  // namespace curvbench
