#include "harness/model/mesh_features.h"

#include <algorithm>
#include <cmath>
#include <numbers>

#include <Eigen/Eigenvalues>

#include "core/errors.h"

namespace curvbench {

namespace {

// The q-quantile (0..1) of v by the nearest rank; v non-empty, reordered.
double quantile(std::vector<double>& v, double q) {
  const size_t k = std::min(v.size() - 1, static_cast<size_t>(q * static_cast<double>(v.size())));
  std::nth_element(v.begin(), v.begin() + static_cast<std::ptrdiff_t>(k), v.end());
  return v[k];
}

}  // namespace

MeshFeatures measure_mesh_features(const Mesh& mesh) {
  if (mesh.num_faces() == 0) throw InputError("mesh features: a mesh without faces has none");
  MeshFeatures m;
  const int n = mesh.num_vertices();
  const double small = kSmallAngleDeg * std::numbers::pi / 180.0;
  const double obtuse = kObtuseAngleDeg * std::numbers::pi / 180.0;
  int small_angles = 0, obtuse_angles = 0;
  double area = 0.0;
  std::vector<std::vector<int>> neighbours(n);
  std::vector<double> edge_sum(n, 0.0);
  std::vector<int> edge_count(n, 0);
  for (int f = 0; f < mesh.num_faces(); ++f) {
    for (int k = 0; k < 3; ++k) {
      const int a = mesh.face_vertex(f, k), b = mesh.face_vertex(f, (k + 1) % 3),
                c = mesh.face_vertex(f, (k + 2) % 3);
      neighbours[a].push_back(b);
      neighbours[a].push_back(c);
      const Vec3 e1 = mesh.position(b) - mesh.position(a);
      const Vec3 e2 = mesh.position(c) - mesh.position(a);
      const double angle = std::atan2(e1.cross(e2).norm(), e1.dot(e2));
      small_angles += angle < small ? 1 : 0;
      obtuse_angles += angle > obtuse ? 1 : 0;
      // Each edge of the face counted at both its ends (an interior edge twice per end).
      edge_sum[a] += e1.norm();
      edge_count[a] += 1;
      edge_sum[b] += e1.norm();
      edge_count[b] += 1;
      if (k == 0) area += 0.5 * e1.cross(e2).norm();
    }
  }
  const double angles = 3.0 * mesh.num_faces();
  m.small_angle_share = small_angles / angles;
  m.obtuse_angle_share = obtuse_angles / angles;

  int interior = 0, irregular = 0;
  std::vector<double> local_h;
  for (int v = 0; v < n; ++v) {
    std::sort(neighbours[v].begin(), neighbours[v].end());
    const auto valence =
        std::unique(neighbours[v].begin(), neighbours[v].end()) - neighbours[v].begin();
    if (valence == 0) continue;  // isolated
    if (edge_count[v] > 0) local_h.push_back(edge_sum[v] / edge_count[v]);
    if (mesh.is_boundary_vertex(v)) continue;
    ++interior;
    irregular += valence != 6 ? 1 : 0;
  }
  m.irregular_valence_share = interior > 0 ? static_cast<double>(irregular) / interior : 0.0;
  m.boundary_share = static_cast<double>(mesh.num_boundary_vertices()) / n;
  m.density_ratio = quantile(local_h, 0.9) / quantile(local_h, 0.1);
  m.size_over_h = std::sqrt(area / (4.0 * std::numbers::pi)) / mesh.mean_edge_length();

  // The edge tensor of each interior vertex over the edges of its triangles, in its tangent
  // plane (a boundary vertex's half fan would read as stretched across the boundary); all
  // vertices when none is interior.
  std::vector<double> stretch;
  stretch.reserve(n);
  const bool interior_only = interior > 0;
  for (int v = 0; v < n; ++v) {
    const auto faces = mesh.vertex_faces(v);
    if (faces.empty() || (interior_only && mesh.is_boundary_vertex(v))) continue;
    const Vec3 normal = mesh.area_weighted_normal(v);
    if (!(normal.norm() > 0)) continue;
    const Eigen::Matrix3d P = Eigen::Matrix3d::Identity() - normal * normal.transpose();
    Eigen::Matrix3d T = Eigen::Matrix3d::Zero();
    for (int f : faces)
      for (int k = 0; k < 3; ++k) {
        const Vec3 e = P * (mesh.position(mesh.face_vertex(f, (k + 1) % 3)) -
                            mesh.position(mesh.face_vertex(f, k)));
        T += e * e.transpose();
      }
    const Eigen::Vector3d lambda = Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d>(T).eigenvalues();
    if (lambda(1) > 0) stretch.push_back(std::sqrt(lambda(2) / lambda(1)));
  }
  if (!stretch.empty()) m.anisotropy = quantile(stretch, 0.5);
  return m;
}

const std::vector<FeatureInfo>& advice_features() {
  static const std::vector<FeatureInfo> features{
      {"small_angle_share", "share of the angles below 20 degrees",
       &MeshFeatures::small_angle_share, false},
      {"obtuse_angle_share", "share of the angles above 100 degrees",
       &MeshFeatures::obtuse_angle_share, false},
      {"irregular_valence_share", "share of the interior vertices of valence other than 6",
       &MeshFeatures::irregular_valence_share, false},
      {"anisotropy", "anisotropy (ratio of the principal edge directions)",
       &MeshFeatures::anisotropy, true},
      {"density_ratio", "density ratio (90th / 10th percentile of the local edge length)",
       &MeshFeatures::density_ratio, true},
      {"boundary_share", "share of the vertices on the boundary", &MeshFeatures::boundary_share,
       false},
  };
  return features;
}

double feature_coordinate(const FeatureInfo& f, const MeshFeatures& m) {
  const double x = m.*(f.field);
  return f.logarithmic ? std::log(x) : x;
}

}  // namespace curvbench
