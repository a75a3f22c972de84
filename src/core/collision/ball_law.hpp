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

#include <algorithm>
#include <cmath>
#include <concepts>

#include "sweetspot/ball_contact.hpp"
#include "sweetspot/roots.hpp"

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

// The damping part b xm^p dx / h of a step, with its derivative in x1,
// b / h (xm^p + p/2 xm^(p-1) dx) (xm moves by half of x1).
inline StepDamping power_damping(double b, double p, double xm, double dx, double inv_h) {
  if (!(b > 0.0 && xm > 0.0)) return {0.0, 0.0};
  const double xp = power(xm, p);
  return {b * xp * dx * inv_h, b * inv_h * (xp + (p > 0.0 ? 0.5 * p * xp / xm * dx : 0.0))};
}

// F = k x^n + b x^p x' (ball_contact.hpp): U = k x^(n+1) / (n+1), and the
// damping part power_damping().
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
    return power_damping(b_, p_, xm, dx, inv_h);
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

// The hysteretic ball (HystereticBallLaw, ball_contact.hpp), a law with a
// memory: the largest compression x_m of the contact so far, which the
// integrator moves on after each step (commit()). Between commits the law is
// the path the ball would take from x_m's branch: below x_m the unloading
// branch, elastic with U(x) = sum B_i(x_m) x_m / (q_i + 1) (x / x_m)^(q_i + 1);
// beyond x_m the loading backbone, whose work the energy continues
// (U(x_m) + the backbones' work from x_m). So the discrete gradient's
// (U(x1) - U(x0)) / dx is the work of the path's force, and once commit()
// has moved x_m to x1 the stored energy U(x1) is less than that path's by the
// loop's loss, which the ledger books as the ball's.
class HystereticLaw {
 public:
  explicit HystereticLaw(const HystereticBallLaw& law)
      : ks_(law.shell_stiffness),
        xb_(law.shell_compression),
        kp_(law.stiffening),
        kw_(law.wall_stiffness),
        qs_(std::max(law.shell_unloading + law.unloading_offset, 1.0)),
        qp_(std::max(law.stiffening_unloading + law.unloading_offset, 2.0)),
        qw_(std::max(law.wall_unloading + law.unloading_offset, 1.0)),
        b_(law.damping) {}

  // The backbones' force and work from 0 at x >= 0 on loading.
  double backbone(double x) const { return ks_ * std::min(x, xb_) + kp_ * x * x + kw_ * x; }
  double backbone_work(double x) const {
    const double s = x <= xb_ ? 0.5 * ks_ * x * x : ks_ * xb_ * (x - 0.5 * xb_);
    return s + kp_ * x * x * x / 3.0 + 0.5 * kw_ * x * x;
  }

  double energy(double x) const { return elastic_at(x).energy; }
  double force(double x) const { return elastic_at(x).force; }
  double stiffness(double x) const {
    if (x <= 0.0) return 0.0;
    if (x >= xm_) return (x < xb_ ? ks_ : 0.0) + 2.0 * kp_ * x + kw_;
    const double r = x / xm_;
    return (branch_slope(shell_at_peak_, qs_, r) + branch_slope(kp_ * xm_ * xm_, qp_, r) +
            branch_slope(kw_ * xm_, qw_, r)) /
           xm_;
  }
  ElasticAt elastic_at(double x) const {
    if (x <= 0.0) return {0.0, 0.0};
    if (x >= xm_) return {stored_at_peak_ + backbone_work(x) - work_at_peak_, backbone(x)};
    const double r = x / xm_;
    const double bp = kp_ * xm_ * xm_, bw = kw_ * xm_;
    return {
        xm_ * (branch_energy(shell_at_peak_, qs_, r) + branch_energy(bp, qp_, r) +
               branch_energy(bw, qw_, r)),
        branch_force(shell_at_peak_, qs_, r) + branch_force(bp, qp_, r) + branch_force(bw, qw_, r)};
  }

  // b sqrt(xm) dx / h, the power law's damping part with p = 1/2.
  StepDamping step_damping(double xm, double dx, double inv_h) const {
    return power_damping(b_, 0.5, xm, dx, inv_h);
  }

  // The compression whose loading work is 1/2 m v^2 (the work increases
  // from 0), and the backbone's secant there.
  double peak_compression(double mass, double speed) const {
    const double target = 0.5 * mass * speed * speed;
    const auto excess = [&](double x) { return backbone_work(x) - target; };
    double hi = xb_;
    while (excess(hi) < 0.0) hi *= 2.0;
    return brent_root(excess, 0.0, hi, -target, excess(hi), 1e-12 * hi);
  }
  double secant_stiffness(double x) const { return backbone(x) / x; }

  // After a step ending at x: the branch's peak moves on; off the surface the
  // ball forgets it.
  void commit(double x) {
    if (x <= 0.0) {
      set_peak(0.0);
    } else if (x > xm_) {
      set_peak(x);
    }
  }
  double peak() const { return xm_; }

 private:
  // One backbone B at x_m unloading as B (x/x_m)^q: its force, slope times
  // x_m, and energy over x_m at r = x / x_m in (0, 1). q = infinity (a plastic
  // ball) is 0 below x_m.
  static double branch_force(double b, double q, double r) {
    return std::isinf(q) ? 0.0 : b * power(r, q);
  }
  static double branch_slope(double b, double q, double r) {
    return std::isinf(q) ? 0.0 : b * q * power(r, q - 1.0);
  }
  static double branch_energy(double b, double q, double r) {
    return std::isinf(q) ? 0.0 : b * r * power(r, q) / (q + 1.0);
  }
  void set_peak(double x) {
    xm_ = x;
    shell_at_peak_ = ks_ * std::min(x, xb_);
    work_at_peak_ = backbone_work(x);
    stored_at_peak_ =
        x > 0.0 ? x * (branch_energy(shell_at_peak_, qs_, 1.0) +
                       branch_energy(kp_ * x * x, qp_, 1.0) + branch_energy(kw_ * x, qw_, 1.0))
                : 0.0;
  }

  double ks_, xb_, kp_, kw_, qs_, qp_, qw_, b_;
  double xm_ = 0.0, shell_at_peak_ = 0.0, work_at_peak_ = 0.0, stored_at_peak_ = 0.0;
};

static_assert(BallLaw<HystereticLaw>);

}  // namespace sweetspot::collision_detail
