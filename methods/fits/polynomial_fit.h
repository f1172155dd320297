// Weighted least-squares polynomial fitting (paper §3.1, eqs. 10-14; docs/algorithms.md §5):
// the one routine every fitting estimator (LHF, LOP, LSCM, Xu) calls.
//
// Input, m rows (m <= kMaxRows) and k right-hand sides (k <= kMaxRhs):
//   u, v  m        parameters of the rows (the centre, if it is a row, at (0, 0))
//   f     m x k    data: heights (LHF, k = 1) or x - p0 (parametric methods, k = 3)
//   w     m        row weights (eq. 13, Omega = diag(w)); size 0 = unweighted
// Output: the degree used and the Taylor derivatives at (0, 0) up to second order per RHS
// (c_jk = j! k! times the monomial coefficient).
//
// Solvers: the safeguarded QR (default, paper §4.3.2, safeguarded_qr.h) or, for comparison,
// truncated SVD (Jacobi or BDC) and Xu's normal-equation eigen-solve (paper §4.3.1,
// least_squares.h). Only the QR lowers the degree; the other solvers return the requested degree
// with a minimum-norm solution of the rank they kept (degree 0 if they kept nothing).
#pragma once

#include <Eigen/Core>

#include "methods/fits/least_squares.h"
#include "methods/fits/vandermonde.h"

namespace curvbench {

enum class LsqSolver {
  safeguarded_qr,  ///< Householder QR with degree safeguard; columns scaled by the 2-norm
  jacobi_svd,      ///< truncated SVD (Eigen::JacobiSVD)
  bdc_svd,         ///< truncated SVD (Eigen::BDCSVD)
  normal_eigen,    ///< Xu: eigen-solve of A^T A with an absolute eigenvalue threshold
  generic_qr,      ///< Eigen's general dynamic-size HouseholderQR, no safeguard (a timing
                   ///< baseline for claim F7: a library QR as the paper's would have been)
};

struct FitSettings {
  int degree = 2;                ///< requested degree, 1..kMaxDegree
  bool include_constant = true;  ///< fit c00 (else the fit passes through the origin)
  LsqSolver solver = LsqSolver::safeguarded_qr;
  double qr_tolerance = 1e-3;  ///< safeguarded QR: |R_jj| and 1/||R^-1||_F threshold
  bool qr_condition = true;    ///< safeguarded QR: the ||R^-1||_F test (else |R_jj| alone)
  /// Column scaling for the SVD and eigen solvers (the QR always uses the 2-norm, eq. 14).
  ColumnScaling scaling = ColumnScaling::two_norm;
  double threshold = 1e-8;          ///< SVD singular-value / eigenvalue cut-off
  bool relative_threshold = false;  ///< SVD: cut-off relative to sigma_1
};

/// Row order of FitResult::taylor.
enum TaylorRow { kF = 0, kFu = 1, kFv = 2, kFuu = 3, kFuv = 4, kFvv = 5 };

struct FitResult {
  int degree = 0;        ///< degree used; 0 = failure (taylor is then all zero)
  int rank = 0;          ///< QR: columns accepted; SVD/eigen: singular values / eigenvalues kept
  int column_rank = 0;   ///< QR: columns accepted by the |R_jj| test alone (QrSolveResult)
  double condition = 0;  ///< QR: where the condition test cut, the columns' condition number
  int rows = 0;          ///< m
  /// Taylor derivatives f, f_u, f_v, f_uu, f_uv, f_vv (TaylorRow) at (0, 0), one column per RHS
  /// (only the first k columns are set). Derivatives of order > degree are 0; f is 0 without the
  /// constant.
  Eigen::Matrix<double, 6, kMaxRhs> taylor = Eigen::Matrix<double, 6, kMaxRhs>::Zero();
};

/// Per-thread buffers of fit_polynomial (fixed capacity; no allocation in the QR path).
struct FitScratch {
  FitMatrix A;
  RhsMatrix B;
  CoeffMatrix X;
  ColVector scale;
  LeastSquaresScratch lsq;
};

FitResult fit_polynomial(const RowVector& u, const RowVector& v, const RhsMatrix& f,
                         const RowVector& w, const FitSettings& settings, FitScratch& scratch);

}  // namespace curvbench
