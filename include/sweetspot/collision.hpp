#pragma once

// The collision solved, not prescribed: the ball, the string bed and the
// flexible frame integrated together through the contact (issue 12; the
// approach of Cross's flexible-beam analysis, "Flexible beam analysis of the
// effects of string tension and frame stiffness on racket performance",
// Sports Eng. 3, 111-122 (2000), ref. 13 of Cross 2004).
//
// Model, one coordinate per body along the line of the impact (positive along
// the ball's incident velocity; everything at rest but the ball at t = 0):
//  * ball: mass m at y, pressed into the strings by x = y - s > 0 through a
//    contact law F = k x^n + b x^p x' (BallContactLaw), never pulling (F >= 0);
//    or a ball of two masses (BallBody), the law on its front mass m_f and a
//    back mass joined to it by a stiffening spring and a dashpot, x the
//    front's y_f - s (collision/bodies.hpp);
//  * string bed: a mass m_s at s on a spring k_s (the membrane stiffness of
//    string_bed.hpp) and a dashpot c_s to the frame at the impact point;
//  * frame: at the impact point x_F it moves as w = u + sum_k phi_k(x_F) q_k,
//    where u is the rigid-body motion of the effective mass M_eff (Cross 2004
//    Eq. 17: the translation and rotation of the rigid body the string force
//    can excite, one coordinate) and q_k the flexible modes of ResponseModel,
//    q_k'' + 2 z_k w_k q_k' + w_k^2 q_k = phi_k(x_F) F_s.
// Everything but the ball's contact is linear.
//
// Integrator: the implicit midpoint rule with a discrete gradient for the
// ball's elastic energy U(x) = k x^(n+1)/(n+1): per step of length h,
//   F_b = (U(x1) - U(x0)) / (x1 - x0) + b xm^p (x1 - x0)/h,  xm = max(0, (x0 + x1)/2),
// clamped at >= 0, and the linear part at the midpoint. The step conserves
// the total energy exactly up to the work of the dissipative terms, each of
// which is booked per step (ball: F_b dx - dU; strings: c_s h v_rel^2; modal
// damping: 2 z w h q'^2), so the energy ledger closes to round-off for every
// step size; the solution is second-order accurate in h. The linear part is
// solved in closed form for the one unknown F_b, a scalar monotone equation
// solved by safeguarded Newton iteration: O(modes) work per step. The force
// has fractional powers of time where a contact starts and ends (and a kink
// where the damping term clamps it to 0), so the mesh is graded there: from
// the onset t_i = 2 T (i/N)^2 until it reaches the base step T/N, towards the
// force's or the compression's zero like t^2 and geometrically down to 1e-3
// of the base step, and once the force is 0 the step lands on the
// separation. On it the error is c h^2 + O(h^3), and two runs at h and h/2
// are Richardson-extrapolated (CollisionOptions::extrapolate).
// The outputs are taken at the last separation.
// Time step: the contact's estimated duration (the ball's secant stiffness at
// its peak compression in series with the strings, on the reduced mass with
// M_eff) over steps_per_contact, or shorter where a faster motion inside the
// contact binds: the ball's own spring on what it touches first (the string
// bed's mass, or the frame's rigid body and modes) at the compression that
// stops their relative motion, and the bed's mass on its spring, each given
// steps_per_contact / 8 steps per half-period. A stiff ball (1e12 and up for
// n = 1.5) is then resolved like a soft one instead of booking a negative ball
// loss to close the ledger.
// Invariants (checked by DesignCollision::at(), invariants.hpp): every ledger
// term >= 0 and the ledger closing to kInvariantRoundOff of E_in; the impulse
// and the contact time > 0; e_A within the rigid-body bounds for M_eff (e = 0)
// and M_eff + m_s (e = 1); the ball gone for good; |e_A(h) - e_A(h/2)| <=
// kMaxStepError. A collision that breaks one is a ModelRefusal.
// Contacts are followed until the ball has left for good: after a separation
// the integration goes on until the gap exceeds twice the largest
// displacement the implement's vibration energy allows at the impact point
// while the ball recedes from the rigid motion, or max_time_s.

