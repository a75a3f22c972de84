#pragma once

// Root finding for smooth scalar functions.

#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>

namespace sweetspot {

// Brent's method on a bracket [a, b] with f(a) = fa and f(b) = fb of opposite
// signs: inverse quadratic interpolation or secant steps, bisection when they
// stall. Returns a root to within abs_tol (plus a few ulps of it).
template <class F>
double brent_root(const F& f, double a, double b, double fa, double fb, double abs_tol) {
  if (fa == 0.0) return a;
  if (fb == 0.0) return b;
  double c = a, fc = fa, d = b - a, e = d;
  for (int iter = 0; iter < 200; ++iter) {
    if ((fb > 0) == (fc > 0)) {  // keep the root between b and c
      c = a;
      fc = fa;
      d = e = b - a;
    }
    if (std::abs(fc) < std::abs(fb)) {  // b is the best estimate
      a = b;
      b = c;
      c = a;
      fa = fb;
      fb = fc;
      fc = fa;
    }
    const double tol = 2.0 * std::numeric_limits<double>::epsilon() * std::abs(b) + 0.5 * abs_tol;
    const double m = 0.5 * (c - b);
    if (std::abs(m) <= tol || fb == 0.0) return b;
    if (std::abs(e) >= tol && std::abs(fa) > std::abs(fb)) {
      // Secant or inverse quadratic interpolation.
      const double s = fb / fa;
      double p, q;
      if (a == c) {
        p = 2.0 * m * s;
        q = 1.0 - s;
      } else {
        const double qa = fa / fc, r = fb / fc;
        p = s * (2.0 * m * qa * (qa - r) - (b - a) * (r - 1.0));
        q = (qa - 1.0) * (r - 1.0) * (s - 1.0);
      }
      if (p > 0) q = -q;
      p = std::abs(p);
      if (2.0 * p < std::min(3.0 * m * q - std::abs(tol * q), std::abs(e * q))) {
        e = d;
        d = p / q;
      } else {
        d = m;
        e = m;
      }
    } else {
      d = m;
      e = m;
    }
    a = b;
    fa = fb;
    b += std::abs(d) > tol ? d : (m > 0 ? tol : -tol);
    fb = f(b);
  }
  return b;
}

// A root of f in [lo, hi] to `abs_tol`, or std::nullopt when f(lo) and f(hi)
// have the same sign.
template <class F>
std::optional<double> find_root(F&& f, double lo, double hi, double abs_tol) {
  const double f_lo = f(lo);
  const double f_hi = f(hi);
  if (std::signbit(f_lo) == std::signbit(f_hi) && f_lo != 0.0 && f_hi != 0.0) return std::nullopt;
  return brent_root(f, lo, hi, f_lo, f_hi, abs_tol);
}

}  // namespace sweetspot
