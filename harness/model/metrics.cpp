#include "harness/model/metrics.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>

#include "core/errors.h"
#include "mesh/mesh_checks.h"

namespace curvbench {

namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

double scalar_of(Quantity q, const VertexEstimate& e) {
  switch (q) {
    case Quantity::H:
      return e.H;
    case Quantity::K:
      return e.K;
    case Quantity::k1:
      return e.k1;
    case Quantity::k2:
      return e.k2;
    default:
      return kNaN;
  }
}

double scalar_of(Quantity q, const SurfacePoint& p) {
  switch (q) {
    case Quantity::H:
      return p.H;
    case Quantity::K:
      return p.K;
    case Quantity::k1:
      return p.k1;
    case Quantity::k2:
      return p.k2;
    default:
      return kNaN;
  }
}

// A vertex contributes to the error of q if it is not excluded and its value of q is finite (a
// method may leave quantities it does not compute NaN; a failed row is NaN throughout).
bool usable(const VertexEstimate& e, Quantity q) {
  if (e.status == VertexStatus::excluded) return false;
  if (q == Quantity::normal) return e.normal.allFinite();
  if (q == Quantity::d1) return e.d1.allFinite();
  return std::isfinite(scalar_of(q, e));
}

}  // namespace

bool computes(const ComputedQuantities& computed, Quantity q) {
  switch (q) {
    case Quantity::normal:
      return computed.normal;
    case Quantity::H:
      return computed.mean;
    case Quantity::K:
      return computed.gaussian;
    case Quantity::k1:
    case Quantity::k2:
      return computed.principal;
    case Quantity::d1:
      return computed.directions;
  }
  return false;
}

void mark_computed(ComputedQuantities& computed, Quantity q) {
  switch (q) {
    case Quantity::normal:
      computed.normal = true;
      break;
    case Quantity::H:
      computed.mean = true;
      break;
    case Quantity::K:
      computed.gaussian = true;
      break;
    case Quantity::k1:
    case Quantity::k2:
      computed.principal = true;
      break;
    case Quantity::d1:
      computed.directions = true;
      break;
  }
}

const char* to_string(Quantity q) {
  switch (q) {
    case Quantity::normal:
      return "normal";
    case Quantity::H:
      return "H";
    case Quantity::K:
      return "K";
    case Quantity::k1:
      return "k1";
    case Quantity::k2:
      return "k2";
    case Quantity::d1:
      return "d1";
  }
  return "?";
}

const char* to_string(Norm n) {
  switch (n) {
    case Norm::L2:
      return "L2";
    case Norm::Linf:
      return "Linf";
    case Norm::angle_rms:
      return "angle-rms";
    case Norm::rectified:
      return "rectified";
  }
  return "?";
}

Quantity parse_quantity(const std::string& s) {
  for (Quantity q :
       {Quantity::normal, Quantity::H, Quantity::K, Quantity::k1, Quantity::k2, Quantity::d1})
    if (s == to_string(q)) return q;
  throw UsageError("unknown quantity '" + s + "' (expected normal, H, K, k1, k2 or d1)");
}

Norm parse_norm(const std::string& s) {
  for (Norm n : {Norm::L2, Norm::Linf, Norm::angle_rms, Norm::rectified})
    if (s == to_string(n)) return n;
  throw UsageError("unknown norm '" + s + "' (expected L2, Linf, angle-rms or rectified)");
}

void check_norm_applies(Quantity q, Norm n) {
  if (n == Norm::angle_rms && q != Quantity::normal)
    throw UsageError(std::string("norm angle-rms measures normals, not ") + to_string(q));
  if (n == Norm::rectified && (q == Quantity::normal || q == Quantity::d1))
    throw UsageError(std::string("norm rectified measures H, K, k1 and k2, not ") + to_string(q));
}

const char* to_string(VertexSet s) {
  switch (s) {
    case VertexSet::all:
      return "all";
    case VertexSet::interior:
      return "interior";
    case VertexSet::boundary_ring:
      return "boundary-ring";
    case VertexSet::valence_4_or_less:
      return "valence-4-or-less";
    case VertexSet::valence_5_or_more:
      return "valence-5-or-more";
  }
  return "?";
}

VertexSet parse_vertex_set(const std::string& s) {
  for (VertexSet v : {VertexSet::all, VertexSet::interior, VertexSet::boundary_ring,
                      VertexSet::valence_4_or_less, VertexSet::valence_5_or_more})
    if (s == to_string(v)) return v;
  throw UsageError("unknown vertex set '" + s +
                   "' (expected all, interior, boundary-ring, valence-4-or-less or "
                   "valence-5-or-more)");
}

std::vector<int> select_vertices(const Mesh& mesh, VertexSet set) {
  const int n = mesh.num_vertices();
  std::vector<char> in(n, 0);
  const std::vector<int> valence =
      set == VertexSet::valence_4_or_less || set == VertexSet::valence_5_or_more
          ? vertex_valences(mesh)
          : std::vector<int>{};
  for (int v = 0; v < n; ++v) {
    switch (set) {
      case VertexSet::all:
        in[v] = 1;
        break;
      case VertexSet::interior:
        in[v] = !mesh.is_boundary_vertex(v);
        break;
      case VertexSet::boundary_ring:
        if (mesh.is_boundary_vertex(v)) {
          in[v] = 1;
          for (int f : mesh.vertex_faces(v))
            for (int k = 0; k < 3; ++k) in[mesh.face_vertex(f, k)] = 1;
        }
        break;
      case VertexSet::valence_4_or_less:
        in[v] = valence[static_cast<size_t>(v)] <= 4;
        break;
      case VertexSet::valence_5_or_more:
        in[v] = valence[static_cast<size_t>(v)] >= 5;
        break;
    }
  }
  std::vector<int> out;
  for (int v = 0; v < n; ++v)
    if (in[v]) out.push_back(v);
  return out;
}

