// Ellipsoid; see ellipsoid.h.
#include "surfaces/ellipsoid.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <memory>
#include <string>

#include "core/errors.h"
#include "core/shape_operator.h"
#include "surfaces/surface_point.h"

namespace curvbench {

namespace {

constexpr int kMaxBisections = 2200;  // more than enough to exhaust a double interval

// The root s of sum_i (r_i z_i / (s + r_i))^2 = 1 in [lo, hi] by bisection until the midpoint
// repeats (Eberly's GetRoot); r_i = (e_i / e_last)^2, the last r is 1.
template <int N>
double bisect_root(const double (&r)[N], const double (&z)[N], double lo, double hi) {
  double s = lo;
  for (int it = 0; it < kMaxBisections; ++it) {
    s = 0.5 * (lo + hi);
    if (s == lo || s == hi) break;
    double g = -1.0;
    for (int i = 0; i < N; ++i) {
      const double t = r[i] * z[i] / (s + r[i]);
      g += t * t;
    }
    if (g > 0.0)
      lo = s;
    else if (g < 0.0)
      hi = s;
    else
      break;
  }
  return s;
}

// Closest point of the ellipse (e0 >= e1) to (y0, y1) >= 0, written to x.
void closest_on_ellipse(double e0, double e1, double y0, double y1, double& x0, double& x1) {
  if (y1 > 0.0) {
    if (y0 > 0.0) {
      const double z[2] = {y0 / e0, y1 / e1};
      const double g = z[0] * z[0] + z[1] * z[1] - 1.0;
      if (g == 0.0) {
        x0 = y0;
        x1 = y1;
        return;
      }
      const double r[2] = {(e0 / e1) * (e0 / e1), 1.0};
      const double hi = g < 0.0 ? 0.0 : std::hypot(r[0] * z[0], z[1]) - 1.0;
      const double s = bisect_root(r, z, z[1] - 1.0, hi);
      x0 = r[0] * y0 / (s + r[0]);
      x1 = y1 / (s + 1.0);
      return;
    }
    x0 = 0.0;
    x1 = e1;
    return;
  }
  const double d = e0 * e0 - e1 * e1;
  if (e0 * y0 < d) {  // inside the evolute's reach: the closest point leaves the axis
    x0 = e0 * e0 * y0 / d;
    x1 = e1 * std::sqrt(std::max(0.0, 1.0 - (x0 / e0) * (x0 / e0)));
    return;
  }
  x0 = e0;
  x1 = 0.0;
}

// Closest point of the ellipsoid (e0 >= e1 >= e2) to y >= 0 (componentwise), written to x.
void closest_on_ellipsoid(const double (&e)[3], const double (&y)[3], double (&x)[3]) {
  if (y[2] > 0.0) {
    if (y[1] > 0.0 && y[0] > 0.0) {
      const double z[3] = {y[0] / e[0], y[1] / e[1], y[2] / e[2]};
      const double g = z[0] * z[0] + z[1] * z[1] + z[2] * z[2] - 1.0;
      if (g == 0.0) {
        std::copy(y, y + 3, x);
        return;
      }
      const double r[3] = {(e[0] / e[2]) * (e[0] / e[2]), (e[1] / e[2]) * (e[1] / e[2]), 1.0};
      const double hi =
          g < 0.0 ? 0.0
                  : std::sqrt(r[0] * z[0] * r[0] * z[0] + r[1] * z[1] * r[1] * z[1] + z[2] * z[2]) -
                        1.0;
      const double s = bisect_root(r, z, z[2] - 1.0, hi);
      for (int i = 0; i < 3; ++i) x[i] = r[i] * y[i] / (s + r[i]);
      return;
    }
    if (y[1] > 0.0) {  // y0 == 0: the ellipse (e1, e2) in the plane x = 0
      x[0] = 0.0;
      closest_on_ellipse(e[1], e[2], y[1], y[2], x[1], x[2]);
    } else if (y[0] > 0.0) {  // y1 == 0: the ellipse (e0, e2) in the plane y = 0
      x[1] = 0.0;
      closest_on_ellipse(e[0], e[2], y[0], y[2], x[0], x[2]);
    } else {
      x[0] = x[1] = 0.0;
      x[2] = e[2];
    }
    return;
  }
  // y2 == 0: the closest point may leave the plane z = 0 (inside, near the middle).
  const double d0 = e[0] * e[0] - e[2] * e[2], d1 = e[1] * e[1] - e[2] * e[2];
  if (e[0] * y[0] < d0 && e[1] * y[1] < d1) {
    const double q0 = e[0] * y[0] / d0, q1 = e[1] * y[1] / d1;
    const double rest = 1.0 - q0 * q0 - q1 * q1;
    if (rest > 0.0) {
      x[0] = e[0] * q0;
      x[1] = e[1] * q1;
      x[2] = e[2] * std::sqrt(rest);
      return;
    }
  }
  x[2] = 0.0;
  closest_on_ellipse(e[0], e[1], y[0], y[1], x[0], x[1]);
}

}  // namespace

Ellipsoid::Ellipsoid(double a, double b, double c) : e_{a, b, c} {
  if (!(std::isfinite(a) && std::isfinite(b) && std::isfinite(c) && a >= b && b >= c && c > 0.0)) {
    throw UsageError(
        "ellipsoid: need finite semi-axes a >= b >= c > 0 (got a = " + std::to_string(a) +
        ", b = " + std::to_string(b) + ", c = " + std::to_string(c) + ")");
  }
}

Vec3 Ellipsoid::position(double u, double v) const {
  const double cv = std::cos(v);
  return Vec3(e_[0] * cv * std::cos(u), e_[1] * cv * std::sin(u), e_[2] * std::sin(v));
}

double Ellipsoid::implicit(const Vec3& p) const {
  const double x = p.x() / e_[0], y = p.y() / e_[1], z = p.z() / e_[2];
  return x * x + y * y + z * z - 1.0;
}

Vec3 Ellipsoid::project(const Vec3& p) const {
  if (!p.allFinite()) return Vec3::Constant(std::numeric_limits<double>::quiet_NaN());
  const double y[3] = {std::abs(p.x()), std::abs(p.y()), std::abs(p.z())};
  double x[3];
  closest_on_ellipsoid(e_, y, x);
  return Vec3(std::copysign(x[0], p.x()), std::copysign(x[1], p.y()), std::copysign(x[2], p.z()));
}

SurfacePoint Ellipsoid::evaluate(const Vec3& p) const {
  const Vec3 q = project(p);
  if (!q.allFinite()) return nan_surface_point();
  const Vec3 d(1.0 / (e_[0] * e_[0]), 1.0 / (e_[1] * e_[1]), 1.0 / (e_[2] * e_[2]));
  const Vec3 g = d.cwiseProduct(q);  // half the gradient of f
  const double len = g.norm();
  const Vec3 n = g / len;
  Vec3 t1, t2;
  orthonormal_tangents(n, t1, t2);
  // W = -t_i^T D t_j / |D q| (B = n . x_uu with n = D q / |D q|).
  const auto w = [&](const Vec3& u, const Vec3& v) { return -u.cwiseProduct(d).dot(v) / len; };
  return to_surface_point(
      q, curvature_from_tangent_tensor(n, w(t1, t1), w(t1, t2), w(t2, t2), t1, t2));
}

SurfacePtr make_ellipsoid(double a, double b, double c) {
  return std::make_shared<const Ellipsoid>(a, b, c);
}

}  // namespace curvbench
