// Common base of the degree-free discrete operators (meyer, taubin, rusinkiewicz, quadric, ...):
// no degree (label "Meyer"), the per-mesh data of prepare() (the method's vertex normals of
// vertex_normals.h), a trivial workspace.
#pragma once

#include <cstdint>
#include <memory>
#include <vector>

#include "core/types.h"
#include "methods/estimator.h"

namespace curvbench {

/// The per-mesh data of an OperatorEstimator (MeshContext::data).
struct OperatorMeshData : MeshData {
  VertexMatrix normals;  ///< the method's vertex normals; empty = MeshContext::approx_normals
  /// With a fit's normals (option vertex-normals = lhf-3, ...): 1 where the fit gave no normal
  /// and normals holds the method's own weighted normal instead; empty otherwise.
  std::vector<std::uint8_t> fallback;
  /// Whether vertex v's normal is a stand-in for a fit's (VertexStatus::normal_fallback).
  bool fell_back(int v) const { return !fallback.empty() && fallback[static_cast<size_t>(v)]; }
  /// Unit normal of vertex v (zero for a vertex without faces).
  Vec3 normal(const MeshContext& ctx, int v) const {
    return normals.rows() > 0 ? Vec3(normals.row(v).transpose())
                              : Vec3(ctx.approx_normals.row(v).transpose());
  }
};

/// Whether an operator takes a fit's normals (option vertex-normals = a fit's label): the ones
/// whose result follows the vertex normals field (ICC, the normal cycle).
enum class FittedNormals : bool { refused, accepted };

class OperatorEstimator : public Estimator {
 public:
  bool takes_degree() const final { return false; }
  double default_ring() const override { return 1.0; }
  std::unique_ptr<Workspace> make_workspace(const Mesh& mesh) const override;
  std::unique_ptr<MeshData> prepare(const Mesh& mesh, const VertexMatrix& approx_normals,
                                    int threads) const override;
  /// The vertex normal weighting in use (options().vertex_normals, or the method's default);
  /// with a fit's normals, the weighting of the method's own normals that orient them and stand
  /// in where the fit gives none.
  VertexNormals normal_weighting() const;
  /// Only the area weighting uses MeshContext::approx_normals (they are those normals).
  bool uses_approx_normals() const override {
    return normal_fit_ == nullptr && normal_weighting() == VertexNormals::area;
  }

 protected:
  /// Throws UsageError for a degree other than 0, negative threads, (unless `ring_option`) a
  /// ring other than 0 and 1, or a fit's normals where `fitted` refuses them or the label is not
  /// a fit's.
  OperatorEstimator(EstimatorOptions options, VertexNormals default_normals,
                    bool ring_option = false, FittedNormals fitted = FittedNormals::refused);
  /// Fills the fields of OperatorMeshData (what prepare() returns); for an override of
  /// prepare() that derives its own data from OperatorMeshData. With a fit's normals: the fit
  /// runs over the whole mesh (its own threads option, the same results for any count), each
  /// normal turned to the side of the method's own weighted normal (the side the faces'
  /// orientation gives: outward on a closed oriented mesh, the convention of estimator.h);
  /// where the fit fails or excludes a vertex, the own normal stands in (data.fallback).
  void fill_mesh_data(const Mesh& mesh, int threads, OperatorMeshData& data) const;
  /// Status ok becomes normal_fallback when `fell_back` (the estimate read a stand-in normal).
  static void mark_fallback(bool fell_back, VertexEstimate& out) {
    if (fell_back && out.status == VertexStatus::ok) out.status = VertexStatus::normal_fallback;
  }
  /// The common start of a method that excludes boundary vertices by design: false, with `out`
  /// set, for a vertex without faces (failed) or on the boundary (excluded).
  static bool interior_with_faces(const Mesh& mesh, int v, VertexEstimate& out);
  static const OperatorMeshData& mesh_data(const MeshContext& ctx) {
    return static_cast<const OperatorMeshData&>(*ctx.data);
  }

 private:
  VertexNormals default_normals_;
  std::shared_ptr<const Estimator> normal_fit_;  ///< the fit of option vertex-normals, or null
};

}  // namespace curvbench
