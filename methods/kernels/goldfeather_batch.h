// The Goldfeather fit (methods/operators/goldfeather.cpp; J. Goldfeather and V. Interrante, ACM TOG 23(1),
// 2004, eqs. 9-11) in pieces shared by its scalar path and its lane-wise path (kBatchLanes
// vertices at once, one per SIMD lane): the monomial sums over the 1-ring, the normal equations
// they make, and (lane-wise) the pivoted LDL^T solve of the cubic.
//
// Every entry of the fit's 7x7 normal equations is a combination of sums over the 1-ring of
// monomials X^a Y^b of the neighbours' scaled local coordinates (X, Y, Z) = (x, y, z) / s:
//   pos[i]     = sum over all neighbours of X^a Y^b           (degrees 4..6; the position rows)
//   pos_z[i]   = sum over all neighbours of Z X^a Y^b         (degrees 2..3; their right side)
//   slope[i]   = sum over the neighbours whose normal is used (degrees 2..4; the slope rows)
//   slope_x[i], slope_y[i] = the same with the slopes z_x, z_y (degrees 1..2; their right side)
// with i = goldfeather_monomial(a, b); entries outside those degrees stay 0.
//
// The lane-wise kernel performs, per lane, the operations of the scalar code in the same order
// (no fused multiply-adds; the file is compiled with -ffp-contract=off), so each lane's results
// have the scalar bits: a lane's padding slots (zero coordinates, `use` 0) add exact zeros.
#pragma once

#include <array>

#include "methods/kernels/batched_fit.h"

