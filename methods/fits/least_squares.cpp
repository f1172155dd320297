// Column scaling and comparison solvers; see least_squares.h.
#include "methods/fits/least_squares.h"

#include <cmath>

#include "methods/fits/fixed_columns.h"

namespace curvbench {

namespace {

// Squared 2-norms of the columns 0..n-1 of the column-major m-row matrix a, all columns in one
// pass over the rows: independent sums, each in row order. N > 0: n = N known at compile time
// (the sums stay in registers); N == 0: any n.
template <int N>
void squared_column_norms(const double* a, Eigen::Index m, int ncols, double* norm2) {
  const int n = N > 0 ? N : ncols;
  double sum[N > 0 ? N : kMaxCols] = {};
  for (Eigen::Index i = 0; i < m; ++i)
    for (int j = 0; j < n; ++j) sum[j] += a[j * m + i] * a[j * m + i];
  for (int j = 0; j < n; ++j) norm2[j] = sum[j];
}

}  // namespace

void scale_columns(FitMatrix& A, int ncols, ColumnScaling scaling, ColVector& s) {
  const Eigen::Index m = A.rows();
  s.resize(ncols);
  double norm[kMaxCols];
  for (int j = 0; j < ncols; ++j) norm[j] = scaling == ColumnScaling::none ? 1.0 : 0.0;
  if (scaling == ColumnScaling::two_norm) {
    with_fixed_columns(
        ncols, [&](auto N) { squared_column_norms<decltype(N)::value>(A.data(), m, ncols, norm); });
    for (int j = 0; j < ncols; ++j) norm[j] = std::sqrt(norm[j]);
  } else if (scaling == ColumnScaling::inf_norm) {
    for (Eigen::Index i = 0; i < m; ++i)
      for (int j = 0; j < ncols; ++j) norm[j] = std::max(norm[j], std::abs(A(i, j)));
  }
  for (int j = 0; j < ncols; ++j) {
    if (!(norm[j] > 0.0) || !std::isfinite(norm[j])) norm[j] = 1.0;
    s(j) = norm[j];
    // Multiplying by 1/s_j rounds once more than dividing, but divisions are the slowest
    // operation of the whole fit (one per entry): a 13 x 6 LHF-2 system spent a
    // third of its QR time here.
    if (norm[j] != 1.0) {
      const double inv = 1.0 / norm[j];
      double* const a = A.data() + static_cast<std::ptrdiff_t>(j) * m;
      for (Eigen::Index i = 0; i < m; ++i) a[i] *= inv;
    }
  }
}

namespace {

// X = V_r diag(1/sigma) U_r^T B over the kept singular values.
template <typename Svd>
int truncated_from(const Svd& svd, const RhsMatrix& B, double threshold, bool relative,
                   CoeffMatrix& X) {
  const auto& sigma = svd.singularValues();
  const Eigen::Index p = sigma.size();
  const double cut = relative ? (p > 0 ? threshold * sigma(0) : 0.0) : threshold;
  X.setZero(svd.matrixV().rows(), B.cols());
  int kept = 0;
  for (Eigen::Index i = 0; i < p; ++i) {
    if (!(sigma(i) > cut)) break;  // sorted in decreasing order
    ++kept;
    for (Eigen::Index c = 0; c < B.cols(); ++c) {
      const double coef = svd.matrixU().col(i).dot(B.col(c)) / sigma(i);
      X.col(c) += coef * svd.matrixV().col(i);
    }
  }
  return kept;
}

}  // namespace

int truncated_svd_solve(const FitMatrix& A, const RhsMatrix& B, SvdAlgorithm algorithm,
                        double threshold, bool relative, CoeffMatrix& X,
                        LeastSquaresScratch& scratch) {
  if (algorithm == SvdAlgorithm::jacobi) {
    scratch.jacobi.compute(A, Eigen::ComputeThinU | Eigen::ComputeThinV);
    return truncated_from(scratch.jacobi, B, threshold, relative, X);
  }
  scratch.bdc.compute(Eigen::MatrixXd(A), Eigen::ComputeThinU | Eigen::ComputeThinV);
  return truncated_from(scratch.bdc, B, threshold, relative, X);
}

int generic_qr_solve(const FitMatrix& A, const RhsMatrix& B, CoeffMatrix& X,
                     LeastSquaresScratch& scratch) {
  const Eigen::Index n = A.cols();
  X.setZero(n, B.cols());
  if (A.rows() < n) return 0;
  scratch.householder.compute(Eigen::MatrixXd(A));
  const auto R = scratch.householder.matrixQR().topLeftCorner(n, n);
  for (Eigen::Index j = 0; j < n; ++j)
    if (!(std::abs(R(j, j)) > 0.0)) return 0;
  X = scratch.householder.solve(Eigen::MatrixXd(B));
  return static_cast<int>(n);
}

int normal_equations_eigen_solve(const FitMatrix& A, const RhsMatrix& B, double threshold,
                                 CoeffMatrix& X, LeastSquaresScratch& scratch) {
  const Eigen::Index n = A.cols();
  const Eigen::Index m = A.rows();
  // Explicit loops: small sizes, fixed summation order (bit-reproducible, no Eigen threading).
  scratch.ata.resize(n, n);
  scratch.atb.resize(n, B.cols());
  for (Eigen::Index a = 0; a < n; ++a) {
    for (Eigen::Index b = 0; b <= a; ++b) {
      double sum = 0.0;
      for (Eigen::Index i = 0; i < m; ++i) sum += A(i, a) * A(i, b);
      scratch.ata(a, b) = scratch.ata(b, a) = sum;
    }
    for (Eigen::Index c = 0; c < B.cols(); ++c) {
      double sum = 0.0;
      for (Eigen::Index i = 0; i < m; ++i) sum += A(i, a) * B(i, c);
      scratch.atb(a, c) = sum;
    }
  }
  scratch.eigen.compute(scratch.ata);
  X.setZero(n, B.cols());
  if (scratch.eigen.info() != Eigen::Success) return 0;
  const auto& lambda = scratch.eigen.eigenvalues();  // increasing
  const auto& U = scratch.eigen.eigenvectors();
  int kept = 0;
  for (Eigen::Index i = n - 1; i >= 0; --i) {
    if (!(lambda(i) >= threshold)) break;
    ++kept;
    for (Eigen::Index c = 0; c < B.cols(); ++c)
      X.col(c) += (U.col(i).dot(scratch.atb.col(c)) / lambda(i)) * U.col(i);
  }
  return kept;
}

}  // namespace curvbench
