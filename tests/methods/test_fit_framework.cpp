// Tests of the fitting framework: monomials, frame, weights (eq. 15), safeguarded QR (§4.3.2),
// comparison solvers (§4.3.1) and polynomial_fit.
#include <gtest/gtest.h>

#include <Eigen/QR>
#include <Eigen/SVD>
#include <cmath>
#include <vector>

#include "meshgen/random.h"
#include "methods/fits/least_squares.h"
#include "methods/fits/polynomial_fit.h"
#include "methods/fits/safeguarded_qr.h"
#include "methods/fits/vandermonde.h"
#include "methods/fits/weights.h"
#include "methods/local_frame.h"

namespace curvbench {
namespace {

TEST(Vandermonde, MonomialOrderAndTaylorFactors) {
  RowVector u(1), v(1);
  u << 2.0;
  v << 3.0;
  FitMatrix V;
  fill_vandermonde(u, v, 3, true, V);
  ASSERT_EQ(V.cols(), 10);
  const double expected[10] = {1, 2, 3, 4, 6, 9, 8, 12, 18, 27};  // 1 | u v | u2 uv v2 | u3 ...
  for (int j = 0; j < 10; ++j) EXPECT_EQ(V(0, j), expected[j]) << j;
  fill_vandermonde(u, v, 2, false, V);
  ASSERT_EQ(V.cols(), 5);
  EXPECT_EQ(V(0, 0), 2.0);
  EXPECT_EQ(V(0, 4), 9.0);
  EXPECT_EQ(monomial_index(0, 0), 0);
  EXPECT_EQ(monomial_index(1, 0), 1);
  EXPECT_EQ(monomial_index(0, 1), 2);
  EXPECT_EQ(monomial_index(2, 1), 7);
  EXPECT_EQ(monomial_index(0, 6), 27);
  EXPECT_EQ(monomial_index(1, 1, false), 3);
  EXPECT_EQ(num_columns(6, true), 28);
  EXPECT_EQ(num_columns(2, false), 5);
  EXPECT_EQ(taylor_factor(3, 2), 12.0);
  EXPECT_EQ(taylor_factor(0, 0), 1.0);
}

TEST(Vandermonde, WeightedRowsAreOmegaTimesV) {
  // Eq. (13): the weighted fill is diag(w) V, to within the rounding of the recurrence (the
  // weight enters at degree 0 instead of last: at most a few ulp per entry).
  Rng rng(11);
  for (const bool ic : {true, false}) {
    for (int degree = 1; degree <= kMaxDegree; ++degree) {
      RowVector u(17), v(17), w(17);
      for (int i = 0; i < 17; ++i) {
        u(i) = rng.uniform(-1.5, 1.5);
        v(i) = rng.uniform(-1.5, 1.5);
        w(i) = rng.uniform(0.1, 3.0);
      }
      FitMatrix V, Vw;
      fill_vandermonde(u, v, degree, ic, V);
      fill_vandermonde(u, v, degree, ic, Vw, w);
      ASSERT_EQ(Vw.cols(), V.cols());
      for (int i = 0; i < 17; ++i)
        for (int j = 0; j < V.cols(); ++j)
          EXPECT_NEAR(Vw(i, j), w(i) * V(i, j), 1e-14 * std::abs(w(i) * V(i, j)))
              << "degree " << degree << " row " << i << " col " << j;
    }
  }
}

TEST(LocalFrame, FollowsNotesSection3) {
  LocalFrame f = make_local_frame(Vec3::UnitZ());
  EXPECT_EQ(f.t1, Vec3::UnitX());
  EXPECT_EQ(f.t2, Vec3::UnitY());
  f = make_local_frame(Vec3::UnitX());  // |m.x| dominant: e = (0, 1, 0)
  EXPECT_EQ(f.t1, Vec3::UnitY());
  EXPECT_EQ(f.t2, Vec3::UnitZ());
  Rng rng(7);
  for (int i = 0; i < 50; ++i) {
    const Vec3 m = Vec3(rng.uniform(-1, 1), rng.uniform(-1, 1), rng.uniform(-1, 1)).normalized();
    f = make_local_frame(m);
    EXPECT_NEAR(f.t1.norm(), 1.0, 1e-15);
    EXPECT_NEAR(f.t1.dot(f.m), 0.0, 1e-15);
    EXPECT_NEAR((f.t1.cross(f.t2) - f.m).norm(), 0.0, 1e-15);  // right-handed
    EXPECT_NEAR((f.m - m).norm(), 0.0, 1e-15);
  }
  f = make_local_frame(Vec3::Zero());  // isolated vertex: global frame, finite
  EXPECT_TRUE(f.t1.allFinite() && f.t2.allFinite() && f.m.allFinite());
}

TEST(Weights, Equation15) {
  RowVector u(3), v(3), g(3), w;
  u << 0, 1, 2;
  v << 0, 0, 1;
  g << 1, 0.5, 1;
  compute_weights(u, v, g, 0.5, w);
  const double eps = 0.01 * (0 + 1 + 5) / 3.0;
  EXPECT_DOUBLE_EQ(w(0), std::pow(eps, -0.5));
  EXPECT_DOUBLE_EQ(w(1), 0.5 * std::pow(1 + eps, -0.5));
  EXPECT_DOUBLE_EQ(w(2), std::pow(5 + eps, -0.5));
  EXPECT_EQ(weight_exponent(2, -1.0), 0.5);
  EXPECT_EQ(weight_exponent(4, -1.0), 1.0);
  EXPECT_EQ(weight_exponent(4, 0.0), 0.0);
  EXPECT_EQ(normal_safeguard_gamma(Vec3::UnitZ(), -Vec3::UnitZ()), 0.0);
  EXPECT_DOUBLE_EQ(normal_safeguard_gamma(Vec3(0, 0.6, 0.8), Vec3::UnitZ()), 0.8);
  // Scale invariance: scaling all (u, v) by s scales every weight by s^(-2p).
  RowVector w2;
  compute_weights(RowVector(3.0 * u), RowVector(3.0 * v), g, 0.5, w2);
  for (int i = 0; i < 3; ++i) EXPECT_NEAR(w2(i) / w(i), 1.0 / 3.0, 1e-14);
}

TEST(Weights, InversePowerMatchesPow) {
  // The square-root forms of x^(-d/4), d = 1..6, agree with std::pow to a few ulp; other
  // exponents go through std::pow itself.
  Rng rng(5);
  for (int q = 1; q <= 6; ++q) {
    for (int i = 0; i < 200; ++i) {
      const double x = std::exp(rng.uniform(-20.0, 20.0));
      const double exact = std::pow(x, -0.25 * q);
      EXPECT_NEAR(inverse_power(x, 0.25 * q), exact, 4e-16 * exact) << "q " << q << " x " << x;
    }
  }
  EXPECT_EQ(inverse_power(3.0, 0.3), std::pow(3.0, -0.3));
  EXPECT_EQ(inverse_power(2.0, 0.0), 1.0);
}

// Random points in the disk of radius 0.3 and a random polynomial of degree d.
struct PolyCase {
  RowVector u, v;
  RhsMatrix f;
  std::vector<double> coef;  // monomial order of vandermonde.h
};

PolyCase make_poly_case(int m, int degree, std::uint64_t seed, bool centre_row) {
  Rng rng(seed);
  PolyCase c;
  c.u.resize(m);
  c.v.resize(m);
  c.f.resize(m, 1);
  for (int i = 0; i < num_coefficients(degree); ++i) c.coef.push_back(rng.uniform(-1, 1));
  for (int i = 0; i < m; ++i) {
    double x, y;
    do {
      x = rng.uniform(-0.3, 0.3);
      y = rng.uniform(-0.3, 0.3);
    } while (x * x + y * y > 0.09);
    if (centre_row && i == 0) x = y = 0.0;
    c.u(i) = x;
    c.v(i) = y;
  }
  FitMatrix V;
  fill_vandermonde(c.u, c.v, degree, true, V);
  for (int i = 0; i < m; ++i) {
    double s = 0;
    for (int j = 0; j < num_coefficients(degree); ++j)
      s += V(i, j) * c.coef[static_cast<size_t>(j)];
    c.f(i, 0) = s;
  }
  return c;
}

TEST(SafeguardedQr, ReproducesPolynomialsOfTheFittedDegree) {
  FitScratch scratch;
  for (int d = 1; d <= 6; ++d) {
    for (bool ic : {true, false}) {
      PolyCase c =
          make_poly_case(2 * num_coefficients(d) + 5, d, 100 + static_cast<unsigned>(d), true);
      if (!ic) {  // a fit through the origin needs data with f(0) = 0
        for (int i = 0; i < c.f.rows(); ++i) c.f(i, 0) -= c.coef[0];
        c.coef[0] = 0;
      }
      RowVector w;
      compute_weights(c.u, c.v, RowVector(RowVector::Ones(c.u.size())), 0.25 * d, w);
      FitSettings s;
      s.degree = d;
      s.include_constant = ic;
      const FitResult r = fit_polynomial(c.u, c.v, c.f, w, s, scratch);
      ASSERT_EQ(r.degree, d) << "d=" << d << " ic=" << ic;
      const auto& t = r.taylor;
      EXPECT_NEAR(t(kF, 0), c.coef[0], 1e-12);
      EXPECT_NEAR(t(kFu, 0), c.coef[1], 1e-11);
      EXPECT_NEAR(t(kFv, 0), c.coef[2], 1e-11);
      if (d >= 2) {
        EXPECT_NEAR(t(kFuu, 0), 2 * c.coef[3], 1e-10);
        EXPECT_NEAR(t(kFuv, 0), c.coef[4], 1e-10);
        EXPECT_NEAR(t(kFvv, 0), 2 * c.coef[5], 1e-10);
      } else {
        EXPECT_EQ(t(kFuu, 0), 0.0);
      }
    }
  }
}

TEST(SafeguardedQr, PreReducesDegreeByPointCount) {
  // 7 rows cannot determine 10 cubic coefficients: degree 2 (6 columns) is used.
  PolyCase c = make_poly_case(7, 2, 5, true);
  FitScratch scratch;
  FitSettings s;
  s.degree = 3;
  const FitResult r = fit_polynomial(c.u, c.v, c.f, RowVector(), s, scratch);
  EXPECT_EQ(r.degree, 2);
  EXPECT_NEAR(r.taylor(kFuu, 0), 2 * c.coef[3], 1e-9);
}

TEST(SafeguardedQr, CollinearPointsFailWithoutNaN) {
  RowVector u(6), v(6);
  RhsMatrix f(6, 1);
  for (int i = 0; i < 6; ++i) {
    u(i) = 0.1 * (i - 2);
    v(i) = 0.5 * u(i);  // all on one line: v is a multiple of u
    f(i, 0) = 1 + u(i) + u(i) * u(i);
  }
  FitScratch scratch;
  FitSettings s;
  s.degree = 2;
  const FitResult r = fit_polynomial(u, v, f, RowVector(), s, scratch);
  EXPECT_EQ(r.degree, 0);  // even a plane is undetermined
  EXPECT_EQ(r.rank, 2);    // columns 1 and u accepted, v rejected
  EXPECT_TRUE(r.taylor.allFinite());
  EXPECT_EQ(r.taylor.norm(), 0.0);
}

TEST(SafeguardedQr, CrossShapedPointsDropTheQuadraticBlock) {
  // Points on the two axes only: the uv column vanishes, so degree 2 is dropped as a block.
  RowVector u(9), v(9);
  RhsMatrix f(9, 1);
  const double t[4] = {-0.2, -0.1, 0.1, 0.2};
  u(0) = v(0) = 0;
  for (int i = 0; i < 4; ++i) {
    u(1 + i) = t[i];
    v(1 + i) = 0;
    u(5 + i) = 0;
    v(5 + i) = t[i];
  }
  for (int i = 0; i < 9; ++i) f(i, 0) = 0.5 + 2 * u(i) - 3 * v(i);
  FitScratch scratch;
  FitSettings s;
  s.degree = 2;
  const FitResult r = fit_polynomial(u, v, f, RowVector(), s, scratch);
  EXPECT_EQ(r.rank, 4);  // 1, u, v, u^2 accepted; uv rejected
  EXPECT_EQ(r.degree, 1);
  EXPECT_NEAR(r.taylor(kFu, 0), 2.0, 1e-13);
  EXPECT_NEAR(r.taylor(kFv, 0), -3.0, 1e-13);
  // The uv column is exactly zero, so even tolerance 0 must reject it (not divide by R_jj = 0).
  s.qr_tolerance = 0.0;
  const FitResult r0 = fit_polynomial(u, v, f, RowVector(), s, scratch);
  EXPECT_EQ(r0.degree, 1);
  EXPECT_NEAR(r0.taylor(kFu, 0), 2.0, 1e-13);
  EXPECT_NEAR(r0.taylor(kFv, 0), -3.0, 1e-13);
}

TEST(SafeguardedQr, ToleranceDecidesNearlyDependentColumns) {
  // Nearly collinear points (v = u/2 + O(1e-6)): after column scaling |R_vv| ~ 1e-5, which
  // passes tol = 1e-8 but not tol = 1e-3.
  Rng rng(3);
  RowVector u(8), v(8);
  RhsMatrix f(8, 1);
  for (int i = 0; i < 8; ++i) {
    u(i) = rng.uniform(-0.2, 0.2);
    v(i) = 0.5 * u(i) + 1e-6 * rng.uniform(-1, 1);
    f(i, 0) = 1 + u(i) + 2 * v(i);
  }
  FitScratch scratch;
  FitSettings s;
  s.degree = 1;
  EXPECT_EQ(fit_polynomial(u, v, f, RowVector(), s, scratch).degree, 0);
  s.qr_tolerance = 1e-8;
  const FitResult r = fit_polynomial(u, v, f, RowVector(), s, scratch);
  EXPECT_EQ(r.degree, 1);
  EXPECT_NEAR(r.taylor(kFv, 0), 2.0, 1e-6);
}

// The weighted rows of an LHF-4 fit (eqs. 13, 15) at the point (x0, y0) of the Gaussian bump of
// §5.2, from the grid points (x0 + i h, y0 + j h), i in [i0, i1], j in [j0, j1], centre first:
// (u, v) and heights in the exact tangent frame at the point (as on a bump-48 mesh).
struct BumpStencil {
  RowVector u, v, w;
  RhsMatrix f;
};

BumpStencil bump_stencil(double x0, double y0, double h, int i0, int i1, int j0, int j1) {
  const auto z = [](double x, double y) {
    return std::exp(-81.0 / 16.0 * ((x - 0.5) * (x - 0.5) + (y - 0.5) * (y - 0.5)));
  };
  const double z0 = z(x0, y0);
  const Vec3 normal =
      Vec3(81.0 / 8.0 * (x0 - 0.5) * z0, 81.0 / 8.0 * (y0 - 0.5) * z0, 1.0).normalized();
  const LocalFrame frame = make_local_frame(normal);
  const int m = (i1 - i0 + 1) * (j1 - j0 + 1);
  BumpStencil s;
  s.u.resize(m);
  s.v.resize(m);
  s.f.resize(m, 1);
  RowVector gamma = RowVector::Ones(m);
  int row = 1;
  for (int j = j0; j <= j1; ++j)
    for (int i = i0; i <= i1; ++i) {
      const double x = x0 + i * h, y = y0 + j * h;
      const Vec3 d(x - x0, y - y0, z(x, y) - z0);
      const int r = i == 0 && j == 0 ? 0 : row++;
      s.u(r) = d.dot(frame.t1);
      s.v(r) = d.dot(frame.t2);
      s.f(r, 0) = d.dot(frame.m);
    }
  compute_weights(s.u, s.v, gamma, weight_exponent(4, -1.0), s.w);
  return s;
}

// The diagonal of R and the 2-norm condition number of the scaled matrix of eq. (14), degree 4.
void quartic_conditioning(const BumpStencil& s, double& min_rjj, double& cond2) {
  FitMatrix V;
  fill_vandermonde(s.u, s.v, 4, true, V, s.w);
  Eigen::MatrixXd A = V;
  for (Eigen::Index c = 0; c < A.cols(); ++c) A.col(c) /= A.col(c).norm();
  const Eigen::MatrixXd R = Eigen::HouseholderQR<Eigen::MatrixXd>(A).matrixQR();
  min_rjj = R.diagonal().cwiseAbs().minCoeff();
  const Eigen::VectorXd sv = Eigen::JacobiSVD<Eigen::MatrixXd>(A).singularValues();
  cond2 = sv(0) / sv(sv.size() - 1);
}

TEST(SafeguardedQr, FourGridLineBoundaryStencilDropsTheQuarticBlock) {
  // The 3-ring of the boundary vertex (0.5, 0) of bump-48 level 4 (h = 1/128): 28 points on the
  // four grid lines y = 0, h, 2h, 3h. Quartics vanishing on four lines exist, so the quartic
  // block is dependent up to O(h): cond_2 grows like 1/h, yet every |R_jj| passes tol = 1e-3.
  const double h = 1.0 / 128;
  const BumpStencil s = bump_stencil(0.5, 0.0, h, -3, 3, 0, 3);
  double min_rjj = 0.0, cond2 = 0.0, min_rjj_coarse = 0.0, cond2_coarse = 0.0;
  quartic_conditioning(s, min_rjj, cond2);
  quartic_conditioning(bump_stencil(0.5, 0.0, 4 * h, -3, 3, 0, 3), min_rjj_coarse, cond2_coarse);
  EXPECT_GT(min_rjj, 2e-3);
  EXPECT_GT(cond2, 2e3);
  EXPECT_GT(cond2, 4 * cond2_coarse);
  FitScratch scratch;
  FitSettings settings;
  settings.degree = 4;
  const FitResult r = fit_polynomial(s.u, s.v, s.f, s.w, settings, scratch);
  EXPECT_EQ(r.degree, 3);  // the condition test of the kept factor drops the quartic block
  EXPECT_GE(r.rank, 10);
  EXPECT_LT(r.rank, 15);
  // Every column passes |R_jj| >= tol, and the reported condition number of the 15 columns is
  // within the bounds of cond_2 (unit-norm columns): cond_2 <= ||A||_F ||A^+||_F <= 15 cond_2.
  EXPECT_EQ(r.column_rank, 15);
  EXPECT_GE(r.condition, cond2 * (1 - 1e-9));
  EXPECT_LE(r.condition, 15.0 * cond2 * (1 + 1e-9));
  // Without the condition test (qr_condition = false, the paper-era safeguard) the quartic
  // block stays, as it does on the same stencil at every tolerance the |R_jj| test passes.
  settings.qr_condition = false;
  const FitResult rjj = fit_polynomial(s.u, s.v, s.f, s.w, settings, scratch);
  EXPECT_EQ(rjj.degree, 4);
  EXPECT_EQ(rjj.rank, 15);
  EXPECT_EQ(rjj.condition, 0.0);  // not computed: the test did not run
  settings.qr_condition = true;
  // A tolerance below 1 / ||R^-1||_F keeps it.
  settings.qr_tolerance = 1e-4;
  EXPECT_EQ(fit_polynomial(s.u, s.v, s.f, s.w, settings, scratch).degree, 4);
  // Half a ring more reaches a fifth grid line: cond_2 stays bounded as h shrinks, and the
  // safeguard keeps degree 4.
  const BumpStencil wider = bump_stencil(0.5, 0.0, h, -4, 4, 0, 4);
  double cond2_wider = 0.0, cond2_wider_coarse = 0.0;
  quartic_conditioning(wider, min_rjj, cond2_wider);
  quartic_conditioning(bump_stencil(0.5, 0.0, 4 * h, -4, 4, 0, 4), min_rjj, cond2_wider_coarse);
  EXPECT_LT(cond2_wider, 1.5 * cond2_wider_coarse);
  EXPECT_LT(cond2_wider, 0.1 * cond2);
  settings.qr_tolerance = 1e-3;
  const FitResult rw = fit_polynomial(wider.u, wider.v, wider.f, wider.w, settings, scratch);
  EXPECT_EQ(rw.degree, 4);
  EXPECT_EQ(rw.rank, 15);
}

TEST(SafeguardedQr, WellConditionedInteriorStencilKeepsDegreeFour) {
  // A 5 x 5 block of grid points around interior points of the bump, coarse and fine.
  for (const double h : {1.0 / 16, 1.0 / 128})
    for (const auto& [x0, y0] : {std::pair{0.25, 0.5}, std::pair{0.5, 0.5}, std::pair{0.3, 0.7}}) {
      const BumpStencil s = bump_stencil(x0, y0, h, -2, 2, -2, 2);
      double min_rjj = 0.0, cond2 = 0.0;
      quartic_conditioning(s, min_rjj, cond2);
      EXPECT_LT(cond2, 100.0) << x0 << " " << y0 << " h " << h;
      FitScratch scratch;
      FitSettings settings;
      settings.degree = 4;
      const FitResult r = fit_polynomial(s.u, s.v, s.f, s.w, settings, scratch);
      EXPECT_EQ(r.degree, 4) << x0 << " " << y0 << " h " << h;
      EXPECT_EQ(r.rank, 15) << x0 << " " << y0 << " h " << h;
    }
}

TEST(LeastSquares, QrAndSvdAgreeOnWellConditionedSystems) {
  Rng rng(11);
  const int m = 30;
  RowVector u(m), v(m), w(m);
  RhsMatrix f(m, 3);
  for (int i = 0; i < m; ++i) {
    u(i) = rng.uniform(-0.3, 0.3);
    v(i) = rng.uniform(-0.3, 0.3);
    w(i) = rng.uniform(0.5, 1.5);
    f(i, 0) = std::exp(u(i) + 0.5 * v(i));
    f(i, 1) = std::sin(2 * u(i)) * std::cos(v(i));
    f(i, 2) = 1.0 / (1.0 + u(i) * u(i) + 2 * v(i) * v(i));
  }
  FitScratch scratch;
  // Degrees 1-4 with and without the constant and 3 right-hand sides: every fixed-size kernel of
  // the QR (safeguarded_qr.cpp) against the SVDs; degrees 5-6 take the generic path.
  for (int d = 1; d <= 6; ++d)
    for (bool ic : {true, false}) {
      FitSettings s;
      s.degree = d;
      s.include_constant = ic;
      const FitResult qr = fit_polynomial(u, v, f, w, s, scratch);
      ASSERT_EQ(qr.degree, d);
      for (LsqSolver solver : {LsqSolver::jacobi_svd, LsqSolver::bdc_svd, LsqSolver::normal_eigen,
                               LsqSolver::generic_qr}) {
        if (solver == LsqSolver::normal_eigen && d > 4) continue;  // cond^2 too large
        s.solver = solver;
        s.scaling =
            solver == LsqSolver::normal_eigen ? ColumnScaling::inf_norm : ColumnScaling::two_norm;
        const FitResult r = fit_polynomial(u, v, f, w, s, scratch);
        EXPECT_EQ(r.degree, d);
        EXPECT_EQ(r.rank, num_columns(d, ic));
        // Normal equations square the condition number: looser for them and high degree.
        const double tol = solver == LsqSolver::normal_eigen ? 1e-7 : 1e-10;
        for (int c = 0; c < 3; ++c)
          for (int row = 0; row < 6; ++row)
            EXPECT_NEAR(r.taylor(row, c), qr.taylor(row, c),
                        tol * std::max(1.0, std::abs(qr.taylor(row, c))))
                << "d=" << d << " ic=" << ic << " solver=" << static_cast<int>(solver) << " row "
                << row;
      }
    }
}

TEST(LeastSquares, GenericQrRefusesFewerRowsThanColumns) {
  FitMatrix A = FitMatrix::Ones(3, 6);
  RhsMatrix B = RhsMatrix::Ones(3, 1);
  CoeffMatrix X;
  LeastSquaresScratch scratch;
  EXPECT_EQ(generic_qr_solve(A, B, X, scratch), 0);
  EXPECT_TRUE((X.array() == 0.0).all());
}

TEST(LeastSquares, EigenThresholdSolvesUnderdeterminedXuSystem) {
  // 4 rows, 5 unknowns (Xu at a valence-4 vertex): rank 4, minimum-norm, interpolating.
  RowVector u(4), v(4);
  RhsMatrix f(4, 3);
  const double r = 0.1;
  for (int j = 0; j < 4; ++j) {
    u(j) = r * std::cos(j * M_PI / 2);
    v(j) = r * std::sin(j * M_PI / 2);
    f(j, 0) = u(j);
    f(j, 1) = v(j);
    f(j, 2) = 0.3 * u(j) * u(j) + 0.2 * v(j) * v(j);
  }
  FitScratch scratch;
  FitSettings s;
  s.include_constant = false;
  s.solver = LsqSolver::normal_eigen;
  s.scaling = ColumnScaling::inf_norm;
  const FitResult res = fit_polynomial(u, v, f, RowVector(), s, scratch);
  EXPECT_EQ(res.degree, 2);
  EXPECT_EQ(res.rank, 4);
  EXPECT_TRUE(res.taylor.allFinite());
  // Interpolates the rows: f_i = c10 u + c01 v + c20 u^2/2 + c11 uv + c02 v^2/2.
  for (int j = 0; j < 4; ++j)
    for (int c = 0; c < 3; ++c) {
      const auto& t = res.taylor;
      const double val = t(kFu, c) * u(j) + t(kFv, c) * v(j) + 0.5 * t(kFuu, c) * u(j) * u(j) +
                         t(kFuv, c) * u(j) * v(j) + 0.5 * t(kFvv, c) * v(j) * v(j);
      EXPECT_NEAR(val, f(j, c), 1e-12);
    }
}

}  // namespace
}  // namespace curvbench
