#pragma once

// The ball's contact law as the integrator sees it (collision.hpp): what a
// ball law must give, and the power law F = k x^n + b x^p x' of
// BallContactLaw (ball_contact.hpp) as its first implementation.
//
// A law is a force F(x, x') = F_e(x) + F_d(x, x') of the compression x [m] and
// its rate x' [m/s], an elastic part F_e = U'(x) with a stored energy U and a
// damping part that vanishes with x'. The integrator never asks for F itself:
// its discrete gradient (collision/contact_force.hpp) takes the elastic part
// as (U(x1) - U(x0)) / (x1 - x0) over a step and the damping part at the
// step's midpoint, so a law gives these pieces and their derivatives in the
// step's end compression x1. A new law is one more type that satisfies
// BallLaw, built from its parameters where collide() builds PowerLaw.

#include <cmath>
#include <concepts>

#include "sweetspot/ball_contact.hpp"

namespace sweetspot::collision_detail {

// The elastic part at one compression: U(x) and F_e(x) = U'(x).
struct ElasticAt {
  double energy;
  double force;
};

// The damping part over one step x0 -> x1 of length h, evaluated at the
// midpoint xm with the step's mean rate (x1 - x0) / h, and its derivative in
// x1 (xm moves by half of x1).
struct StepDamping {
  double force;
  double d_force_dx1;
};

// What the integrator asks of a ball law. All compressions are in m, x <= 0
// meaning no contact (every term 0 there).
template <class L>
concept BallLaw = requires(const L& law, double x, double dx, double inv_h, double mass,
                           double speed) {
  // U(x) [J], the energy the ledger books as stored, not lost.
  { law.energy(x) } -> std::same_as<double>;
  // F_e(x) = U'(x) [N] and dF_e/dx [N/m]: the step force where x1 ~ x0.
  { law.force(x) } -> std::same_as<double>;
  { law.stiffness(x) } -> std::same_as<double>;
  // U(x) and U'(x) together (one power of x for both).
  { law.elastic_at(x) } -> std::same_as<ElasticAt>;
  // The damping part at the midpoint x of a step of length 1 / inv_h whose
  // compression changes by dx, with its derivative in the step's end.
  { law.step_damping(x, dx, inv_h) } -> std::same_as<StepDamping>;
  // The time step's estimates: the compression at which U stores the kinetic
  // energy 1/2 mass speed^2, and the secant stiffness F_e(x) / x there.
  { law.peak_compression(mass, speed) } -> std::same_as<double>;
  { law.secant_stiffness(x) } -> std::same_as<double>;
};

// x^e for x > 0 with the calibrated ball's exponents fast (no pow).
inline double power(double x, double e) {
  if (e == 0.5) return std::sqrt(x);
  if (e == 1.0) return x;
  if (e == 1.5) return x * std::sqrt(x);
  if (e == 2.0) return x * x;
  if (e == 2.5) return x * x * std::sqrt(x);
  if (e == 0.0) return 1.0;
  return std::pow(x, e);
}

// F = k x^n + b x^p x' (ball_contact.hpp): U = k x^(n+1) / (n+1), and the
// damping part b xm^p dx / h with derivative b / h (xm^p + p/2 xm^(p-1) dx).
class PowerLaw {
 public:
  explicit PowerLaw(const BallContactLaw& law)
      : k_(law.stiffness), n_(law.exponent), b_(law.damping), p_(law.damping_exponent) {}

  double energy(double x) const { return x > 0.0 ? k_over_n1_ * x * power(x, n_) : 0.0; }
  double force(double x) const { return x > 0.0 ? k_ * power(x, n_) : 0.0; }
  double stiffness(double x) const { return x > 0.0 ? k_ * n_ * power(x, n_ - 1.0) : 0.0; }

  // x^(n+1) as x x^n, the same power for the energy and the force.
  ElasticAt elastic_at(double x) const {
    const double xn = x > 0.0 ? power(x, n_) : 0.0;
    return {k_over_n1_ * x * xn, k_ * xn};
  }

  StepDamping step_damping(double xm, double dx, double inv_h) const {
    if (!(b_ > 0.0 && xm > 0.0)) return {0.0, 0.0};
    const double xp = power(xm, p_);
    return {b_ * xp * dx * inv_h, b_ * inv_h * (xp + (p_ > 0.0 ? 0.5 * p_ * xp / xm * dx : 0.0))};
  }

  double peak_compression(double mass, double speed) const {
    return std::pow((n_ + 1.0) * mass * speed * speed / (2.0 * k_), 1.0 / (n_ + 1.0));
  }
  double secant_stiffness(double x) const { return k_ * std::pow(x, n_ - 1.0); }

 private:
  double k_, n_, b_, p_;
  double k_over_n1_ = k_ / (n_ + 1.0);
};

static_assert(BallLaw<PowerLaw>);

}  // namespace sweetspot::collision_detail
