// Filling a VertexEstimate (estimator.h) from fitted quantities, or as failed / excluded.
// Shared by every estimator so that the status conventions live in one place.
#pragma once

#include <span>
#include <vector>

#include "core/shape_operator.h"
#include "methods/estimator.h"
#include "methods/local_frame.h"

namespace curvbench {

/// No estimate possible (degree 0 after all growth, e.g. an isolated vertex or too few points):
/// every value NaN, degree 0, status failed. docs/algorithms.md §5.4 suggests answering "flat"
/// (normal m0, k = 0); we output NaN instead so that no row carries numbers that are not an
/// estimate (NaN in failed/excluded rows only, docs/robustness.md). The metrics count these vertices in
/// their `failed` column.
void set_failed(double ring, int points, VertexEstimate& out);

/// Not computed by design (e.g. Xu at a boundary vertex): every value NaN, degree 0,
/// status excluded.
void set_excluded(double ring, int points, VertexEstimate& out);

/// Copies c into out with status ok (degree == requested) or degree_reduced (1 <= degree <
/// requested). Returns false, leaving out untouched, if degree < 1 or any value of c is not
/// finite.
bool set_quantities(const Curvature& c, int degree, int requested, int points, double ring,
                    VertexEstimate& out);

/// A degree-free method's estimate (degree 0): copies the quantities `computed` says the method
/// computes and leaves the others NaN. Status ok if every computed quantity is finite; partial
/// if only some are (the others NaN: e.g. H and K without the directions); returns false, with
/// `out` set failed, if none is.
bool set_operator_quantities(const Curvature& c, const ComputedQuantities& computed, int points,
                             double ring, VertexEstimate& out);

/// Where a method's fit of the curvatures is singular but it has the vertex normal its frame is
/// built on: that normal, every other value NaN, degree 0, status partial (failed if the normal
/// is not finite).
void set_normal_only(const Vec3& normal, int points, double ring, VertexEstimate& out);

/// Marks every vertex v with undetermined[v] != 0 and an estimate (ok, degree_reduced, disk_cut,
/// partial: values NaN where partial) as sign_undetermined (mesh/orientation.h); failed and
/// excluded rows stay as they are. The sign problem wins over partial: a row's NaNs say what is
/// missing, its status that the signs of what is there are arbitrary.
/// `undetermined` and `estimates` start at the same vertex (a block: both subspans).
void mark_sign_undetermined(std::span<const unsigned char> undetermined,
                            std::span<VertexEstimate> estimates);

}  // namespace curvbench
