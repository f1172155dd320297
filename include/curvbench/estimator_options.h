// The estimator options: ONE table, CURVBENCH_ESTIMATOR_OPTIONS below, from which everything that
// names an option is derived: the struct EstimatorOptions (the library's and the public API's),
// the experiment files' method options (`method lhf-2 rings=2.5`), the case store's key, the
// check that an option suits the method it is given to, the command line's flags
// (`curvbench estimate --rings 2.5`), Python's keyword arguments (`estimate(..., rings=2.5)`),
// their help texts and their one validation (methods/option_schema.h; docs/extending.md).
//
// Each line: X(type, field, "name", default, scope, role, lowest, highest, "help")
//   type      bool, int, double, an enum below (text values: its *_names list), or
//             VertexNormalSource (a weighting's name or a fit's label)
//   field     the member of EstimatorOptions
//   name      the option's name: experiment key and CLI flag (--name); Python's keyword is the
//             name with '-' as '_'
//   default   the value meaning "not given"
//   scope     which methods take it (any other value than the default elsewhere is an error):
//             all; fits (the degree-d fits); ring_fits (the fits of the paper's weighted
//             least-squares framework on rings: LHF, LOP, LSCM; Estimator::ring_fit()); operators
//             (the degree-free discrete operators); or the methods it names, each spelled as
//             its name with '_' for '-', several joined by '|' (quadric); or ball_radius (the
//             methods whose registry line declares a ball of radius C h as their neighbourhood,
//             NeighbourhoodSize::ball_factor in methods/estimator.h)
//   role      result: it changes the estimates (an experiment's method line may set it, and it
//             is part of a stored case's key); run: how they are computed, not what (threads,
//             kernel: the command line, C++ and Python only)
//   lowest, highest  the valid range of a number (inclusive; NaN is never valid)
//   help      one line for --help, Python's docstring and docs/cli.md
#pragma once

#include <cstdint>
#include <string>

