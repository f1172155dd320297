// Safeguarded Householder QR (docs/algorithms.md §5.4); see safeguarded_qr.h.
//
// Speed. The systems are small (LHF-2: 13 x 6 on a valence-6 mesh), so the cost is
// the latency of the dot-product chains, not the flops. A reflector is therefore applied to many
// columns in one pass over the rows: their dot products are independent chains the CPU runs side
// by side, each split in two halves to shorten the chains further. For degrees 1-4 (with or
// without the constant, one or three right-hand sides) the column count is a template parameter
// (fixed_columns.h), so the loops over columns unroll and the sums stay in registers (up to
// degree 3). The summation order depends on the sizes only: results are deterministic for any
// thread count.
#include "methods/fits/safeguarded_qr.h"

#include <cmath>

#include "methods/fits/fixed_columns.h"
#include "methods/fits/least_squares.h"

namespace curvbench {

namespace {

// The Householder reflector of column x at step j (rows j..m-1), from sigma = sum_{i>=j} x_i^2.
// Returns false if the column is nearly dependent (|R_jj| < tol, norm 0 or NaN): the safeguard
// stops there. Otherwise stores v = x - alpha e_1 in x[j..m), R_jj = alpha in rdiag and
// beta = 2 / |v|^2 (0 if v = 0, which cannot happen with norm > 0).
bool make_reflector(double* x, int j, double sigma, double tol, double& rdiag, double& beta) {
  const double norm = std::sqrt(sigma);
  if (!(norm >= tol) || !(norm > 0.0)) return false;
  const double alpha = x[j] > 0.0 ? -norm : norm;  // R_jj, sign avoids cancellation
  const double v0 = x[j] - alpha;
  x[j] = v0;
  const double vnorm2 = 2.0 * norm * std::abs(v0);  // |v|^2 = 2 |x| (|x| + |x0|)
  rdiag = alpha;
  beta = vnorm2 > 0.0 ? 2.0 / vnorm2 : 0.0;
  return true;
}

double column_sigma(const double* x, int j, int m) {
  double sigma = 0.0;
  for (int i = j; i < m; ++i) sigma += x[i] * x[i];
  return sigma;
}

// col_c -= (beta v . col_c) v over rows j..m-1 for the columns cols[0..C) (C > 0: a compile-time
// count, the loops over columns unroll and the sums stay in registers; C == 0: `count` columns),
// with v in x[j..m). Returns sum_{i>j} cols[0][i]^2 after the update: the sigma of the next
// step. Each dot product is summed in two interleaved halves (rows j, j+2, ... and j+1, j+3,
// ...), which halves the length of its dependency chain; the order depends on the sizes only.
template <int C>
double apply_reflector(const double* x, int j, int m, double beta, double* const* cols,
                       int count = C) {
  constexpr int kCap = C > 0 ? C : kMaxCols + kMaxRhs;
  const int n = C > 0 ? C : count;
  if (n == 0) return 0.0;
  double* c[kCap];
  double even[kCap], odd[kCap], d[kCap];
  for (int q = 0; q < n; ++q) c[q] = cols[q], even[q] = 0.0, odd[q] = 0.0;
  int i = j;
  for (; i + 1 < m; i += 2) {
    const double x0 = x[i], x1 = x[i + 1];
    for (int q = 0; q < n; ++q) {
      even[q] += x0 * c[q][i];
      odd[q] += x1 * c[q][i + 1];
    }
  }
  if (i < m)
    for (int q = 0; q < n; ++q) even[q] += x[i] * c[q][i];
  for (int q = 0; q < n; ++q) d[q] = beta * (even[q] + odd[q]);
  for (int q = 0; q < n; ++q) c[q][j] -= d[q] * x[j];
  double sigma_even = 0.0, sigma_odd = 0.0;
  for (i = j + 1; i + 1 < m; i += 2) {
    const double x0 = x[i], x1 = x[i + 1];
    for (int q = 0; q < n; ++q) {
      c[q][i] -= d[q] * x0;
      c[q][i + 1] -= d[q] * x1;
    }
    sigma_even += c[0][i] * c[0][i];
    sigma_odd += c[0][i + 1] * c[0][i + 1];
  }
  if (i < m) {
    for (int q = 0; q < n; ++q) c[q][i] -= d[q] * x[i];
    sigma_even += c[0][i] * c[0][i];
  }
  return sigma_even + sigma_odd;
}

// Steps J..N-1 of the factorization of N columns of A followed by K of B, with the column
// counts known at compile time. Returns the rank.
template <int N, int K, int J>
int factor_fixed(double* const* col, int m, double tol, double sigma, double* rdiag) {
  if constexpr (J == N) {
    return N;
  } else {
    if (J >= m) return J;
    double beta;
    if (!make_reflector(col[J], J, sigma, tol, rdiag[J], beta)) return J;
    const double next = apply_reflector<N + K - J - 1>(col[J], J, m, beta, col + J + 1);
    return factor_fixed<N, K, J + 1>(col, m, tol, next, rdiag);
  }
}

// The same for any column counts.
int factor_any(double* const* col, int n, int k, int m, double tol, double sigma, double* rdiag) {
  for (int j = 0; j < n; ++j) {
    if (j >= m) return j;
    double beta;
    if (!make_reflector(col[j], j, sigma, tol, rdiag[j], beta)) return j;
    sigma = apply_reflector<0>(col[j], j, m, beta, col + j + 1, n + k - j - 1);
  }
  return n;
}

// Rank of the safeguarded factorization of n columns of A and k of B (pointers in col): the
// fixed-size steps for the usual column counts (fixed_columns.h) and k = 1 or 3, else generic.
int factor(double* const* col, int n, int k, int m, double tol, double* rdiag) {
  const double sigma0 = m > 0 ? column_sigma(col[0], 0, m) : 0.0;
  return with_fixed_columns(n, [&](auto N) {
    constexpr int kN = decltype(N)::value;
    if constexpr (kN > 0) {
      if (k == 1) return factor_fixed<kN, 1, 0>(col, m, tol, sigma0, rdiag);
      if (k == 3) return factor_fixed<kN, 3, 0>(col, m, tol, sigma0, rdiag);
    }
    return factor_any(col, n, k, m, tol, sigma0, rdiag);
  });
}

// The leading columns k <= rank that the condition test keeps: ||R_k^-1||_F <= 1 / tol for the
// factor R_k = R(0:k, 0:k) (paper §4.3.2: A_k and R_k have the same condition number). This
// certifies sigma_min(A_k) >= tol, the nearness to dependence of all k columns together, where
// |R_jj| >= tol only measures column j against the columns before it (sigma_min <= min |R_jj|).
// The columns have unit norm, so cond_2(A_k) <= sqrt(k) / tol: the kept fit has a bounded
// condition number (Proposition 1). ||R_k^-1||_F grows with k, and ||R_{j+1}^-1||_F >= 1 / |R_jj|.
// Column j of R^-1: z_j = 1 / R_jj, z_i = -(sum_{l=i+1..j} R_il z_l) / R_ii (R_il = col[l][i]).
// Where the test cuts, `condition` gets sqrt(rank) ||R_rank^-1||_F over all `rank` columns (the
// loop goes on past the cut, which the usual stencil never reaches).
int conditioned_rank(double* const* col, const double* rdiag, int rank, double tol,
                     double& condition) {
  if (!(tol > 0.0)) return rank;
  const double limit = 1.0 / (tol * tol);
  double inv_r[kMaxCols], z[kMaxCols];
  double inv2 = 0.0;  // ||R_k^-1||_F^2
  int kept = rank;
  for (int j = 0; j < rank; ++j) {
    inv_r[j] = 1.0 / rdiag[j];
    z[j] = inv_r[j];
    double norm2 = z[j] * z[j];
    for (int i = j - 1; i >= 0; --i) {
      double sum = 0.0;
      for (int l = i + 1; l <= j; ++l) sum += col[l][i] * z[l];
      z[i] = -sum * inv_r[i];
      norm2 += z[i] * z[i];
    }
    inv2 += norm2;
    if (!(inv2 <= limit) && kept == rank) kept = j;
  }
  if (kept < rank) condition = std::sqrt(static_cast<double>(rank) * inv2);
  return kept;
}

}  // namespace

QrSolveResult safeguarded_qr_solve(FitMatrix& A, RhsMatrix& B, int degree, bool include_constant,
                                   double tol, CoeffMatrix& X, ColVector& scale,
                                   bool condition_test) {
  QrSolveResult result;
  const int m = static_cast<int>(A.rows());
  const int k = static_cast<int>(B.cols());
  X.resize(0, k);
  int d = degree;
  // §5.2: degree pre-reduction by point count.
  while (d > 1 && m < num_columns(d, include_constant)) --d;
  int n = num_columns(d, include_constant);
  if (d < 1 || n < 1) return result;
  // §5.3: 2-norm column scaling of the weighted matrix.
  scale_columns(A, n, ColumnScaling::two_norm, scale);

  // §5.4: Householder QR, left to right, with B updated in the same loop, stopping at the first
  // nearly dependent column. Columns as pointers (column-major, leading dimension m): col[c] is
  // A(:, c) for c < n and B(:, c - n) after.
  double* col[kMaxCols + kMaxRhs];
  for (int c = 0; c < n; ++c) col[c] = A.data() + static_cast<std::ptrdiff_t>(c) * m;
  for (int c = 0; c < k; ++c) col[n + c] = B.data() + static_cast<std::ptrdiff_t>(c) * m;
  double rdiag[kMaxCols];
  // §4.3.2: the leading columns, so far free of a nearly dependent column, that are also well
  // conditioned together (unless the condition test is off: the |R_jj| test alone).
  result.column_rank = factor(col, n, k, m, tol, rdiag);
  int rank = condition_test
                 ? conditioned_rank(col, rdiag, result.column_rank, tol, result.condition)
                 : result.column_rank;
  result.rank = rank;
  // Drop whole degree blocks from the right until the accepted columns cover the degree.
  while (rank < n) {
    --d;
    n = num_columns(d, include_constant);
    if (d < 1 || n < 1) return result;  // failure: degree 0
  }
  // Back substitution with R(0:n, 0:n) (strict upper part in A, diagonal in rdiag), column by
  // column: x_i = y_i / R_ii, then y(0:i) -= x_i R(0:i, i), a contiguous update of column i
  // (no dot products re-reading just-written x). Then c_j = x_j / s_j. The reciprocals are
  // computed first, off the dependency chain, which then multiplies instead of dividing.
  double inv_r[kMaxCols], inv_s[kMaxCols], y[kMaxCols];
  for (int i = 0; i < n; ++i) inv_r[i] = 1.0 / rdiag[i], inv_s[i] = 1.0 / scale(i);
  X.resize(n, k);
  for (int c = 0; c < k; ++c) {
    for (int i = 0; i < n; ++i) y[i] = B(i, c);
    for (int i = n - 1; i >= 0; --i) {
      const double xi = y[i] * inv_r[i];
      const double* r = col[i];  // R(0:i, i)
      for (int j = 0; j < i; ++j) y[j] -= r[j] * xi;
      X(i, c) = xi * inv_s[i];
    }
  }
  result.degree = d;
  return result;
}

}  // namespace curvbench
