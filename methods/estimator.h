// The estimator interface: one small abstract class, one implementation per file in methods/,
// one registration line in methods/registry.cpp.
//
// Output per vertex (paper §2, Table 1): unit normal, principal curvatures k1 >= k2 with unit
// directions d1, d2, mean curvature H = (k1+k2)/2, Gaussian curvature K = k1 k2, in the sign
// convention B = n . x_uu with outward/upward normals (a sphere of radius a: k1 = k2 = -1/a).
#pragma once

#include <cstdint>
#include <limits>
#include <memory>
#include <string>
#include <vector>

#include "core/types.h"
#include "mesh/mesh.h"
#include "mesh/rings.h"

namespace curvbench {

/// Per-vertex outcome.
enum class VertexStatus : std::uint8_t {
  ok = 0,                 ///< fitted at the requested degree
  degree_reduced = 1,     ///< the safeguard lowered the degree (>= 1); values are finite
  failed = 2,             ///< no fit possible (degree 0): normal = approximate normal, k = 0
  excluded = 3,           ///< not computed by design (e.g. Xu at a boundary vertex): values NaN
  disk_cut = 4,           ///< fitted at the requested degree on part of the ring's points: the
                          ///< ring is not a topological disk, cut to one around the vertex (LSCM)
  sign_undetermined = 5,  ///< finite values, but the surface around the vertex cannot be oriented
                          ///< (non-orientable or non-manifold, mesh/orientation.h): the signs of
                          ///< the normal and the curvatures are arbitrary
};

const char* to_string(VertexStatus status);

struct VertexEstimate {
  static constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
  Vec3 normal = Vec3::Constant(kNaN);
  double k1 = kNaN;
  double k2 = kNaN;
  double H = kNaN;
  double K = kNaN;
  Vec3 d1 = Vec3::Constant(kNaN);
  Vec3 d2 = Vec3::Constant(kNaN);
  int degree = 0;     ///< degree actually used
  int points = 0;     ///< rows in the least-squares system (neighbours with non-zero weight,
                      ///< plus the centre when it is a row)
  double ring = 0.0;  ///< ring actually used (after adaptive growth)
  VertexStatus status = VertexStatus::failed;
};

/// Options shared by all methods. Defaults follow the paper and ALGORITHM_NOTES.
struct EstimatorOptions {
  int degree = 2;                ///< requested fitting degree d (1..6; Xu: 2)
  double ring = 0.0;             ///< 0 = method default (Xu: 1; others (d+1)/2, +0.5 if noisy)
  bool noisy = false;            ///< noisy input: default ring +0.5 (paper §5.3)
  bool adaptive = true;          ///< half-ring growth: point count and rank-failure rules (§1.2)
  double qr_tolerance = 1e-3;    ///< |R_kk| threshold of the safeguarded QR (§5.4, [C1])
  double weight_power = -1.0;    ///< < 0: eq. (15) exponent d/4, w = gamma (|u|^2+eps)^(-d/4)
  bool normal_safeguard = true;  ///< gamma_i = max(0, m_i . m_0) of eq. (15)
  bool include_centre = true;    ///< fit c00 with the centre as a row (else interpolate p0)
  int threads = 0;               ///< 0 = OpenMP default
};

/// Mesh data shared read-only by all threads during one estimation run.
struct MeshContext {
  const Mesh& mesh;
  const VertexMatrix& approx_normals;  ///< area-weighted vertex normals (ALGORITHM_NOTES §2)
};

/// Per-thread scratch space; each method derives its own.
class Workspace {
 public:
  virtual ~Workspace() = default;
};

class Estimator {
 public:
  explicit Estimator(EstimatorOptions options) : options_(options) {}
  virtual ~Estimator() = default;

  /// Short lower-case name, e.g. "lhf".
  virtual std::string name() const = 0;
  /// Name as the paper writes it, e.g. "LHF", "Xu"; default: name() in upper case.
  virtual std::string display_name() const;
  /// Display name with degree, e.g. "LHF-2", "Xu-2".
  std::string label() const;
  const EstimatorOptions& options() const { return options_; }

  /// Ring used when options().ring == 0.
  virtual double default_ring() const;

  /// The starting neighbourhood of vertex v, the same for every ring-based method (paper §4.1,
  /// ALGORITHM_NOTES §1.2): ring r0 = options().ring or default_ring(); when options().adaptive,
  /// grown by half rings until min_neighbours(degree) neighbours or ring 2 r0. Returns r0.
  double collect_neighbourhood(RingCollector& rings, int v) const;

  virtual std::unique_ptr<Workspace> make_workspace(const Mesh& mesh) const = 0;

  /// Estimates vertex v. Must not throw; must fill every field of `out`.
  virtual void estimate(const MeshContext& ctx, int v, Workspace& ws,
                        VertexEstimate& out) const = 0;

 protected:
  EstimatorOptions options_;
};

/// Creates an estimator by name: "lhf", "lop", "xu", "lscm", "lscm-fast", "jet", or with the
/// degree attached, "LHF-2" (case-insensitive; the attached degree overrides options.degree).
/// Throws UsageError for an unknown name or an unsupported degree.
std::unique_ptr<Estimator> make_estimator(const std::string& name, EstimatorOptions options);

/// Names accepted by make_estimator (without degree).
std::vector<std::string> estimator_names();

/// Runs the estimator on every vertex, in parallel over vertices (OpenMP). The result is
/// bit-identical for any number of threads.
std::vector<VertexEstimate> estimate_mesh(const Mesh& mesh, const Estimator& estimator);

}  // namespace curvbench
