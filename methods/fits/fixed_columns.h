// Compile-time column counts for the small dense kernels of the fit (column norms, safeguarded
// QR): the sizes that occur in practice get loops the compiler unrolls, with the per-column sums
// in registers; every other size takes the generic path.
#pragma once

#include <type_traits>

namespace curvbench {

/// Calls f(std::integral_constant<int, N>{}) with N = n when n is the column count of a fit of
/// degree 1-4, with or without the constant (2, 3, 5, 6, 9, 10, 14, 15), else with N = 0 (the
/// generic path, n known at run time only). Returns what f returns.
template <class F>
decltype(auto) with_fixed_columns(int n, F&& f) {
  switch (n) {
    case 2:
      return f(std::integral_constant<int, 2>{});
    case 3:
      return f(std::integral_constant<int, 3>{});
    case 5:
      return f(std::integral_constant<int, 5>{});
    case 6:
      return f(std::integral_constant<int, 6>{});
    case 9:
      return f(std::integral_constant<int, 9>{});
    case 10:
      return f(std::integral_constant<int, 10>{});
    case 14:
      return f(std::integral_constant<int, 14>{});
    case 15:
      return f(std::integral_constant<int, 15>{});
    default:
      return f(std::integral_constant<int, 0>{});
  }
}

}  // namespace curvbench
