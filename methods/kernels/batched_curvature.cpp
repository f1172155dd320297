// Lane-wise local frames and height-function curvature; see batched_curvature.h. Compiled once
// per Highway target (foreach_target.h re-includes this file), dispatched at run time. Every
// expression mirrors the scalar one it stands for, operation by operation (Eigen's Vec3
// reductions sum as ((x + y) + z)); comments name the scalar line.
#undef HWY_TARGET_INCLUDE
#define HWY_TARGET_INCLUDE "methods/kernels/batched_curvature.cpp"
#include <hwy/foreach_target.h>  // IWYU pragma: keep
// Highway must come after foreach_target.h.
#include <hwy/highway.h>

#include "methods/kernels/batched_curvature.h"

#include "methods/kernels/lanes-inl.h"

HWY_BEFORE_NAMESPACE();
namespace curvbench {
namespace HWY_NAMESPACE {
namespace {


struct V3 {
  V x, y, z;
};

HWY_INLINE V3 load3(D d, const double* p) {
  return {hn::LoadU(d, p), hn::LoadU(d, p + L), hn::LoadU(d, p + 2 * L)};
}
HWY_INLINE void store3(D d, const V3& a, double* p) {
  hn::StoreU(a.x, d, p);
  hn::StoreU(a.y, d, p + L);
  hn::StoreU(a.z, d, p + 2 * L);
}
HWY_INLINE V dot3(const V3& a, const V3& b) {
  return hn::Add(hn::Add(hn::Mul(a.x, b.x), hn::Mul(a.y, b.y)), hn::Mul(a.z, b.z));
}
HWY_INLINE V3 scale3(V s, const V3& a) {
  return {hn::Mul(s, a.x), hn::Mul(s, a.y), hn::Mul(s, a.z)};
}
HWY_INLINE V3 add3(const V3& a, const V3& b) {
  return {hn::Add(a.x, b.x), hn::Add(a.y, b.y), hn::Add(a.z, b.z)};
}
HWY_INLINE V3 sub3(const V3& a, const V3& b) {
  return {hn::Sub(a.x, b.x), hn::Sub(a.y, b.y), hn::Sub(a.z, b.z)};
}
HWY_INLINE V3 div3(const V3& a, V s) {
  return {hn::Div(a.x, s), hn::Div(a.y, s), hn::Div(a.z, s)};
}
HWY_INLINE M finite3(const V3& a) {
  return hn::And(hn::And(hn::IsFinite(a.x), hn::IsFinite(a.y)), hn::IsFinite(a.z));
}
HWY_INLINE void store_mask(D d, M mask, bool* out) {
  alignas(64) double buf[L];
  hn::StoreU(hn::IfThenElseZero(mask, hn::Set(d, 1.0)), d, buf);
  for (size_t l = 0; l < hn::Lanes(d); ++l) out[l] = buf[l] != 0.0;
}
// norm2d() of shape_operator.cpp on the lanes where max(|a|, |b|) lies in (1e-150, 1e150); the
// other lanes are cleared from `regular`.
HWY_INLINE V norm2d_regular(D d, V a, V b, M& regular) {
  const V big = hn::Max(hn::Abs(a), hn::Abs(b));
  regular =
      hn::And(regular, hn::And(hn::Lt(big, hn::Set(d, 1e150)), hn::Gt(big, hn::Set(d, 1e-150))));
  return hn::Sqrt(hn::Add(hn::Mul(a, a), hn::Mul(b, b)));
}

void BatchedLocalFrames(const double* normals, BatchedFrames& out) {
  const D d;
  const int N = static_cast<int>(hn::Lanes(d));
  const V zero = hn::Zero(d), one = hn::Set(d, 1.0);
  for (int o = 0; o < L; o += N) {
    const V3 n = load3(d, normals + o);
    // len = m.norm(); a zero or non-finite length is the scalar function's special case.
    const V len = hn::Sqrt(dot3(n, n));
    M regular = hn::And(hn::Gt(len, zero), hn::IsFinite(len));
    const V3 m = div3(n, len);
    // e = (|m.x| > |m.y| && |m.x| > |m.z|) ? (0, 1, 0) : (1, 0, 0)
    const V ax = hn::Abs(m.x);
    const M use_y = hn::And(hn::Gt(ax, hn::Abs(m.y)), hn::Gt(ax, hn::Abs(m.z)));
    const V3 e{hn::IfThenElse(use_y, zero, one), hn::IfThenElse(use_y, one, zero), zero};
    // t1 = (e - e.dot(m) m).normalized(): divided by the root of the squared norm if positive.
    const V3 r = sub3(e, scale3(dot3(e, m), m));
    const V sq = dot3(r, r);
    regular = hn::And(regular, hn::Gt(sq, zero));
    const V3 t1 = div3(r, hn::Sqrt(sq));
    // t2 = m x t1
    const V3 t2{hn::Sub(hn::Mul(m.y, t1.z), hn::Mul(m.z, t1.y)),
                hn::Sub(hn::Mul(m.z, t1.x), hn::Mul(m.x, t1.z)),
                hn::Sub(hn::Mul(m.x, t1.y), hn::Mul(m.y, t1.x))};
    store3(d, m, out.m.data() + o);
    store3(d, t1, out.t1.data() + o);
    store3(d, t2, out.t2.data() + o);
    store_mask(d, regular, out.regular.data() + o);
  }
}

// The lanes o, o + 1, ... of `out`.
HWY_INLINE void store_curvature(D d, const V3& normal, V k1, V k2, V H, V K, const V3& d1,
                                const V3& d2, M regular, BatchedCurvature& out, int o) {
  store3(d, normal, out.normal.data() + o);
  store3(d, d1, out.d1.data() + o);
  store3(d, d2, out.d2.data() + o);
  hn::StoreU(k1, d, out.k1.data() + o);
  hn::StoreU(k2, d, out.k2.data() + o);
  hn::StoreU(H, d, out.H.data() + o);
  hn::StoreU(K, d, out.K.data() + o);
  store_mask(d, regular, out.regular.data() + o);
}

// principal_from_symmetric(w11, w12, w22, q1, q2): eq. (7) for k1 >= k2, eq. (8) for d1, d2;
// lanes at the scalar function's special cases (exact umbilic, norms outside norm2d's plain
// range, non-finite directions) are cleared from `regular`.
HWY_INLINE void principal_lanes(D d, V w11, V w12, V w22, const V3& q1, const V3& q2, M& regular,
                                V& k1, V& k2, V3& d1, V3& d2) {
  const V zero = hn::Zero(d), two = hn::Set(d, 2.0), half = hn::Set(d, 0.5);
  const V mean = hn::Mul(half, hn::Add(w11, w22));
  const V disc = hn::Mul(half, norm2d_regular(d, hn::Sub(w11, w22), hn::Mul(two, w12), regular));
  k1 = hn::Add(mean, disc);
  k2 = hn::Sub(mean, disc);
  regular = hn::And(regular, hn::Ne(k1, k2));  // the exact umbilic is the scalar's case
  // Eq. (8), eigen_direction(w11, w12, ki, kj): (w11 - kj, w12) if |w11 - kj| > |w11 - ki|,
  // else (w12, -(w11 - ki)).
  const V r1 = hn::Sub(w11, k1), r2 = hn::Sub(w11, k2);
  const M first1 = hn::Gt(hn::Abs(r2), hn::Abs(r1));
  const M first2 = hn::Gt(hn::Abs(r1), hn::Abs(r2));
  V a1x = hn::IfThenElse(first1, r2, w12), a1y = hn::IfThenElse(first1, w12, hn::Neg(r1));
  V a2x = hn::IfThenElse(first2, r1, w12), a2y = hn::IfThenElse(first2, w12, hn::Neg(r2));
  const V n1 = hn::Sqrt(hn::Add(hn::Mul(a1x, a1x), hn::Mul(a1y, a1y)));
  const V n2 = hn::Sqrt(hn::Add(hn::Mul(a2x, a2x), hn::Mul(a2y, a2y)));
  regular = hn::And(regular, hn::And(hn::And(hn::Gt(n1, zero), hn::IsFinite(n1)),
                                     hn::And(hn::Gt(n2, zero), hn::IsFinite(n2))));
  a1x = hn::Div(a1x, n1);
  a1y = hn::Div(a1y, n1);
  a2x = hn::Div(a2x, n2);
  a2y = hn::Div(a2y, n2);
  // Right-handed: a2 = -a2 if det[a1 a2] < 0.
  const M flip = hn::Lt(hn::Sub(hn::Mul(a1x, a2y), hn::Mul(a1y, a2x)), zero);
  a2x = hn::IfThenElse(flip, hn::Neg(a2x), a2x);
  a2y = hn::IfThenElse(flip, hn::Neg(a2y), a2y);
  d1 = add3(scale3(a1x, q1), scale3(a1y, q2));
  d2 = add3(scale3(a2x, q1), scale3(a2y, q2));
}

void BatchedCurvatureFromHeight(const BatchedFrames& frames, const double* taylor, int stride,
                                BatchedCurvature& out) {
  const D d;
  const int N = static_cast<int>(hn::Lanes(d));
  const V one = hn::Set(d, 1.0), two = hn::Set(d, 2.0);
  for (int o = 0; o < L; o += N) {
    const V3 t1 = load3(d, frames.t1.data() + o), t2 = load3(d, frames.t2.data() + o),
             m = load3(d, frames.m.data() + o);
    const V fu = hn::LoadU(d, taylor + 1 * stride + o), fv = hn::LoadU(d, taylor + 2 * stride + o),
            fuu = hn::LoadU(d, taylor + 3 * stride + o),
            fuv = hn::LoadU(d, taylor + 4 * stride + o),
            fvv = hn::LoadU(d, taylor + 5 * stride + o);
    M regular = hn::And(hn::And(finite3(t1), finite3(t2)), finite3(m));
    regular = hn::And(regular, hn::And(hn::And(hn::IsFinite(fu), hn::IsFinite(fv)),
                                       hn::And(hn::IsFinite(fuu), hn::IsFinite(fuv))));
    regular = hn::And(regular, hn::IsFinite(fvv));
    // g = norm2d(fu, fv); ell2 = 1 + fu fu + fv fv; ell = sqrt(ell2)
    const V g = norm2d_regular(d, fu, fv, regular);
    const V ell2 = hn::Add(hn::Add(one, hn::Mul(fu, fu)), hn::Mul(fv, fv));
    const V ell = hn::Sqrt(ell2);
    // normal = (m - fu t1 - fv t2) / ell
    const V3 normal = div3(sub3(sub3(m, scale3(fu, t1)), scale3(fv, t2)), ell);
    // gHg = fu fu fuu + 2 fu fv fuv + fv fv fvv
    const V gHg =
        hn::Add(hn::Add(hn::Mul(hn::Mul(fu, fu), fuu), hn::Mul(hn::Mul(hn::Mul(two, fu), fv), fuv)),
                hn::Mul(hn::Mul(fv, fv), fvv));
    // H = (fuu + fvv) / (2 ell) - gHg / (2 ell2 ell); K = (fuu fvv - fuv fuv) / (ell2 ell2)
    const V H = hn::Sub(hn::Div(hn::Add(fuu, fvv), hn::Mul(two, ell)),
                        hn::Div(gHg, hn::Mul(hn::Mul(two, ell2), ell)));
    const V K = hn::Div(hn::Sub(hn::Mul(fuu, fvv), hn::Mul(fuv, fuv)), hn::Mul(ell2, ell2));
    // cs = fu / g, sn = fv / g (g > 0 on regular lanes)
    const V cs = hn::Div(fu, g), sn = hn::Div(fv, g), nsn = hn::Neg(sn);
    // q1 = (cs / ell) t1 + (sn / ell) t2 + (g / ell) m; q2 = -sn t1 + cs t2
    const V3 q1 = add3(add3(scale3(hn::Div(cs, ell), t1), scale3(hn::Div(sn, ell), t2)),
                       scale3(hn::Div(g, ell), m));
    const V3 q2 = add3(scale3(nsn, t1), scale3(cs, t2));
    const V hc_u = hn::Add(hn::Mul(fuu, cs), hn::Mul(fuv, sn));
    const V hc_v = hn::Add(hn::Mul(fuv, cs), hn::Mul(fvv, sn));
    const V hp_u = hn::Add(hn::Mul(hn::Neg(fuu), sn), hn::Mul(fuv, cs));
    const V hp_v = hn::Add(hn::Mul(hn::Neg(fuv), sn), hn::Mul(fvv, cs));
    const V w11 = hn::Div(hn::Add(hn::Mul(cs, hc_u), hn::Mul(sn, hc_v)), hn::Mul(ell2, ell));
    const V w12 = hn::Div(hn::Add(hn::Mul(nsn, hc_u), hn::Mul(cs, hc_v)), ell2);
    const V w22 = hn::Div(hn::Add(hn::Mul(nsn, hp_u), hn::Mul(cs, hp_v)), ell);
    V k1, k2;
    V3 d1, d2;
    principal_lanes(d, w11, w12, w22, q1, q2, regular, k1, k2, d1, d2);
    store_curvature(d, normal, k1, k2, H, K, d1, d2, regular, out, o);
  }
}

void BatchedCurvatureFromTangentTensor(const BatchedFrames& frames, const double* w11,
                                       const double* w12, const double* w22,
                                       BatchedCurvature& out) {
  const D d;
  const int N = static_cast<int>(hn::Lanes(d));
  const V half = hn::Set(d, 0.5);
  for (int o = 0; o < L; o += N) {
    const V3 t1 = load3(d, frames.t1.data() + o), t2 = load3(d, frames.t2.data() + o),
             m = load3(d, frames.m.data() + o);
    const V a = hn::LoadU(d, w11 + o), b = hn::LoadU(d, w12 + o), c = hn::LoadU(d, w22 + o);
    M regular = hn::And(hn::And(finite3(t1), finite3(t2)), finite3(m));
    regular = hn::And(regular, hn::And(hn::And(hn::IsFinite(a), hn::IsFinite(b)), hn::IsFinite(c)));
    V k1, k2;
    V3 d1, d2;
    principal_lanes(d, a, b, c, t1, t2, regular, k1, k2, d1, d2);
    // curvature_from_tangent_tensor: normal m, H = (k1 + k2) / 2, K = k1 k2
    store_curvature(d, m, k1, k2, hn::Mul(half, hn::Add(k1, k2)), hn::Mul(k1, k2), d1, d2, regular,
                    out, o);
  }
}

}  // namespace
// NOLINTNEXTLINE(google-readability-namespace-comments)
}  // namespace HWY_NAMESPACE
}  // namespace curvbench
HWY_AFTER_NAMESPACE();

