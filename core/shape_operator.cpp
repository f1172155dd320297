// Curvature formulas of paper §2 (eqs. 1-8, Table 1); see shape_operator.h.
#include "core/shape_operator.h"

#include <algorithm>
#include <cmath>

namespace curvbench {

namespace {

bool all_finite(const Vec3& v) {
  return v.allFinite();
}

// sqrt(a^2 + b^2) without overflow or underflow of the squares: the plain formula when both are
// in a safe range (within an ulp of std::hypot, several times faster), std::hypot else.
double norm2d(double a, double b) {
  const double big = std::max(std::abs(a), std::abs(b));
  if (big < 1e150 && big > 1e-150) return std::sqrt(a * a + b * b);
  return std::hypot(a, b);
}

// Eq. (8) for eigenvalue ki (other eigenvalue kj), as coefficients (a, b) of q1, q2.
Vec2 eigen_direction(double w11, double w12, double ki, double kj) {
  if (std::abs(w11 - kj) > std::abs(w11 - ki)) return Vec2(w11 - kj, w12);  // first form
  return Vec2(w12, -(w11 - ki));                                            // second form
}

}  // namespace

bool is_umbilic(double k1, double k2) {
  return std::abs(k1 - k2) <= kUmbilicTolerance * std::max(std::abs(k1), std::abs(k2));
}

void principal_from_symmetric(double w11, double w12, double w22, const Vec3& q1, const Vec3& q2,
                              double& k1, double& k2, Vec3& d1, Vec3& d2) {
  // Eq. (7); norm2d avoids overflow of the squares.
  const double mean = 0.5 * (w11 + w22);
  const double disc = 0.5 * norm2d(w11 - w22, 2.0 * w12);
  k1 = mean + disc;
  k2 = mean - disc;
  if (k1 == k2) {  // exact umbilic: the paper's choice e1 = q1, e2 = q2
    d1 = q1;
    d2 = q2;
    return;
  }
  Vec2 a1 = eigen_direction(w11, w12, k1, k2);
  Vec2 a2 = eigen_direction(w11, w12, k2, k1);
  const double n1 = a1.norm();
  const double n2 = a2.norm();
  // With k1 > k2 both norms are >= (k1 - k2)/2 > 0; the guard only catches NaN/Inf input.
  if (!(n1 > 0.0) || !(n2 > 0.0) || !std::isfinite(n1) || !std::isfinite(n2)) {
    const double nan = Curvature::kNaN;
    if (!std::isfinite(k1) || !std::isfinite(k2)) k1 = k2 = nan;
    d1 = d2 = Vec3::Constant(nan);
    return;
  }
  a1 /= n1;
  a2 /= n2;
  // Right-handed in the (q1, q2) plane: det[a1 a2] > 0, i.e. d1 x d2 = q1 x q2.
  if (a1.x() * a2.y() - a1.y() * a2.x() < 0.0) a2 = -a2;
  d1 = a1.x() * q1 + a1.y() * q2;
  d2 = a2.x() * q1 + a2.y() * q2;
}

Curvature curvature_from_parametric(const Vec3& xu, const Vec3& xv, const Vec3& xuu,
                                    const Vec3& xuv, const Vec3& xvv) {
  Curvature c;  // all NaN
  if (!all_finite(xu) || !all_finite(xv) || !all_finite(xuu) || !all_finite(xuv) ||
      !all_finite(xvv)) {
    return c;
  }
  // Eq. (1).
  const Vec3 cross = xu.cross(xv);
  const double ell = cross.norm();
  if (!(ell > 0.0) || !std::isfinite(ell)) return c;
  const Vec3 n = cross / ell;
  // Eq. (2).
  const double b11 = n.dot(xuu);
  const double b12 = n.dot(xuv);
  const double b22 = n.dot(xvv);
  // Gram-Schmidt QR of J = [xu xv] (docs/algorithms.md §6.2 step 3).
  const double r11 = xu.norm();
  const Vec3 q1 = xu / r11;
  const double r12 = q1.dot(xv);
  const Vec3 qt = xv - r12 * q1;
  const double r22 = qt.norm();
  if (!(r11 > 0.0) || !(r22 > 0.0)) return c;
  const Vec3 q2 = qt / r22;
  // Eq. (5): W~ = R^-T B R^-1 with R^-1 = [1/r11, -r12/(r11 r22); 0, 1/r22].
  const double i11 = 1.0 / r11;
  const double i12 = -r12 / (r11 * r22);
  const double i22 = 1.0 / r22;
  // M = B R^-1 (columns of R^-1: (i11, 0), (i12, i22)).
  const double m11 = b11 * i11;
  const double m12 = b11 * i12 + b12 * i22;
  const double m21 = b12 * i11;
  const double m22 = b12 * i12 + b22 * i22;
  // W~ = R^-T M (rows of R^-T: (i11, 0), (i12, i22)); symmetric in exact arithmetic.
  const double w11 = i11 * m11;
  const double w12 = 0.5 * (i11 * m12 + (i12 * m11 + i22 * m21));
  const double w22 = i12 * m12 + i22 * m22;
  c.normal = n;
  principal_from_symmetric(w11, w12, w22, q1, q2, c.k1, c.k2, c.d1, c.d2);
  c.H = 0.5 * (c.k1 + c.k2);
  c.K = c.k1 * c.k2;
  return c;
}

Curvature curvature_from_height(const Vec3& t1, const Vec3& t2, const Vec3& m, double fu, double fv,
                                double fuu, double fuv, double fvv) {
  Curvature c;  // all NaN
  if (!all_finite(t1) || !all_finite(t2) || !all_finite(m) || !std::isfinite(fu) ||
      !std::isfinite(fv) || !std::isfinite(fuu) || !std::isfinite(fuv) || !std::isfinite(fvv)) {
    return c;
  }
  const double g = norm2d(fu, fv);  // |grad f|
  const double ell2 = 1.0 + fu * fu + fv * fv;
  const double ell = std::sqrt(ell2);
  if (!std::isfinite(ell)) return c;
  // Table 1, height-function column.
  c.normal = (m - fu * t1 - fv * t2) / ell;
  const double gHg = fu * fu * fuu + 2.0 * fu * fv * fuv + fv * fv * fvv;
  c.H = (fuu + fvv) / (2.0 * ell) - gHg / (2.0 * ell2 * ell);
  c.K = (fuu * fvv - fuv * fuv) / (ell2 * ell2);
  // Orthonormal tangent basis (docs/algorithms.md §6.1); q1 x q2 = normal.
  double cs = 1.0;
  double sn = 0.0;
  if (g > 0.0) {
    cs = fu / g;
    sn = fv / g;
  }
  const Vec3 q1 = (cs / ell) * t1 + (sn / ell) * t2 + (g / ell) * m;
  const Vec3 q2 = -sn * t1 + cs * t2;
  // Hess applied to (c, s) and (-s, c).
  const double hc_u = fuu * cs + fuv * sn;
  const double hc_v = fuv * cs + fvv * sn;
  const double hp_u = -fuu * sn + fuv * cs;
  const double hp_v = -fuv * sn + fvv * cs;
  const double w11 = (cs * hc_u + sn * hc_v) / (ell2 * ell);
  const double w12 = (-sn * hc_u + cs * hc_v) / ell2;
  const double w22 = (-sn * hp_u + cs * hp_v) / ell;
  principal_from_symmetric(w11, w12, w22, q1, q2, c.k1, c.k2, c.d1, c.d2);
  return c;
}

Curvature curvature_from_tangent_tensor(const Vec3& n, double w11, double w12, double w22,
                                        const Vec3& q1, const Vec3& q2) {
  Curvature c;
  c.normal = n;
  principal_from_symmetric(w11, w12, w22, q1, q2, c.k1, c.k2, c.d1, c.d2);
  c.H = 0.5 * (c.k1 + c.k2);
  c.K = c.k1 * c.k2;
  return c;
}

}  // namespace curvbench
