// Safeguarded Householder QR (ALGORITHM_NOTES §5.4); see safeguarded_qr.h.
#include "methods/safeguarded_qr.h"

#include <cmath>

#include "methods/least_squares.h"

namespace curvbench {

QrSolveResult safeguarded_qr_solve(FitMatrix& A, RhsMatrix& B, int degree, bool include_constant,
                                   double tol, CoeffMatrix& X, ColVector& scale) {
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
  // §5.4: Householder QR, left to right, with B updated in the same loop.
  double rdiag[kMaxCols];
  int rank = n;
  for (int j = 0; j < n; ++j) {
    if (j >= m) {
      rank = j;
      break;
    }
    double sigma = 0.0;
    for (int i = j; i < m; ++i) sigma += A(i, j) * A(i, j);
    const double norm = std::sqrt(sigma);
    // |R_jj| < tol, an exactly dependent column (norm 0, also when tol = 0), or NaN: the first
    // nearly dependent column.
    if (!(norm >= tol) || !(norm > 0.0)) {
      rank = j;
      break;
    }
    const double alpha = A(j, j) > 0.0 ? -norm : norm;  // R_jj, sign avoids cancellation
    const double v0 = A(j, j) - alpha;
    A(j, j) = v0;                                     // reflector v = x - alpha e_1 in A(j:m, j)
    const double vnorm2 = 2.0 * norm * std::abs(v0);  // |v|^2 = 2 |x| (|x| + |x0|)
    rdiag[j] = alpha;
    if (!(vnorm2 > 0.0)) continue;  // x = alpha e_1 already (cannot happen with norm > 0)
    const double beta = 2.0 / vnorm2;
    for (int c = j + 1; c < n; ++c) {
      double dot = 0.0;
      for (int i = j; i < m; ++i) dot += A(i, j) * A(i, c);
      const double f = beta * dot;
      for (int i = j; i < m; ++i) A(i, c) -= f * A(i, j);
    }
    for (int c = 0; c < k; ++c) {
      double dot = 0.0;
      for (int i = j; i < m; ++i) dot += A(i, j) * B(i, c);
      const double f = beta * dot;
      for (int i = j; i < m; ++i) B(i, c) -= f * A(i, j);
    }
  }
  result.rank = rank;
  // Drop whole degree blocks from the right until the accepted columns cover the degree.
  while (rank < n) {
    --d;
    n = num_columns(d, include_constant);
    if (d < 1 || n < 1) return result;  // failure: degree 0
  }
  // Back substitution with R(0:n, 0:n) (strict upper part in A, diagonal in rdiag).
  X.resize(n, k);
  for (int c = 0; c < k; ++c) {
    for (int i = n - 1; i >= 0; --i) {
      double sum = B(i, c);
      for (int j = i + 1; j < n; ++j) sum -= A(i, j) * X(j, c);
      X(i, c) = sum / rdiag[i];
    }
    for (int i = 0; i < n; ++i) X(i, c) /= scale(i);
  }
  result.degree = d;
  return result;
}

}  // namespace curvbench