namespace curvbench {

/// Vertex normals used by the discrete operators: method_default = what the method's authors'
/// code uses (area for Meyer, Taubin, the quadric and the normal cycle; max for Rusinkiewicz
/// and Goldfeather, and for ICC, whose accuracy follows that of the normals).
enum class VertexNormals : std::uint8_t { method_default, area, angle, max };
inline constexpr const char* kVertexNormalsNames[] = {"default", "area", "angle", "max"};

/// Where a discrete operator's vertex normals come from (option vertex-normals): a weighting of
/// the face normals, or the normals of a degree-d fit run over the mesh first (`fit`, the fit's
/// label in lower case as make_estimator reads it, e.g. "lhf-3"; empty: the weighting). Text: a
/// weighting's name or the fit's label. ICC and the normal cycle take a fit's normals.
struct VertexNormalSource {
  VertexNormals weighting = VertexNormals::method_default;
  std::string fit;
  VertexNormalSource() = default;
  VertexNormalSource(VertexNormals w) : weighting(w) {}  // NOLINT: implicit, a weighting
  bool fitted() const { return !fit.empty(); }
  friend bool operator==(const VertexNormalSource&, const VertexNormalSource&) = default;
};

/// How a fitting method solves its systems (LHF-d, LOP-d, d = 1..4; the others ignore it):
/// batched = several vertices at once, one per SIMD lane, falling back to the scalar path for
/// every vertex it cannot finish (safeguard, degree reduction, growth); scalar = one vertex at a
/// time, the reference. Both give the same results up to rounding.
enum class Kernel : std::uint8_t { batched, scalar };
inline constexpr const char* kKernelNames[] = {"batched", "scalar"};

/// The neighbourhood of a method that fits neighbours without faces, in place of its rings
/// (docs/point_sets.md): the k nearest other points (knn=K), the other points within a radius
/// (radius=R), or within a multiple of the point set's mean spacing (radius=2.5s). none: the
/// rings on a mesh, the default k-NN on a point set. Text: "default", "knn=20", "radius=0.1",
/// "radius=2.5s".
struct PointNeighbourhood {
  enum class Kind : std::uint8_t { none, knn, radius, radius_spacing };
  Kind kind = Kind::none;
  double size = 0.0;  ///< K, R, or the multiple of the mean spacing
  bool operator==(const PointNeighbourhood&) const = default;
};

/// Where the starting normals of a point set come from (docs/point_sets.md): pca (PCA of the
/// point and its 16 nearest neighbours) or jet (CGAL's jet normal, degree 2, the same
/// neighbours), each oriented over the neighbour graph (MST, then one global rule); or file (the
/// normals the file gives, normalised, their signs as given). A mesh's starting normals are its
/// area-weighted vertex normals: there, only pca (the default) is accepted.
enum class PointNormalSource : std::uint8_t { pca, jet, file };
inline constexpr const char* kPointNormalSourceNames[] = {"pca", "jet", "file"};

// clang-format off
#define CURVBENCH_ESTIMATOR_OPTIONS(X)                                                             \
  X(int, degree, "degree", 0, fits, result, 0, 6,                                                  \
    "fitting degree d of a fit (0: the degree attached to the method name, e.g. LHF-4, else 2)")   \
  X(double, rings, "rings", 0.0, all, result, 0.0, 1e6,                                            \
    "neighbourhood in rings 1, 1.5, 2, ... (0: the method's default: (d+1)/2 for a fit, "          \
    "+0.5 if noisy; Xu 1; quadric 5; APSS and surface-variation 2; the other operators take "      \
    "the 1-ring only)")                                                                            \
  X(bool, noisy, "noisy", false, all, result, 0, 1,                                                \
    "noisy input: a fit's default ring + 0.5 (paper section 5.3); operators ignore it")            \
  X(bool, adaptive, "adaptive", true, fits, result, 0, 1,                                          \
    "grow the ring by half rings until the fit has enough points (paper section 4.1)")             \
  X(double, qr_tolerance, "qr-tol", 1e-3, ring_fits, result, 0.0, 1e300,                           \
    "safeguarded QR tolerance: the degree is lowered where |R_kk|, or the smallest singular "     \
    "value bound 1/||R^-1||_F of the kept columns, falls below it (section 5.4)")                 \
  X(bool, qr_condition, "qr-condition", true, ring_fits, result, 0, 1,                             \
    "the safeguarded QR's condition test ||R^-1||_F <= 1/qr-tol (no: the |R_kk| test alone, the "  \
    "safeguard of the paper's time)")                                                              \
  X(double, weight_power, "weight-power", -1.0, ring_fits, result, -1e300, 1e300,                  \
    "exponent p of the distance weights (|u|^2+eps)^(-p); negative: eq. (15)'s d/4")               \
  X(bool, normal_safeguard, "safeguard", true, ring_fits, result, 0, 1,                            \
    "weight gamma_i = max(0, m_i . m_0) of eq. (15): drop points whose normal turns away")         \
  X(bool, include_centre, "centre", true, ring_fits, result, 0, 1,                                 \
    "fit the constant term with the vertex as a row (no: interpolate through the vertex)")         \
  X(VertexNormalSource, vertex_normals, "vertex-normals", VertexNormals::method_default,          \
    operators, result, 0, 0,                                                                       \
    "vertex normals of a discrete operator: area, angle or max (default: the method's own), or "   \
    "for icc and normal-cycle a fit's label (lhf-3, jet-4, ...) whose normals are fitted first")   \
  X(bool, quadric_constant, "quadric-constant", false, quadric, result, 0, 1,                      \
    "fit 6 coefficients (a constant term) instead of libigl's 5")                                  \
  X(double, ball_factor, "ball-factor", 0.0, ball_radius, result, 0.0, 1e6,                        \
    "the ball of radius C times the mean edge length instead of the 1-ring (0: the 1-ring)")      \
  X(PointNeighbourhood, neighbourhood, "neighbourhood", PointNeighbourhood{}, all, result, 0, 0,   \
    "neighbours without faces instead of rings: knn=K, radius=R or radius=Cs (C times the mean "   \
    "spacing); default: rings on a mesh, knn=2(d+1)(d+2)/2 on a point set")                       \
  X(PointNormalSource, point_normals, "point-normals", PointNormalSource::pca, all, result, 0, 0,  \
    "starting normals of a point set: pca or jet (of the 16 nearest neighbours, oriented over "   \
    "the neighbour graph), or file (the file's nx ny nz, normalised, signs as given)")            \
  X(double, apss_beta, "apss-beta", 1.0, apss, result, 1e-6, 1e12,                              \
    "APSS: weight of the normal constraints against the positions, in units of the kernel "       \
    "support h squared (beta = apss-beta h^2; Guennebaud and Gross 2007)")                         \
  X(int, threads, "threads", 0, all, run, 0, 1 << 20,                                               \
    "OpenMP threads (0: all cores); the results do not depend on it")                             \
  X(Kernel, kernel, "kernel", Kernel::batched, all, run, 0, 0,                                     \
    "fitting kernel of LHF/LOP degree 1-4: batched (several vertices per SIMD instruction) or "    \
    "scalar (one vertex at a time, the reference); the same results up to rounding")
// clang-format on

/// The options of every estimator (see the table above; defaults follow the paper and
/// docs/algorithms.md). The library's make_estimator() and the public estimate() take it.
struct EstimatorOptions {
#define CURVBENCH_OPTION_FIELD(type, field, name, fallback, ...) type field = fallback;
  CURVBENCH_ESTIMATOR_OPTIONS(CURVBENCH_OPTION_FIELD)
#undef CURVBENCH_OPTION_FIELD
};

}  // namespace curvbench
