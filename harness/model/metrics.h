// Error metrics and convergence rates of the paper §5 (docs/algorithms.md §12).
//
//   normals      L2 = sqrt(mean_i |n~_i - n_i|^2),  Linf = max_i |n~_i - n_i|        (absolute)
//   H, K, k1, k2 L2 = |k~ - k|_2 / |k|_2,          Linf = |k~ - k|_inf / |k|_inf    (relative)
//                when |k| = 0 over the scored vertices (k1 and K on a cylinder), the denominator
//                is the same norm of the curvature scale s_i = max(|k1_i|, |k2_i|) (s_i^2 for K):
//                an absolute error in units of the surface's curvature (NaN if s = 0 too)
//   d1           L2 = sqrt(mean_i e_i^2), e_i = min(|d~1 - d1|, |d~1 + d1|), over non-umbilic
//                vertices (|k1 - k2| > 1e-8 max|k|), Linf = max_i e_i
//   rate         log(e_1 / e_N) / log(h_1 / h_N) with the measured mean edge lengths (a point
//                set's nominal spacing sqrt(area / n))
// Two norms of the point-cloud literature (PCPNet, Guerrero et al. 2018), for the point-cloud
// study:
//   normals      angle-rms = sqrt(mean_i theta_i^2) in degrees, theta_i = acos |n~_i . n_i| (the
//                unoriented angle: a flipped normal counts as right, as PCPNet scores it)
//   H, K, k1, k2 rectified = mean_i |k~_i - k_i| / max(|k_i|, 1)
//
// Vertices whose estimate is `excluded`, or whose value of the quantity scored is NaN (failed, or
// not computed by the method), are left out of every sum and counted.
#pragma once

#include <span>
#include <string>
#include <vector>

#include "methods/estimator.h"
#include "surfaces/surface.h"

namespace curvbench {

enum class Quantity { normal, H, K, k1, k2, d1 };
enum class Norm { L2, Linf, angle_rms, rectified };

const char* to_string(Quantity q);
const char* to_string(Norm n);
/// Parses "normal", "H", "K", "k1", "k2", "d1" (case-sensitive); throws UsageError otherwise.
Quantity parse_quantity(const std::string& s);
/// Parses "L2", "Linf", "angle-rms", "rectified"; throws UsageError otherwise.
Norm parse_norm(const std::string& s);
/// Throws UsageError unless the norm measures the quantity: angle-rms only normals, rectified
/// only H, K, k1, k2 (L2 and Linf every quantity).
void check_norm_applies(Quantity q, Norm n);

/// Which vertices an error is taken over.
enum class VertexSet {
  all,                ///< every vertex
  interior,           ///< vertices not on the boundary
  boundary_ring,      ///< boundary vertices and their 1-ring neighbours (paper Figs. 13-14)
  valence_4_or_less,  ///< vertices with at most 4 edge neighbours (diagnostic of claim B4)
  valence_5_or_more,  ///< vertices with at least 5 edge neighbours
};
const char* to_string(VertexSet s);
VertexSet parse_vertex_set(const std::string& s);

/// Indices of the vertices in the set, increasing.
std::vector<int> select_vertices(const Mesh& mesh, VertexSet set);

struct ErrorValue {
  double value = 0.0;  ///< the error; NaN if no vertex contributed
  int vertices = 0;    ///< vertices that contributed
  int excluded = 0;    ///< vertices of the set skipped because their estimate is excluded/NaN
  /// H, K, k1, k2: the exact quantity is zero on every scored vertex, so `value` is relative to
  /// the curvature scale instead of to the quantity's own norm.
  bool zero_exact_norm = false;
};

/// Whether a method computing `computed` outputs quantity q (d1: the directions).
bool computes(const ComputedQuantities& computed, Quantity q);
/// Marks q as output (k1 or k2: the principal curvatures; d1: the directions).
void mark_computed(ComputedQuantities& computed, Quantity q);

/// Error of one quantity in one norm over the given vertices (indices into both arrays).
ErrorValue compute_error(Quantity q, Norm norm, std::span<const VertexEstimate> estimates,
                         std::span<const SurfacePoint> exact, std::span<const int> vertices);

/// Average convergence rate log(e_first/e_last) / log(h_first/h_last) (paper §5 with measured
/// h). NaN when an error is zero, non-finite, or the sizes do not differ.
double convergence_rate(double e_first, double e_last, double h_first, double h_last);

/// The paper's rate: (1/(L-1)) log2(e_1/e_L) over levels 1..L, i.e. each level assumed to halve
/// h; here log2(e_first/e_last) / (level_last - level_first). NaN when an error is zero or
/// non-finite, or the levels are equal.
double level_halving_rate(double e_first, double e_last, int level_first, int level_last);

/// Rates between consecutive levels (size N-1 for N levels).
std::vector<double> pairwise_rates(std::span<const double> errors, std::span<const double> h);

}  // namespace curvbench
