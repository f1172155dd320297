// The Goldfeather fit's shared pieces and its lane-wise path; see goldfeather_batch.h. The
// lane-wise kernel is compiled once per Highway target (foreach_target.h re-includes this file)
// and dispatched at run time.
#undef HWY_TARGET_INCLUDE
#define HWY_TARGET_INCLUDE "methods/kernels/goldfeather_batch.cpp"
#include <hwy/foreach_target.h>  // IWYU pragma: keep
// Highway must come after foreach_target.h.
#include <hwy/highway.h>

#include "methods/kernels/goldfeather_batch.h"

#include "methods/kernels/lanes-inl.h"

HWY_BEFORE_NAMESPACE();
namespace curvbench {
namespace HWY_NAMESPACE {
namespace {

constexpr auto monomial = goldfeather_monomial;

// goldfeather.cpp's scalar steps lane-wise, operation by operation: add_goldfeather_neighbour()
// per slot (an unused normal adds zeros instead of being skipped), goldfeather_normal_equations(),
// then Ldlt<7>: the pivot order by the initial diagonal, the factorisation, the rank test and the
// solve.
void GoldfeatherFitKernel(GoldfeatherBatch& b) {
  using goldfeather::kMatrixEntries;
  using goldfeather::kRhsEntries;
  const D d;
  const hn::RebindToSigned<D> di;
  const int N = static_cast<int>(hn::Lanes(d));
  const V zero = hn::Zero(d), one = hn::Set(d, 1.0);
  for (int o = 0; o < L; o += N) {
    // ---- the sums ----
    V pos[kGoldfeatherMonomials], pos_z[kGoldfeatherMonomials], slope[kGoldfeatherMonomials],
        slope_x[kGoldfeatherMonomials], slope_y[kGoldfeatherMonomials];
    for (int i = 0; i < kGoldfeatherMonomials; ++i)
      pos[i] = pos_z[i] = slope[i] = slope_x[i] = slope_y[i] = zero;
    for (int j = 0; j < b.slots; ++j) {
      const int at = j * L + o;
      const V x = hn::LoadU(d, b.x.data() + at), y = hn::LoadU(d, b.y.data() + at);
      const V z = hn::LoadU(d, b.z.data() + at);
      V m[kGoldfeatherMonomials];
      m[0] = zero;
      m[1] = x;
      m[2] = y;
      for (int deg = 2, i = 3; deg <= 6; ++deg, ++i) {
        for (int p = 0; p < deg; ++p, ++i) m[i] = hn::Mul(x, m[i - deg]);
        m[i] = hn::Mul(y, m[i - deg - 1]);
      }
      for (int i = monomial(4, 0); i < kGoldfeatherMonomials; ++i) pos[i] = hn::Add(pos[i], m[i]);
      for (int i = monomial(2, 0); i < monomial(4, 0); ++i)
        pos_z[i] = hn::Add(pos_z[i], hn::Mul(z, m[i]));
      const auto use = hn::Ne(hn::LoadU(d, b.use.data() + at), zero);
      const V zx = hn::LoadU(d, b.zx.data() + at), zy = hn::LoadU(d, b.zy.data() + at);
      for (int i = monomial(2, 0); i < monomial(5, 0); ++i)
        slope[i] = hn::Add(slope[i], hn::IfThenElseZero(use, m[i]));
      for (int i = monomial(1, 0); i < monomial(3, 0); ++i) {
        slope_x[i] = hn::Add(slope_x[i], hn::IfThenElseZero(use, hn::Mul(zx, m[i])));
        slope_y[i] = hn::Add(slope_y[i], hn::IfThenElseZero(use, hn::Mul(zy, m[i])));
      }
    }
    // ---- the normal equations ----
    const V s = hn::LoadU(d, b.scale.data() + o);
    const V ss = hn::Mul(s, s);
    V g[7][7], rhs[7];
    for (int i = 0, k = 0; i < 7; ++i) {
      for (int j = i; j < 7; ++j, ++k) {
        const goldfeather::Entry& e = kMatrixEntries[static_cast<size_t>(k)];
        g[i][j] = g[j][i] =
            hn::Add(hn::Add(hn::Mul(hn::Mul(hn::Set(d, e.pos_coef), ss), pos[e.pos]),
                            hn::Mul(hn::Set(d, e.x_coef), slope[e.x])),
                    hn::Mul(hn::Set(d, e.y_coef), slope[e.y]));
      }
      const goldfeather::Entry& e = kRhsEntries[static_cast<size_t>(i)];
      rhs[i] = hn::Add(hn::Add(hn::Mul(hn::Mul(hn::Set(d, e.pos_coef), ss), pos_z[e.pos]),
                               hn::Mul(hn::Set(d, e.x_coef), slope_x[e.x])),
                       hn::Mul(hn::Set(d, e.y_coef), slope_y[e.y]));
    }
    for (int i = 0; i < 7; ++i) {
      for (int j = 0; j < 7; ++j) hn::StoreU(g[i][j], d, b.ata.data() + (i * 7 + j) * L + o);
      hn::StoreU(rhs[i], d, b.atb.data() + i * L + o);
    }
    // ---- Ldlt<7>: the order of the diagonal, largest magnitude first (selection with swaps) ----
    V diag[7], perm[7];
    for (int k = 0; k < 7; ++k) {
      diag[k] = hn::Abs(g[k][k]);
      perm[k] = hn::Set(d, k);
    }
    for (int k = 0; k < 7; ++k) {
      V best = diag[k], big = hn::Set(d, k);
      for (int i = k + 1; i < 7; ++i) {
        const auto greater = hn::Gt(diag[i], best);
        best = hn::IfThenElse(greater, diag[i], best);
        big = hn::IfThenElse(greater, hn::Set(d, i), big);
      }
      const V perm_k = perm[k], diag_k = diag[k];
      V perm_big = perm_k;
      for (int i = k + 1; i < 7; ++i) {
        const auto at_big = hn::Eq(big, hn::Set(d, i));
        perm_big = hn::IfThenElse(at_big, perm[i], perm_big);
        perm[i] = hn::IfThenElse(at_big, perm_k, perm[i]);
        diag[i] = hn::IfThenElse(at_big, diag_k, diag[i]);
      }
      perm[k] = perm_big;
      diag[k] = best;
    }
    // P g P^T and P rhs, gathered from the stored equations.
    const auto lane = hn::Iota(di, 0);
    hn::Vec<decltype(di)> row[7];
    for (int k = 0; k < 7; ++k) row[k] = hn::ConvertTo(di, perm[k]);
    const auto stride = hn::Set(di, L);
    V a[7][7], y[7], inverse[7];
    for (int k = 0; k < 7; ++k) {
      for (int i = k; i < 7; ++i) {
        const auto index =
            hn::Add(hn::Mul(hn::Add(hn::Mul(row[k], hn::Set(di, 7)), row[i]), stride), lane);
        a[k][i] = hn::GatherIndex(d, b.ata.data() + o, index);
      }
      y[k] = hn::GatherIndex(d, b.atb.data() + o, hn::Add(hn::Mul(row[k], stride), lane));
    }
    // The factorisation: D_kk on the diagonal, L_ik (i > k) in a[k][i].
    for (int k = 0; k < 7; ++k) {
      inverse[k] = hn::Div(one, a[k][k]);
      for (int i = k + 1; i < 7; ++i) {
        const V l = hn::Mul(a[k][i], inverse[k]);
        for (int j = i; j < 7; ++j) a[i][j] = hn::Sub(a[i][j], hn::Mul(l, a[k][j]));
        a[k][i] = l;
      }
    }
    // full_rank(cubic_tolerance2): big = max |D_kk| (std::max from 0), every D_kk > tol2 big.
    V largest = zero;
    for (int k = 0; k < 7; ++k) {
      const V mag = hn::Abs(a[k][k]);
      largest = hn::IfThenElse(hn::Lt(largest, mag), mag, largest);
    }
    auto ok = hn::And(hn::Gt(largest, zero), hn::IsFinite(largest));
    const V threshold = hn::Mul(hn::Set(d, b.cubic_tolerance2), largest);
    for (int k = 0; k < 7; ++k) ok = hn::And(ok, hn::Gt(a[k][k], threshold));
    // solve: forward, then backward with 1 / D_kk; x[perm[i]] = y[i].
    for (int i = 0; i < 7; ++i)
      for (int k = 0; k < i; ++k) y[i] = hn::Sub(y[i], hn::Mul(a[k][i], y[k]));
    for (int i = 6; i >= 0; --i) {
      y[i] = hn::Mul(y[i], inverse[i]);
      for (int j = i + 1; j < 7; ++j) y[i] = hn::Sub(y[i], hn::Mul(a[i][j], y[j]));
    }
    for (int c = 0; c < 3; ++c) {
      V coef = zero;
      for (int i = 0; i < 7; ++i) coef = hn::IfThenElse(hn::Eq(perm[i], hn::Set(d, c)), y[i], coef);
      hn::StoreU(hn::Div(coef, s), d, b.w.data() + c * L + o);
    }
    hn::StoreU(hn::IfThenElseZero(ok, one), d, b.cubic_ok.data() + o);
  }
}

}  // namespace
// NOLINTNEXTLINE(google-readability-namespace-comments)
}  // namespace HWY_NAMESPACE
}  // namespace curvbench
HWY_AFTER_NAMESPACE();

