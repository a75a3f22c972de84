#pragma once

// The implement's answer to the ball: a half-sine force at the impact point
// drives the rigid-body motion and the flexible modes (Cross 2004, Secs. III,
// IV and VI), the vibration energy the frame keeps after the impact, and the
// coefficient of restitution that this energy leaves the ball.
//
// Model. Linear modal superposition. With the force F(t) = F0 sin(pi t / T),
// 0 <= t <= T (Cross 2004 Sec. VI), acting transversely at x_F:
//  * rigid-body part ("dc", Sec. III): the body accelerates as a whole; the
//    velocity of a point x is v_dc(x, t) = (1/M - A b / I_0) J(t), Eq. (4),
//    with the impulse delivered so far J(t) = F0 T/pi (1 - cos(pi t/T)).
//  * vibration part ("ac"): each mode k with mass-normalised shape phi_k(x)
//    [kg^-1/2] (int mu phi_k^2 dx + sum m_j phi_k(x_j)^2 = 1), undamped angular
//    frequency w_k and damping ratio z_k obeys
//      q_k'' + 2 z_k w_k q_k' + w_k^2 q_k = phi_k(x_F) F(t),  q_k(0) = q_k'(0) = 0,
//    solved in closed form during and after the pulse (half_sine_modal_response);
//    v_ac(x, t) = sum_k phi_k(x) q_k'(t).
// The free implement (suspended on strings) uses its free-free modes; the
// hand-held one the modes of beam_modes' hand_held_modes, whose rigid body is
// implement plus hand (the arm is not modelled) and whose modes include the
// hand rocking on the grip. Those modes are complex (the grip damping is not
// proportional); each is used here as a real mode: the real part of the turned
// shape (Mode::fe_dofs, mass-normalised), the undamped frequency |s| and the
// damping ratio -Re(s)/|s|. This is exact for a real mode and a first-order
// approximation in Mode::complexity otherwise; overdamped (real) roots, which
// hand_held_modes does not report, are missing from the sum.

#include <optional>
#include <string>
#include <vector>

#include "sweetspot/beam_modes.hpp"
#include "sweetspot/design.hpp"
#include "sweetspot/implement.hpp"
#include "sweetspot/mass_properties.hpp"

