#pragma once

// The ball's force over one step of the integrator (collision.hpp): the
// discrete gradient of the law's stored energy plus its damping part at the
// step's midpoint, clamped at >= 0, and the scalar equation that fixes it.
// Generic in the law (collision/ball_law.hpp).

#include <algorithm>
#include <cmath>
#include <limits>

#include "core/collision/ball_law.hpp"

namespace sweetspot::collision_detail {

// The step's ball force for compressions x0 -> x1 (clamped at >= 0) and its
// derivative in x1.
struct StepForce {
  double force;
  double d_force_dx1;
};

// u0 = U(x0), kept from the step before.
template <BallLaw Law>
StepForce step_force(const Law& law, double x0, double u0, double x1, double inv_h) {
  const double dx = x1 - x0;
  const double xm = 0.5 * (x0 + x1);
  double g, dg;
  const double scale = std::abs(x0) + std::abs(x1);
  if (std::abs(dx) > 1e-7 * scale && (x0 > 0.0 || x1 > 0.0)) {
    // (U(x1) - U(x0)) / dx and its derivative (U'(x1) - g) / dx.
    const ElasticAt e1 = law.elastic_at(x1);
    const double inv_dx = 1.0 / dx;
    g = (e1.energy - u0) * inv_dx;
    dg = (e1.force - g) * inv_dx;
  } else {
    g = law.force(xm);
    dg = 0.5 * law.stiffness(xm);
  }
  const StepDamping d = law.step_damping(xm, dx, inv_h);
  const double f = g + d.force;
  if (f <= 0.0) return {0.0, 0.0};
  return {f, dg + d.d_force_dx1};
}

// Solves F = Phi(a - c F) for F >= 0 (Phi the step force, increasing in x1):
// g(F) = F - Phi(a - c F) is increasing with g' >= 1, so the root is unique,
// lies in [0, Phi(a)], and |F - F*| <= |g(F)|. Newton from `guess`, kept in
// the bracket (Phi(a) is evaluated only if Newton leaves [0, inf)).
template <BallLaw Law>
double solve_force(const Law& law, double x0, double u0, double a, double c, double h, double guess,
                   double force_floor) {
  if (x0 <= 0.0 && a <= 0.0) return 0.0;
  constexpr double kInf = std::numeric_limits<double>::infinity();
  const double inv_h = 1.0 / h;
  double lo = 0.0, hi = kInf;
  double f = std::max(guess, 0.0);
  for (int it = 0; it < 100; ++it) {
    const StepForce s = step_force(law, x0, u0, a - c * f, inv_h);
    const double g = f - s.force;
    const double scale = std::max({f, s.force, force_floor});
    if (std::abs(g) <= 1e-15 * scale) return f;
    if (g > 0.0)
      hi = f;
    else
      lo = f;
    const double newton = f - g / (1.0 + c * s.d_force_dx1);
    // Newton converges quadratically: a step this small leaves ~its square
    // (relative to the force, or to the contact's typical force near 0).
    if (newton > lo && newton < hi && std::abs(newton - f) <= 1e-7 * scale) return newton;
    double next = newton;
    if (!(next > lo && next < hi)) {
      if (hi == kInf) hi = std::max(step_force(law, x0, u0, a, inv_h).force, lo);
      next = 0.5 * (lo + hi);
    }
    if (next == f || hi - lo <= 1e-15 * hi) return next;
    f = next;
  }
  return f;
}

}  // namespace sweetspot::collision_detail
