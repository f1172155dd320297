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
  const bool finite = (!computed.normal || c.normal.allFinite()) &&
                      (!computed.principal || (std::isfinite(c.k1) && std::isfinite(c.k2))) &&
                      (!computed.mean || std::isfinite(c.H)) &&
                      (!computed.gaussian || std::isfinite(c.K)) &&
                      (!computed.directions || (c.d1.allFinite() && c.d2.allFinite()));
  if (!finite) return false;
  out = VertexEstimate{};  // NaN everywhere
  if (computed.normal) out.normal = c.normal;
  if (computed.principal) {
    out.k1 = c.k1;
    out.k2 = c.k2;
  }
  if (computed.mean) out.H = c.H;
  if (computed.gaussian) out.K = c.K;
  if (computed.directions) {
    out.d1 = c.d1;
    out.d2 = c.d2;
  }
  out.degree = 0;
  out.points = points;
  out.ring = ring;
  out.status = VertexStatus::ok;
  return true;
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
