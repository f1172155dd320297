// curvbench's public C++ API: per-vertex normals, principal curvatures and directions of a
// triangle mesh by the paper's local polynomial fits (Wang, Jiao et al., CAGD 2009), CGAL's jet
// fitting and the common discrete operators (methods()), in the style of libigl/pmp: Eigen
// matrices in, an options struct, a result struct out.
//
//   V  n x 3 double  vertex positions
//   F  m x 3 int     triangles (0-based), counter-clockwise seen from outside (closed surfaces)
//                    or from +z (height fields)
//
// Sign convention (paper §2): B = n . x_uu with outward (closed) or upward (height field)
// normals, so a sphere of radius r has k1 = k2 = H = -1/r; k1 >= k2, d1 goes with k1,
// H = (k1 + k2) / 2, K = k1 k2.
//
// This header includes only Eigen and the standard library (and <curvbench/errors.h>,
// <curvbench/estimator_options.h>, <curvbench/status.h>); the library's internal headers are not
// installed. Link with curvbench::curvbench (CMake:
// find_package(curvbench CONFIG)).
#pragma once

#include <Eigen/Core>
#include <cstdint>
#include <limits>
#include <optional>
#include <string>
#include <utility>
#include <variant>
#include <vector>

#include "curvbench/errors.h"
#include "curvbench/estimator_options.h"
#include "curvbench/status.h"

