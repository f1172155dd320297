// Weighted polynomial fitting; see polynomial_fit.h.
#include "methods/fits/polynomial_fit.h"

#include "methods/fits/safeguarded_qr.h"

namespace curvbench {

FitResult fit_polynomial(const RowVector& u, const RowVector& v, const RhsMatrix& f,
                         const RowVector& w, const FitSettings& settings, FitScratch& scratch) {
  FitResult result;
  const Eigen::Index m = u.size();
  const Eigen::Index k = f.cols();
  const bool ic = settings.include_constant;
  result.rows = static_cast<int>(m);
  if (m == 0 || settings.degree < 1 || settings.degree > kMaxDegree) return result;

  // Eq. (13): V~ = Omega V, b = Omega f.
  FitMatrix& A = scratch.A;
  RhsMatrix& B = scratch.B;
  const bool weighted = w.size() == m;
  if (weighted)
    fill_vandermonde(u, v, settings.degree, ic, A, w);
  else
    fill_vandermonde(u, v, settings.degree, ic, A);
  B.resize(m, k);
  for (Eigen::Index j = 0; j < k; ++j)
    for (Eigen::Index i = 0; i < m; ++i) B(i, j) = weighted ? f(i, j) * w(i) : f(i, j);

  CoeffMatrix& X = scratch.X;
  if (settings.solver == LsqSolver::safeguarded_qr) {
    const QrSolveResult qr = safeguarded_qr_solve(A, B, settings.degree, ic, settings.qr_tolerance,
                                                  X, scratch.scale, settings.qr_condition);
    result.degree = qr.degree;
    result.rank = qr.rank;
    result.column_rank = qr.column_rank;
    result.condition = qr.condition;
  } else {
    // Eq. (14): A = V~ S^-1, then the comparison solver, then c = S^-1 d.
    const int n = static_cast<int>(A.cols());
    scale_columns(A, n, settings.scaling, scratch.scale);
    int rank = 0;
    if (settings.solver == LsqSolver::normal_eigen) {
      rank = normal_equations_eigen_solve(A, B, settings.threshold, X, scratch.lsq);
    } else if (settings.solver == LsqSolver::generic_qr) {
      rank = generic_qr_solve(A, B, X, scratch.lsq);
    } else {
      const SvdAlgorithm alg =
          settings.solver == LsqSolver::jacobi_svd ? SvdAlgorithm::jacobi : SvdAlgorithm::bdc;
      rank = truncated_svd_solve(A, B, alg, settings.threshold, settings.relative_threshold, X,
                                 scratch.lsq);
    }
    for (int j = 0; j < n; ++j) X.row(j) /= scratch.scale(j);
    result.rank = rank;
    result.degree = rank > 0 ? settings.degree : 0;
  }
  if (result.degree < 1) return result;

  // Monomial coefficients -> Taylor derivatives c_jk = j! k! coefficient.
  static constexpr int kPowers[5][2] = {{1, 0}, {0, 1}, {2, 0}, {1, 1}, {0, 2}};
  for (Eigen::Index c = 0; c < k; ++c) {
    if (ic) result.taylor(kF, c) = X(0, c);
    for (int t = 0; t < 5; ++t) {
      const int pj = kPowers[t][0];
      const int pk = kPowers[t][1];
      if (pj + pk > result.degree) continue;
      result.taylor(1 + t, c) = taylor_factor(pj, pk) * X(monomial_index(pj, pk, ic), c);
    }
  }
  return result;
}

}  // namespace curvbench
