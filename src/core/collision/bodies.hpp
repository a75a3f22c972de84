#pragma once

// The ball and the string bed along the line of the impact (collision.hpp),
// the two bodies the integrator steps beside the frame's modal state.

#include <cmath>
#include <optional>

#include "sweetspot/collision.hpp"

namespace sweetspot::collision_detail {

// The ball: mass m, incident speed v1, position y and velocity y', and its
// compression x = y - s with the energy U(x) it stores.
struct Ball {
  double m, v1;
  double y = 0.0, vy = v1;
  double x = 0.0, u_x = 0.0;  // compression and its elastic energy
  double x_dot = v1;          // the last step's mean compression rate

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
