// Common base of the degree-free discrete operators (meyer, taubin, rusinkiewicz, quadric, ...):
// no degree (label "Meyer"), the per-mesh data of prepare() (the method's vertex normals of
// vertex_normals.h), a trivial workspace.
#pragma once

#include <memory>

#include "core/types.h"
#include "methods/estimator.h"

namespace curvbench {

/// The per-mesh data of an OperatorEstimator (MeshContext::data).
struct OperatorMeshData : MeshData {
  VertexMatrix normals;  ///< the method's vertex normals; empty = MeshContext::approx_normals
  /// Unit normal of vertex v (zero for a vertex without faces).
  Vec3 normal(const MeshContext& ctx, int v) const {
    return normals.rows() > 0 ? Vec3(normals.row(v).transpose())
                              : Vec3(ctx.approx_normals.row(v).transpose());
  }
};

class OperatorEstimator : public Estimator {
 public:
  bool takes_degree() const final { return false; }
  double default_ring() const override { return 1.0; }
  std::unique_ptr<Workspace> make_workspace(const Mesh& mesh) const override;
  std::unique_ptr<MeshData> prepare(const Mesh& mesh, const VertexMatrix& approx_normals,
                                    int threads) const override;
  /// The vertex normal weighting in use (options().vertex_normals, or the method's default).
  VertexNormals normal_weighting() const;
  /// Only the area weighting uses MeshContext::approx_normals (they are those normals).
  bool uses_approx_normals() const override { return normal_weighting() == VertexNormals::area; }

 protected:
  /// Throws UsageError for a degree other than 0, negative threads, or (unless
  /// `ring_option`) a ring other than 0 and 1.
  OperatorEstimator(EstimatorOptions options, VertexNormals default_normals,
                    bool ring_option = false);
  /// Fills the fields of OperatorMeshData (what prepare() returns); for an override of
  /// prepare() that derives its own data from OperatorMeshData.
  void fill_mesh_data(const Mesh& mesh, int threads, OperatorMeshData& data) const;
  /// The common start of a method that excludes boundary vertices by design: false, with `out`
  /// set, for a vertex without faces (failed) or on the boundary (excluded).
  static bool interior_with_faces(const Mesh& mesh, int v, VertexEstimate& out);
  static const OperatorMeshData& mesh_data(const MeshContext& ctx) {
    return static_cast<const OperatorMeshData&>(*ctx.data);
  }

 private:
  VertexNormals default_normals_;
};

}  // namespace curvbench
