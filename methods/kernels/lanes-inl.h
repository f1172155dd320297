// The lane types every batched kernel uses, per Highway target: D (kBatchLanes doubles, one
// vertex per lane), its vector V and mask M, and L = kBatchLanes (the row stride of the
// structure-of-arrays buffers). Included by each kernel after <hwy/highway.h>; foreach_target.h
// re-includes the kernel once per target, and the toggle below lets this header follow.
#if defined(CURVBENCH_KERNELS_LANES_INL_H_) == defined(HWY_TARGET_TOGGLE)
#ifdef CURVBENCH_KERNELS_LANES_INL_H_
#undef CURVBENCH_KERNELS_LANES_INL_H_
#else
#define CURVBENCH_KERNELS_LANES_INL_H_
#endif

#include <hwy/highway.h>

#include "methods/kernels/batched_fit.h"  // kBatchLanes

HWY_BEFORE_NAMESPACE();
namespace curvbench {
namespace HWY_NAMESPACE {

namespace hn = hwy::HWY_NAMESPACE;
using D = hn::CappedTag<double, kBatchLanes>;
using V = hn::Vec<D>;
using M = hn::Mask<D>;
inline constexpr int L = kBatchLanes;

}  // namespace HWY_NAMESPACE
}  // namespace curvbench
HWY_AFTER_NAMESPACE();

#endif  // CURVBENCH_KERNELS_LANES_INL_H_