#include <optional>
#include <string>
#include <vector>

#include "sweetspot/ball_contact.hpp"
#include "sweetspot/design.hpp"
#include "sweetspot/impact_response.hpp"

namespace sweetspot {

class ModeCache;  // mode_cache.hpp

// ------------------------------------------------------------ the strings and frame

// The string bed's moving part between ball and frame: its stiffness, the
// mass that moves with the ball, and its loss as a damping ratio
// z_s = c_s / (2 sqrt(k_s m_ball)) (a string bed alone returns e_s^2 =
// exp(-2 pi z_s / sqrt(1 - z_s^2)) of the energy a rigid ball gives it).
struct StringBedDynamics {
  double stiffness_N_m = 0.0;    // k_s [N/m], > 0 (string_bed_stiffness)
  double mass_kg = 0.004;        // m_s [kg], > 0
  double damping_ratio = 0.008;  // z_s, in [0, 1)
};

// One flexible mode as the ball sees it at the impact point.
struct ModeAtImpact {
  double phi = 0.0;            // phi_k(x_F) [kg^-1/2]
  double omega_rad_s = 0.0;    // w_k > 0
  double damping_ratio = 0.0;  // z_k in [0, 1)
};

// The frame at the impact point: the rigid body's effective mass
// (Eq. 17; inverse 0 = immovable) and its flexible modes.
struct FrameAtImpact {
  double inverse_effective_mass_per_kg = 0.0;  // 1 / M_eff, >= 0
  std::vector<ModeAtImpact> modes;
};

// The frame of `model` at `impact_from_butt_m`: M_eff of model.rigid_body
// (Eq. 17) and the first `modes` flexible modes (all when < 0). Throws
// std::invalid_argument for an impact off the implement.
FrameAtImpact frame_at_impact(const ResponseModel& model, double impact_from_butt_m,
                              int modes = -1);

// An immovable, rigid frame.
FrameAtImpact rigid_frame();

struct CollisionOptions {
  // Time step: the estimated contact time (linearised ball and strings on
  // M_eff) over this, in [16, 1e6].
  int steps_per_contact = 64;
  // Richardson extrapolation: run at h and h/2 and report (4 fine - coarse)/3
  // of every smooth output (the midpoint rule's error is c h^2 + O(h^3) on the
  // graded mesh); off: one run at h.
  bool extrapolate = true;
  double max_time_s = 0.05;     // stop following re-contacts after this [s], > 0
  bool record_history = false;  // keep the force history (time, force) per step

