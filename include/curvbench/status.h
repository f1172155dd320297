// The outcome of an estimate at one vertex (public: installed with <curvbench/curvbench.h>): the
// library's estimators, the C++ API, the Python module and the PLY/CSV output of `curvbench
// estimate` all use this one enum. The numbers are written to files: a new value goes at the
// end, with the next number, its word in to_string(VertexStatus) (methods/estimate_mesh.cpp) and
// kStatusCount raised.
#pragma once

#include <cstdint>

namespace curvbench {

enum class Status : std::uint8_t {
  ok = 0,                 ///< estimated (at the requested degree, for a fit); the quantities the
                          ///< method computes are finite, the others (e.g. the directions of
                          ///< Meyer's operator) NaN
  degree_reduced = 1,     ///< the safeguard lowered the degree (>= 1); values are finite
  failed = 2,             ///< no estimate possible (or the estimator threw): every value NaN
  excluded = 3,           ///< not computed by design (e.g. Xu at a boundary vertex): values NaN
  disk_cut = 4,           ///< fitted at the requested degree on part of the ring's points: the
                          ///< ring is not a topological disk, cut to one around the vertex (LSCM)
  sign_undetermined = 5,  ///< an estimate (finite values; NaN where it would be partial), but the
                          ///< surface around the vertex cannot be oriented (non-orientable or
                          ///< non-manifold): the signs of the normal and the curvatures are
                          ///< arbitrary
  partial = 6,      ///< the quantities that can be determined at the vertex are finite, the rest
                    ///< of what the method computes NaN (e.g. Meyer's H and K where the edge
                    ///< tensor fit of the directions is singular: d1, d2 NaN; or only the normal
                    ///< where a fit of the curvatures is singular)
  reprojected = 7,  ///< LSCM: the map of the ring folded it (the fitted normal turned more than
                    ///< 90 degrees from the mesh's vertex normal); fitted on the ring's
                    ///< orthogonal projection onto the tangent plane instead (LOP's map)
  normal_fallback = 8,  ///< an operator fed a fit's normals (option vertex-normals = lhf-3, ...):
                        ///< the fit gave no normal at a vertex whose normal this estimate reads
                        ///< (the vertex itself, or a corner of a face it sums); the operator's
                        ///< own vertex normal stood in there; values finite
};

/// The number of Status values (arrays indexed by status).
inline constexpr int kStatusCount = 9;

/// "ok", "degree_reduced", "failed", "excluded", "disk_cut", "sign_undetermined", "partial",
/// "reprojected", "normal_fallback"; "unknown" for a number that is not a Status.
const char* status_name(Status status);

}  // namespace curvbench
