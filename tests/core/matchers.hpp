#pragma once
// Domain assertions for the core tests: angles modulo 2π, and matrices compared element-wise
// with the worst element reported on failure.

#include <gtest/gtest.h>

#include <Eigen/Core>
#include <cmath>
#include <sstream>

#include "dynpos/core/angle.hpp"

namespace dynpos::core::testing {

/// Passes when a and b [rad] are within tol of each other modulo 2π (π and −π are equal).
inline ::testing::AssertionResult AnglesNear(double a_rad, double b_rad, double tol_rad) {
  const double diff = std::abs(angle_diff(a_rad, b_rad));
  if (diff <= tol_rad) return ::testing::AssertionSuccess();
  return ::testing::AssertionFailure()
         << "angles " << a_rad << " and " << b_rad << " rad differ by " << diff
         << " rad modulo 2π (> " << tol_rad << ")";
}

/// Passes when every |a(i,j) − b(i,j)| ≤ tol; on failure names the worst element.
template <typename DerivedA, typename DerivedB>
::testing::AssertionResult MatricesNear(const Eigen::MatrixBase<DerivedA>& a,
                                        const Eigen::MatrixBase<DerivedB>& b, double tol) {
  if (a.rows() != b.rows() || a.cols() != b.cols()) {
    return ::testing::AssertionFailure() << "sizes differ: " << a.rows() << "x" << a.cols()
                                         << " vs " << b.rows() << "x" << b.cols();
  }
  double worst = -1.0;
  Eigen::Index wi = 0;
  Eigen::Index wj = 0;
  for (Eigen::Index i = 0; i < a.rows(); ++i) {
    for (Eigen::Index j = 0; j < a.cols(); ++j) {
      const double d = std::abs(a(i, j) - b(i, j));
      if (!(d <= worst)) {  // NaN counts as worst
        worst = d;
        wi = i;
        wj = j;
      }
    }
  }
  if (worst <= tol) return ::testing::AssertionSuccess();
  std::ostringstream os;
  os << "worst element (" << wi << "," << wj << "): " << a(wi, wj) << " vs " << b(wi, wj)
     << ", |diff| = " << worst << " > " << tol << "\nfirst:\n"
     << a << "\nsecond:\n"
     << b;
  return ::testing::AssertionFailure() << os.str();
}

}  // namespace dynpos::core::testing
