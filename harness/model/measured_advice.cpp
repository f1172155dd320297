#include "harness/model/measured_advice.h"

#include <algorithm>
#include <cmath>
#include <memory>

#include "core/errors.h"
#include "core/text.h"
#include "mesh/neighbourhood_table.h"
#include "meshgen/random.h"
#include "methods/estimator.h"

namespace curvbench {

const std::vector<std::string>& measured_quantities() {
  static const std::vector<std::string> q{"normal", "H"};
  return q;
}

namespace {

// One candidate's outputs on the mesh (run 0) and on each perturbed mesh (runs 1..P), per
// quantity: the normals as 3 values a vertex, H as 1.
struct Outputs {
  std::vector<std::vector<double>> normal, H;
  const std::vector<double>& of(int quantity, int run) const {
    return quantity == 0 ? normal[run] : H[run];
  }
};

void record(const std::vector<VertexEstimate>& est, Outputs& out) {
  std::vector<double> n(3 * est.size()), H(est.size());
  for (size_t v = 0; v < est.size(); ++v) {
    for (int k = 0; k < 3; ++k) n[3 * v + k] = est[v].normal[k];
    H[v] = est[v].H;
  }
  out.normal.push_back(std::move(n));
  out.H.push_back(std::move(H));
}

// The mean over the vertices where every value is finite of |sum_i s_i a_i|^2 for the vectors
// a_i with signs s_i (width values a vertex); NaN when no vertex has them all.
double mean_square(int width,
                   const std::vector<std::pair<const std::vector<double>*, double>>& terms,
                   const std::vector<unsigned char>& left_out) {
  const size_t n = terms.front().first->size() / width;
  double sum = 0.0;
  size_t counted = 0;
  for (size_t v = 0; v < n; ++v) {
    if (left_out[v]) continue;
    double sq = 0.0;
    bool finite = true;
    for (int k = 0; k < width && finite; ++k) {
      double x = 0.0;
      for (const auto& [a, sign] : terms) {
        const double y = (*a)[width * v + k];
        if (!std::isfinite(y)) finite = false;
        x += sign * y;
      }
      sq += x * x;
    }
    if (!finite) continue;
    sum += sq;
    ++counted;
  }
  return counted ? sum / static_cast<double>(counted) : std::numeric_limits<double>::quiet_NaN();
}

}  // namespace

MeasuredAdvice measure_advice(const Mesh& mesh, const std::vector<EstimatorChoice>& candidates,
                              const MeasuredAdviceOptions& options) {
  if (!(options.sigma_over_h >= 0.0) || !std::isfinite(options.sigma_over_h))
    throw UsageError("measure_advice: sigma/h " + format_g(options.sigma_over_h) +
                     " must be finite and >= 0");
  if (options.perturbations < 1) throw UsageError("measure_advice: perturbations must be >= 1");
  if (candidates.empty()) throw UsageError("measure_advice: no candidate estimator");
  if (!(mesh.mean_edge_length() > 0.0))
    throw InputError(mesh.source() + ": no edge to measure the advice on");

  std::vector<unsigned char> left_out(static_cast<size_t>(mesh.num_vertices()), 0);
  for (int v : options.left_out) {
    if (v < 0 || v >= mesh.num_vertices())
      throw UsageError("measure_advice: vertex " + std::to_string(v) +
                       " to leave out is not one of the " + std::to_string(mesh.num_vertices()));
    left_out[static_cast<size_t>(v)] = 1;
  }

  MeasuredAdvice advice;
  advice.h = mesh.mean_edge_length();
  advice.sigma_over_h = options.sigma_over_h;
  advice.perturbation_over_h = std::max(options.sigma_over_h, kMeasuredNoiseFloor);
  advice.perturbations = options.perturbations;

  // The reference ladder after the candidates (each reused when it is one).
  std::vector<EstimatorChoice> runs = candidates;
  std::vector<size_t> ladder;
  for (const char* label : kMeasuredReferences) {
    size_t at = runs.size();
    for (size_t i = 0; i < candidates.size(); ++i)
      if (runs[i].label == label) at = i;
    if (at == runs.size()) runs.push_back(estimator_choice(label));
    ladder.push_back(at);
  }
  std::vector<std::unique_ptr<Estimator>> estimators;
  for (const EstimatorChoice& c : runs) {
    EstimatorOptions opt = c.options;
    opt.threads = options.threads;
    estimators.push_back(make_estimator(c.method, opt));
  }

  std::vector<Outputs> out(runs.size());
  const auto run_all = [&](const Mesh& m) {
    NeighbourhoodCache cache(m);  // rings and balls shared by the candidates on this geometry
    for (size_t i = 0; i < runs.size(); ++i)
      record(estimate_mesh(m, *estimators[i], &cache), out[i]);
  };
  run_all(mesh);

  // Perturbations along the normals of the ladder's first (least biased) rung, no move where it
  // has none.
  const std::vector<double> normals = out[ladder.front()].normal[0];  // a copy: out grows
  const double step = advice.perturbation_over_h * advice.h;
  for (int p = 0; p < options.perturbations; ++p) {
    Rng rng(derive_seed(options.seed, static_cast<std::uint64_t>(p)));
    VertexMatrix V = mesh.vertices();
    for (int v = 0; v < V.rows(); ++v) {
      const double xi = rng.normal();
      const Vec3 n(normals[3 * v], normals[3 * v + 1], normals[3 * v + 2]);
      if (n.allFinite()) V.row(v) += (step * xi) * n.transpose();
    }
    run_all(Mesh(std::move(V), mesh.faces(), mesh.source()));
  }

  const int P = options.perturbations;
  for (int q = 0; q < static_cast<int>(measured_quantities().size()); ++q) {
    const int width = q == 0 ? 3 : 1;
    // V_c: the mean square change the perturbations cause.
    const auto noise2 = [&](size_t c) {
      double sum = 0.0;
      for (int p = 1; p <= P; ++p)
        sum += mean_square(width, {{&out[c].of(q, p), 1.0}, {&out[c].of(q, 0), -1.0}}, left_out);
      return sum / P;
    };
    // B_c against r: ||x_c - x_r||^2 less the perturbations' mean square change of c - r.
    const auto bias2 = [&](size_t c, size_t r) {
      if (c == r) return 0.0;
      double pair = 0.0;
      for (int p = 1; p <= P; ++p)
        pair += mean_square(width,
                            {{&out[c].of(q, p), 1.0},
                             {&out[c].of(q, 0), -1.0},
                             {&out[r].of(q, p), -1.0},
                             {&out[r].of(q, 0), 1.0}},
                            left_out);
      const double apart =
          mean_square(width, {{&out[c].of(q, 0), 1.0}, {&out[r].of(q, 0), -1.0}}, left_out);
      const double d = apart - pair / P;
      return std::isnan(d) ? d : std::max(0.0, d);  // NaN: no vertex where both are finite
    };
    // The reference: the rung of least predicted error against the first rung (a rung without
    // a finite prediction is none).
    size_t reference = runs.size();
    double least = std::numeric_limits<double>::infinity();
    for (size_t r : ladder) {
      const double e = bias2(r, ladder.front()) + noise2(r);
      if (e < least) least = e, reference = r;
    }
    MeasuredQuantity mq;
    mq.quantity = measured_quantities()[q];
    if (reference == runs.size()) {  // no rung finite: nothing to measure against
      for (const EstimatorChoice& c : candidates) {
        MeasuredCase mc;
        mc.label = c.label;
        mc.predicted = std::numeric_limits<double>::infinity();
        mq.cases.push_back(mc);
      }
      advice.quantities.push_back(std::move(mq));
      continue;
    }
    mq.reference = runs[reference].label;
    // H relative to the reference's RMS (the relative norm ratio's denominator); normals absolute.
    // Where the reference's H vanishes (planes), absolute: no relative error exists there.
    const double rms =
        q == 1 ? std::sqrt(mean_square(1, {{&out[reference].of(q, 0), 1.0}}, left_out)) : 1.0;
    const double scale = rms > 0.0 ? rms : 1.0;
    for (size_t i = 0; i < candidates.size(); ++i) {
      const double noise = noise2(i), bias = bias2(i, reference);
      MeasuredCase c;
      c.label = runs[i].label;
      if (std::isfinite(noise) && std::isfinite(bias) && std::isfinite(scale)) {
        c.noise_part = std::sqrt(noise) / scale;
        c.bias_part = std::sqrt(bias) / scale;
        c.predicted = std::sqrt(noise + bias) / scale;
      } else {
        c.predicted = std::numeric_limits<double>::infinity();
      }
      mq.cases.push_back(c);
    }
    for (size_t i = 0; i < mq.cases.size(); ++i)
      if (std::isfinite(mq.cases[i].predicted) &&
          (mq.chosen < 0 || mq.cases[i].predicted < mq.cases[mq.chosen].predicted))
        mq.chosen = static_cast<int>(i);
    advice.quantities.push_back(std::move(mq));
  }
  return advice;
}

}  // namespace curvbench
