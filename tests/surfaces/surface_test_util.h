// Test helpers for tests/surfaces: an independent finite-difference reference for the
// differential quantities of a parameterized surface (classical route: G = J^T J, B, W = G^-1 B
// and its eigen-decomposition, paper eqs. 1-3; deliberately NOT core/shape_operator), and checks
// of the frame conventions of surface.h.
#pragma once

#include <gtest/gtest.h>

#include <Eigen/Eigenvalues>
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <numbers>
#include <random>

#include "surfaces/surface.h"

namespace curvbench::test {

inline constexpr double kPi = std::numbers::pi;

/// Differential quantities computed by the classical formulas.
struct Reference {
  Vec3 point, normal, d1, d2;
  double k1, k2, H, K;
};

/// Eqs. (1)-(3): n = xu x xv/|.|, G = J^T J, B = [n.x_ij], W = G^-1 B; eigenpairs of the
/// (non-symmetric) W by Eigen::EigenSolver, sorted k1 >= k2; e_i = J d_i / |J d_i|.
inline Reference reference_from_derivatives(const Vec3& xu, const Vec3& xv, const Vec3& xuu,
                                            const Vec3& xuv, const Vec3& xvv) {
  Reference r;
  Eigen::Matrix<double, 3, 2> J;
  J << xu, xv;
  r.normal = xu.cross(xv).normalized();
  const Mat2 G = J.transpose() * J;
  Mat2 B;
  B << r.normal.dot(xuu), r.normal.dot(xuv), r.normal.dot(xuv), r.normal.dot(xvv);
  const Mat2 W = G.inverse() * B;
  Eigen::EigenSolver<Mat2> es(W);
  Vec2 lam = es.eigenvalues().real();
  Mat2 vec = es.eigenvectors().real();
  int i1 = lam[0] >= lam[1] ? 0 : 1;
  r.k1 = lam[i1];
  r.k2 = lam[1 - i1];
  r.d1 = (J * vec.col(i1)).normalized();
  r.d2 = (J * vec.col(1 - i1)).normalized();
  r.H = 0.5 * W.trace();
  r.K = W.determinant();
  return r;
}

/// Derivatives of position(u, v) by central differences with one Richardson step
/// (steps h and h/2; error O(h^4) + O(eps/h^2)), then reference_from_derivatives.
inline Reference fd_reference(const Surface& s, double u, double v, double h = 1e-3) {
  auto x = [&](double a, double b) { return s.position(a, b); };
  struct D {
    Vec3 xu, xv, xuu, xuv, xvv;
  };
  auto diffs = [&](double k) {
    D d;
    const Vec3 x0 = x(u, v);
    d.xu = (x(u + k, v) - x(u - k, v)) / (2 * k);
    d.xv = (x(u, v + k) - x(u, v - k)) / (2 * k);
    d.xuu = (x(u + k, v) - 2 * x0 + x(u - k, v)) / (k * k);
    d.xvv = (x(u, v + k) - 2 * x0 + x(u, v - k)) / (k * k);
    d.xuv = (x(u + k, v + k) - x(u + k, v - k) - x(u - k, v + k) + x(u - k, v - k)) / (4 * k * k);
    return d;
  };
  const D a = diffs(h);
  const D b = diffs(0.5 * h);
  auto rich = [](const Vec3& coarse, const Vec3& fine) { return (4.0 * fine - coarse) / 3.0; };
  Reference r = reference_from_derivatives(rich(a.xu, b.xu), rich(a.xv, b.xv), rich(a.xuu, b.xuu),
                                           rich(a.xuv, b.xuv), rich(a.xvv, b.xvv));
  r.point = x(u, v);
  return r;
}

/// |sin angle| between two lines (direction up to sign).
inline double line_angle(const Vec3& a, const Vec3& b) {
  return a.normalized().cross(b.normalized()).norm();
}

/// Compares an exact SurfacePoint with the FD reference: normal (with sign), k1, k2, H, K to
/// tol * max(1, |exact|), directions up to sign when |k1 - k2| >= min_gap. Returns true if the
/// directions were compared.
inline bool expect_matches_reference(const SurfacePoint& e, const Reference& r, double tol,
                                     double min_gap, const char* where) {
  SCOPED_TRACE(where);
  EXPECT_LE((e.point - r.point).norm(), 1e-12 * std::max(1.0, r.point.norm()));
  EXPECT_LE((e.normal - r.normal).norm(), tol);
  EXPECT_NEAR(e.k1, r.k1, tol * std::max(1.0, std::abs(e.k1)));
  EXPECT_NEAR(e.k2, r.k2, tol * std::max(1.0, std::abs(e.k2)));
  EXPECT_NEAR(e.H, r.H, tol * std::max(1.0, std::abs(e.H)));
  EXPECT_NEAR(e.K, r.K, tol * std::max(1.0, std::abs(e.K)));
  if (std::abs(e.k1 - e.k2) < min_gap) return false;
  EXPECT_LE(line_angle(e.d1, r.d1), tol);
  EXPECT_LE(line_angle(e.d2, r.d2), tol);
  return true;
}

/// Conventions of surface.h: unit normal, k1 >= k2, H and K consistent, unit orthogonal
/// tangent directions with (d1, d2, n) right-handed.
inline void expect_frame_conventions(const SurfacePoint& s, const char* where) {
  SCOPED_TRACE(where);
  constexpr double eps = 1e-13;
  EXPECT_NEAR(s.normal.norm(), 1.0, eps);
  EXPECT_GE(s.k1, s.k2);
  EXPECT_NEAR(s.H, 0.5 * (s.k1 + s.k2), eps * std::max(1.0, std::abs(s.k1) + std::abs(s.k2)));
  EXPECT_NEAR(s.K, s.k1 * s.k2, eps * std::max(1.0, s.k1 * s.k1 + s.k2 * s.k2));
  EXPECT_NEAR(s.d1.norm(), 1.0, eps);
  EXPECT_NEAR(s.d2.norm(), 1.0, eps);
  EXPECT_NEAR(s.d1.dot(s.d2), 0.0, eps);
  EXPECT_NEAR(s.d1.dot(s.normal), 0.0, eps);
  EXPECT_NEAR(s.d2.dot(s.normal), 0.0, eps);
  EXPECT_LE((s.d1.cross(s.d2) - s.normal).norm(), eps);  // right-handed
}

/// Uniform double in [lo, hi) from the 53 high bits of a mt19937_64 draw (portable).
inline double uniform(std::mt19937_64& rng, double lo, double hi) {
  const double u01 = static_cast<double>(rng() >> 11) * 0x1.0p-53;
  return lo + (hi - lo) * u01;
}

}  // namespace curvbench::test