  std::string validate() const;
};

// What the collision gives.
struct CollisionResult {
  bool separated = false;       // the ball left for good before max_time_s
  int contacts = 0;             // separate contacts (re-contacts counted)
  double contact_time_s = 0.0;  // first touch to the last separation [s]
  double in_contact_s = 0.0;    // the sum of the contacts' durations [s]
  double peak_force_N = 0.0;    // the largest ball force
  // The most the ball's centre of mass came towards what it touches, y - s:
  // the compression a drop test measures (one mass: the law's x; two masses:
  // the front's x plus m_b/m of the internal compression).
  double peak_ball_compression_m = 0.0;
  double peak_string_deflection_m = 0.0;  // max |s - w|
  double impulse_N_s = 0.0;               // int F_b dt, the ball's loss of momentum
  double ball_velocity_after_m_s = 0.0;   // along the incident direction (< 0: rebounding)
  double frame_velocity_after_m_s = 0.0;  // the rigid-body velocity of the impact point
  double implement_momentum_N_s = 0.0;    // M_eff u' + m_s s' then (at the impact point)
  double apparent_cor = 0.0;              // e_A = -ball_velocity_after / v1
  // Every mode's energy 1/2 (q'^2 + w^2 q^2) when the ball leaves for good [J].
  std::vector<double> mode_energy_J;
  double string_bed_energy_J = 0.0;  // 1/2 m_s s'^2 + 1/2 k_s (s - w)^2 then [J]
  // The energy ledger [J]: ball_in = ball_out + implement_rigid + vibration + ball_loss +
  // strings_loss.
  double ball_in_J = 0.0;
  double ball_out_J = 0.0;
  double implement_rigid_J = 0.0;  // 1/2 M_eff u'^2
  double vibration_J = 0.0;  // modes + string bed + what the modal damping took during the run
  double modal_damping_loss_J = 0.0;  // part of vibration_J
  double ball_loss_J = 0.0;  // the law's loss, and a two-mass ball's internal dashpot and ring
  double strings_loss_J = 0.0;
  double step_s = 0.0;
  int steps = 0;
  // |e_A(h/2) - e_A(h)| of the two extrapolated runs: an upper estimate of the
  // coarse run's step error in the apparent COR (0 with extrapolate off).
  double step_error = 0.0;
  std::vector<double> time_s, force_N;  // when record_history
};

// Solves the ball (mass `ball_mass_kg`, `law`) hitting the string bed at
// `speed_m_s` (> 0) on `frame`. No string bed (std::nullopt): the ball hits
// the frame directly. Throws std::invalid_argument naming the argument.
CollisionResult collide(const FrameAtImpact& frame, const std::optional<StringBedDynamics>& strings,
                        double ball_mass_kg, const BallContactLaw& law, double speed_m_s,
                        const CollisionOptions& options = {});

// ------------------------------------------------------------ the ball alone

// The ITF's drop test: 100 in (2.54 m) onto a rigid surface, v = sqrt(2 g h)
// with g = 9.81 m/s^2.
inline constexpr double kDropTestSpeed_m_s = 7.059376743;

// The ball's COR on a rigid surface at `speed_m_s` (collide() on rigid_frame()).
double rigid_surface_cor(const BallContactLaw& law, double ball_mass_kg,
                         double speed_m_s = kDropTestSpeed_m_s);

// `law` with its loss set so that the ball's COR on a rigid surface at the
// drop test's speed is `cor`, in [0, 1): for the power law its damping b, for
// the hysteretic law its unloading offset (+infinity for cor = 0, a plastic
// ball). Throws FieldError at "ball/cor_on_rigid_surface" when the law cannot
// reach it (the power law's deadest ball at b = kMaxBallDamping; the
// hysteretic law's liveliest at the smallest offset).
BallContactLaw with_rigid_surface_cor(const BallContactLaw& law, double ball_mass_kg, double cor);

// The ITF's slow compression test on the ball at rate 0 (no damping, the
// hysteretic ball relaxed to its wall B_w): loaded to `force_N`, the forward
// deformation; loaded on to `max_compression_m` and unloaded to `force_N`, the
// return deformation; the loop's area, loading work less the work returned
// to 0, which the ball loses in it [J]. The power law has no loop (forward =
// return, area 0). Throws std::invalid_argument if the relaxed ball has no
// stiffness or cannot reach the force.
struct StaticLoop {
  double forward_deformation_m = 0.0;
  double return_deformation_m = 0.0;
  double loop_energy_J = 0.0;
};
StaticLoop static_loop(const BallContactLaw& law, double force_N = kItfStaticForce_N,
                       double max_compression_m = kItfStaticMaxCompression_m);

// ------------------------------------------------------------ on the implement

// The COR at the impact point that Cross (2004) Eq. (16) maps to an apparent
// COR with the ball and effective masses m and M_eff:
//   e = (e_A (M_eff + m) + m) / M_eff.
double cor_from_apparent(double apparent_cor, double ball_mass_kg, double effective_mass_kg);

// The dynamic string bed of `bed` (string_bed_stiffness) with mass and loss.
StringBedDynamics string_bed_dynamics(const StringBed& bed, double mass_kg = kStringBedMass_kg,
                                      double damping_ratio = kStringBedDampingRatio);

// ------------------------------------------------------------ a design's collision

// Flexible modes of the free frame a design's collision uses (the exact
// solver's most; convergence: tests/collision_test.cpp, truncation < 1e-4 in e_A).
inline constexpr int kCollisionModes = 6;

// A design's collision, set up once (the free frame's kCollisionModes modes
// to `rel_tol`, the string bed, the polar inertia) and solved at any impact
// point: what evaluate() at Fidelity::kCollision solves at the design's own.
// An impact y off the long axis also twists the implement: the rigid body's
// effective mass is the rigid model's, 1/M_eff = 1/M + b^2/I + y^2/I_polar
// (rigid_impact.hpp); the flexible modes stay the bending modes (torsional
// modes are not modelled). Nothing is added on the axis, so y = 0 is the
// in-plane collision to the bit.
// The design's support (Design::support) decides the frame: free, the free
// modes and M_eff; hand, the hand-held modes (hand_held_response_model()) and
// M_eff of implement and hand; handle clamped over the hand's grip, the
// clamped modes and no rigid motion; pivoted, the pinned modes and 1/M_eff =
// (x - p)^2 / I_p; head clamped, the strings on an immovable frame; a rigid
// surface, the ball alone on an immovable plate (no strings, no implement).
class DesignCollision {
 public:
  // Validates the design (validate()) and throws std::invalid_argument naming
  // the design's path: a given COR (frame/cor, Design::cor_given), a derived
  // one (frame/cor_rigid), no string tension (strings/tension_N) or no
  // stiffness (frame/EI_N_m2) where the support needs them, an impact off the
  // long axis on a rig that would twist (impact/off_axis_m).
  explicit DesignCollision(const Design& design, double rel_tol = 1e-6);
  // The same, with the free modes from `cache` (mode_cache.hpp).
  DesignCollision(const Design& design, double rel_tol, ModeCache& cache);