#if HWY_ONCE
namespace curvbench {

HWY_EXPORT(GoldfeatherFitKernel);

void add_goldfeather_neighbour(double x, double y, double z, bool use_normal, double zx, double zy,
                               GoldfeatherSums& sums) {
  constexpr auto monomial = goldfeather_monomial;
  // X^a Y^b, degrees 1 to 6: degree d is X times degree d - 1, and Y^d.
  double m[kGoldfeatherMonomials];
  m[0] = 0.0;
  m[1] = x;
  m[2] = y;
  for (int d = 2, i = 3; d <= 6; ++d, ++i) {
    for (int b = 0; b < d; ++b, ++i) m[i] = x * m[i - d];
    m[i] = y * m[i - d - 1];
  }
  for (int i = monomial(4, 0); i < kGoldfeatherMonomials; ++i) sums.pos[i] += m[i];
  for (int i = monomial(2, 0); i < monomial(4, 0); ++i) sums.pos_z[i] += z * m[i];
  if (!use_normal) return;
  for (int i = monomial(2, 0); i < monomial(5, 0); ++i) sums.slope[i] += m[i];
  for (int i = monomial(1, 0); i < monomial(3, 0); ++i) {
    sums.slope_x[i] += zx * m[i];
    sums.slope_y[i] += zy * m[i];
  }
}

void goldfeather_normal_equations(const GoldfeatherSums& sums, double s, double (&ata)[7][7],
                                  double (&atb)[7]) {
  using goldfeather::kMatrixEntries;
  using goldfeather::kRhsEntries;
  const double ss = s * s;
  for (int i = 0, k = 0; i < 7; ++i) {
    for (int j = i; j < 7; ++j, ++k) {
      const goldfeather::Entry& e = kMatrixEntries[static_cast<size_t>(k)];
      ata[i][j] = ata[j][i] = e.pos_coef * ss * sums.pos[e.pos] + e.x_coef * sums.slope[e.x] +
                              e.y_coef * sums.slope[e.y];
    }
    const goldfeather::Entry& e = kRhsEntries[static_cast<size_t>(i)];
    atb[i] = e.pos_coef * ss * sums.pos_z[e.pos] + e.x_coef * sums.slope_x[e.x] +
             e.y_coef * sums.slope_y[e.y];
  }
}

void goldfeather_fit_lanes(GoldfeatherBatch& batch) {
  HWY_DYNAMIC_DISPATCH(GoldfeatherFitKernel)(batch);
}

}  // namespace curvbench
#endif  // HWY_ONCE