namespace sweetspot {

// ------------------------------------------------------------ the pulse

// Cross (2004) Sec. VI: F(t) = F0 sin(pi t / T) for 0 <= t <= T, zero after.
struct HalfSinePulse {
  double peak_force_N = 0.0;  // F0 [N], >= 0
  double duration_s = 0.0;    // T [s], > 0
};

// Throws std::invalid_argument naming "pulse.peak_force_N" or "pulse.duration_s".
void validate(const HalfSinePulse& pulse);

// int_0^T F dt = 2 F0 T / pi [N s].
double half_sine_impulse(const HalfSinePulse& pulse);

// The impulse delivered by time t: F0 T/pi (1 - cos(pi t/T)) for 0 <= t <= T,
// 0 before, the whole impulse after [N s].
double half_sine_impulse_until(const HalfSinePulse& pulse, double t_s);

// The half-sine of duration T [s] carrying the impulse J [N s]: F0 = pi J / (2 T).
HalfSinePulse half_sine_with_impulse(double impulse_N_s, double duration_s);

// |F^(w)| / J, the magnitude of the pulse's Fourier transform
// F^(w) = int_0^T F(t) e^{-i w t} dt over its impulse J (dimensionless):
//   S(w T) = |cos(w T / 2)| / |1 - (w T / pi)^2|,  S -> pi/4 at w T = pi.
// S(0) = 1 (an impulse); its first zero is at f = w/2pi = 1.5/T, the paper's
// "the frequency spectrum for a half-sine impulse of duration T extends only to
// about f = 1.5/T" (Sec. III); above it S <= 1/((2 f T)^2 - 1).
double half_sine_spectrum_ratio(double omega_rad_s, double duration_s);

// Energy an undamped mode keeps after a half-sine pulse [J]:
//   E = 1/2 (J phi_k(x_F))^2 S(w_k T)^2,
// J [N s], phi_k(x_F) [kg^-1/2] mass-normalised, w_k [rad/s], T [s]. From rest,
// an undamped mode's q' + i w q = phi int_0^t F(tau) e^{i w (t - tau)} dtau, so
// after the pulse its energy 1/2 (q'^2 + w^2 q^2) = 1/2 phi^2 |F^(w)|^2.
// T -> 0 gives the impulse limit 1/2 (J phi)^2. Throws std::invalid_argument
// for T <= 0 or w < 0.
double half_sine_residual_energy(double impulse_N_s, double phi_at_impact_per_sqrt_kg,
                                 double omega_rad_s, double duration_s);

// A modal coordinate and its rate: q [m kg^1/2], q' [m kg^1/2 s^-1]. The
// physical displacement and velocity at x are phi(x) q and phi(x) q'.
struct ModalState {
  double q = 0.0;
  double q_dot = 0.0;
};

// Closed-form solution of q'' + 2 z w q' + w^2 q = P sin(pi t/T) (0 <= t <= T;
// no force after), q(0) = q'(0) = 0, at time t [s] (t < 0: at rest).
// P = F0 phi(x_F) [N kg^-1/2], w > 0 [rad/s], z in [0, 1). During the pulse,
// with lambda = -z w + i w_d, w_d = w sqrt(1 - z^2), a = i pi/T and the divided
// difference g(a, b; t) = (e^{a t} - e^{b t}) / (a - b) (Duhamel's integral of
// e^{a tau} against e^{b (t - tau)}),
//   q(t)  = P Im[(g(a, lambda) - g(a, conj lambda)) / (lambda - conj lambda)],
//   q'(t) = P Im[(lambda g(a, lambda) - conj lambda g(a, conj lambda)) / (lambda - conj lambda)],
// finite at resonance (w = pi/T, z = 0); after the pulse, free damped
// vibration from q(T), q'(T). Throws std::invalid_argument for w <= 0, z
// outside [0, 1) or T <= 0.
ModalState half_sine_modal_response(double omega_rad_s, double damping_ratio,
                                    double modal_peak_force, double duration_s, double t_s);

// ------------------------------------------------------------ the model

// One vibration mode prepared for modal superposition.
struct ResponseMode {
  Mode mode;                              // shape as beam_modes reports it
  double shape_to_mass_normalised = 0.0;  // phi(x) = this * mode_shape_at(mode, x) [kg^-1/2]
  double omega_rad_s = 0.0;               // undamped w [rad/s], > 0
  double damping_ratio = 0.0;             // z, in [0, 1)
};

// Mass-normalised shape phi_k(x) [kg^-1/2]. Throws std::invalid_argument if x
// is outside the implement.
double mass_normalised_shape(const ResponseMode& mode, double x_m);

// What moves when the implement is hit: a rigid body plus vibration modes.
// Immutable value; build it with one of the functions below.
struct ResponseModel {
  MassProperties rigid_body;        // the body the impulse accelerates as a whole
  std::vector<ResponseMode> modes;  // ascending frequency
  double length_m = 0.0;
  bool hand_held = false;
  // On a rig (supported_modes()): clamped, the rigid body does not move;
  // pinned, it only turns about the pivot. The modes are the supported ones.
  std::optional<BeamSupport> rig;
};

// The free implement (Sec. III) from its free modes (free_modes with the same
// sections and point masses, exact or finite elements). Exact modes are
// mass-normalised by integrating mu w^2 over each piece (Gauss-Legendre, exact
// to round-off for these smooth shapes) plus the point masses; FE modes by
// their fe_dofs. `damping_ratio` in [0, 1) is given to every mode (the free
// beam has none of its own; material damping of a frame is ~0.005).
// Throws std::invalid_argument for inconsistent arguments.
ResponseModel free_response_model(const std::vector<Section>& sections,
                                  const std::vector<PointMass>& point_masses,
                                  const ModalResult& free, double damping_ratio = 0.0);

// The hand-held implement (Sec. IV) from hand_held_modes with the same
// sections, point masses and hand: the rigid body is implement plus hand
// (mass at the grip centre, rotary inertia as in HandCoupling), the modes
// their real, mass-normalised parts (see the header comment).
ResponseModel hand_held_response_model(const std::vector<Section>& sections,
                                       const std::vector<PointMass>& point_masses,
                                       const HandCoupling& hand, const ModalResult& hand_held);

// The same model with every mode's frequency multiplied by f1_Hz / f1: the
// frame with every EI scaled by (f1_Hz / f1)^2, exact for Euler-Bernoulli
// (shapes do not depend on a common EI factor). Throws for f1_Hz <= 0 or a
// model without modes.
ResponseModel with_fundamental(const ResponseModel& model, double f1_Hz);

struct ResponseOptions {
  enum class Support { kFree, kHandHeld, kRig };
  Support support = Support::kFree;
  BeamSupport rig{};  // kRig: the clamp or the pivot (supported_modes(), finite elements)
  int modes = 6;      // flexible modes (hand-held: including the hand's), in [1, kMaxModes]
  double free_damping_ratio = 0.0;  // z of every free mode, in [0, 1)
  double rel_tol =
      1e-6;  // FE (hand-held, Timoshenko): relative error of f1, in [kMinRelTol, kMaxRelTol]