namespace {

// The point-cloud literature's norms (metrics.h): PCPNet's RMS angle and rectified error.
ErrorValue point_cloud_error(Quantity q, Norm norm, std::span<const VertexEstimate> estimates,
                             std::span<const SurfacePoint> exact, std::span<const int> vertices) {
  check_norm_applies(q, norm);
  ErrorValue r;
  double sum = 0.0;
  for (int v : vertices) {
    const VertexEstimate& e = estimates[v];
    if (!usable(e, q)) {
      ++r.excluded;
      continue;
    }
    const SurfacePoint& p = exact[v];
    if (norm == Norm::angle_rms) {
      const double c = std::min(1.0, std::abs(e.normal.normalized().dot(p.normal)));
      const double degrees = std::acos(c) * 180.0 / std::numbers::pi;
      sum += degrees * degrees;
    } else {
      const double k = scalar_of(q, p);
      sum += std::abs(scalar_of(q, e) - k) / std::max(std::abs(k), 1.0);
    }
    ++r.vertices;
  }
  r.value = r.vertices == 0           ? kNaN
            : norm == Norm::angle_rms ? std::sqrt(sum / r.vertices)
                                      : sum / r.vertices;
  return r;
}

}  // namespace

ErrorValue compute_error(Quantity q, Norm norm, std::span<const VertexEstimate> estimates,
                         std::span<const SurfacePoint> exact, std::span<const int> vertices) {
  if (norm == Norm::angle_rms || norm == Norm::rectified)
    return point_cloud_error(q, norm, estimates, exact, vertices);
  ErrorValue r;
  double num = 0.0, den = 0.0;  // L2: sums of squares; Linf: maxima
  if (q == Quantity::d1) {
    double kmax = 0.0;
    for (int v : vertices) kmax = std::max({kmax, std::abs(exact[v].k1), std::abs(exact[v].k2)});
    for (int v : vertices) {
      const SurfacePoint& p = exact[v];
      if (p.umbilic || std::abs(p.k1 - p.k2) <= 1e-8 * kmax) continue;
      const VertexEstimate& e = estimates[v];
      if (!usable(e, q)) {
        ++r.excluded;
        continue;
      }
      const double err = std::min((e.d1 - p.d1).norm(), (e.d1 + p.d1).norm());
      if (norm == Norm::L2)
        num += err * err;
      else
        num = std::max(num, err);
      ++r.vertices;
    }
    r.value = r.vertices == 0 ? kNaN : (norm == Norm::L2 ? std::sqrt(num / r.vertices) : num);
    return r;
  }
  double scale = 0.0;  // the same norm of the curvature scale (see zero_exact_norm below)
  const auto accumulate = [norm](double& sum, double x) {
    sum = norm == Norm::L2 ? sum + x * x : std::max(sum, x);
  };
  for (int v : vertices) {
    const VertexEstimate& e = estimates[v];
    if (!usable(e, q)) {
      ++r.excluded;
      continue;
    }
    const SurfacePoint& p = exact[v];
    if (q == Quantity::normal) {
      accumulate(num, (e.normal - p.normal).norm());
    } else {
      accumulate(num, std::abs(scalar_of(q, e) - scalar_of(q, p)));
      accumulate(den, std::abs(scalar_of(q, p)));
      const double k = std::max(std::abs(p.k1), std::abs(p.k2));
      accumulate(scale, q == Quantity::K ? k * k : k);
    }
    ++r.vertices;
  }
  if (r.vertices == 0) {
    r.value = kNaN;
  } else if (q == Quantity::normal) {
    r.value = norm == Norm::L2 ? std::sqrt(num / r.vertices) : num;
  } else {
    // A quantity that vanishes on every scored vertex (k1 and K on a cylinder) has no relative
    // error: it is measured against the curvature scale instead (metrics.h).
    r.zero_exact_norm = !(den > 0.0);
    const double d = r.zero_exact_norm ? scale : den;
    r.value = d > 0.0 ? (norm == Norm::L2 ? std::sqrt(num / d) : num / d) : kNaN;
  }
  return r;
}

double convergence_rate(double e_first, double e_last, double h_first, double h_last) {
  if (!(e_first > 0.0) || !(e_last > 0.0) || !std::isfinite(e_first) || !std::isfinite(e_last) ||
      !(h_first > 0.0) || !(h_last > 0.0) || h_first == h_last)
    return kNaN;
  return std::log(e_first / e_last) / std::log(h_first / h_last);
}

double level_halving_rate(double e_first, double e_last, int level_first, int level_last) {
  if (!(e_first > 0.0) || !(e_last > 0.0) || !std::isfinite(e_first) || !std::isfinite(e_last) ||
      level_last == level_first)
    return kNaN;
  return std::log2(e_first / e_last) / (level_last - level_first);
}

std::vector<double> pairwise_rates(std::span<const double> errors, std::span<const double> h) {
  std::vector<double> out;
  for (size_t i = 1; i < errors.size() && i < h.size(); ++i)
    out.push_back(convergence_rate(errors[i - 1], errors[i], h[i - 1], h[i]));
  return out;
}

}  // namespace curvbench
