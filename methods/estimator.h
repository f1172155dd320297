// The estimator interface: one small abstract class, one implementation per file in methods/,
// one registration line in methods/registry.cpp.
//
// A method is either a degree-d fit (LHF-2, Jet-3; label "<Name>-<d>") or degree-free (a
// discrete operator such as Meyer's cotangent formula; label "<Name>", options().degree == 0).
// Per mesh, estimate_mesh() calls prepare() once (optional per-mesh data: per-face quantities,
// cotangent weights, mixed areas), then estimate() once per vertex in parallel; a vertex whose
// estimate() throws is reported as failed.
//
// Output per vertex (paper §2, Table 1): unit normal, principal curvatures k1 >= k2 with unit
// directions d1, d2, mean curvature H = (k1+k2)/2, Gaussian curvature K = k1 k2, in the sign
// convention B = n . x_uu with outward/upward normals (a sphere of radius a: k1 = k2 = -1/a).
#pragma once

#include <cstdint>
#include <limits>
#include <memory>
#include <span>
#include <string>
#include <vector>

#include "core/types.h"
#include "curvbench/estimator_options.h"
#include "curvbench/status.h"
#include "mesh/mesh.h"
#include "mesh/rings.h"

namespace curvbench {

class NeighbourhoodTable;  // mesh/neighbourhood_table.h
class NeighbourhoodCache;

/// Per-vertex outcome: the public enum (include/curvbench/status.h), whose numbers are stored
/// in PLY output.
using VertexStatus = Status;

/// The number of VertexStatus values (arrays indexed by status).
inline constexpr int kVertexStatusCount = kStatusCount;

/// The word of a status: "ok", "degree_reduced", ... (the public status_name()).
const char* to_string(VertexStatus status);

/// The quantities a method computes. A quantity it does not compute is NaN in every row, also
/// with status ok, and the harness skips its errors instead of counting the vertices as failed.
struct ComputedQuantities {
  bool normal = true;      ///< VertexEstimate::normal
  bool principal = true;   ///< k1, k2
  bool mean = true;        ///< H
  bool gaussian = true;    ///< K
  bool directions = true;  ///< d1, d2
};

struct VertexEstimate {
  static constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
  Vec3 normal = Vec3::Constant(kNaN);
  double k1 = kNaN;
  double k2 = kNaN;
  double H = kNaN;
  double K = kNaN;
  Vec3 d1 = Vec3::Constant(kNaN);
  Vec3 d2 = Vec3::Constant(kNaN);
  int degree = 0;     ///< degree actually used (0 for a degree-free method)
  int points = 0;     ///< rows in the least-squares system (neighbours with non-zero weight,
                      ///< plus the centre when it is a row)
  double ring = 0.0;  ///< ring actually used (after adaptive growth)
  VertexStatus status = VertexStatus::failed;
};

/// Per-mesh data of a method, computed once by Estimator::prepare(); derive from it.
class MeshData {
 public:
  virtual ~MeshData() = default;
};

/// Mesh data shared read-only by all threads during one estimation run.
struct MeshContext {
  const Mesh& mesh;
  /// Area-weighted vertex normals (docs/algorithms.md §2); on a point set (no faces), the normals
  /// of option point-normals: PCA or jet oriented over the k-NN graph, or the file's
  /// (points/point_normals.h).
  const VertexMatrix& approx_normals;
  const MeshData* data = nullptr;  ///< what Estimator::prepare() returned (may be null)
  /// The estimator's starting neighbourhoods, gathered once (Estimator::neighbourhood_spec(),
  /// with faces if neighbourhood_use() says so), or null: collect_neighbourhood() then collects.
  const NeighbourhoodTable* neighbourhoods = nullptr;
};

/// What a method reads of the starting neighbourhood (Estimator::collect_neighbourhood), so that
/// MeshEstimation knows whether a table of neighbourhoods serves it, and whether with faces.
enum class NeighbourhoodUse : std::uint8_t {
  none,        ///< the method does not call collect_neighbourhood (Xu, the discrete operators)
  neighbours,  ///< neighbours() and ring() only
  neighbours_and_faces,  ///< also faces() (e.g. a ring parameterization such as LSCM)
};

/// Per-thread scratch space; each method derives its own. Aligned to a cache line, so that two
/// threads' workspaces never share one.
class alignas(64) Workspace {
 public:
  virtual ~Workspace() = default;
};

class Estimator {
 public:
  /// Checks every option against the schema (methods/option_schema.h); throws UsageError.
  explicit Estimator(EstimatorOptions options);
  virtual ~Estimator() = default;

