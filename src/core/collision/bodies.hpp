#pragma once

// The ball and the string bed along the line of the impact (collision.hpp),
// the two bodies the integrator steps beside the frame's modal state.

#include <cmath>
#include <optional>

#include "sweetspot/collision.hpp"

namespace sweetspot::collision_detail {

// The ball: mass m, incident speed v1, its centre of mass at y with velocity
// y', and its compression x = (front) - s with the energy U(x) it stores.
// A two-mass ball (BallBody) is its front mass m_f and back mass m_b = m - m_f,
// the back d closer to the front than at rest (the internal spring's
// compression), on the spring G(d) = k_i d + k_3 d^3 with energy
// V(d) = k_i d^2 / 2 + k_3 d^4 / 4 and the dashpot c_i: in the centre of
// mass's coordinates the front is at y - (m_b / m) d, and
//   m y'' = -F,   mu d'' = -G(d) - c_i d' + (m_b / m) F,   mu = m_f m_b / m.
// One mass: m_b = 0, the front is y. The step is the implicit midpoint rule
// with G's discrete gradient g = (V(d1) - V(d0)) / (d1 - d0), the unknown the
// integrator solves for beside the contact's force (collision.cpp).
struct Ball {
  double m, v1;
  double mf = m, mb = 0.0, mu = 0.0;    // the two masses (mb = 0: one mass)
  double ki = 0.0, k3 = 0.0, ci = 0.0;  // the internal spring and dashpot
  double y = 0.0, vy = v1;
  double d = 0.0, vd = 0.0;   // the internal compression and its rate
  double x = 0.0, u_x = 0.0;  // compression and its elastic energy
  double x_dot = v1;          // the last step's mean compression rate
  double damp = 1.0;          // 1 / (1 + h c_i / (2 mu)) for the current step

  Ball(double mass, double speed, const BallBody& body) : m(mass), v1(speed) {
    if (!body.two_masses()) return;
    mf = body.front_mass_fraction * mass;
    mb = mass - mf;
    mu = mf * mb / mass;
    ki = body.internal_stiffness;
    k3 = body.internal_cubic_stiffness;
    ci = 2.0 * body.internal_damping_ratio * std::sqrt(ki * mu);
  }

  bool two_masses() const { return mb > 0.0; }

  void set_step(double h) { damp = two_masses() ? 1.0 / (1.0 + 0.5 * h * ci / mu) : 1.0; }

  // The internal spring's discrete gradient from d to d1.
  double inner_gradient(double d1) const {
    const double s = d + d1;
    return 0.5 * ki * s + 0.25 * k3 * s * (d * d + d1 * d1);
  }
  double inner_energy(double dd) const { return dd * dd * (0.5 * ki + 0.25 * k3 * dd * dd); }

  // The front's velocity now.
  double front_velocity() const { return vy - mb / m * vd; }

  // Over a step of length h with the internal spring's gradient g: the
  // front's midpoint velocity is A - B F; A(g) = A0 + A1 g.
  struct Start {
    double A0, A1, B;
  };
  Start begin_step(double h) const {
    if (!two_masses()) return {vy, 0.0, 0.5 * h / m};
    const double r = mb / m * damp;
    return {vy - r * vd, r * 0.5 * h / mu, 0.5 * h / m + r * 0.5 * h / mf};
  }
  // The internal compression at the step's end under F and g.
  double inner_end(double h, double F, double g) const {
    return d + h * damp * (vd + 0.5 * h * (F / mf - g / mu));
  }

  // The step of length h under the force F on the front and the internal
  // gradient g; returns the power the internal dashpot takes at the midpoint.
  double advance(double h, double F, double g) {
    const double vy_mid = vy - 0.5 * h / m * F;
    y += h * vy_mid;
    vy = 2.0 * vy_mid - vy;
    if (!two_masses()) return 0.0;
    const double vd_mid = damp * (vd + 0.5 * h * (F / mf - g / mu));
    d += h * vd_mid;
    vd = 2.0 * vd_mid - vd;
    return ci * vd_mid * vd_mid;
  }

  // The front's position, and the distance the centre of mass has come
  // towards the surface at s: the compression a drop test measures (the
  // force integrated twice over m; one mass: x).
  double front() const { return two_masses() ? y - mb / m * d : y; }
  double centre_compression(double s) const { return y - s; }

  // What the two halves ring with, mu d'^2 / 2 + V(d) [J], and a bound on how
  // far the ring moves the front, (m_b / m) sqrt(2 E / k_i) [m].
  double internal_energy() const {
    return two_masses() ? 0.5 * mu * vd * vd + inner_energy(d) : 0.0;
  }
  double internal_reach() const {
    return two_masses() ? mb / m * std::sqrt(2.0 * internal_energy() / ki) : 0.0;
  }

  // The step of length h ends at compression x1, storing u1 = U(x1).
  void compress_to(double x1, double u1, double h) {
    x_dot = (x1 - x) / h;
    x = x1;
    u_x = u1;
  }
};

// The string bed's moving mass m_s on its spring k_s and dashpot c_s to the
// frame, at s with velocity s'. Without strings (present false) s follows the
// frame's impact point.
struct Bed {
  bool present;
  double ks, ms, cs;
  double s = 0.0, vs = 0.0;
  double kappa = 0.0;  // k_s h / 2 + c_s for the current step

  Bed(const std::optional<StringBedDynamics>& strings, double ball_mass)
      : present(strings.has_value()),
        ks(present ? strings->stiffness_N_m : 0.0),
        ms(present ? strings->mass_kg : 0.0),
        cs(present ? 2.0 * strings->damping_ratio * std::sqrt(ks * ball_mass) : 0.0) {}

  void set_step(double h) { kappa = 0.5 * ks * h + cs; }
};

}  // namespace sweetspot::collision_detail