namespace curvbench {

/// The method and its options. The options (degree, rings, noisy, threads, vertex_normals,
/// ball_factor, ...) are those of <curvbench/estimator_options.h>, each documented there; an
/// option set away from its default for a method that does not take it is a UsageError.
struct EstimateOptions : EstimatorOptions {
  /// A name of methods(), case-insensitive; "LHF-4" attaches d. Or "auto": the estimator and
  /// radius recommend() gives the mesh from the installed table (then only the run options
  /// threads and kernel may be set; EstimateResult::recommendation holds the advice).
  std::string method = "lhf";
};

/// The advice of `curvbench recommend` for a mesh: its quality class and noise, and the most
/// accurate case of the sweep run on meshes of that class at that noise (results/
/// recommendations.csv).
struct MeshAdvice {
  static constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
  std::string quality;         ///< the mesh's quality class
  std::string quality_reason;  ///< why
  double sigma_over_h = 0.0;   ///< its noise sigma/h along the normal, given or estimated
  bool noise_estimated = false;
  double noise_level = 0.0;  ///< the table's nearest noise level
  /// False: no sweep ran for that class and level; the fields of the choice below are empty.
  bool swept = false;
  std::string method;          ///< EstimateOptions::method of the choice ("lhf-4")
  std::string parameter;       ///< the neighbourhood option it sets ("rings", "ball-factor") or ""
  double radius = kNaN;        ///< that option's value (NaN without one)
  std::string label;           ///< the sweep's case ("LHF-4 rings=2")
  std::string quantity, norm;  ///< what the sweep ranked by ("H", "L2")
  double error = kNaN;         ///< the error the sweep measured
  std::string experiment, family;  ///< the sweep and the mesh it measured on
  int level = 0;
  std::string table;       ///< the recommendations file read
  std::string provenance;  ///< its first comment line
  // With the advice from mesh features (advice_cases.csv beside the table; docs/advice.md) the
  // choice above is the mean curvature's, learned from the swept meshes nearest in the mesh's
  // features (experiment, family, level: the nearest; error: the choice's error there), and:
  std::string normal_method;     ///< the normals' choice ("" without one)
  std::string normal_parameter;  ///< its neighbourhood option
  double normal_radius = kNaN;
  std::string normal_label;                    ///< its case
  double error_low = kNaN, error_high = kNaN;  ///< the choice's error on the nearest meshes
  /// Cross-validation on those meshes: the choice learned without each, over the best error.
  double regret_median = kNaN, regret_worst = kNaN;
  std::vector<std::string> out_of_range;  ///< features outside the swept meshes' range
  // With RecommendOptions::measure (docs/advice.md, "Measured on the mesh"): both choices are
  // those measured on the mesh itself, `error` is the curvature choice's predicted relative L2
  // error in H, experiment is "measured on the mesh" (family empty, level 0, error_low and
  // error_high NaN: no swept mesh stands behind it), and regret_median, regret_worst are what the
  // same measurement did for H on the swept meshes (advice_measured.csv beside the table; NaN
  // without it).
  bool measured = false;
  double normal_predicted = kNaN;  ///< the normals' choice's predicted RMS error
};

/// Per-vertex estimates; row/entry i belongs to vertex i.
struct EstimateResult {
  std::string method;       ///< label with degree, e.g. "LHF-2"
  Eigen::MatrixX3d normal;  ///< n x 3 unit normals
  Eigen::VectorXd k1, k2;   ///< n principal curvatures, k1 >= k2
  Eigen::VectorXd H, K;     ///< n mean and Gaussian curvature
  Eigen::MatrixX3d d1, d2;  ///< n x 3 principal directions
  Eigen::VectorXi degree;   ///< n degree actually used
  Eigen::VectorXi points;   ///< n points in each least-squares fit
  Eigen::VectorXd ring;     ///< n ring actually used
  std::vector<Status> status;
  std::optional<MeshAdvice> recommendation;  ///< method "auto": the advice it followed
};

/// Estimates every vertex of the mesh (V, F). Throws InputError for an invalid mesh (index out
/// of range, repeated vertex in a face, NaN/Inf coordinate) and UsageError for an unknown method,
/// an unsupported degree, a degree that contradicts the one in `method`, an option out of range
/// or given to a method that does not take it; the messages are the command line's. Method
/// "auto" throws as recommend() does, InputError when the table's row for the mesh was not
/// swept, and UsageError for an option of the estimate (not threads or kernel) set away from its
/// default. The result is bit-identical to `curvbench estimate` on the same mesh and does not
/// depend on the thread count.
EstimateResult estimate(const Eigen::MatrixXd& V, const Eigen::MatrixXi& F,
                        const EstimateOptions& options = {});

/// Reads an OFF, OBJ or PLY file (polygons fan-triangulated) into V (n x 3) and F (m x 3).
/// With `warnings`, one line each about what the reader dropped (faces with fewer than 3
/// vertices or a repeated index), as the command line prints them. Throws InputError naming the
/// file.
void read_mesh(const std::string& path, Eigen::MatrixXd& V, Eigen::MatrixXi& F,
               std::vector<std::string>* warnings = nullptr);

/// recommend()'s inputs besides the mesh.
struct RecommendOptions {
  /// The mesh's noise sigma/h along the normal; NaN: estimated from the residuals of a degree-4
  /// fit at each vertex.
  double noise = std::numeric_limits<double>::quiet_NaN();
  /// A folder holding the recommendations.csv to read; "": the table installed with curvbench
  /// (or the source tree's, for a build tree).
  std::string results;
  /// Also measure the advice on the mesh itself (`curvbench recommend --measure`): every swept
  /// case runs on it 3 times. Needs advice_cases.csv beside the table.
  bool measure = false;
  int threads = 0;  ///< of the measurement (0: all cores)
};

/// The estimator and radius recommended for the mesh (V, F), as `curvbench recommend`. Throws
/// InputError for a mesh it cannot classify (under 50 vertices, non-manifold) or a missing,
/// truncated or foreign table; UsageError for a negative or non-finite noise.
MeshAdvice recommend(const Eigen::MatrixXd& V, const Eigen::MatrixXi& F,
                     const RecommendOptions& options = {});

// ---- test meshes with their exact answers, and the harness's error metrics ----------------

/// A test mesh of curvbench's families, as `curvbench mesh` makes it.
struct TestMeshOptions {
  std::string family;      ///< "torus-structured", "torus-iso", "bump-48", ... (mesh_families())
  int level = 1;           ///< 1 = coarsest
  int noise_order = 0;     ///< k >= 1 adds alpha h^k noise along the normal; 0 = none
  std::uint64_t seed = 1;  ///< of the noise, jitter and irregular points
  /// Mesh options by name, in order (mesh_options(): {"aspect", 16}); only for the families
  /// that take them.
  std::vector<std::pair<std::string, double>> shape;
};

/// The exact quantities of the surface at each vertex of a test mesh; row/entry i is vertex i.
struct ExactQuantities {
  Eigen::MatrixX3d point;     ///< n x 3 the surface point the vertex stands for (the vertex itself
                              ///< unless noise moved it)
  Eigen::MatrixX3d normal;    ///< n x 3 unit normals, in the sign convention above
  Eigen::VectorXd k1, k2;     ///< n principal curvatures, k1 >= k2
  Eigen::VectorXd H, K;       ///< n mean and Gaussian curvature
  Eigen::MatrixX3d d1, d2;    ///< n x 3 principal directions (sign arbitrary)
  std::vector<bool> umbilic;  ///< n: k1 == k2 there, so d1 and d2 are arbitrary
};

struct TestMesh {
  Eigen::MatrixXd V;  ///< n x 3 vertex positions
  Eigen::MatrixXi F;  ///< m x 3 triangles
  ExactQuantities exact;
  std::string surface;      ///< name of the analytic surface
  std::string description;  ///< one line: parameters, seed, noise
};

/// Generates the mesh. Throws UsageError (naming the valid values) for an unknown family or
/// mesh option, a level out of range, a noise order outside 0..4, or a mesh option out of range
/// or not taken by the family.
TestMesh generate_mesh(const TestMeshOptions& options);

/// Names of the test-mesh families, in table order.
std::vector<std::string> mesh_families();

/// One mesh option of TestMeshOptions::shape.
struct MeshOptionDescription {
  std::string name;      ///< "aspect"
  double default_value;  ///< used when not given
  std::string help;      ///< one line: what it sets, the families that take it
};
std::vector<MeshOptionDescription> mesh_options();

/// One quantity's errors (docs/metrics.md): normal absolute (RMS and max of |n~ - n|); H, K,
/// k1, k2 relative norm ratios; d1 over the non-umbilic vertices.
struct QuantityError {
  std::string quantity;  ///< "normal", "H", "K", "k1", "k2", "d1"
  double L2 = 0.0;       ///< NaN when no vertex contributed
  double Linf = 0.0;
  int counted = 0;   ///< vertices that contributed
  int excluded = 0;  ///< vertices of the set left out: their estimate is excluded or NaN
};

/// The errors of an estimate of the mesh (V, F) against its exact quantities over a vertex set
/// ("all", "interior", "boundary-ring"), as the harness computes them: one QuantityError per
/// quantity normal, H, K, k1, k2, d1 in that order. Throws InputError when the estimate or the
/// exact quantities have another vertex count than V, UsageError for an unknown vertex set.
std::vector<QuantityError> score(const Eigen::MatrixXd& V, const Eigen::MatrixXi& F,
                                 const ExactQuantities& exact, const EstimateResult& estimate,
                                 const std::string& vertex_set = "all");

// ---- the estimator option table, for bindings -----------------------------------------------

/// One option of EstimatorOptions (<curvbench/estimator_options.h>), as its table declares it.
struct OptionDescription {
  std::string name;          ///< "ball-factor": the command line's --ball-factor
  std::string python_name;   ///< "ball_factor": a keyword (the C++ field's name)
  std::string type;          ///< "bool", "int", "double" or "choice"
  std::string default_text;  ///< the default as text ("0", "yes", "default")
  std::string help;          ///< one line
};
/// Every option, in the table's order.
std::vector<OptionDescription> estimator_options();

/// A value as a binding hands it over.
using OptionValue = std::variant<bool, long long, double, std::string>;
/// Sets option `name` (its name or python_name) from a typed value: a bool for a bool, an
/// integer for an int, a number for a double, a string for a choice. Throws UsageError
/// "<name>: <problem>" for an unknown name, a value of the wrong type or out of range.
void set_estimator_option(EstimatorOptions& options, const std::string& name,
                          const OptionValue& value);

/// Estimates every point of a point set V (no faces; docs/point_sets.md) with a method that
/// reads neighbours only (lhf, lop, jet, ...): the neighbourhood is options.neighbourhood
/// (knn=K, radius=R, radius=Cs), by default the k nearest neighbours, K = 2 (d+1)(d+2)/2; the
/// normals are PCA normals oriented over the k-NN graph (outward on a closed set, upward on an
/// open one; status sign_undetermined where no rule decides). The same as estimate(V, F) with
/// an empty F. A method that needs faces is a UsageError.
EstimateResult estimate(const Eigen::MatrixXd& V, const EstimateOptions& options);

/// Names accepted as EstimateOptions::method (without degree).
std::vector<std::string> methods();

/// e.g. "0.1.0".
std::string version();

}  // namespace curvbench
