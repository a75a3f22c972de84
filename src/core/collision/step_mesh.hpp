#pragma once

// The integrator's time steps (collision.hpp): the base step from the
// contact's estimated duration and its fastest motions, and the graded mesh
// at a contact's onset, towards the force's or the compression's zero, and
// between contacts.

#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>

#include "core/collision/ball_law.hpp"
#include "sweetspot/collision.hpp"
#include "sweetspot/string_bed.hpp"

namespace sweetspot::collision_detail {

inline constexpr double kPi = 3.14159265358979323846;

// What the next step's length depends on, at the start of the step.
struct MeshState {
  double compression;      // x [m]
  double closing_speed;    // y' - s' [m/s], > 0 when the ball closes in
  double since_onset;      // time since the contact began [s] (used in contact)
  double x_dot;            // the last step's mean compression rate [m/s]
  double f_prev, f_prev2;  // the ball force of the last two steps [N]
  double h_last;           // the last step's length [s]
};

class StepMesh {
 public:
  template <BallLaw Law>
  StepMesh(const FrameAtImpact& frame, const std::optional<StringBedDynamics>& strings, double m,
           const Law& law, const BallBody& body, double v1, const CollisionOptions& options)
      : steps_per_contact_(options.steps_per_contact) {
    // Time step from the linearised contact: the ball's secant stiffness at
    // its elastic peak compression on a rigid surface, in series with the strings.
    const double x_peak = law.peak_compression(m, v1);
    double k_lin = law.secant_stiffness(x_peak);
    if (strings) k_lin = series_stiffness(k_lin, strings->stiffness_N_m);
    const double mu = m / (1.0 + m * frame.inverse_effective_mass_per_kg);
    t_est_ = kPi * std::sqrt(mu / k_lin);
    // The fastest motions within the contact: the ball's own spring on what it
    // touches first (the string bed's moving mass, or the frame's rigid body and
    // modes at the impact point), at the compression that stops their relative
    // motion, and the string bed's mass on its spring. A stiff ball (or stiff
    // strings) makes these far shorter than the contact; the step resolves them
    // with steps_per_contact / kFastShare steps per half-period, which never
    // binds for the calibrated ball at any tension in the strings' range.
    double frame_mobility = frame.inverse_effective_mass_per_kg;  // [1/kg], instantaneous
    for (const ModeAtImpact& md : frame.modes) frame_mobility += md.phi * md.phi;
    // (A two-mass ball touches with its front mass, and its halves ring at
    // w_i = sqrt(k_i / mu_i).)
    const double partner_mobility = strings ? 1.0 / strings->mass_kg : frame_mobility;
    const double m_front = body.front_mass_fraction * m;
    const double mu_ball = m_front / (1.0 + m_front * partner_mobility);
    const double x_ball = law.peak_compression(mu_ball, v1);
    double t_fast = kPi * std::sqrt(mu_ball / law.secant_stiffness(x_ball));
    if (body.two_masses()) {
      // At its stiffest: the internal spring's slope k_i + 3 k_3 d^2 where it
      // would store all the ball's energy (k_i d^2 / 2 + k_3 d^4 / 4 = m v1^2 / 2).
      const double mu_i = m_front * (m - m_front) / m, ki = body.internal_stiffness;
      const double k3 = body.internal_cubic_stiffness, e = 0.5 * m * v1 * v1;
      const double d2 = k3 > 0.0 ? (std::sqrt(ki * ki + 4.0 * k3 * e) - ki) / k3 : 2.0 * e / ki;
      t_fast = std::min(t_fast, kPi * std::sqrt(mu_i / (ki + 3.0 * k3 * d2)));
    }
    if (strings) {
      const double mu_bed = strings->mass_kg / (1.0 + strings->mass_kg * frame_mobility);
      t_fast = std::min(t_fast, kPi * std::sqrt(mu_bed / strings->stiffness_N_m));
    }
    constexpr double kFastShare = 8.0;
    // The time the step resolves (the contact's, unless a faster motion binds).
    t_res_ = std::min(t_est_, kFastShare * t_fast);
    h_base_ = t_res_ / options.steps_per_contact;
    // Forces below this are round-off for the force solve: 1e-9 of the mean force.
    force_floor_ = 1e-9 * m * v1 / t_est_;
    h_min_ = h_base_ * kRefine;
    // At most 64 steps per base step until max_time_s, and never more than
    // kMaxSteps, counted in double (a contact resolved by a tiny step would
    // overflow a long). A contact that alone needs more than kMaxContactSteps
    // is not stepped at all: the ball is left in contact, which the invariants
    // refuse (invariants.hpp) at once rather than after minutes of stepping.
    // The calibrated balls take some 10^2 steps a contact; a stiff ball or a
    // bed of micrograms up to some 10^7, a linear ball of 1e15 N/m on the
    // strings 3 10^6 (about 2 s); kMaxSteps bounds the run to some 20 s.
    constexpr double kMaxSteps = 4e7;
    constexpr double kMaxContactSteps = 2e7;
    max_steps_ = t_est_ / h_base_ > kMaxContactSteps
                     ? 0L
                     : static_cast<long>(
                           std::min(kMaxSteps, 64.0 * std::ceil(options.max_time_s / h_base_)));
  }

