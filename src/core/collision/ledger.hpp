#pragma once

// The energy ledger of the solved collision (collision.hpp): the ball's
// kinetic energy in = what the ball takes out + the implement's rigid motion
// + its vibration + the losses. The integrator books each dissipative term's
// work per step; the stored terms are read from the state when the result is
// taken (at a separation and at the end).

#include "core/collision/bodies.hpp"
#include "core/collision/modal_state.hpp"
#include "sweetspot/collision.hpp"

namespace sweetspot::collision_detail {

class EnergyLedger {
 public:
  // The ball's damping over a step: the work F dx less the stored energy's change dU.
  void book_ball(double force, double dx, double du) { ball_loss_ += force * dx - du; }
  // A two-mass ball's internal dashpot over a step of length h at power 2 z_i w_i q'^2.
  void book_ball_internal_damping(double h, double power) { ball_loss_ += h * power; }
  // The strings' dashpot c_s over a step of length h at relative velocity rel.
  void book_strings(double cs, double h, double rel) { strings_loss_ += cs * h * rel * rel; }
  // The modal damping over a step of length h at power sum 2 z w q'^2.
  void book_modal_damping(double h, double power) { modal_damping_loss_ += h * power; }

  // The ledger's terms from the state now, into res: ball_in_J, ball_out_J,
  // implement_rigid_J, vibration_J with its parts (mode_energy_J,
  // string_bed_energy_J, modal_damping_loss_J), ball_loss_J, strings_loss_J.
  void report(const Ball& ball, const Bed& bed, const ModalState& modes,
              double inverse_effective_mass, CollisionResult& res) const;

 private:
  double ball_loss_ = 0.0, strings_loss_ = 0.0, modal_damping_loss_ = 0.0;
};

inline void EnergyLedger::report(const Ball& ball, const Bed& bed, const ModalState& modes,
                                 double inverse_effective_mass, CollisionResult& res) const {
  res.ball_in_J = 0.5 * ball.m * ball.v1 * ball.v1;
  res.ball_out_J = 0.5 * ball.m * ball.vy * ball.vy + ball.u_x;  // u_x = 0 once separated
  res.mode_energy_J.assign(modes.flexible_modes(), 0.0);
  const double w = modes.displacement();
  double vibration = modal_damping_loss_;
  for (std::size_t k = 0; k < res.mode_energy_J.size(); ++k) {
    res.mode_energy_J[k] = modes.mode_energy(k);
    vibration += res.mode_energy_J[k];
  }
  // The string bed rides on the frame: the rigid motion of both is their
  // common momentum P on M_eff + m_s; the rest is the bed's vibration.
  const double inv_M = inverse_effective_mass;
  const double uF = modes.rigid_velocity();
  double rigid = modes.rigid_energy();
  res.string_bed_energy_J = 0.0;
  if (bed.present) {
    const double ms = bed.ms, ks = bed.ks, vs = bed.vs;
    const double d = bed.s - w;
    if (inv_M > 0.0) {
      const double M = 1.0 / inv_M, P = M * uF + ms * vs;
      rigid = 0.5 * P * P / (M + ms);
      const double mu_s = M * ms / (M + ms);
      res.string_bed_energy_J = 0.5 * mu_s * (uF - vs) * (uF - vs) + 0.5 * ks * d * d;
    } else {
      res.string_bed_energy_J = 0.5 * ms * vs * vs + 0.5 * ks * d * d;
    }
  }
  res.implement_rigid_J = rigid;
  res.vibration_J = vibration + res.string_bed_energy_J;
  res.modal_damping_loss_J = modal_damping_loss_;
  // What the ball's two halves still ring with is the ball's: it leaves as heat.
  res.ball_loss_J = ball_loss_ + ball.internal_energy();
  res.strings_loss_J = strings_loss_;
}

}  // namespace sweetspot::collision_detail
