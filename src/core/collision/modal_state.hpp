#pragma once

// The frame at the impact point in the integrator's coordinates
// (collision.hpp): coordinate 0 the rigid body (unit modal mass,
// phi = 1/sqrt(M_eff), w = 0), then the flexible modes, each with its
// displacement and velocity and the midpoint rule's coefficients for the
// current step. One array per quantity, so the loops over the modes vectorise.

#include <cmath>
#include <cstddef>
#include <vector>

#include "sweetspot/collision.hpp"

namespace sweetspot::collision_detail {

class ModalState {
 public:
  explicit ModalState(const FrameAtImpact& frame)
      : n_(frame.modes.size() + 1),
        phi_(n_),
        om2_(n_),
        damp_(n_),
        r_(n_, 0.0),
        v_(n_, 0.0),
        inv_den_(n_),
        beta_(n_),
        half_om2_(n_),
        alpha_(n_) {
    phi_[0] = std::sqrt(frame.inverse_effective_mass_per_kg);
    for (std::size_t j = 1; j < n_; ++j) {
      const ModeAtImpact& md = frame.modes[j - 1];
      phi_[j] = md.phi;
      om2_[j] = md.omega_rad_s * md.omega_rad_s;
      damp_[j] = 2.0 * md.damping_ratio * md.omega_rad_s;
    }
  }

  // The flexible modes (coordinate 0, the rigid body, not counted).
  std::size_t flexible_modes() const { return n_ - 1; }

  // The static compliance of the vibration at the impact point, sum phi^2 / w^2 [m/N].
  double static_compliance() const {
    double compliance = 0.0;
    for (std::size_t j = 1; j < n_; ++j) compliance += phi_[j] * phi_[j] / om2_[j];
    return compliance;
  }

  // The step the coefficients are for (0 before the first).
  double step() const { return h_; }

  // The midpoint rule's coefficients for a step of length h; true if h is new.
  bool set_step(double h) {
    if (h == h_) return false;
    h_ = h;
    B_w_ = coefficients(n_, h, phi_.data(), om2_.data(), damp_.data(), inv_den_.data(),
                        beta_.data(), half_om2_.data());
    return true;
  }

  // The impact point's velocity per unit force over the step, B_w = sum phi beta.
  double compliance_rate() const { return B_w_; }

  // At the step's start: the midpoint velocities without the force (alpha),
  // the impact point's share of them, A_w, and its displacement w0.
  struct Start {
    double A_w, w0;
  };
  Start begin_step() {
    return start(n_, phi_.data(), inv_den_.data(), half_om2_.data(), r_.data(), v_.data(),
                 alpha_.data());
  }

  // The step under the string force Fs, from the midpoint velocities: the
  // impact point's midpoint velocity and the power the modal damping takes.
  struct Advance {
    double w_dot_mid, damping_power;
  };
  Advance advance(double Fs) {
    return update(n_, h_, Fs, phi_.data(), damp_.data(), alpha_.data(), beta_.data(), r_.data(),
                  v_.data());
  }

  // The impact point's displacement w = sum phi q.
  double displacement() const {
    double w = 0.0;
    for (std::size_t j = 0; j < n_; ++j) w += phi_[j] * r_[j];
    return w;
  }

  // The rigid body's velocity at the impact point, u'.
  double rigid_velocity() const { return phi_[0] * v_[0]; }
  // The rigid body's momentum M_eff u' (0 for an immovable frame).
  double rigid_momentum(double inverse_effective_mass) const {
    return inverse_effective_mass > 0.0 ? v_[0] / phi_[0] : 0.0;
  }
  // The rigid body's kinetic energy 1/2 M_eff u'^2.
  double rigid_energy() const { return 0.5 * v_[0] * v_[0]; }

  // Flexible mode k's energy 1/2 (q'^2 + w^2 q^2), k from 0.
  double mode_energy(std::size_t k) const {
    const std::size_t j = k + 1;
    return 0.5 * (v_[j] * v_[j] + om2_[j] * r_[j] * r_[j]);
  }
  // The flexible modes' energy.
  double vibration_energy() const {
    double e = 0.0;
    for (std::size_t k = 0; k + 1 < n_; ++k) e += mode_energy(k);
    return e;
  }

 private:
  // The loops over the coordinates, on arrays that never overlap: __restrict
  // spares the vectorised loops a run-time overlap test on every step (a
  // few percent of the collision's instructions with its seven coordinates).
  // coefficients() returns B_w.
  static double coefficients(std::size_t n, double h, const double* __restrict phi,
                             const double* __restrict om2, const double* __restrict damp,
                             double* __restrict inv_den, double* __restrict beta,
                             double* __restrict half_om2) {
    for (std::size_t j = 0; j < n; ++j) {  // vectorisable: no sum
      inv_den[j] = 1.0 / (1.0 + 0.5 * h * damp[j] + 0.25 * h * h * om2[j]);
      beta[j] = 0.5 * h * phi[j] * inv_den[j];
      half_om2[j] = 0.5 * h * om2[j];
    }
    double B_w = 0.0;
    for (std::size_t j = 0; j < n; ++j) B_w += phi[j] * beta[j];
    return B_w;
  }
  static Start start(std::size_t n, const double* __restrict phi, const double* __restrict inv_den,
                     const double* __restrict half_om2, const double* __restrict r,
                     const double* __restrict v, double* __restrict alpha) {
    double A_w = 0.0, w0 = 0.0;
    for (std::size_t j = 0; j < n; ++j) {
      alpha[j] = (v[j] - half_om2[j] * r[j]) * inv_den[j];
      A_w += phi[j] * alpha[j];
      w0 += phi[j] * r[j];
    }
    return {A_w, w0};
  }
  static Advance update(std::size_t n, double h, double Fs, const double* __restrict phi,
                        const double* __restrict damp, const double* __restrict alpha,
                        const double* __restrict beta, double* __restrict r, double* __restrict v) {
    // (Sums in locals: an accumulator kept in memory serialises the loop.)
    double w_dot_mid = 0.0, damping_power = 0.0;
    for (std::size_t j = 0; j < n; ++j) {
      const double vm = alpha[j] + beta[j] * Fs;
      w_dot_mid += phi[j] * vm;
      damping_power += damp[j] * vm * vm;
      r[j] += h * vm;
      v[j] = 2.0 * vm - v[j];
    }
    return {w_dot_mid, damping_power};
  }

  std::size_t n_;
  // Per coordinate: phi at the impact point, w^2 and 2 z w.
  std::vector<double> phi_, om2_, damp_;
  // Per coordinate: displacement q and velocity q'.
  std::vector<double> r_, v_;
  // Per coordinate, for the step h_: 1 / (1 + h z w + h^2 w^2 / 4), the
  // midpoint velocity per unit force (beta) and h w^2 / 2.
  std::vector<double> inv_den_, beta_, half_om2_;
  // Per coordinate, this step: the midpoint velocity without the force.
  std::vector<double> alpha_;
  double h_ = 0.0, B_w_ = 0.0;
};

}  // namespace sweetspot::collision_detail