#if HWY_ONCE
namespace curvbench {

HWY_EXPORT(BatchedLocalFrames);
HWY_EXPORT(BatchedCurvatureFromHeight);
HWY_EXPORT(BatchedCurvatureFromTangentTensor);

namespace {
Vec3 lane3(const std::array<double, 3 * kBatchLanes>& a, int l) {
  return {a[static_cast<size_t>(l)], a[static_cast<size_t>(kBatchLanes + l)],
          a[static_cast<size_t>(2 * kBatchLanes + l)]};
}
}  // namespace

LocalFrame BatchedFrames::frame(int l) const {
  LocalFrame f;
  f.t1 = lane3(t1, l);
  f.t2 = lane3(t2, l);
  f.m = lane3(m, l);
  return f;
}

Curvature BatchedCurvature::curvature(int l) const {
  Curvature c;
  const auto i = static_cast<size_t>(l);
  c.normal = lane3(normal, l);
  c.k1 = k1[i];
  c.k2 = k2[i];
  c.H = H[i];
  c.K = K[i];
  c.d1 = lane3(d1, l);
  c.d2 = lane3(d2, l);
  return c;
}

void batched_local_frames(const double* normals, BatchedFrames& out) {
  HWY_DYNAMIC_DISPATCH(BatchedLocalFrames)(normals, out);
}

void batched_curvature_from_height(const BatchedFrames& frames, const double* taylor, int stride,
                                   BatchedCurvature& out) {
  HWY_DYNAMIC_DISPATCH(BatchedCurvatureFromHeight)(frames, taylor, stride, out);
}

void batched_curvature_from_tangent_tensor(const BatchedFrames& frames, const double* w11,
                                           const double* w12, const double* w22,
                                           BatchedCurvature& out) {
  HWY_DYNAMIC_DISPATCH(BatchedCurvatureFromTangentTensor)(frames, w11, w12, w22, out);
}

}  // namespace curvbench
#endif  // HWY_ONCE
