#include "harness/run/runner.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <map>
#include <optional>
#include <set>

#include "core/errors.h"
#include "core/text.h"
#include "harness/run/case_store.h"
#include "harness/run/external_estimator.h"
#include "meshgen/generate.h"
#include "methods/estimator.h"
#include "methods/option_schema.h"

namespace curvbench {

namespace {

std::string noise_label(const Experiment& e, const ExperimentMesh& m) {
  if (const int order = e.noise_order_of(m); order > 0)
    return curvbench::noise_label(order, e.noise_model_of(m));
  return mesh_family(m.family).noise_label;
}

NoiseLevel noise_level(const Experiment& e, const ExperimentMesh& m) {
  const int order = e.noise_order_of(m);
  if (order > 0) return curvbench::noise_level(order, e.noise_model_of(m));
  // A family's own noise, as its table line names it: "none", or "isosurface" (not a sigma h).
  return parse_noise_label(mesh_family(m.family).noise_label);
}

double case_work(const RunCase& c) {
  return static_cast<double>(1u << (2 * c.level));
}

// Seconds per vertex relative to LHF-2: the method's registry cost at degree 2 (MethodInfo::cost)
// times the factor of its degree (0: a degree-free operator; from results/table5_timing.csv).
double method_cost(const std::string& name, int degree) {
  static const double per_degree[] = {0.5, 0.6, 1.0, 1.8, 3.7, 7.0, 12.0};
  double base = 1.0;
  for (const MethodInfo& m : method_table())
    if (m.name == name) base = m.cost;
  return base * per_degree[std::clamp(degree, 0, 6)];
}

}  // namespace

double case_cost(const RunCase& c) {
  double method = 1.0;
  try {
    method = method_cost(method_info(c.method->spec).name,
                         estimator_degree(c.method->spec, EstimatorOptions{}));
  } catch (const UsageError&) {
    // not a built-in estimator: cost 1
  }
  return case_work(c) * method;
}

std::vector<size_t> shard_cases(const std::vector<RunCase>& cases, int k, int n) {
  if (n < 1 || k < 1 || k > n)
    throw UsageError("--shard " + std::to_string(k) + "/" + std::to_string(n) +
                     ": need 1 <= K <= N");
  std::vector<double> cost(cases.size());
  for (size_t i = 0; i < cases.size(); ++i) cost[i] = case_cost(cases[i]);
  std::vector<size_t> order(cases.size());
  for (size_t i = 0; i < order.size(); ++i) order[i] = i;
  std::stable_sort(order.begin(), order.end(),
                   [&](size_t a, size_t b) { return cost[a] > cost[b]; });
  std::vector<double> load(static_cast<size_t>(n), 0.0);
  std::vector<size_t> mine;
  for (size_t i : order) {
    const size_t s = static_cast<size_t>(std::min_element(load.begin(), load.end()) - load.begin());
    load[s] += cost[i];
    if (s == static_cast<size_t>(k - 1)) mine.push_back(i);
  }
  std::sort(mine.begin(), mine.end());
  return mine;
}

std::vector<std::pair<Quantity, Norm>> panel_measures(const Experiment& e) {
  std::vector<std::pair<Quantity, Norm>> out;
  std::set<std::pair<Quantity, Norm>> seen;
  for (const auto& p : e.panels)
    if (seen.insert({p.quantity, p.norm}).second) out.push_back({p.quantity, p.norm});
  return out;
}

const ScoredMesh& MeshCache::get(const std::string& family, int level, int noise_order,
                                 std::uint64_t seed, const NoiseModel& model,
                                 const MeshShape& shape) {
  MeshSpec spec;
  spec.family = family;
  spec.level = level;
  spec.noise_order = noise_order;
  spec.seed = seed;
  spec.noise_model = model;
  spec.shape = shape;
  return get(spec);
}

const ScoredMesh& MeshCache::get(const MeshSpec& spec) {
  const auto key = std::make_tuple(spec.family, spec.level, spec.noise_order, spec.seed,
                                   spec.noise_model, spec.shape);
  auto it = meshes_.find(key);
  if (it != meshes_.end()) return *it->second;
  auto scored = std::make_unique<ScoredMesh>();
  scored->generated = generate_mesh(spec);
  const auto& g = scored->generated;
  scored->exact.resize(g.mesh.num_vertices());
  for (int v = 0; v < g.mesh.num_vertices(); ++v)
    scored->exact[v] = g.surface->evaluate(g.exact_points.row(v).transpose());
  scored->neighbourhoods = std::make_unique<NeighbourhoodCache>(g.mesh);
  return *(meshes_[key] = std::move(scored));
}

// radius-scaling (experiment.h): the neighbourhood of radius c h^alpha as the method's own
// size parameter (its registry line's NeighbourhoodSize), n = c h^(alpha - 1) edge lengths: half
// rings, whole rings or the ball factor; a fixed 1-ring stays.
void scale_radius(const Experiment& e, const std::string& method, double h, EstimatorOptions& opt) {
  const double n = e.radius_c * std::pow(h, e.radius_alpha - 1.0);
  switch (method_info(method).radius) {
    case NeighbourhoodSize::half_rings:
      opt.rings = std::max(1.0, std::round(2.0 * n) / 2.0);
      break;
    case NeighbourhoodSize::whole_rings:
      opt.rings = std::max(1.0, std::round(n));
      break;
    case NeighbourhoodSize::ball_factor:
      opt.ball_factor = n;
      break;
    case NeighbourhoodSize::fixed:
      break;
  }
}

std::vector<RunCase> expand_cases(const std::vector<Experiment>& experiments) {
  std::vector<RunCase> cases;
  for (const auto& e : experiments)
    for (const auto& m : e.meshes)
      for (int level : m.levels)
        for (const auto& method : e.methods) cases.push_back({&e, &m, level, &method});
  return cases;
}

std::vector<ErrorRow> run_case(const RunCase& c, MeshCache& cache, int threads,
                               std::vector<CauseRow>* causes) {
  const Experiment& e = *c.experiment;
  const ScoredMesh& sm = cache.get(e.mesh_spec(*c.mesh, c.level));
  const Mesh& mesh = sm.generated.mesh;

  using clock = std::chrono::steady_clock;
  std::vector<VertexEstimate> est;
  double seconds = 0.0;
  std::string method_label, rings = "";
  int degree = 0;
  bool interior_only = false;     // the method scores interior vertices only (Xu-2, paper §5.2)
  ComputedQuantities computed{};  // quantities the method outputs (an outside one: what it wrote)
  if (c.method->is_external()) {
    ExternalRun run;
    run.command = c.method->command;
    run.timeout_seconds = c.method->timeout_seconds;
    run.case_name = "experiment " + e.name + ", " + c.mesh->label() + " level " +
                    std::to_string(c.level) + ", method " + c.method->label;
    ExternalResult ext = run_external_estimator(mesh, run);
    est = std::move(ext.estimates);
    seconds = ext.seconds;
    method_label = c.method->label;
    computed = ComputedQuantities{false, false, false, false, false};
    for (Quantity q : ext.quantities) mark_computed(computed, q);
  } else {
    EstimatorOptions opt = c.method->options;
    opt.threads = threads;
    // The noisy-data half ring for the degrees the experiment gives it (the degree is the
    // estimator's, from its spec).
    opt.noisy = opt.noisy || e.noisy_for_degree(estimator_degree(c.method->spec, opt));
    if (e.radius_c > 0.0) scale_radius(e, c.method->spec, mesh_size(sm.generated), opt);
    const auto estimator = make_estimator(c.method->spec, opt);
    // The case's time includes gathering the neighbourhoods when this is the first case of the
    // mesh with its neighbourhood spec (later ones read the cache's table).
    const auto t0 = clock::now();
    est = estimate_mesh(mesh, *estimator, sm.neighbourhoods.get());
    seconds = std::chrono::duration<double>(clock::now() - t0).count();
    method_label = c.method->label.empty() ? estimator->label() : c.method->label;
    interior_only = estimator->scores_interior_only();
    computed = estimator->computes();
    degree = estimator->options().degree;
    // Under radius-scaling the rings change with the level: the column names the rule, so that
    // the levels form one series.
    // A point neighbourhood (a point set, or the option `neighbourhood`) is named by its rule.
    const NeighbourhoodSpec start = estimator->neighbourhood_spec(mesh);
    rings = start.is_points()  ? point_rule_text(start)
            : e.radius_c > 0.0 ? format_g(e.radius_c) + "h^" + format_g(e.radius_alpha)
                               : format_g(opt.rings > 0 ? opt.rings : estimator->default_ring());
  }

  int reduced = 0, failed = 0;
  for (const auto& x : est) {
    reduced += x.status == VertexStatus::degree_reduced;
    failed += x.status == VertexStatus::failed;
  }

  // A method that scores interior vertices only (Xu-2, paper §5.2) gets the interior on open
  // meshes unless told otherwise.
  VertexSet set = e.vertex_set;
  if (c.method->has_vertex_set)
    set = c.method->vertex_set;
  else if (interior_only && mesh.has_boundary() && set == VertexSet::all)
    set = VertexSet::interior;
  const std::vector<int> vertices = select_vertices(mesh, set);

  ErrorRow like;  // the columns every row of the case shares
  like.experiment = e.name;
  like.surface = sm.generated.surface->name();
  like.family = c.mesh->label();
  like.level = c.level;
  like.vertices = mesh.num_vertices();
  like.h = mesh_size(sm.generated);
  like.method = method_label;
  like.degree = degree;
  like.rings = rings;
  like.noise = noise_label(e, *c.mesh);
  like.method_base =
      c.method->radius_parameter.empty() ? method_label : c.method->radius_base_label;
  like.radius_parameter = c.method->radius_parameter;
  like.radius = c.method->radius;
  like.noise_level = noise_level(e, *c.mesh);
  like.vertex_set = to_string(set);
  like.degree_reduced = reduced;
  like.failed = failed;
  like.seconds = seconds;
  std::vector<ErrorRow> rows;
  for (const auto& [q, norm] : panel_measures(e)) {
    if (!computes(computed, q)) continue;  // not an output of the method: no error row
    const ErrorValue ev = compute_error(q, norm, est, sm.exact, vertices);
    ErrorRow r = like;
    r.quantity = to_string(q);
    r.norm = to_string(norm);
    r.error = ev.value;
    r.counted = ev.vertices;
    r.excluded = ev.excluded;
    rows.push_back(std::move(r));
  }
  if (causes != nullptr) {
    causes->clear();
    if (finest_level(*c.mesh, c.level) && computes(computed, kCauseQuantity)) {
      if (!sm.causes) sm.causes = std::make_unique<VertexCauses>(vertex_causes(mesh, sm.exact));
      *causes = cause_rows(like, *sm.causes, est, sm.exact, vertices);
    }
  }
  return rows;
}

RunSummary run_experiments(const std::vector<Experiment>& experiments, const RunOptions& options) {
  using clock = std::chrono::steady_clock;
  const auto cases = expand_cases(experiments);
  const bool sharded = options.shard_count > 1;
  // The cases this run does (all of them unless sharded), in case order.
  std::vector<size_t> todo;
  if (sharded) {
    todo = shard_cases(cases, options.shard, options.shard_count);
  } else {
    todo.resize(cases.size());
    for (size_t i = 0; i < cases.size(); ++i) todo[i] = i;
  }
  std::optional<CaseStore> store;
  if (!options.store_dir.empty()) store.emplace(options.store_dir);
  // Stored rows of the unchanged cases, read up front so the ETA covers only the work left.
  std::vector<std::optional<std::vector<ErrorRow>>> stored(cases.size());
  std::vector<std::vector<CauseRow>> stored_causes(cases.size());
  if (store && !options.force)
    for (size_t i : todo) stored[i] = store->load(cases[i], &stored_causes[i]);
  // ETA from vertices: sizes are known from the levels only after generation, so weight each
  // case by 4^level (every family's vertex count grows about 4x per level).
  double total_work = 0.0, done_work = 0.0;
  for (size_t i : todo)
    if (!stored[i]) total_work += case_work(cases[i]);
  MeshCache cache;
  RunSummary summary;
  // Commands of outside estimators that said they cannot run here, with their reason.
  std::map<std::string, std::string>& unavailable = summary.unavailable;
  unavailable = options.unavailable;
  const auto skip = [&](const RunCase& c, const std::string& reason) {
    ++summary.skipped;
    if (store) store->save_skipped(c, reason);
    for (SkippedMethod& s : summary.skipped_methods)
      if (s.experiment == c.experiment->name && s.method == c.method->label) {
        ++s.cases;
        return;
      }
    summary.skipped_methods.push_back({c.experiment->name, c.method->label, 1, reason});
  };
  summary.total = static_cast<int>(todo.size());
  const auto start = clock::now();
  RunProgress p;
  p.total = summary.total;
  for (size_t t = 0; t < todo.size(); ++t) {
    const size_t i = todo[t];
    const RunCase& c = cases[i];
    const auto t0 = clock::now();
    std::vector<ErrorRow> case_rows;
    std::vector<CauseRow> case_causes;
    p.reused = stored[i].has_value();
    p.skipped = false;
    if (p.reused) {
      case_rows = std::move(*stored[i]);
      case_causes = std::move(stored_causes[i]);
      ++summary.reused;
    } else if (const auto u = c.method->is_external() ? unavailable.find(c.method->command)
                                                      : unavailable.end();
               u != unavailable.end()) {
      skip(c, u->second);
      p.skipped = true;
      done_work += case_work(c);
    } else {
      try {
        case_rows = run_case(c, cache, options.threads, &case_causes);
        if (store) store->save(c, case_rows, case_causes);
        ++summary.computed;
      } catch (const ExternalEstimatorUnavailable& e) {
        unavailable[c.method->command] = e.reason();
        if (options.message)
          options.message("[run] skipped method " + c.method->label + ": " + e.reason());
        skip(c, e.reason());
        p.skipped = true;
      }
      done_work += case_work(c);
    }
    const auto t1 = clock::now();
    ++p.done;
    p.current = &c;
    p.case_seconds = std::chrono::duration<double>(t1 - t0).count();
    p.elapsed_seconds = std::chrono::duration<double>(t1 - start).count();
    p.eta_seconds = done_work > 0 ? p.elapsed_seconds * (total_work - done_work) / done_work : 0.0;
    p.vertices = case_rows.empty() ? 0 : case_rows.front().vertices;
    if (options.progress) options.progress(p);
    summary.rows.insert(summary.rows.end(), case_rows.begin(), case_rows.end());
    summary.cause_rows.insert(summary.cause_rows.end(), case_causes.begin(), case_causes.end());
    const bool last_of_experiment =
        i + 1 == cases.size() || cases[i + 1].experiment != c.experiment;
    if (!sharded && last_of_experiment && options.experiment_done) {
      std::vector<ErrorRow> mine;
      for (const auto& r : summary.rows)
        if (r.experiment == c.experiment->name) mine.push_back(r);
      options.experiment_done(*c.experiment, mine);
    }
    if (!sharded && last_of_experiment && options.causes_done) {
      std::vector<CauseRow> mine;
      for (const auto& r : summary.cause_rows)
        if (r.experiment == c.experiment->name) mine.push_back(r);
      options.causes_done(*c.experiment, mine);
    }
    if (t + 1 < todo.size() && options.stop && options.stop()) {
      summary.interrupted = true;
      return summary;
    }
  }
  if (store && !sharded) store->prune(cases);
  return summary;
}

}  // namespace curvbench