  /// Short lower-case name, e.g. "lhf".
  virtual std::string name() const = 0;
  /// Name as the paper writes it, e.g. "LHF", "Xu"; default: name() in upper case.
  virtual std::string display_name() const;
  /// False for a degree-free method (a discrete operator, not a degree-d fit).
  virtual bool takes_degree() const { return true; }
  /// True for a fit of the paper's weighted least-squares framework on rings (LHF, LOP, LSCM):
  /// the ones that read the options qr-tol, weight-power, safeguard and centre.
  virtual bool ring_fit() const { return false; }
  /// Display name with the degree for a fit ("LHF-2", "Xu-2"), without for a degree-free
  /// method ("Meyer").
  std::string label() const;
  const EstimatorOptions& options() const { return options_; }

  /// True if the method is scored over interior vertices only on a mesh with a boundary (Xu,
  /// paper §5.2): the harness's default vertex set for it. See also scores_interior_only(name).
  virtual bool scores_interior_only() const { return false; }
  /// The quantities the method computes (default: all).
  virtual ComputedQuantities computes() const { return {}; }
  /// Why the method fails a vertex where the mesh shows no defect, for `estimate`'s count of
  /// failed vertices by cause (default: a fit's system was singular).
  virtual std::string failure_without_defect() const { return "a singular fit"; }

  /// Ring used when options().rings == 0.
  virtual double default_ring() const;

  /// The starting neighbourhood of vertex v, the same for every ring-based method (paper §4.1,
  /// docs/algorithms.md §1.2): ring r0 = options().rings or default_ring(); when
  /// options().adaptive, grown by half rings until min_neighbours(degree) neighbours or ring 2 r0.
  /// Returns r0.
  double collect_neighbourhood(RingCollector& rings, int v) const;
  /// The same, served from ctx.neighbourhoods when that table holds this neighbourhood (same
  /// spec, and faces if neighbourhood_use() reads them): identical neighbours, order, faces and
  /// ring; `rings` can grow() from there as after collecting.
  double collect_neighbourhood(const MeshContext& ctx, RingCollector& rings, int v) const;
  /// The spec of that starting neighbourhood: ring r0, and with options().adaptive
  /// min_neighbours(degree) and max ring 2 r0; or the point neighbourhood of the option
  /// `neighbourhood` (knn=K, radius=R, radius=Cs) when it is set.
  NeighbourhoodSpec neighbourhood_spec() const;
  /// The same on `mesh`: on a point set (a mesh without faces) with no `neighbourhood` option,
  /// the default k-NN, knn = default_knn() (docs/point_sets.md).
  NeighbourhoodSpec neighbourhood_spec(const Mesh& mesh) const;
  /// K of the default k-NN of a point set: 2 (d+1)(d+2)/2, about the vertices of the default
  /// ring (d+1)/2 on a regular valence-6 mesh (12 for d = 2, 30 for d = 4); 3 (d+1)(d+2)/2 when
  /// noisy (half a ring more); at least regular_ring_size(default_ring()) (18 for APSS and the
  /// surface variation, whose default is the 2-ring).
  int default_knn() const;
  /// What the method reads of it; default none. A method that calls collect_neighbourhood says
  /// so, or it is never handed a table.
  virtual NeighbourhoodUse neighbourhood_use() const { return NeighbourhoodUse::none; }

  /// Whether prepare() or estimate() reads MeshContext::approx_normals (the area-weighted vertex
  /// normals). If not, MeshEstimation does not compute them and hands over an empty matrix.
  virtual bool uses_approx_normals() const { return true; }

  virtual std::unique_ptr<Workspace> make_workspace(const Mesh& mesh) const = 0;

  /// Per-mesh precomputation (per-face tensors, cotangent weights, mixed areas ...), run once
  /// by estimate_mesh() before the per-vertex loop, with `threads` OpenMP threads. The result
  /// must not depend on `threads` (each face or vertex writes only its own slots; sums are
  /// gathered in a fixed order). It may throw (outside any parallel region). Default: none.
  virtual std::unique_ptr<MeshData> prepare(const Mesh& mesh, const VertexMatrix& approx_normals,
                                            int threads) const;

  /// Estimates vertex v; must fill every field of `out`. It may throw: estimate_mesh() then
  /// reports the vertex as failed (every value NaN).
  virtual void estimate(const MeshContext& ctx, int v, Workspace& ws,
                        VertexEstimate& out) const = 0;

