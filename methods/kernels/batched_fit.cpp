// Batched fits, one vertex per SIMD lane; see batched_fit.h. Compiled once per Highway target
// (foreach_target.h re-includes this file); batched_fit() dispatches to the best one at run time.
#undef HWY_TARGET_INCLUDE
#define HWY_TARGET_INCLUDE "methods/kernels/batched_fit.cpp"
#include <hwy/foreach_target.h>  // IWYU pragma: keep
// Highway must come after foreach_target.h.
#include <hwy/highway.h>

#include <algorithm>
#include <cmath>
#include <limits>

#include "methods/fits/polynomial_fit.h"
#include "methods/kernels/batched_fit.h"

#include "methods/kernels/lanes-inl.h"

HWY_BEFORE_NAMESPACE();
namespace curvbench {
namespace HWY_NAMESPACE {
namespace {

// Householder update of C columns by the reflector v in x[j..m) (lane-wise):
// col -= (beta v . col) v. The dot products run side by side, each in two halves (even and odd
// rows), so 2 C independent chains hide the latency of the fused multiply-adds.
template <int C>
HWY_INLINE void reflect_columns(D d, const double* x, double* const* cols, int j, int m, V beta) {
  V even[C], odd[C];
  for (int q = 0; q < C; ++q) even[q] = odd[q] = hn::Zero(d);
  int i = j;
  for (; i + 1 < m; i += 2) {
    const V x0 = hn::LoadU(d, x + i * L), x1 = hn::LoadU(d, x + (i + 1) * L);
    for (int q = 0; q < C; ++q) {
      even[q] = hn::MulAdd(x0, hn::LoadU(d, cols[q] + i * L), even[q]);
      odd[q] = hn::MulAdd(x1, hn::LoadU(d, cols[q] + (i + 1) * L), odd[q]);
    }
  }
  if (i < m) {
    const V x0 = hn::LoadU(d, x + i * L);
    for (int q = 0; q < C; ++q) even[q] = hn::MulAdd(x0, hn::LoadU(d, cols[q] + i * L), even[q]);
  }
  for (int q = 0; q < C; ++q) even[q] = hn::Mul(beta, hn::Add(even[q], odd[q]));
  for (i = j; i < m; ++i) {
    const V xi = hn::LoadU(d, x + i * L);
    for (int q = 0; q < C; ++q) {
      double* const p = cols[q] + i * L;
      hn::StoreU(hn::NegMulAdd(even[q], xi, hn::LoadU(d, p)), d, p);
    }
  }
}

// The reflectors H_k = I - beta_k v_k v_k^T, k = 0..B-1, of columns j0 + k (v_k in rows
// j0 + k .. m-1 of vs[k]), applied one after another to C columns in one pass (a block
// reflector, as in the compact WY form): with a_k = v_k . col and s[k][i] = v_k . v_i,
//   t_k = beta_k (a_k - sum_{i<k} t_i s[k][i]),   col -= sum_k t_k v_k,
// which is H_{B-1} ... H_0 col. Each column is read twice and written once per B reflectors
// instead of B times (the unblocked update is bound by its stores).
template <int B, int C>
HWY_INLINE void reflect_block(D d, const double* const* vs, const V* beta, const V (*s)[B],
                              double* const* cols, int j0, int m) {
  V a[B][C];
  for (int k = 0; k < B; ++k)
    for (int q = 0; q < C; ++q) a[k][q] = hn::Zero(d);
  const int head_end = std::min(j0 + B - 1, m);  // rows where only some v_k are non-zero
  int i = j0;
  for (; i < head_end; ++i)
    for (int k = 0; k <= i - j0; ++k) {
      const V vk = hn::LoadU(d, vs[k] + i * L);
      for (int q = 0; q < C; ++q) a[k][q] = hn::MulAdd(vk, hn::LoadU(d, cols[q] + i * L), a[k][q]);
    }
  for (; i < m; ++i) {
    V c[C];
    for (int q = 0; q < C; ++q) c[q] = hn::LoadU(d, cols[q] + i * L);
    for (int k = 0; k < B; ++k) {
      const V vk = hn::LoadU(d, vs[k] + i * L);
      for (int q = 0; q < C; ++q) a[k][q] = hn::MulAdd(vk, c[q], a[k][q]);
    }
  }
  V t[B][C];
  for (int k = 0; k < B; ++k)
    for (int q = 0; q < C; ++q) {
      V sum = a[k][q];
      for (int p = 0; p < k; ++p) sum = hn::NegMulAdd(t[p][q], s[k][p], sum);
      t[k][q] = hn::Mul(beta[k], sum);
    }
  for (i = j0; i < head_end; ++i)
    for (int q = 0; q < C; ++q) {
      double* const p = cols[q] + i * L;
      V c = hn::LoadU(d, p);
      for (int k = 0; k <= i - j0; ++k) c = hn::NegMulAdd(t[k][q], hn::LoadU(d, vs[k] + i * L), c);
      hn::StoreU(c, d, p);
    }
  for (; i < m; ++i) {
    V v[B];
    for (int k = 0; k < B; ++k) v[k] = hn::LoadU(d, vs[k] + i * L);
    for (int q = 0; q < C; ++q) {
      double* const p = cols[q] + i * L;
      V c = hn::LoadU(d, p);
      for (int k = 0; k < B; ++k) c = hn::NegMulAdd(t[k][q], v[k], c);
      hn::StoreU(c, d, p);
    }
  }
}

// reflect_block<B, C> over `count` columns, four at a time.
template <int B>
HWY_INLINE void reflect_block_columns(D d, const double* const* vs, const V* beta, const V (*s)[B],
                                      double* const* cols, int count, int j0, int m) {
  int c = 0;
  for (; c + 4 <= count; c += 4) reflect_block<B, 4>(d, vs, beta, s, cols + c, j0, m);
  switch (count - c) {
    case 3:
      reflect_block<B, 3>(d, vs, beta, s, cols + c, j0, m);
      break;
    case 2:
      reflect_block<B, 2>(d, vs, beta, s, cols + c, j0, m);
      break;
    case 1:
      reflect_block<B, 1>(d, vs, beta, s, cols + c, j0, m);
      break;
    default:
      break;
  }
}

// The inner products s[k][p] = v_k . v_p (p < k; rows from j0 + k, where v_k starts) of the
// reflectors of a block, side by side, then the block applied to `count` columns.
template <int B>
HWY_INLINE void apply_block(D d, const double* const* vs, const V* beta, double* const* cols,
                            int count, int j0, int m) {
  V s[B][B];
  if constexpr (B > 1) {
    for (int k = 1; k < B; ++k)
      for (int p = 0; p < k; ++p) s[k][p] = hn::Zero(d);
    const int head_end = std::min(j0 + B - 1, m);
    int i = j0 + 1;
    for (; i < head_end; ++i)
      for (int k = 1; k <= i - j0; ++k)
        for (int p = 0; p < k; ++p)
          s[k][p] = hn::MulAdd(hn::LoadU(d, vs[k] + i * L), hn::LoadU(d, vs[p] + i * L), s[k][p]);
    for (; i < m; ++i) {
      V v[B];
      for (int k = 0; k < B; ++k) v[k] = hn::LoadU(d, vs[k] + i * L);
      for (int k = 1; k < B; ++k)
        for (int p = 0; p < k; ++p) s[k][p] = hn::MulAdd(v[k], v[p], s[k][p]);
    }
  }
  reflect_block_columns<B>(d, vs, beta, s, cols, count, j0, m);
}

// The sum of x_i^2 over rows j .. m-1, in four interleaved partial sums (one dependent chain
// of fused multiply-adds would be bound by their latency).
HWY_INLINE V sum_of_squares(D d, const double* x, int j, int m) {
  V s0 = hn::Zero(d), s1 = s0, s2 = s0, s3 = s0;
  int i = j;
  for (; i + 3 < m; i += 4) {
    const V x0 = hn::LoadU(d, x + i * L), x1 = hn::LoadU(d, x + (i + 1) * L);
    const V x2 = hn::LoadU(d, x + (i + 2) * L), x3 = hn::LoadU(d, x + (i + 3) * L);
    s0 = hn::MulAdd(x0, x0, s0);
    s1 = hn::MulAdd(x1, x1, s1);
    s2 = hn::MulAdd(x2, x2, s2);
    s3 = hn::MulAdd(x3, x3, s3);
  }
  // Row i always goes to partial sum (i - j) mod 4, whatever m is: a lane's padding rows (zero)
  // then add exact zeros, and its result does not depend on the other lanes' row counts.
  if (i < m) {
    const V x0 = hn::LoadU(d, x + i * L);
    s0 = hn::MulAdd(x0, x0, s0);
  }
  if (i + 1 < m) {
    const V x1 = hn::LoadU(d, x + (i + 1) * L);
    s1 = hn::MulAdd(x1, x1, s1);
  }
  if (i + 2 < m) {
    const V x2 = hn::LoadU(d, x + (i + 2) * L);
    s2 = hn::MulAdd(x2, x2, s2);
  }
  return hn::Add(hn::Add(s0, s1), hn::Add(s2, s3));
}

// x^(-q/4) as inverse_power() in weights.h (same correctly rounded operations).
HWY_INLINE V inverse_power_q(V x, int q) {
  const D d;
  const V one = hn::Set(d, 1.0);
  switch (q) {
    case 1:
      return hn::Div(one, hn::Sqrt(hn::Sqrt(x)));
    case 2:
      return hn::Div(one, hn::Sqrt(x));
    case 3: {
      const V s = hn::Sqrt(x);
      return hn::Div(one, hn::Mul(s, hn::Sqrt(s)));
    }
    default:
      return hn::Div(one, x);
  }
}

void BatchedFitKernel(BatchedSystems& s) {
  const D d;
  const int N = static_cast<int>(hn::Lanes(d));
  const bool ic = s.include_constant;
  const int deg = s.degree;
  const int n = num_columns(deg, ic);
  const int k = s.rhs;
  const int m = std::min(s.max_rows, kMaxRows);
  const int q = static_cast<int>(std::lround(4.0 * s.power));
  double* const work = s.work.data();
  // Column c of [A B] for the lanes from o: m rows, stride L (compact, so the columns of a small
  // system share cache lines instead of aliasing at a fixed large stride).
  const auto column = [&](int c, int o) { return work + c * m * L + o; };
  alignas(64) double rows_d[L], solved[L];
  for (int l = 0; l < L; ++l) rows_d[l] = std::max(s.rows[static_cast<size_t>(l)], 1);
  const V zero = hn::Zero(d);
  const V one = hn::Set(d, 1.0);
  const V tol = hn::Set(d, s.tol);
  const V inf = hn::Set(d, std::numeric_limits<double>::infinity());

  for (int o = 0; o < L; o += N) {
    const double* const u = s.u.data() + o;
    const double* const v = s.v.data() + o;
    double* const w = s.gamma.data() + o;  // gamma, overwritten with the weights

    // Eq. (15) weights, as compute_weights(): the padding rows add 0 to the sum.
    V sum = zero;
    for (int i = 0; i < m; ++i) {
      const V uu = hn::LoadU(d, u + i * L), vv = hn::LoadU(d, v + i * L);
      sum = hn::Add(sum, hn::Add(hn::Mul(uu, uu), hn::Mul(vv, vv)));
    }
    const V mean = hn::Div(sum, hn::LoadU(d, rows_d + o));
    const V eps = hn::Mul(hn::Set(d, 0.01), mean);
    const auto positive = hn::Gt(mean, zero);
    for (int i = 0; i < m; ++i) {
      const V uu = hn::LoadU(d, u + i * L), vv = hn::LoadU(d, v + i * L);
      const V g = hn::LoadU(d, w + i * L);
      const V x = hn::Add(hn::Add(hn::Mul(uu, uu), hn::Mul(vv, vv)), eps);
      hn::StoreU(hn::IfThenElse(positive, hn::Mul(g, inverse_power_q(x, q)), g), d, w + i * L);
    }

    // Eq. (13): Omega V in the column order of vandermonde.h, then Omega f.
    int first = 0;
    if (ic) {
      for (int i = 0; i < m; ++i) hn::StoreU(hn::LoadU(d, w + i * L), d, column(0, o) + i * L);
      first = 1;
    }
    for (int i = 0; i < m; ++i) {
      const V wi = hn::LoadU(d, w + i * L);
      hn::StoreU(hn::Mul(wi, hn::LoadU(d, u + i * L)), d, column(first, o) + i * L);
      hn::StoreU(hn::Mul(wi, hn::LoadU(d, v + i * L)), d, column(first + 1, o) + i * L);
    }
    for (int p = 2; p <= deg; ++p) {
      const int block = num_columns(p - 1, ic), prev = num_columns(p - 2, ic);
      for (int i = 0; i < m; ++i) {
        const V uu = hn::LoadU(d, u + i * L), vv = hn::LoadU(d, v + i * L);
        for (int c = 0; c < p; ++c)
          hn::StoreU(hn::Mul(hn::LoadU(d, column(prev + c, o) + i * L), uu), d,
                     column(block + c, o) + i * L);
        hn::StoreU(hn::Mul(hn::LoadU(d, column(prev + p - 1, o) + i * L), vv), d,
                   column(block + p, o) + i * L);
      }
    }
    for (int c = 0; c < k; ++c) {
      const double* const fc = s.f.data() + c * kMaxRows * L + o;
      for (int i = 0; i < m; ++i)
        hn::StoreU(hn::Mul(hn::LoadU(d, fc + i * L), hn::LoadU(d, w + i * L)), d,
                   column(n + c, o) + i * L);
    }

    // Eq. (14): the 2-norms s_c of the columns (a zero or non-finite norm counts as 1). The
    // scaling is not applied to the matrix: a Householder reflector does not change when its
    // column is scaled, so the QR of A S^-1 is Q (R S^-1), and the safeguard's test on the scaled
    // diagonal, |R_jj| / s_j >= tol, is made on R directly; back substitution with R gives the
    // monomial coefficients c = S^-1 y at once.
    V scale[kBatchCols];
    for (int c = 0; c < n; ++c) {
      const V norm = hn::Sqrt(sum_of_squares(d, column(c, o), 0, m));
      scale[c] = hn::IfThenElse(hn::And(hn::Gt(norm, zero), hn::Lt(norm, inf)), norm, one);
    }

    // Householder QR of [A B], left to right, in panels of kPanel columns: each reflector
    // updates the rest of its panel at once, and the panel's reflectors update the columns to
    // its right together (apply_block). A lane is solved if every |R_jj| >= tol and its factor
    // passes the condition test below.
    constexpr int kPanel = 4;
    auto ok = hn::FirstN(d, static_cast<size_t>(N));
    V rdiag[kBatchCols];
    for (int j0 = 0; j0 < n; j0 += kPanel) {
      const int panel = std::min(kPanel, n - j0);
      const double* vs[kPanel];
      V beta[kPanel];
      for (int j = j0; j < j0 + panel; ++j) {
        double* const x = column(j, o);
        const V norm = hn::Sqrt(sum_of_squares(d, x, j, m));
        ok = hn::And(ok, hn::And(hn::Ge(norm, hn::Mul(tol, scale[j])), hn::Gt(norm, zero)));
        const V xj = hn::LoadU(d, x + j * L);
        const V alpha = hn::IfThenElse(hn::Gt(xj, zero), hn::Neg(norm), norm);  // R_jj
        const V v0 = hn::Sub(xj, alpha);
        hn::StoreU(v0, d, x + j * L);
        const V vnorm2 = hn::Mul(hn::Add(norm, norm), hn::Abs(v0));  // |v|^2
        beta[j - j0] =
            hn::IfThenElseZero(hn::And(ok, hn::Gt(vnorm2, zero)), hn::Div(hn::Set(d, 2.0), vnorm2));
        vs[j - j0] = x;
        rdiag[j] = hn::IfThenElse(ok, alpha, one);
        double* cols[kPanel];
        const int rest = j0 + panel - j - 1;  // the panel's columns right of j
        for (int c = 0; c < rest; ++c) cols[c] = column(j + 1 + c, o);
        switch (rest) {
          case 3:
            reflect_columns<3>(d, x, cols, j, m, beta[j - j0]);
            break;
          case 2:
            reflect_columns<2>(d, x, cols, j, m, beta[j - j0]);
            break;
          case 1:
            reflect_columns<1>(d, x, cols, j, m, beta[j - j0]);
            break;
          default:
            break;
        }
      }
      double* cols[kBatchCols + kMaxRhs];
      const int rest = n + k - j0 - panel;  // the columns right of the panel
      for (int c = 0; c < rest; ++c) cols[c] = column(j0 + panel + c, o);
      switch (panel) {
        case 4:
          apply_block<4>(d, vs, beta, cols, rest, j0, m);
          break;
        case 3:
          apply_block<3>(d, vs, beta, cols, rest, j0, m);
          break;
        case 2:
          apply_block<2>(d, vs, beta, cols, rest, j0, m);
          break;
        default:
          apply_block<1>(d, vs, beta, cols, rest, j0, m);
          break;
      }
    }
    V inv_r[kBatchCols];
    for (int i = 0; i < n; ++i) inv_r[i] = hn::Div(one, rdiag[i]);

    // §4.3.2: the scalar safeguard's condition test, ||R_k^-1||_F <= 1 / tol for the scaled
    // factor R_k S^-1 (safeguarded_qr.cpp). The norm grows with k, so the lane keeps the degree
    // iff the test passes for all n columns. The inverse of R S^-1 is S R^-1: its column j is S y
    // with R y = e_j.
    if (s.tol > 0.0 && s.condition) {
      const V limit = hn::Set(d, 1.0 / (s.tol * s.tol));
      V inv2 = zero;
      for (int j = 0; j < n; ++j) {
        V y[kBatchCols];
        y[j] = inv_r[j];
        const V zj = hn::Mul(scale[j], y[j]);
        V norm2 = hn::Mul(zj, zj);
        for (int i = j - 1; i >= 0; --i) {
          V dot = zero;
          for (int l = i + 1; l <= j; ++l)
            dot = hn::MulAdd(hn::LoadU(d, column(l, o) + i * L), y[l], dot);
          y[i] = hn::Neg(hn::Mul(dot, inv_r[i]));
          const V zi = hn::Mul(scale[i], y[i]);
          norm2 = hn::MulAdd(zi, zi, norm2);
        }
        inv2 = hn::Add(inv2, norm2);
      }
      ok = hn::And(ok, hn::Le(inv2, limit));
    }
    hn::StoreU(hn::IfThenElseZero(ok, one), d, solved + o);

    // Back substitution R c = (Q^T B)(0:n) for the monomial coefficients c, then the
    // Taylor derivatives c_jk = j! k! coefficient (polynomial_fit.h).
    static constexpr int kPowers[5][2] = {{1, 0}, {0, 1}, {2, 0}, {1, 1}, {0, 2}};
    for (int c = 0; c < k; ++c) {
      V y[kBatchCols], coef[kBatchCols];
      const double* const b = column(n + c, o);
      for (int i = 0; i < n; ++i) y[i] = hn::LoadU(d, b + i * L);
      for (int i = n - 1; i >= 0; --i) {
        const V xi = hn::Mul(y[i], inv_r[i]);
        const double* const r = column(i, o);  // R(0:i, i)
        for (int jj = 0; jj < i; ++jj) y[jj] = hn::NegMulAdd(hn::LoadU(d, r + jj * L), xi, y[jj]);
        coef[i] = xi;
      }
      double* const t = s.taylor.data() + o;
      hn::StoreU(ic ? coef[0] : zero, d, t + (kF * kMaxRhs + c) * L);
      for (int e = 0; e < 5; ++e) {
        const int pj = kPowers[e][0], pk = kPowers[e][1];
        const V value = pj + pk > deg ? zero
                                      : hn::Mul(hn::Set(d, taylor_factor(pj, pk)),
                                                coef[monomial_index(pj, pk, ic)]);
        hn::StoreU(value, d, t + ((1 + e) * kMaxRhs + c) * L);
      }
    }
  }
  for (int l = 0; l < L; ++l)
    s.solved[static_cast<size_t>(l)] = solved[l] != 0.0 && s.rows[static_cast<size_t>(l)] > 0;
}

}  // namespace
// NOLINTNEXTLINE(google-readability-namespace-comments)
}  // namespace HWY_NAMESPACE
}  // namespace curvbench
HWY_AFTER_NAMESPACE();

#if HWY_ONCE
namespace curvbench {

HWY_EXPORT(BatchedFitKernel);

bool batched_weight_power_supported(double power) {
  const double q = 4.0 * power;
  return q == 1.0 || q == 2.0 || q == 3.0 || q == 4.0;
}

void batched_fit(BatchedSystems& s) {
  HWY_DYNAMIC_DISPATCH(BatchedFitKernel)(s);
}

}  // namespace curvbench
#endif  // HWY_ONCE
