#pragma once

// Root bracketing for smooth scalar functions.

#include <cmath>
#include <optional>

namespace sweetspot {

// A root of f in [lo, hi] by bisection, to `x_tolerance`, or std::nullopt when
// f(lo) and f(hi) have the same sign. Bisection is slow but cannot fail on a
// bracket, and the callers here need a few dozen evaluations at most.
template <class F>
std::optional<double> bisect(F&& f, double lo, double hi, double x_tolerance) {
  double f_lo = f(lo);
  const double f_hi = f(hi);
  if (f_lo == 0.0) return lo;
  if (f_hi == 0.0) return hi;
  if (std::signbit(f_lo) == std::signbit(f_hi)) return std::nullopt;
  while (hi - lo > x_tolerance) {
    const double mid = 0.5 * (lo + hi);
    const double f_mid = f(mid);
    if (f_mid == 0.0) return mid;
    if (std::signbit(f_mid) == std::signbit(f_lo)) {
      lo = mid;
      f_lo = f_mid;
    } else {
      hi = mid;
    }
  }
  return 0.5 * (lo + hi);
}

}  // namespace sweetspot
