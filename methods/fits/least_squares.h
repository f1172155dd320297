// Column scaling (paper eq. 14) and the comparison least-squares solvers of paper §4.3.1:
// truncated SVD, Xu's eigen-solve of the normal equations and a generic Householder QR. The default
// solver, the safeguarded QR of §4.3.2, is in safeguarded_qr.h.
//
// Shapes: A is m x n (m rows <= kMaxRows, n columns <= kMaxCols, already row-weighted and
// column-scaled), B is m x k (k <= kMaxRhs), X is n x k. All solvers treat every right-hand side
// with one decomposition.
#pragma once

#include <Eigen/Eigenvalues>
#include <Eigen/QR>
#include <Eigen/SVD>

#include "methods/fits/vandermonde.h"

namespace curvbench {

/// Column scaling S of eq. (14): A(:, j) /= s_j.
enum class ColumnScaling {
  none,      ///< s_j = 1
  two_norm,  ///< s_j = ||A(:, j)||_2 (Jiao and Zha; approximately minimises cond(A S^-1))
  inf_norm,  ///< s_j = ||A(:, j)||_inf (Xu 2007, Cazals and Pouget 2005)
};

/// Scales the first ncols columns of A in place and writes their factors s (ncols); a zero or
/// non-finite column norm gives s_j = 1. The solution of the scaled problem is d = S c, so the
/// coefficients are c_j = d_j / s_j. Columns are multiplied by 1/s_j (to within an ulp of the
/// division, much faster).
void scale_columns(FitMatrix& A, int ncols, ColumnScaling scaling, ColVector& s);

enum class SvdAlgorithm { jacobi, bdc };

/// Reusable decompositions (one per thread). JacobiSVD and the eigen-solver use fixed-capacity
/// storage and do not allocate; BDCSVD allocates internally (a comparison solver only).
struct LeastSquaresScratch {
  using SquareMatrix =
      Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, Eigen::ColMajor, kMaxCols, kMaxCols>;
  Eigen::JacobiSVD<FitMatrix> jacobi;
  Eigen::BDCSVD<Eigen::MatrixXd> bdc;
  Eigen::HouseholderQR<Eigen::MatrixXd> householder;
  Eigen::SelfAdjointEigenSolver<SquareMatrix> eigen;
  SquareMatrix ata;
  CoeffMatrix atb;
  CoeffMatrix tmp;
};

/// Truncated SVD of A (paper §4.3.1): X = sum over sigma_i > t of v_i u_i^T B / sigma_i with
/// t = threshold * sigma_1 (relative) or t = threshold (absolute). Returns the number of singular
/// values kept (the numerical rank; 0 gives X = 0).
int truncated_svd_solve(const FitMatrix& A, const RhsMatrix& B, SvdAlgorithm algorithm,
                        double threshold, bool relative, CoeffMatrix& X,
                        LeastSquaresScratch& scratch);

/// Least squares by Eigen's general HouseholderQR on a dynamic-size copy of A (no rank or degree
/// safeguard; allocates). A timing baseline only: the safeguarded QR (safeguarded_qr.h) is the
/// solver of the fits. Returns n when every |R_jj| > 0, else 0 with X = 0.
int generic_qr_solve(const FitMatrix& A, const RhsMatrix& B, CoeffMatrix& X,
                     LeastSquaresScratch& scratch);

/// Xu's solver (paper §4.3.1, docs/algorithms.md §7): eigendecomposition A^T A = U diag(s) U^T,
/// X = sum over s_i >= threshold of u_i u_i^T A^T B / s_i (absolute threshold on the eigenvalues,
/// 1e-8 in Xu 2007): the minimum-norm solution in the scaled variables. Returns the number of
/// eigenvalues kept.
int normal_equations_eigen_solve(const FitMatrix& A, const RhsMatrix& B, double threshold,
                                 CoeffMatrix& X, LeastSquaresScratch& scratch);

}  // namespace curvbench