namespace curvbench {

inline constexpr int kGoldfeatherMonomials = 28;  ///< X^a Y^b, a + b <= 6
/// The index of X^a Y^b: by degree, then by b.
constexpr int goldfeather_monomial(int a, int b) {
  return (a + b) * (a + b + 1) / 2 + b;
}
/// Neighbours a batched lane can hold; a vertex with more takes the scalar path.
inline constexpr int kGoldfeatherMaxNeighbours = 32;

namespace goldfeather {

/// The position row of eq. (9), r_i = kCoef[i] x^kPowX[i] y^kPowY[i] for the unknowns
/// (A, B, C, D, E, F, G); the slope rows of eqs. (10)-(11) are its derivatives d/dx and d/dy.
inline constexpr double kCoef[7] = {0.5, 1.0, 0.5, 1.0, 1.0, 1.0, 1.0};
inline constexpr int kPowX[7] = {2, 1, 0, 3, 2, 1, 0};
inline constexpr int kPowY[7] = {0, 1, 2, 0, 1, 2, 3};

/// An entry of the normal equations as a combination of monomial sums,
///   pos_coef s^2 pos[pos] + x_coef slope[x] + y_coef slope[y]
/// (matrix) or pos_coef s^2 pos_z[pos] + x_coef slope_x[x] + y_coef slope_y[y] (right-hand side),
/// with the sums below; an absent term has coefficient 0.
struct Entry {
  int pos = 0;
  double pos_coef = 0.0;
  int x = 0;
  double x_coef = 0.0;
  int y = 0;
  double y_coef = 0.0;
};

/// The 28 entries (i, j), j >= i, of the upper triangle, row by row: r_i r_j, plus the products
/// of the slope rows, (d r_i/dx)(d r_j/dx) + (d r_i/dy)(d r_j/dy).
inline constexpr std::array<Entry, 28> kMatrixEntries = [] {
  std::array<Entry, 28> e{};
  for (int i = 0, k = 0; i < 7; ++i)
    for (int j = i; j < 7; ++j, ++k) {
      const int a = kPowX[i] + kPowX[j], b = kPowY[i] + kPowY[j];
      const double c = kCoef[i] * kCoef[j];
      e[k].pos = goldfeather_monomial(a, b);
      e[k].pos_coef = c;
      if (kPowX[i] > 0 && kPowX[j] > 0) {
        e[k].x = goldfeather_monomial(a - 2, b);
        e[k].x_coef = c * kPowX[i] * kPowX[j];
      }
      if (kPowY[i] > 0 && kPowY[j] > 0) {
        e[k].y = goldfeather_monomial(a, b - 2);
        e[k].y_coef = c * kPowY[i] * kPowY[j];
      }
    }
  return e;
}();

/// The right-hand side: r_i z, plus the slope rows times the slopes, (d r_i/dx) z_x +
/// (d r_i/dy) z_y.
inline constexpr std::array<Entry, 7> kRhsEntries = [] {
  std::array<Entry, 7> e{};
  for (int i = 0; i < 7; ++i) {
    const int a = kPowX[i], b = kPowY[i];
    e[i].pos = goldfeather_monomial(a, b);
    e[i].pos_coef = kCoef[i];
    if (a > 0) {
      e[i].x = goldfeather_monomial(a - 1, b);
      e[i].x_coef = kCoef[i] * a;
    }
    if (b > 0) {
      e[i].y = goldfeather_monomial(a, b - 1);
      e[i].y_coef = kCoef[i] * b;
    }
  }
  return e;
}();

}  // namespace goldfeather

/// The sums of one vertex.
struct GoldfeatherSums {
  double pos[kGoldfeatherMonomials] = {};
  double pos_z[kGoldfeatherMonomials] = {};
  double slope[kGoldfeatherMonomials] = {};
  double slope_x[kGoldfeatherMonomials] = {};
  double slope_y[kGoldfeatherMonomials] = {};
};

/// Adds one neighbour with scaled local coordinates (x, y, z) and, if `use_normal`, its slopes
/// (zx, zy) to the sums.
void add_goldfeather_neighbour(double x, double y, double z, bool use_normal, double zx, double zy,
                               GoldfeatherSums& sums);

/// The normal equations ata x = atb of the cubic (unknowns A s, B s, C s, D s^2, ..., G s^2)
/// from the sums of a vertex whose coordinates were scaled by s.
void goldfeather_normal_equations(const GoldfeatherSums& sums, double s, double (&ata)[7][7],
                                  double (&atb)[7]);

/// kBatchLanes vertices: value of slot j of lane l at [j * kBatchLanes + l]; a lane's slots past
/// its neighbour count must hold zeros (use = 0), an unused lane has scale 1 and no slots.
struct GoldfeatherBatch {
  // ---- input ----
  int slots = 0;  ///< the largest neighbour count of the lanes (<= kGoldfeatherMaxNeighbours)
  std::array<double, kGoldfeatherMaxNeighbours * kBatchLanes> x{}, y{}, z{}, zx{}, zy{};
  std::array<double, kGoldfeatherMaxNeighbours * kBatchLanes> use{};  ///< 1: normal used, 0: not
  std::array<double, kBatchLanes> scale{};                            ///< s of each lane
  double cubic_tolerance2 = 0.0;  ///< the cubic's rank test on the LDL^T pivots
  // ---- output, entry i of lane l at [i * kBatchLanes + l] ----
  std::array<double, 49 * kBatchLanes> ata{};  ///< the normal equations, row-major 7 x 7
  std::array<double, 7 * kBatchLanes> atb{};
  /// Lane l's cubic passed the rank test (1) or not (0: ata and atb are set, w is not).
  std::array<double, kBatchLanes> cubic_ok{};
  std::array<double, 3 * kBatchLanes> w{};  ///< (A, B, C) of the cubic: the Weingarten tensor
};

/// The sums, the normal equations and the pivoted LDL^T solve of the cubic (as the scalar
/// Ldlt<7> of goldfeather.cpp: symmetric pivoting by the initial diagonal, largest first) of
/// every lane of `batch`.
void goldfeather_fit_lanes(GoldfeatherBatch& batch);

}  // namespace curvbench
