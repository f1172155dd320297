// VertexEstimate fillers; see vertex_result.h.
#include "methods/vertex_result.h"

#include <cmath>

namespace curvbench {

namespace {

// A row without an estimate: every value NaN (VertexEstimate's defaults), degree 0.
void set_no_estimate(VertexStatus status, double ring, int points, VertexEstimate& out) {
  out = VertexEstimate{};
  out.degree = 0;
  out.points = points;
  out.ring = ring;
  out.status = status;
}

}  // namespace

void set_failed(double ring, int points, VertexEstimate& out) {
  set_no_estimate(VertexStatus::failed, ring, points, out);
}

void set_excluded(double ring, int points, VertexEstimate& out) {
  set_no_estimate(VertexStatus::excluded, ring, points, out);
}

bool set_quantities(const Curvature& c, int degree, int requested, int points, double ring,
                    VertexEstimate& out) {
  const bool finite = c.normal.allFinite() && std::isfinite(c.k1) && std::isfinite(c.k2) &&
                      std::isfinite(c.H) && std::isfinite(c.K) && c.d1.allFinite() &&
                      c.d2.allFinite();
  if (degree < 1 || !finite) return false;
  out.normal = c.normal;
  out.k1 = c.k1;
  out.k2 = c.k2;
  out.H = c.H;
  out.K = c.K;
  out.d1 = c.d1;
  out.d2 = c.d2;
  out.degree = degree;
  out.points = points;
  out.ring = ring;
  out.status = degree >= requested ? VertexStatus::ok : VertexStatus::degree_reduced;
  return true;
}

bool set_operator_quantities(const Curvature& c, const ComputedQuantities& computed, int points,
                             double ring, VertexEstimate& out) {
  out = VertexEstimate{};  // NaN everywhere
  int kept = 0, missing = 0;
  // Copies a computed group of values if all of it is finite; counts it as kept or missing.
  const auto take = [&](bool is_computed, bool finite, auto&& copy) {
    if (!is_computed) return;
    if (finite) {
      copy();
      ++kept;
    } else {
      ++missing;
    }
  };
  take(computed.normal, c.normal.allFinite(), [&] { out.normal = c.normal; });
  take(computed.principal, std::isfinite(c.k1) && std::isfinite(c.k2), [&] {
    out.k1 = c.k1;
    out.k2 = c.k2;
  });
  take(computed.mean, std::isfinite(c.H), [&] { out.H = c.H; });
  take(computed.gaussian, std::isfinite(c.K), [&] { out.K = c.K; });
  take(computed.directions, c.d1.allFinite() && c.d2.allFinite(), [&] {
    out.d1 = c.d1;
    out.d2 = c.d2;
  });
  out.degree = 0;
  out.points = points;
  out.ring = ring;
  out.status = missing == 0 ? VertexStatus::ok : VertexStatus::partial;
  if (kept > 0) return true;
  set_failed(ring, points, out);
  return false;
}

void set_normal_only(const Vec3& normal, int points, double ring, VertexEstimate& out) {
  set_no_estimate(VertexStatus::failed, ring, points, out);
  if (!normal.allFinite() || !(normal.squaredNorm() > 0.25)) return;  // no unit normal
  out.normal = normal;
  out.status = VertexStatus::partial;
}

void mark_sign_undetermined(std::span<const unsigned char> undetermined,
                            std::span<VertexEstimate> estimates) {
  for (size_t v = 0; v < estimates.size() && v < undetermined.size(); ++v) {
    VertexStatus& s = estimates[v].status;
    if (undetermined[v] && s != VertexStatus::failed && s != VertexStatus::excluded)
      s = VertexStatus::sign_undetermined;
  }
}

}  // namespace curvbench
