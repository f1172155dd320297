// The one shared implementation of the curvature formulas of paper §2 (eqs. 1-8, Table 1;
// docs/algorithms.md §6). Every estimator and every analytic height field goes through these.
//
// Sign convention (docs/algorithms.md §0): B = n . x_uu with n = x_u x x_v / |x_u x x_v|, so a
// sphere of radius a parameterized with outward x_u x x_v has k1 = k2 = H = -1/a. k1 >= k2
// algebraically (eq. 7); d1 goes with k1, and (d1, d2, normal) is right-handed.
//
// All vectors are 3-vectors in global coordinates. Degenerate input (rank-deficient Jacobian,
// NaN or Inf) gives NaN in every field of the result; nothing throws.
#pragma once

#include <limits>

#include "core/types.h"

namespace curvbench {

/// Normal, principal curvatures/directions, mean and Gaussian curvature at one point.
struct Curvature {
  static constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
  Vec3 normal = Vec3::Constant(kNaN);  ///< unit normal
  double k1 = kNaN;                    ///< larger principal curvature
  double k2 = kNaN;                    ///< smaller principal curvature
  double H = kNaN;                     ///< mean curvature
  double K = kNaN;                     ///< Gaussian curvature
  Vec3 d1 = Vec3::Constant(kNaN);      ///< unit principal direction of k1 (sign arbitrary)
  Vec3 d2 = Vec3::Constant(kNaN);      ///< unit principal direction of k2, d1 x d2 = normal
};

/// Relative tolerance of the umbilic test |k1 - k2| <= tol * max(|k1|, |k2|) (docs/algorithms.md
/// §11.2: such points are excluded from principal-direction errors).
inline constexpr double kUmbilicTolerance = 1e-8;

/// True if |k1 - k2| <= kUmbilicTolerance * max(|k1|, |k2|) (so also for k1 = k2 = 0).
/// False if either value is NaN.
bool is_umbilic(double k1, double k2);

/// Eqs. (7)-(8): principal curvatures and directions of the symmetric 2x2 shape operator
/// W~ = [w11 w12; w12 w22] given in the orthonormal tangent basis (q1, q2) (3-vectors).
///   k1,2 = (w11 + w22 +- sqrt((w11 - w22)^2 + 4 w12^2)) / 2,  k1 >= k2.
///   e_i = (w11 - k_{3-i}) q1 + w12 q2  (first form of eq. 8) if |w11 - k_{3-i}| > |w11 - k_i|,
///   e_i = w12 q1 - (w11 - k_i) q2      (second form) otherwise; then normalised.
/// If k1 == k2 exactly: d1 = q1, d2 = q2. The sign of d2 is chosen so that d1 x d2 = q1 x q2
/// (right-handed with the normal when q1 x q2 is the normal). NaN input gives NaN output.
void principal_from_symmetric(double w11, double w12, double w22, const Vec3& q1, const Vec3& q2,
                              double& k1, double& k2, Vec3& d1, Vec3& d2);

/// The whole Curvature of a symmetric tangent tensor [w11 w12; w12 w22] in the frame (q1, q2) with
/// normal n (a discrete operator's shape operator): principal_from_symmetric, H = (k1 + k2)/2,
/// K = k1 k2.
Curvature curvature_from_tangent_tensor(const Vec3& n, double w11, double w12, double w22,
                                        const Vec3& q1, const Vec3& q2);

/// Parametric surface x(u,v) (docs/algorithms.md §6.2): eq. (1) normal n = x_u x x_v / |x_u x x_v|,
/// eq. (2) B = [n.x_uu n.x_uv; n.x_uv n.x_vv], Gram-Schmidt QR J = [x_u x_v] = [q1 q2] R, eq. (5)
/// W~ = R^-T B R^-1, eqs. (7)-(8) for the principal pair; H = (k1 + k2)/2, K = k1 k2.
/// |x_u x x_v| == 0 or non-finite input: every field NaN.
Curvature curvature_from_parametric(const Vec3& xu, const Vec3& xv, const Vec3& xuu,
                                    const Vec3& xuv, const Vec3& xvv);

/// Local height function w = f(u,v) in the right-handed orthonormal frame (t1, t2, m), given in
/// global coordinates (U = [t1 t2 m]); paper §2.2, Table 1 height-function column,
/// docs/algorithms.md §6.1. With grad = (fu, fv), Hess = [fuu fuv; fuv fvv], l = sqrt(1 +
/// |grad|^2):
///   normal = U (-fu, -fv, 1) / l,
///   H = tr(Hess)/(2 l) - grad^T Hess grad / (2 l^3),   K = det(Hess) / l^4   (Table 1),
///   principal pair from eqs. (7)-(8) in the basis q1 = U (c/l, s/l, |grad|/l), q2 = U (-s, c, 0)
///   with (c, s) = grad/|grad| ((1, 0) if grad = 0):
///   w11 = (c,s) Hess (c,s)^T / l^3,  w12 = (c,s) Hess (-s,c)^T / l^2,  w22 = (-s,c) Hess (-s,c)^T
///   / l.
/// Non-finite input: every field NaN.
Curvature curvature_from_height(const Vec3& t1, const Vec3& t2, const Vec3& m, double fu, double fv,
                                double fuu, double fuv, double fvv);

}  // namespace curvbench
