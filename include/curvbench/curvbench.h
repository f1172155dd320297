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
// <curvbench/estimator_options.h>); the
// library's internal headers are not installed. Link with curvbench::curvbench (CMake:
// find_package(curvbench CONFIG)).
#pragma once

#include <Eigen/Core>
#include <cstdint>
#include <string>
#include <vector>

#include "curvbench/errors.h"
#include "curvbench/estimator_options.h"

namespace curvbench {

/// Outcome per vertex (the same codes as the CSV/PLY output of `curvbench estimate`).
enum class Status : std::uint8_t {
  ok = 0,              ///< estimated (at the requested degree, for a fit); quantities the method
                       ///< does not compute (e.g. directions of Meyer's operator) are NaN
  degree_reduced = 1,  ///< the safeguard lowered the degree; values are finite
  failed = 2,          ///< no estimate possible: every value NaN
  excluded = 3,        ///< not computed by design (e.g. Xu at a boundary vertex): values NaN
  disk_cut = 4,        ///< fitted on part of the ring: the ring was not a disk and was cut (LSCM)
  sign_undetermined = 5,  ///< finite, but the surface there cannot be oriented (non-orientable
                          ///< or non-manifold): the signs of normal and curvatures are arbitrary
  partial = 6,  ///< what can be determined at the vertex is finite, the rest NaN (e.g. Meyer's
                ///< directions where its edge tensor fit is singular, or only the normal)
  reprojected = 7,  ///< LSCM: the map folded the ring (its normal turned more than 90 degrees
                    ///< from the mesh's); fitted on the ring's projection onto the tangent plane
};

/// "ok", "degree_reduced", "failed", "excluded", "disk_cut", "sign_undetermined", "partial",
/// "reprojected".
const char* status_name(Status status);

/// The method and its options. The options (degree, rings, noisy, threads, vertex_normals,
/// ball_factor, ...) are those of <curvbench/estimator_options.h>, each documented there; an
/// option set away from its default for a method that does not take it is a UsageError.
struct EstimateOptions : EstimatorOptions {
  std::string method = "lhf";  ///< a name of methods(), case-insensitive; "LHF-4" attaches d
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
};

/// Estimates every vertex of the mesh (V, F). Throws InputError for an invalid mesh (index out
/// of range, repeated vertex in a face, NaN/Inf coordinate) and UsageError for an unknown method,
/// an unsupported degree, a degree that contradicts the one in `method`, an option out of range
/// or given to a method that does not take it; the messages are the command line's. The result is bit-identical to `curvbench estimate` on the same mesh and
/// does not depend on the thread count.
EstimateResult estimate(const Eigen::MatrixXd& V, const Eigen::MatrixXi& F,
                        const EstimateOptions& options = {});

/// Estimates every point of a point set V (no faces; docs/point_sets.md) with a method that
/// reads neighbours only (lhf, lop, jet, ...): the neighbourhood is options.neighbourhood
/// (knn=K, radius=R, radius=Cs), by default the k nearest neighbours, K = 2 (d+1)(d+2)/2; the
/// normals are PCA normals oriented over the k-NN graph (outward on a closed set, upward on an
/// open one; status sign_undetermined where no rule decides). The same as estimate(V, F) with
/// an empty F. A method that needs faces is a UsageError.
EstimateResult estimate(const Eigen::MatrixXd& V, const EstimateOptions& options);

/// Reads an OFF, OBJ or PLY file (polygons fan-triangulated). Throws InputError naming the file.
void read_mesh(const std::string& path, Eigen::MatrixXd& V, Eigen::MatrixXi& F);

/// Names accepted as EstimateOptions::method (without degree).
std::vector<std::string> methods();

/// e.g. "0.1.0".
std::string version();

}  // namespace curvbench