  // Empty if consistent, otherwise the first problem, naming the field and value.
  std::string validate() const;
};

// The design's frame (flexible_frame) free or in its hand (hand_coupling),
// with its modes computed here. Free Euler-Bernoulli frames use the exact
// solver (at most kMaxExactModes), everything else finite elements. Throws
// std::invalid_argument when the design has no stiffness, a hand-held model is
// asked without a hand, or the options are invalid.
ResponseModel response_model(const Design& design, const ResponseOptions& options = {});

// ------------------------------------------------------------ the response

struct PointVelocity {
  double from_butt_m = 0.0;
  std::vector<double> dc_m_s;                 // rigid-body part at each time [m/s]
  std::vector<double> ac_m_s;                 // vibration part, sum of the modes [m/s]
  std::vector<std::vector<double>> mode_m_s;  // mode_m_s[k][i]: mode k's share [m/s]
};

struct ModeExcitation {
  double frequency_Hz = 0.0;            // damped, w sqrt(1 - z^2) / 2pi
  double phi_at_impact = 0.0;           // phi_k(x_F) [kg^-1/2]
  double energy_after_J = 0.0;          // 1/2 (q'^2 + w^2 q^2) at t = T [J]
  double impulse_limit_energy_J = 0.0;  // 1/2 (J phi_k(x_F))^2 [J], the T -> 0 limit
};

struct ImpactResponse {
  std::vector<double> time_s;
  std::vector<PointVelocity> points;    // in the order asked
  std::vector<ModeExcitation> modes;    // as model.modes
  double impulse_N_s = 0.0;             // 2 F0 T / pi
  double rigid_kinetic_energy_J = 0.0;  // J^2 / (2 M_eff), Eq. (17) for model.rigid_body
  double vibration_energy_J = 0.0;      // sum of energy_after_J
};

// Velocities of `points_from_butt_m` at `time_s` (any order, t < 0 at rest)
// for `pulse` at `impact_from_butt_m`; positive along the force. Every
// position must lie on the implement, times must be finite. Throws
// std::invalid_argument naming the argument.
ImpactResponse impact_response(const ResponseModel& model, double impact_from_butt_m,
                               const HalfSinePulse& pulse,
                               const std::vector<double>& points_from_butt_m,
                               const std::vector<double>& time_s);

// Energy left in the modes per unit impulse squared: kappa = 2 E_vib / J^2
// = sum_k phi_k(x_F)^2 R_k(T) [kg^-1], R_k = 2 E_k / (J phi_k)^2 from the closed
// form at t = T (S(w_k T)^2 for an undamped mode). Linear modes make E_vib
// exactly J^2 kappa / 2 for a pulse of fixed duration.
double vibration_compliance(const ResponseModel& model, double impact_from_butt_m,
                            double duration_s);

// The same per mode: kappa_k = phi_k(x_F)^2 R_k(T) [kg^-1], as model.modes.
std::vector<double> vibration_compliance_per_mode(const ResponseModel& model,
                                                  double impact_from_butt_m, double duration_s);

// ------------------------------------------------------------ derived COR

// The COR at the impact point lowered by the energy the frame keeps as
// vibration. Model (energy bookkeeping of the effective-mass collision):
//  * The ball (m, v1) meets the effective mass M_eff of the implement at the
//    impact point (Cross 2004 Eq. 17); reduced mass mu = m M_eff / (m + M_eff).
//    A collision with COR e delivers J = mu v1 (1 + e) (the impulse of Eq. 15
//    with e_A of Eq. 16) and turns 1/2 mu v1^2 (1 - e^2) of the kinetic energy
//    into something other than ball speed and rigid-body motion.
//  * On a rigid frame that loss is what the ball and strings dissipate,
//    1/2 mu v1^2 (1 - e_r^2) with e_r = cor_rigid; a flexible frame also keeps
//    E_vib = J^2 kappa / 2 (vibration_compliance) as vibration. So
//      1/2 mu v1^2 (1 - e^2) = 1/2 mu v1^2 (1 - e_r^2) + 1/2 mu^2 v1^2 (1 + e)^2 kappa,
//    i.e. e^2 + mu kappa (1 + e)^2 = e_r^2, whose root in [0, e_r] is
//      e = (sqrt(e_r^2 (1 + mu kappa) - mu kappa) - mu kappa) / (1 + mu kappa).
//    F0 depends on e (Eq. 15) and E_vib on F0; for a pulse of given duration
//    the loop closes exactly in this quadratic (no iteration needed).
// Assumptions: the pulse keeps its half-sine shape and duration on the
// flexible frame (the frame's motion does not feed back on the force); the
// loss in ball and strings per unit rigid-frame collision energy is that of
// cor_rigid; the vibration is counted at the end of contact (energy dissipated
// by modal damping during contact is counted as vibration); the modes are
// those of the model (the paper's free implement: the ball leaves before the
// bending wave returns from the hand, Sec. VI).
// Validity: the balance has a root e in [0, e_r] only when mu kappa <= e_r^2.
// Then the vibration energy, 1/2 mu v1^2 (e_r^2 - e^2), is at most what the
// collision loses, 1/2 mu v1^2 (1 - e^2), itself at most the ball's loss of
// kinetic energy, so vibration_share lies in [0, 1]. Beyond it (a long or
// soft frame: mu kappa grows with the implement's compliance) the prescribed
// half-sine would put more energy into the modes than the collision has: the
// real force would soften and lengthen instead, which this model does not
// describe, so derive_cor refuses rather than report energy from nowhere.
struct DerivedCor {
  double cor = 0.0;                          // e
  double cor_rigid = 0.0;                    // e_r
  double apparent_cor = 0.0;                 // e_A, Eq. (16)
  double effective_mass_kg = 0.0;            // M_eff, Eq. (17)
  double reduced_mass_kg = 0.0;              // mu
  double vibration_compliance_per_kg = 0.0;  // kappa
  HalfSinePulse pulse;                       // F0 of Eq. (15) with e_A, the given T
  double impulse_N_s = 0.0;                  // J = m v1 (1 + e_A)
  double collision_energy_J = 0.0;           // 1/2 m v1^2, the ball's incident kinetic energy
  double vibration_energy_J = 0.0;           // J^2 kappa / 2
  double vibration_share = 0.0;              // vibration_energy_J / collision_energy_J
  double rigid_loss_J = 0.0;                 // 1/2 mu v1^2 (1 - e_r^2)
  std::vector<double> mode_energy_J;         // per model.modes
};

// Throws std::invalid_argument for cor_rigid outside [0, 1], a ball mass or
// speed <= 0, T <= 0 or an impact off the implement, and, naming
// "cor_rigid", outside the model's validity (mu kappa > cor_rigid^2, above).
DerivedCor derive_cor(const ResponseModel& model, double impact_from_butt_m, double cor_rigid,
                      const Ball& ball, double duration_s);

// The free fundamental [Hz] in [f_lo_Hz, f_hi_Hz] at which derive_cor gives
// `target_cor`, scaling every EI of the model's frame (with_fundamental);
// std::nullopt when the target is not bracketed. To `abs_tol_Hz`. Where the
// model does not hold (too soft a frame) e is taken as 0, its limit at the
// validity boundary, so a target > 0 is bracketed as before.
std::optional<double> fundamental_for_cor(const ResponseModel& model, double impact_from_butt_m,
                                          double cor_rigid, const Ball& ball, double duration_s,
                                          double target_cor, double f_lo_Hz, double f_hi_Hz,
                                          double abs_tol_Hz = 1e-6);

}  // namespace sweetspot
