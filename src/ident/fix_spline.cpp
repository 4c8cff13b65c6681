#include "fix_spline.hpp"

#include <cmath>
#include <cstddef>

namespace dynpos::ident::detail {
namespace {

// The second derivatives at the knots (xs, ys) of the natural cubic spline (tridiagonal solve).
std::vector<double> natural_moments(const std::vector<double>& xs, const std::vector<double>& ys) {
  const std::size_t n = xs.size();
  std::vector<double> m(n, 0.0);
  if (n < 3) return m;
  std::vector<double> diag(n, 1.0), rhs(n, 0.0), upper(n, 0.0);
  for (std::size_t i = 1; i + 1 < n; ++i) {
    const double h0 = xs[i] - xs[i - 1], h1 = xs[i + 1] - xs[i];
    const double lower = h0 / 6.0;
    diag[i] = (h0 + h1) / 3.0;
    upper[i] = h1 / 6.0;
    rhs[i] = (ys[i + 1] - ys[i]) / h1 - (ys[i] - ys[i - 1]) / h0;
    // Eliminate the lower diagonal with the row before (m₀ = 0: row 0 is the identity).
    const double f = lower / diag[i - 1];
    diag[i] -= f * upper[i - 1];
    rhs[i] -= f * rhs[i - 1];
  }
  for (std::size_t i = n - 1; i-- > 1;) m[i] = (rhs[i] - upper[i] * m[i + 1]) / diag[i];
  return m;
}

// Fills out[lo..hi] (row indices) from the spline through the valid samples of that range.
void fill_run(const std::vector<double>& t, const std::vector<double>& x, std::size_t lo,
              std::size_t hi, std::vector<double>& out) {
  std::vector<double> xs, ys;
  std::vector<std::size_t> at;
  for (std::size_t i = lo; i <= hi; ++i) {
    if (std::isnan(x[i])) continue;
    xs.push_back(t[i]);
    ys.push_back(x[i]);
    at.push_back(i);
  }
  const std::vector<double> m = natural_moments(xs, ys);
  for (std::size_t k = 0; k + 1 < xs.size(); ++k) {
    const double h = xs[k + 1] - xs[k];
    for (std::size_t i = at[k] + 1; i < at[k + 1]; ++i) {
      const double a = (xs[k + 1] - t[i]) / h, b = (t[i] - xs[k]) / h;
      out[i] = a * ys[k] + b * ys[k + 1] +
               ((a * a * a - a) * m[k] + (b * b * b - b) * m[k + 1]) * h * h / 6.0;
    }
  }
}

}  // namespace

std::vector<double> fill_between_fixes(const std::vector<double>& t, const std::vector<double>& x,
                                       double max_gap_s) {
  std::vector<double> out = x;
  std::size_t run_lo = 0, last = 0;
  bool any = false, in_run = false;
  for (std::size_t i = 0; i < x.size(); ++i) {
    if (std::isnan(x[i])) continue;
    if (any && t[i] - t[last] <= max_gap_s) {
      if (!in_run) run_lo = last;
      in_run = true;
    } else if (in_run) {
      fill_run(t, x, run_lo, last, out);
      in_run = false;
    }
    any = true;
    last = i;
  }
  if (in_run) fill_run(t, x, run_lo, last, out);
  return out;
}

}  // namespace dynpos::ident::detail