  double base_step() const { return h_base_; }
  // The steps the contact's estimated duration takes at the base step.
  double contact_steps() const { return t_est_ / h_base_; }
  double force_floor() const { return force_floor_; }
  long max_steps() const { return max_steps_; }

  // The next step. From a contact's onset, where the force grows like
  // sqrt(t) (x^p x' with p = 1/2), the mesh is t_i = kOnset T (i/N)^2
  // (the force a smooth function of i) until it reaches the base step, then
  // uniform. Towards an instant where the force or the compression falls to
  // 0 (a kink or a fractional power of the time) the steps shrink like t^2
  // and geometrically to kRefine of the base step; once the force is 0 the
  // step lands on the separation; between contacts, with the ball receding,
  // steps are kFreeSteps times longer, and a new touch is approached
  // geometrically. (kOnset = 2 and kRefine = 1e-3 keep the default's COR and
  // its observed order; docs/model.md, "The solved collision".)
  double next(const MeshState& st) const {
    const double x = st.compression;
    if (x > 0.0 || (x == 0.0 && st.closing_speed > 0.0)) return in_contact(st);
    if (st.closing_speed > 0.0) {
      const double tau = -x / st.closing_speed;  // to the next touch
      return std::clamp(kGrade * tau, h_min_, h_base_);
    }
    return kFreeSteps * h_base_;
  }

 private:
  static constexpr double kOnset = 2.0, kRefine = 1e-3, kGrade = 0.5, kFreeSteps = 4.0;

  double in_contact(const MeshState& st) const {
    double hh = h_base_;
    const double since = st.since_onset;
    // (The square roots only where they can shorten the step.)
    if (kOnset * since < 0.25 * t_res_)
      hh = h_base_ * (2.0 * std::sqrt(kOnset * since / t_res_) + kOnset / steps_per_contact_);
    const bool force_falls = st.f_prev > 0.0 && st.f_prev < st.f_prev2;
    if (st.x_dot < 0.0 || force_falls) {
      double tau =
          st.x_dot < 0.0 ? st.compression / -st.x_dot : std::numeric_limits<double>::infinity();
      if (force_falls) tau = std::min(tau, st.f_prev * st.h_last / (st.f_prev2 - st.f_prev));
      if (st.f_prev > 0.0)
        hh = std::min({hh, kGrade * tau,
                       tau < 0.25 * t_res_ ? 2.0 * h_base_ * std::sqrt(tau / t_res_) : h_base_});
      else
        hh = std::min(hh, tau);  // no force: land on the separation
    }
    return std::clamp(hh, h_min_, h_base_);
  }

  int steps_per_contact_;
  double t_est_ = 0.0, t_res_ = 0.0, h_base_ = 0.0, h_min_ = 0.0, force_floor_ = 0.0;
  long max_steps_ = 0;
};

}  // namespace sweetspot::collision_detail