  /// Estimates vertices first, ..., first + count - 1 into out[0 .. count) (the batch hook of
  /// the batched kernels). Each vertex's result must be what estimate() gives up to rounding and
  /// must not depend on the other vertices of the batch. Default: estimate() per vertex, a
  /// vertex that throws is failed. An override may throw: MeshEstimation then redoes the batch
  /// vertex by vertex with estimate().
  virtual void estimate_batch(const MeshContext& ctx, int first, int count, Workspace& ws,
                              VertexEstimate* out) const;

 protected:
  /// The ring option of a ring-based fit: 0 (the default) or a multiple of half a ring >= 1,
  /// returned rounded to the half ring; throws UsageError naming `method` otherwise.
  static double half_rings(double rings, const std::string& method);

  EstimatorOptions options_;
};

/// Creates an estimator by name: "lhf", "lop", "xu", "lscm", "jet", "meyer", ...
/// (estimator_names()), a fit optionally with the degree attached, "LHF-2" (case-insensitive;
/// the attached degree overrides options.degree). options.degree == 0 gives a fit its default
/// degree 2. Throws UsageError for an unknown name, an unsupported degree, any degree (given
/// or attached) for a degree-free method, an option out of its range, or an option set for a
/// method it does not apply to (methods/option_schema.h).
std::unique_ptr<Estimator> make_estimator(const std::string& name, EstimatorOptions options);

/// The degree make_estimator(name, options) builds the estimator with (options().degree), without
/// building it: the degree attached to the name, else options.degree, else 2 for a fit; 0 for a
/// degree-free method. Throws make_estimator's UsageErrors for the name and the degree.
int estimator_degree(const std::string& name, EstimatorOptions options);

/// The family a method belongs to on the results site and in the leaderboard's filters.
enum class MethodGroup {
  paper_fit,  ///< the paper's parameterization-based fits (LHF, LOP, Xu, LSCM)
  jet,        ///< CGAL's osculating jet
  discrete,   ///< an operator on the 1-ring or a ball (Meyer, Taubin, ICC, ...): the methods
              ///< an experiment's `method all-operators` runs
  point_set,  ///< an estimator of the point-set literature (APSS, surface variation)
  outside,    ///< not in the registry: an outside estimator (a command of an experiment file)
};
/// "paper fits", "jets", "discrete operators", "point-set estimators", "outside estimators".
const char* to_string(MethodGroup g);

/// What a method's neighbourhood size is, declared on its registry line: the runner's radius
/// scaling, the sweeps and the advice read it instead of the method's name.
enum class NeighbourhoodSize {
  fixed,        ///< one 1-ring, nothing to size (Xu, Meyer, Taubin, ...)
  half_rings,   ///< option `rings`, in steps of 1/2 (the polynomial fits, the jet)
  whole_rings,  ///< option `rings`, whole rings (the quadric)
  ball_factor,  ///< option `ball-factor`: a ball of radius C h (normal cycle, ICC)
};
/// The option that sets a neighbourhood size of this kind: "rings" (half_rings, whole_rings),
/// "ball-factor" (ball_factor), "" (fixed).
const char* radius_option(NeighbourhoodSize size);
/// Every kind, for code that looks an option name up (is "rings" a radius option?).
inline constexpr NeighbourhoodSize kNeighbourhoodSizes[] = {
    NeighbourhoodSize::fixed, NeighbourhoodSize::half_rings, NeighbourhoodSize::whole_rings,
    NeighbourhoodSize::ball_factor};

/// One line of the registry (methods/registry.cpp): what the rest of the project needs to know
/// of a method besides its estimator.
struct MethodInfo {
  std::string name;    ///< --method name, e.g. "lhf"
  int min_degree = 0;  ///< degrees of a fit; 0, 0 for a degree-free operator
  int max_degree = 0;
  std::vector<int> bench_degrees;  ///< make bench's rows (0: a degree-free operator, once)
  double cost = 1.0;               ///< seconds per vertex relative to LHF-2 (shard balance)
  std::string summary;             ///< one line for --help
  MethodGroup group = MethodGroup::discrete;            ///< its family on the results site
  NeighbourhoodSize radius = NeighbourhoodSize::fixed;  ///< what its neighbourhood size is
  bool is_fit() const { return max_degree > 0; }
};

/// The registry line of a method name or label ("lhf", "LHF-2", "Meyer"); throws UsageError for
/// a name no registered method has.
const MethodInfo& method_info(const std::string& name_or_label);

/// The group of a method label as the result CSVs spell it ("LHF-2", "Meyer", "LSCM-fast-4",
/// case-insensitive, a trailing degree ignored), a variant's label included ("LHF-2
/// (1.5-ring)", "LHF-2 rings=3", "ICC-ball2": the longest registered name that starts it);
/// MethodGroup::outside when no registered method starts it.
MethodGroup method_group(const std::string& label);

/// Every registered method, in registry order.
std::vector<MethodInfo> method_table();

/// The name a method's labels start with ("LHF", "LSCM-fast", "SurfVar"): its estimator's
/// display_name().
std::string display_name(const MethodInfo& method);

using EstimatorFactory = std::unique_ptr<Estimator> (*)(EstimatorOptions);

/// Adds a method to the registry, after the built-in ones (docs/extending.md): from then on
/// make_estimator(), the experiment files (`method NAME`, `method all-operators`), the runner and
/// every list of methods include it. Call it before estimating (not thread-safe against
/// concurrent lookups). Throws UsageError for an empty or upper-case name, a name that exists,
/// degrees other than 0, 0 or 1 <= min <= max, or a null factory.
void register_estimator(const MethodInfo& info, EstimatorFactory factory);

/// Labels of every method: each fit at each of its degrees within [lowest, highest]
/// ("lhf-2", ...), each degree-free operator once ("meyer"); registry order.
std::vector<std::string> method_labels(int lowest_degree, int highest_degree);

/// Names accepted by make_estimator (without degree).
std::vector<std::string> estimator_names();

/// The names of the methods that work on a point set (neighbourhood_use() is neighbours), in
/// registry order, joined by ", ".
std::string point_set_methods();

/// Whether the built-in method named by `method` (a name or label as make_estimator accepts,
/// e.g. "Xu-2") scores interior vertices only (Estimator::scores_interior_only()); false for a
/// name that is not a built-in method (e.g. an outside estimator's label).
bool scores_interior_only(const std::string& method);

/// One estimation run of `estimator` over `mesh`, vertex range by vertex range, so that a caller
/// can stream results in blocks instead of holding one record per vertex. The constructor does
/// the per-mesh work once (area-weighted normals, Estimator::prepare(), one workspace per
/// thread); run() estimates a range of vertices in parallel (OpenMP). Results are bit-identical
/// for any number of threads and any split into ranges. The mesh and estimator must outlive it.
/// On a point set (a mesh without faces) the normals are those of option point-normals (oriented
/// PCA or jet normals, or the file's; throws InputError for `file` without given normals) and the
/// neighbourhoods k-NN or balls (docs/point_sets.md); a vertex whose normal's sign is undecided
/// gets status sign_undetermined. On a mesh with faces, point-normals other than pca throws
/// UsageError. A method that needs faces (neighbourhood_use() other than
/// neighbours) throws UsageError on a point set, and so does one given the `neighbourhood` option.
/// With a NeighbourhoodCache of the same mesh, a method that reads starting neighbourhoods
/// (Estimator::neighbourhood_use()) takes them from the cache's table of its spec (built now if
/// the cache has none), with the same results; throws std::invalid_argument for a cache of
/// another mesh.
class MeshEstimation {
 public:
  MeshEstimation(const Mesh& mesh, const Estimator& estimator,
                 NeighbourhoodCache* neighbourhoods = nullptr);
  ~MeshEstimation();
  MeshEstimation(const MeshEstimation&) = delete;
  MeshEstimation& operator=(const MeshEstimation&) = delete;

  int num_vertices() const { return mesh_.num_vertices(); }
  int threads() const { return threads_; }
  /// Estimates vertices first, ..., first + out.size() - 1 into out (out[i] is vertex first + i).
  /// Throws std::out_of_range for a range outside the mesh.
  void run(int first, std::span<VertexEstimate> out);

 private:
  const Mesh& mesh_;
  const Estimator& estimator_;
  VertexMatrix normals_;
  std::unique_ptr<MeshData> data_;
  std::shared_ptr<const NeighbourhoodTable> neighbourhoods_;
  std::vector<unsigned char> sign_undetermined_;  // point set: normals whose sign is undecided
  std::vector<std::unique_ptr<Workspace>> workspaces_;
  int threads_ = 1;
};

/// Runs the estimator on every vertex (one MeshEstimation over the whole mesh, with the optional
/// cache of starting neighbourhoods). The result is bit-identical for any number of threads,
/// with or without the cache.
std::vector<VertexEstimate> estimate_mesh(const Mesh& mesh, const Estimator& estimator,
                                          NeighbourhoodCache* neighbourhoods = nullptr);

}  // namespace curvbench
