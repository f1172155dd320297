// Errors by cause (after Gatzke and Grimm 2006): at the finest level of each mesh of a study,
// the relative L2 error in H (metrics.h compute_error) restricted to the vertices of bins of
//   valence         <=4, 5, 6, 7, >=8 edge neighbours (mesh_checks.h vertex_valences)
//   smallest angle  the smallest corner angle of the triangles around the vertex, in degrees:
//                   <10, 10-20, 20-30, 30-45, >=45 (a vertex without triangles is in none)
//   sign of K       the exact Gaussian curvature: K>0, K<0, or K~0 (|K| <= kTinyGaussian
//                   times the largest |K| of the mesh's vertices)
// plus the whole vertex set ("all", the reference), each intersected with the case's vertex set.
//
// errors-by-cause CSV (one per experiment, results/errors_by_cause/<name>.csv), one row per
//   (mesh family, finest level, method, bin):
//   experiment,surface,family,level,vertices,h,method,degree,noise,vertex_set,quantity,norm,
//   cause,bin,error,counted,excluded
//   counted + excluded = the vertices of the set in the bin.
#pragma once

#include <span>
#include <string>
#include <vector>

#include "harness/model/experiment.h"
#include "harness/model/metrics.h"
#include "harness/model/results_table.h"
#include "mesh/mesh.h"
#include "surfaces/surface.h"

namespace curvbench {

/// |K| at most this fraction of the mesh's largest |K| counts as "tiny".
inline constexpr double kTinyGaussian = 0.01;

struct CauseBin {
  const char* cause;  ///< "all", "valence", "min-angle", "K-sign"
  const char* bin;    ///< "all", "<=4", "5", ..., "<10", "10-20", ..., "K>0", "K<0", "K~0"
};

/// The bins in table order: "all" first, then valence, smallest angle and sign of K.
std::span<const CauseBin> cause_bins();

/// The quantity and norm of the errors by cause (the relative L2 error in H).
inline constexpr Quantity kCauseQuantity = Quantity::H;
inline constexpr Norm kCauseNorm = Norm::L2;

/// Smallest corner angle (degrees) of the triangles incident on each vertex; NaN without one.
std::vector<double> min_incident_angles(const Mesh& mesh);

/// What the bins of a mesh's vertices are made from, computed once per mesh.
struct VertexCauses {
  std::vector<int> valence;       ///< vertex_valences
  std::vector<double> min_angle;  ///< min_incident_angles
  double max_abs_K = 0.0;         ///< the largest finite |K| of the exact points
};
/// `exact` holds the exact surface point of every mesh vertex.
VertexCauses vertex_causes(const Mesh& mesh, std::span<const SurfacePoint> exact);

/// For each bin of cause_bins(), the vertices of `vertices` in it (increasing if `vertices` is).
std::vector<std::vector<int>> cause_bin_vertices(const VertexCauses& causes,
                                                 std::span<const SurfacePoint> exact,
                                                 std::span<const int> vertices);

struct CauseRow {
  std::string experiment, surface, family;
  int level = 0;
  int vertices = 0;  ///< of the mesh
  double h = 0.0;
  std::string method;
  int degree = 0;
  std::string noise, vertex_set, quantity, norm;
  std::string cause, bin;
  double error = 0.0;  ///< NaN for an empty bin (or one whose exact H vanishes throughout)
  int counted = 0;
  int excluded = 0;
};

/// One row per bin: compute_error(kCauseQuantity, kCauseNorm) over the bin's vertices, the other
/// columns copied from `like` (a row of the case).
std::vector<CauseRow> cause_rows(const ErrorRow& like, const VertexCauses& causes,
                                 std::span<const VertexEstimate> estimates,
                                 std::span<const SurfacePoint> exact,
                                 std::span<const int> vertices);

/// Whether the runner computes the errors by cause of a case at this level of the mesh: its
/// finest level.
bool finest_level(const ExperimentMesh& mesh, int level);

/// The CSV text: `comment` (one or more '#' lines without the final newline; none if empty),
/// the header, the rows.
std::string cause_csv_text(const std::vector<CauseRow>& rows, const std::string& comment);
/// Writes the CSV (provenance comment, header, rows) atomically.
void write_cause_csv(const std::string& path, const std::vector<CauseRow>& rows);
/// Parses the CSV text; `name` names it in error messages (InputError).
std::vector<CauseRow> parse_cause_csv(const std::string& text, const std::string& name);
/// Reads the CSV file; throws InputError.
std::vector<CauseRow> read_cause_csv(const std::string& path);

}  // namespace curvbench
