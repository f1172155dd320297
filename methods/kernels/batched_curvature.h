// The per-vertex formulas around a batched fit (methods/kernels/batched_fit.h), one vertex per SIMD lane
// (docs/performance.md): the local frame of make_local_frame() (local_frame.h, docs/algorithms.md §3)
// before the fit, and the height-function curvature of curvature_from_height()
// (core/shape_operator.h: Table 1 and eqs. (7)-(8) of the paper) after it; and the curvature of
// a tangent-plane tensor, curvature_from_tangent_tensor() (eqs. (7)-(8)).
//
// They are lane-wise twins of those scalar functions, written with the same operations in the
// same order (no fused multiply-adds), so a lane's result has the same bits as the scalar call
// (tests/methods/test_batched_curvature.cpp). The scalar functions stay the reference and the
// only place the formulas are explained. A lane is `regular` when none of the scalar functions'
// special cases applies (non-finite or zero input, |grad f| or the eigenvalue gap outside
// [1e-150, 1e150], an exact umbilic); the caller computes the other lanes with the scalar
// functions, whose results the lane-wise code does not attempt to reproduce.
//
// Layout (structure of arrays): component c of lane l at [c * kBatchLanes + l].
#pragma once

#include <array>

#include "core/shape_operator.h"
#include "methods/kernels/batched_fit.h"
#include "methods/local_frame.h"

namespace curvbench {

struct BatchedFrames {
  alignas(64) std::array<double, 3 * kBatchLanes> t1{}, t2{}, m{};
  std::array<bool, kBatchLanes> regular{};

  /// The frame of lane l (only meaningful if regular[l]).
  LocalFrame frame(int l) const;
};

/// make_local_frame() of each lane's normal (normals: component c of lane l at
/// [c * kBatchLanes + l]). Lanes with a zero or non-finite normal are not regular.
void batched_local_frames(const double* normals, BatchedFrames& out);

struct BatchedCurvature {
  alignas(64) std::array<double, 3 * kBatchLanes> normal{}, d1{}, d2{};
  alignas(64) std::array<double, kBatchLanes> k1{}, k2{}, H{}, K{};
  std::array<bool, kBatchLanes> regular{};

  /// The curvature of lane l (only meaningful if regular[l]).
  Curvature curvature(int l) const;
};

/// curvature_from_height(t1, t2, m, fu, fv, fuu, fuv, fvv) of each lane, with the frames of
/// `frames` and the Taylor derivatives fu, fv, fuu, fuv, fvv at taylor[(1 + e) * stride + l]
/// (e = 0..4; the layout of BatchedSystems::taylor with stride kMaxRhs * kBatchLanes).
void batched_curvature_from_height(const BatchedFrames& frames, const double* taylor, int stride,
                                   BatchedCurvature& out);

/// curvature_from_tangent_tensor(m, w11, w12, w22, t1, t2) of each lane, with the frames
/// (t1, t2, m) of `frames` and the tensor entries w11[l], w12[l], w22[l] (the operator methods'
/// route, e.g. goldfeather).
void batched_curvature_from_tangent_tensor(const BatchedFrames& frames, const double* w11,
                                           const double* w12, const double* w22,
                                           BatchedCurvature& out);

}  // namespace curvbench
