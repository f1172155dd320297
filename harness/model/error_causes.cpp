#include "harness/model/error_causes.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <numbers>
#include <sstream>

#include "core/build_info.h"
#include "core/errors.h"
#include "mesh/io.h"
#include "mesh/mesh_checks.h"

namespace curvbench {

namespace {

constexpr const char* kCauseHeader =
    "experiment,surface,family,level,vertices,h,method,degree,noise,vertex_set,quantity,norm,"
    "cause,bin,error,counted,excluded";

// clang-format off
constexpr CauseBin kBins[] = {
    {"all", "all"},
    {"valence", "<=4"}, {"valence", "5"}, {"valence", "6"}, {"valence", "7"}, {"valence", ">=8"},
    {"min-angle", "<10"}, {"min-angle", "10-20"}, {"min-angle", "20-30"}, {"min-angle", "30-45"},
    {"min-angle", ">=45"},
    {"K-sign", "K>0"}, {"K-sign", "K<0"}, {"K-sign", "K~0"},
};
// clang-format on
constexpr int kValenceFirst = 1, kAngleFirst = 6, kSignFirst = 11;
// Upper ends (degrees) of the angle bins but the last.
constexpr double kAngleEdges[] = {10.0, 20.0, 30.0, 45.0};

}  // namespace

std::span<const CauseBin> cause_bins() {
  return kBins;
}

std::vector<double> min_incident_angles(const Mesh& mesh) {
  std::vector<double> face_min(static_cast<size_t>(mesh.num_faces()));
  for (int f = 0; f < mesh.num_faces(); ++f) {
    double m = std::numeric_limits<double>::infinity();
    for (int k = 0; k < 3; ++k) {
      const Vec3 a = mesh.position(mesh.face_vertex(f, k));
      const Vec3 e1 = mesh.position(mesh.face_vertex(f, (k + 1) % 3)) - a;
      const Vec3 e2 = mesh.position(mesh.face_vertex(f, (k + 2) % 3)) - a;
      m = std::min(m, std::atan2(e1.cross(e2).norm(), e1.dot(e2)));  // 0 when degenerate
    }
    face_min[static_cast<size_t>(f)] = m * 180.0 / std::numbers::pi;
  }
  std::vector<double> out(static_cast<size_t>(mesh.num_vertices()),
                          std::numeric_limits<double>::quiet_NaN());
  for (int v = 0; v < mesh.num_vertices(); ++v)
    for (int f : mesh.vertex_faces(v)) {
      double& m = out[static_cast<size_t>(v)];
      m = std::isnan(m) ? face_min[static_cast<size_t>(f)]
                        : std::min(m, face_min[static_cast<size_t>(f)]);
    }
  return out;
}

VertexCauses vertex_causes(const Mesh& mesh, std::span<const SurfacePoint> exact) {
  VertexCauses c;
  c.valence = vertex_valences(mesh);
  c.min_angle = min_incident_angles(mesh);
  for (int v = 0; v < mesh.num_vertices(); ++v)
    if (std::isfinite(exact[static_cast<size_t>(v)].K))
      c.max_abs_K = std::max(c.max_abs_K, std::abs(exact[static_cast<size_t>(v)].K));
  return c;
}

std::vector<std::vector<int>> cause_bin_vertices(const VertexCauses& causes,
                                                 std::span<const SurfacePoint> exact,
                                                 std::span<const int> vertices) {
  const std::vector<int>& valence = causes.valence;
  const std::vector<double>& angle = causes.min_angle;
  const double kmax = causes.max_abs_K;
  std::vector<std::vector<int>> bins(std::size(kBins));
  for (int v : vertices) {
    const auto i = static_cast<size_t>(v);
    bins[0].push_back(v);
    bins[kValenceFirst + std::clamp(valence[i], 4, 8) - 4].push_back(v);
    if (!std::isnan(angle[i])) {
      int b = 0;
      while (b < static_cast<int>(std::size(kAngleEdges)) && angle[i] >= kAngleEdges[b]) ++b;
      bins[kAngleFirst + b].push_back(v);
    }
    const double K = exact[i].K;
    if (std::abs(K) <= kTinyGaussian * kmax)
      bins[kSignFirst + 2].push_back(v);
    else if (K > 0.0)
      bins[kSignFirst].push_back(v);
    else if (K < 0.0)
      bins[kSignFirst + 1].push_back(v);
  }
  return bins;
}

std::vector<CauseRow> cause_rows(const ErrorRow& like, const VertexCauses& causes,
                                 std::span<const VertexEstimate> estimates,
                                 std::span<const SurfacePoint> exact,
                                 std::span<const int> vertices) {
  const auto bins = cause_bin_vertices(causes, exact, vertices);
  std::vector<CauseRow> out;
  for (size_t b = 0; b < bins.size(); ++b) {
    const ErrorValue ev = compute_error(kCauseQuantity, kCauseNorm, estimates, exact, bins[b]);
    CauseRow r;
    r.experiment = like.experiment;
    r.surface = like.surface;
    r.family = like.family;
    r.level = like.level;
    r.vertices = like.vertices;
    r.h = like.h;
    r.method = like.method;
    r.degree = like.degree;
    r.noise = like.noise;
    r.vertex_set = like.vertex_set;
    r.quantity = to_string(kCauseQuantity);
    r.norm = to_string(kCauseNorm);
    r.cause = kBins[b].cause;
    r.bin = kBins[b].bin;
    r.error = ev.value;
    r.counted = ev.vertices;
    r.excluded = ev.excluded;
    out.push_back(std::move(r));
  }
  return out;
}

bool finest_level(const ExperimentMesh& mesh, int level) {
  return !mesh.levels.empty() && level == *std::max_element(mesh.levels.begin(), mesh.levels.end());
}

std::string cause_csv_text(const std::vector<CauseRow>& rows, const std::string& comment) {
  std::ostringstream out;
  if (!comment.empty()) out << comment << "\n";
  out << kCauseHeader << "\n";
  for (const CauseRow& r : rows)
    out << r.experiment << ',' << r.surface << ',' << r.family << ',' << r.level << ','
        << r.vertices << ',' << format_double(r.h) << ',' << r.method << ',' << r.degree << ','
        << r.noise << ',' << r.vertex_set << ',' << r.quantity << ',' << r.norm << ',' << r.cause
        << ',' << r.bin << ',' << format_double(r.error) << ',' << r.counted << ',' << r.excluded
        << "\n";
  return out.str();
}

void write_cause_csv(const std::string& path, const std::vector<CauseRow>& rows) {
  write_file_atomic(path, cause_csv_text(rows, provenance_comment()));
}

std::vector<CauseRow> parse_cause_csv(const std::string& text, const std::string& name) {
  const CsvTable t = parse_csv_table(text, name);
  const size_t c_exp = t.col("experiment"), c_surf = t.col("surface"), c_fam = t.col("family"),
               c_level = t.col("level"), c_verts = t.col("vertices"), c_h = t.col("h"),
               c_method = t.col("method"), c_degree = t.col("degree"), c_noise = t.col("noise"),
               c_set = t.col("vertex_set"), c_q = t.col("quantity"), c_norm = t.col("norm"),
               c_cause = t.col("cause"), c_bin = t.col("bin"), c_err = t.col("error"),
               c_counted = t.col("counted"), c_excl = t.col("excluded");
  std::vector<CauseRow> out;
  for (size_t i = 0; i < t.rows.size(); ++i) {
    CauseRow r;
    r.experiment = t.text(i, c_exp);
    r.surface = t.text(i, c_surf);
    r.family = t.text(i, c_fam);
    r.level = t.integer(i, c_level);
    r.vertices = t.integer(i, c_verts);
    r.h = t.number(i, c_h);
    r.method = t.text(i, c_method);
    r.degree = t.integer(i, c_degree);
    r.noise = t.text(i, c_noise);
    r.vertex_set = t.text(i, c_set);
    r.quantity = t.text(i, c_q);
    r.norm = t.text(i, c_norm);
    r.cause = t.text(i, c_cause);
    r.bin = t.text(i, c_bin);
    r.error = t.number(i, c_err);
    r.counted = t.integer(i, c_counted);
    r.excluded = t.integer(i, c_excl);
    out.push_back(std::move(r));
  }
  return out;
}

std::vector<CauseRow> read_cause_csv(const std::string& path) {
  return parse_cause_csv(read_file(path), path);
}

}  // namespace curvbench
