// The closed-form interpolated corrected curvature measures of one triangle, and the curvatures
// of a vertex from measures summed over a region (methods/operators/icc.cpp is the estimator).
// Exposed so that the tests can feed exact normals (a cylinder, the Schwarz lantern).
//
// J.-O. Lachaud, P. Romon, B. Thibert, D. Coeurjolly, "Interpolated corrected curvature measures
// for polygonal surfaces", Computer Graphics Forum 39(5), 2020 (SGP), and "Corrected curvature
// measures", Discrete & Computational Geometry 68, 2022. On the triangle (x0, x1, x2) with the
// corner normals (u0, u1, u2) interpolated linearly, u_bar = (u0 + u1 + u2)/3, x_ij = x_j - x_i,
// u_ij = u_j - u_i (each formula is the integral of a polynomial of degree <= 1 in the barycentric
// coordinates, hence exact with the mean normal):
//   mu0       = 1/2 u_bar . (x01 x x02)                                  corrected area
//   mu1       = 1/2 u_bar . (u01 x x02 - u02 x x01)                      mean curvature measure
//               (the paper's 1/2 u_bar . sum_i (u_{i+2} - u_{i+1}) x x_i, written about x0)
//   mu2       = 1/2 u0 . (u1 x u2)                                       Gaussian curvature measure
//   mu(X, Y)  = 1/2 u_bar . ((Y . u02) X x x01 - (Y . u01) X x x02)      anisotropic measure,
//             = X^T M Y with M = 1/2 (p u02^T - q u01^T), p = x01 x u_bar, q = x02 x u_bar (3x3)
// and mu1 = -trace(M). For a smooth surface with its normal field, mu0 -> area, mu1 -> 2 H_c area,
// mu2 -> K area, M -> -(shape operator dn) area, with H_c > 0 on a sphere with outward normals
// (the papers' convention; ours is the opposite, see icc_curvature).
#pragma once

#include "core/shape_operator.h"
#include "core/types.h"

namespace curvbench {

/// The measures of one triangle; m holds the symmetrised M as xx, xy, xz, yy, yz, zz.
struct IccMeasures {
  double mu0 = 0.0, mu1 = 0.0, mu2 = 0.0;
  double m[6] = {0.0, 0.0, 0.0, 0.0, 0.0, 0.0};

  /// this += w * o (the ball's partially covered faces count with their covered fraction w).
  void add(const IccMeasures& o, double w = 1.0) {
    mu0 += w * o.mu0;
    mu1 += w * o.mu1;
    mu2 += w * o.mu2;
    for (int i = 0; i < 6; ++i) m[i] += w * o.m[i];
  }
};

/// The measures of the triangle (x0, x1, x2) with corner normals (u0, u1, u2) (unit or not; the
/// formulas take them as given).
inline IccMeasures icc_triangle_measures(const Vec3& x0, const Vec3& x1, const Vec3& x2,
                                         const Vec3& u0, const Vec3& u1, const Vec3& u2) {
  const Vec3 x01 = x1 - x0, x02 = x2 - x0, u01 = u1 - u0, u02 = u2 - u0;
  const Vec3 ub = (u0 + u1 + u2) / 3.0;
  IccMeasures r;
  r.mu0 = 0.5 * ub.dot(x01.cross(x02));
  r.mu1 = 0.5 * ub.dot(u01.cross(x02) - u02.cross(x01));
  r.mu2 = 0.5 * u0.dot(u1.cross(u2));
  // M = 1/2 (p u02^T - q u01^T); its symmetric part (M + M^T)/2 in six entries.
  const Vec3 p = x01.cross(ub), q = x02.cross(ub);
  const auto sym = [&](int i, int j) {
    return 0.25 * (p[i] * u02[j] - q[i] * u01[j] + p[j] * u02[i] - q[j] * u01[i]);
  };
  r.m[0] = sym(0, 0);
  r.m[1] = sym(0, 1);
  r.m[2] = sym(0, 2);
  r.m[3] = sym(1, 1);
  r.m[4] = sym(1, 2);
  r.m[5] = sym(2, 2);
  return r;
}

/// The curvatures of summed measures s at a vertex of unit normal n, in curvbench's convention
/// (B = n . x_uu, a sphere of radius r with outward normals has k1 = k2 = H = -1/r):
///   H = -mu1 / (2 mu0),  K = mu2 / mu0;
///   the tangent part of M / mu0 in the frame (t1, t2) of n has eigenvalues l1 >= l2 with
///   eigenvectors d1, d2 (M ~ -dn area, and -dn is our shape operator, so no sign change);
///   k1,2 = H +- (l1 - l2)/2: the mean from mu1, the split and the directions from M, so that
///   H = (k1 + k2)/2 exactly (K = mu2/mu0 is not k1 k2, as Meyer's angle deficit is not).
/// The normal is n. A non-positive or non-finite mu0 gives NaN everywhere.
Curvature icc_curvature(const IccMeasures& s, const Vec3& n);

}  // namespace curvbench