  // The frame as the ball sees it at `from_butt_m` on the axis and
  // `off_axis_m` across it. Throws std::invalid_argument (impact/off_axis_m)
  // for an off-axis impact without a polar inertia, or for an impact off the
  // implement.
  FrameAtImpact frame_at(double from_butt_m, double off_axis_m) const;

  // The collision there. Throws as frame_at(), or ModelRefusal (invariants.hpp,
  // naming collision_suspect()) when the ball has not left for good within
  // options.max_time_s, the step does not resolve the contact (step_error >
  // kMaxStepError), the contact time is outside [kMinDuration_s,
  // kMaxDuration_s], or the result breaks an invariant above.
  CollisionResult at(double from_butt_m, double off_axis_m,
                     const CollisionOptions& options = {}) const;
  // The same with the ball arriving at `speed_m_s` (> 0) instead of the
  // design's ball.speed_m_s: a swung racquet meets the ball at a speed that
  // moves with the impact point (meeting_at(), evaluate.hpp). A refusal names
  // ball/speed_m_s with this speed as the speed's value.
  CollisionResult at_speed(double from_butt_m, double off_axis_m, double speed_m_s,
                           const CollisionOptions& options = {}) const;

  const ResponseModel& model() const { return model_; }
  // The ball's law as solved (ball.cor_on_rigid_surface applied).
  const BallContactLaw& ball_law() const { return design_.ball_contact; }

 private:
  void init(double rel_tol, ModeCache& cache);
  Design design_;
  ResponseModel model_;                   // no modes for an immovable frame
  bool immovable_ = false;                // head clamped or a rigid surface: rigid_frame()
  std::optional<StringBedDynamics> bed_;  // none on a rigid surface
  std::optional<double> polar_inertia_kg_m2_;
};

}  // namespace sweetspot
