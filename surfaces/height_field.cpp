// Generic analytic height field; see height_field.h.
#include "surfaces/height_field.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <utility>

#include "core/errors.h"
#include "core/shape_operator.h"
#include "surfaces/surface_point.h"

namespace curvbench {

HeightField::HeightField(std::string name, HeightFunction fn, double xmin, double xmax, double ymin,
                         double ymax)
    : name_(std::move(name)),
      fn_(std::move(fn)),
      xmin_(xmin),
      xmax_(xmax),
      ymin_(ymin),
      ymax_(ymax) {
  if (!fn_.f || !fn_.fx || !fn_.fy || !fn_.fxx || !fn_.fxy || !fn_.fyy) {
    throw UsageError("height field '" + name_ + "': f and all derivatives up to 2nd order needed");
  }
  if (!(std::isfinite(xmin) && std::isfinite(xmax) && std::isfinite(ymin) && std::isfinite(ymax) &&
        xmin < xmax && ymin < ymax)) {
    throw UsageError("height field '" + name_ + "': domain must be finite with min < max");
  }
}

Vec3 HeightField::position(double x, double y) const {
  return Vec3(x, y, fn_.f(x, y));
}

Vec3 HeightField::project(const Vec3& p) const {
  if (!p.allFinite()) return Vec3::Constant(std::numeric_limits<double>::quiet_NaN());
  const Vec2 lo(xmin_, ymin_);
  const Vec2 hi(xmax_, ymax_);
  const Vec2 target(p.x(), p.y());
  auto clamp = [&](const Vec2& x) { return x.cwiseMax(lo).cwiseMin(hi); };

  // D(x) = |position(x) - p|^2 / 2 and its gradient, with the components that point out of the
  // domain at an active bound zeroed (projected gradient).
  struct State {
    Vec2 x;
    double e;   // f(x) - pz
    Vec2 grad;  // grad f(x)
    Vec2 g;     // grad D(x)
    double dist;
    double pgrad;  // |projected grad D|_inf
    bool active[2];
  };
  auto state = [&](const Vec2& x) {
    State s;
    s.x = x;
    s.e = fn_.f(x.x(), x.y()) - p.z();
    s.grad = Vec2(fn_.fx(x.x(), x.y()), fn_.fy(x.x(), x.y()));
    s.g = (x - target) + s.e * s.grad;
    s.dist = 0.5 * ((x - target).squaredNorm() + s.e * s.e);
    s.pgrad = 0.0;
    for (int i = 0; i < 2; ++i) {
      s.active[i] = (x[i] <= lo[i] && s.g[i] > 0.0) || (x[i] >= hi[i] && s.g[i] < 0.0);
      if (!s.active[i]) s.pgrad = std::max(s.pgrad, std::abs(s.g[i]));
    }
    return s;
  };

  State cur = state(clamp(target));
  for (int it = 0; it < kMaxIterations && std::isfinite(cur.dist); ++it) {
    if (cur.pgrad == 0.0) break;  // stationary (e.g. p on the surface)
    const double x = cur.x.x(), y = cur.x.y();
    Mat2 hess;
    hess << fn_.fxx(x, y), fn_.fxy(x, y), fn_.fxy(x, y), fn_.fyy(x, y);
    const Mat2 gauss_newton = Mat2::Identity() + cur.grad * cur.grad.transpose();
    const Mat2 newton = gauss_newton + cur.e * hess;
    Vec2 step = Vec2::Zero();
    if (!cur.active[0] && !cur.active[1]) {
      const bool pd = newton(0, 0) > 0.0 && newton.determinant() > 0.0;
      step = -(pd ? newton : gauss_newton).inverse() * cur.g;
    } else {
      for (int i = 0; i < 2; ++i) {
        if (cur.active[i]) continue;
        step[i] = -cur.g[i] / (newton(i, i) > 0.0 ? newton(i, i) : gauss_newton(i, i));
      }
    }
    if (!step.allFinite() || step.isZero(0.0)) break;

    // Backtracking along the clamped path. D itself cannot resolve steps below
    // sqrt(eps D), so a step is also accepted when it reduces the projected gradient.
    State next = state(clamp(cur.x + step));
    double t = 1.0;
    auto accept = [&](const State& n) { return n.dist < cur.dist || n.pgrad < cur.pgrad; };
    for (int h = 0; h < kMaxHalvings && !accept(next); ++h) {
      t *= 0.5;
      next = state(clamp(cur.x + t * step));
    }
    if (!accept(next)) break;  // no progress possible: converged to roundoff
    const double moved = (next.x - cur.x).lpNorm<Eigen::Infinity>();
    cur = next;
    if (moved <= kStepTolerance * (1.0 + cur.x.lpNorm<Eigen::Infinity>())) break;
  }
  return position(cur.x.x(), cur.x.y());
}

SurfacePoint HeightField::evaluate(const Vec3& p) const {
  const Vec3 q = project(p);
  if (!q.allFinite()) return nan_surface_point();
  const double x = q.x();
  const double y = q.y();
  const Curvature c =
      curvature_from_height(Vec3::UnitX(), Vec3::UnitY(), Vec3::UnitZ(), fn_.fx(x, y), fn_.fy(x, y),
                            fn_.fxx(x, y), fn_.fxy(x, y), fn_.fyy(x, y));
  return to_surface_point(q, c);
}

}  // namespace curvbench
