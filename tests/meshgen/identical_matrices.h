// Exact comparison of two Eigen matrices that may differ in shape. Eigen's operator== asserts
// equal shapes (an abort in the assertion-enabled sanitizer build), so tests that compare meshes
// which may have different vertex counts (another seed, another level) use this instead.
#pragma once

#include <gtest/gtest.h>

namespace curvbench::test {

template <class A, class B>
::testing::AssertionResult identical(const A& a, const B& b) {
  if (a.rows() != b.rows() || a.cols() != b.cols())
    return ::testing::AssertionFailure() << "shapes differ: " << a.rows() << "x" << a.cols()
                                         << " against " << b.rows() << "x" << b.cols();
  for (Eigen::Index i = 0; i < a.rows(); ++i)
    for (Eigen::Index j = 0; j < a.cols(); ++j)
      if (a(i, j) != b(i, j))
        return ::testing::AssertionFailure() << "first difference at (" << i << ", " << j
                                             << "): " << a(i, j) << " against " << b(i, j);
  return ::testing::AssertionSuccess() << "identical " << a.rows() << "x" << a.cols();
}

}  // namespace curvbench::test
