#pragma once

// Every quantity of the rigid-body model of Cross (2004) for one design.

#include <array>
#include <optional>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "sweetspot/collision.hpp"
#include "sweetspot/design.hpp"
#include "sweetspot/frame_modes.hpp"
#include "sweetspot/invariants.hpp"
#include "sweetspot/rigid_impact.hpp"
#include "sweetspot/swing.hpp"

namespace sweetspot {

class ModeCache;  // mode_cache.hpp

// The model that answers (the invariants of each are listed below).
enum class Fidelity { kRigid, kModal, kResponse, kCollision };

struct Evaluation {
  // The model that gave these numbers: every field below that the fidelity
  // computes is set, the others are absent.
  Fidelity fidelity = Fidelity::kRigid;

  // The implement (with its point masses), Section III.
  double length_m = 0.0;
  double mass_kg = 0.0;
  double balance_from_butt_m = 0.0;
  double I_cm_kg_m2 = 0.0;         // recoil weight, in SI
  double swingweight_kg_m2 = 0.0;  // about the axis 10 cm from the butt
  double impact_from_butt_m = 0.0;
  double impact_from_com_m = 0.0;  // b of Eq. (17)
  // COP of the free implement for an axis through the butt (Eq. 5).
  std::optional<double> cop_free_from_butt_m;
  // Rotation axis of the free implement for this impact (Eq. 5).
  std::optional<double> rotation_axis_free_from_butt_m;

  // The ball on the strings, Section VI.
  double effective_mass_kg = 0.0;    // Eq. (17)
  double apparent_cor = 0.0;         // Eq. (16)
  double rebound_speed_m_s = 0.0;    // e_A v1, away from the implement when > 0
  double impulse_N_s = 0.0;          // m v1 (1 + e_A)
  double peak_impact_force_N = 0.0;  // Eq. (15)

  // Implement and hand, Section V.
  double system_mass_kg = 0.0;
  double system_com_from_butt_m = 0.0;  // h
  double system_I_cm_kg_m2 = 0.0;
  std::optional<double> cop_hand_from_butt_m;            // Eq. (13)
  std::optional<double> rotation_axis_hand_from_butt_m;  // s = h - A, Eq. (12)
  double wrist_force_ratio = 0.0;                        // F_w / F, Eq. (11)
  double peak_wrist_force_N = 0.0;                       // |F_w / F| F0

  // The second dimension (head_geometry.hpp): the impact's distance off the long
  // axis, the polar inertia about that axis (frame plus point masses; absent when
  // neither a twistweight nor a head is given), and what the twist does.
  double impact_off_axis_m = 0.0;
  std::optional<double> polar_inertia_kg_m2;
  bool polar_inertia_estimated = false;  // from the head's size, not measured
  // The handle's roll rate about the long axis just after the impact,
  // J y / I_polar [rad/s] (free implement, as Eq. 17), signed like y; 0 on the axis.
  double twist_rate_rad_s = 0.0;
  // The peak torque of the impact about the long axis, F0 |y| [N m]: what the
  // hand must supply to stop the handle turning in it. The paper's hand is a
  // point mass on the axis, so its model passes no torque about the long axis to
  // the forearm; this is the upper bound, reached by a grip that lets no roll
  // through (see docs/model.md, "Twist").
  double peak_twist_torque_N_m = 0.0;

  // The shot off a swinging racquet (swing.hpp): the swing used (the design's,
  // scaled to its swingweight when asked, or kTypicalGroundstroke when the
  // design gives none: swing_assumed), the racquet's speed V at the impact
  // point, the incoming ball's speed v_in (ball.speed_m_s) and the outgoing
  // ball's, e_A v_in + (1 + e_A) V.
  Swing swing = kTypicalGroundstroke;
  bool swing_assumed = true;
  double racquet_speed_m_s = 0.0;
  double incoming_speed_m_s = 0.0;
  double shot_speed_m_s = 0.0;
  // Where along the string bed the shot is fastest (power_point_on_axis() in
  // the studies, set by the commands that answer one design): from the butt
  // [m] and the shot speed there [m/s]; absent when not searched.
  std::optional<double> power_point_from_butt_m;
  std::optional<double> power_point_shot_speed_m_s;

  // The flexible frame, when evaluated with Fidelity::kModal or kResponse.
  std::optional<ModalOutputs> modal;

  // What the evaluation used: given, or derived (the COR from cor_rigid and the
  // frame's vibration, the duration from the string tension).
  double cor = 0.0;
  bool cor_derived = false;
  double impact_duration_s = 0.0;
  bool impact_duration_derived = false;
  // The string bed, when the design gives one (string_bed.hpp): the mains'
  // tension in the bed [N], the bed's stiffness [N/m] and its ring [Hz].
  std::optional<double> string_bed_tension_N;
  std::optional<double> string_bed_stiffness_N_m;
  std::optional<double> string_bed_ring_Hz;
  // Energy the frame keeps as vibration after the impact (free implement),
  // Fidelity::kResponse only [J], and its share of the ball's kinetic energy.
  std::optional<double> vibration_energy_J;
  std::optional<double> vibration_share;
  // What only the modal and response models add beyond numbers; absent for the
  // rigid model, so that a rigid Evaluation copies as plain data.
  struct Details {
    // Per mode of the free frame (response): damped frequency [Hz] and the energy it keeps [J].
    std::vector<std::pair<double, double>> vibration_modes;
    // Fidelity::kCollision: the solved collision (force history, energy ledger).
    std::optional<CollisionResult> collision;
  };
  std::optional<Details> details;
  // What held the implement (the design's): on a rig (is_rig()) nothing of
  // the player is computed (the hand, the forearm, the swing, the centres of
  // percussion), an immovable impact point has an infinite effective mass,
  // and a rigid surface has no implement; the outputs say so (absent).
  Support support{};
  // A ball on a rigid surface (support rigid_surface): the ITF's slow test of
  // the same ball, its forward and return deformation at 18 lbf
  // (static_loop(), collision.hpp); none elsewhere.
  std::optional<double> static_forward_deformation_m, static_return_deformation_m;
};

// How much model an evaluation uses: the rigid body of the paper alone; also
// the vibration modes of the flexible frame (which need its stiffness); or
// also the frame's response to the ball (vibration energy, a derived COR).
// Above them, the collision solved as a dynamic problem (collision.hpp): the
// COR, the contact time, the peak force and the vibration come out of it.
//
// What each guarantees (checked on every evaluation by check_invariants(),
// invariants.hpp, to kInvariantRoundOff; an evaluation that breaks one is a
// ModelRefusal, never an answer), with m the ball's mass, v1 its speed,
// E_in = m v1^2 / 2, M_eff Eq. (17) (with the twist, rigid_impact.hpp):
//  * every fidelity: every output finite; 0 <= e <= 1; Eq. (16)'s bounds
//    -m / (M_eff + m) <= e_A <= e (e = 0 and the given or derived e; e_A < 0 is
//    right near the rim, where M_eff < m / e); the impulse J, the contact time
//    T and the peak force F0 > 0; the ball's energy out, E_in e_A^2, <= E_in;
//    the rigid body's J^2 / (2 M_eff) <= what the ball lost.
//  * kRigid: the above, which Eqs. (15)-(17) satisfy exactly for inputs in
//    validate()'s ranges. Valid while the implement is rigid for the impact
//    (its fundamental above ~1.5 / T, Sec. III) and the pulse a half-sine.
//  * kModal: the rigid model's answer (the modes add outputs, not impact
//    numbers). Valid for a slender beam (Euler-Bernoulli; Timoshenko with a
//    cross-section) whose modes are linear.
//  * kResponse: also 0 <= every mode's energy, and the vibration <= what the
//    ball lost. The prescribed half-sine stops being valid where the frame
//    would keep more than the collision loses (derive_cor refuses: a long or
//    soft frame) and for a given COR on a frame that compliant (refused).
//  * kCollision: also (collision.hpp) the derived e = Eq. (16) inverted within
//    [0, 1]; e_A <= (M' - m)/(M' + m), M' = M_eff + m_s (an elastic collision
//    with the frame and its string bed); every ledger term and mode energy >= 0,
//    the ledger closing; the ball gone for good within max_time_s; the step
//    error of e_A <= kMaxStepError. Valid over the ranges of design.hpp
//    (tension, string bed mass, head) and ball_contact.hpp, for an impact on
//    the head, while the bed's deflection stays small against the head.

// Every name a fidelity is asked by: the four levels and "auto" (the
// cheapest that answers the design, needed_fidelity).
inline constexpr std::array<std::string_view, 5> kFidelityNames{"rigid", "modal", "response",
                                                                "collision", "auto"};

// "rigid", "modal", "response" or "collision".
std::string_view to_string(Fidelity fidelity);

// The level `name` asks for; std::nullopt for "auto". Throws
// std::invalid_argument naming the accepted names for any other.
std::optional<Fidelity> parse_fidelity(std::string_view name);

// The level to evaluate `design` at when `name` is asked ("auto" resolves to
// needed_fidelity(design)). Throws like parse_fidelity.
Fidelity resolve_fidelity(std::string_view name, const Design& design);

// The level an evaluation was made at (its own record of it).
inline Fidelity fidelity_of(const Evaluation& evaluation) { return evaluation.fidelity; }

// The cheapest fidelity that answers everything the design asks: kCollision
// when a string tension and the frame's stiffness are given and the COR is
// not (neither given nor cor_rigid), kResponse when the COR is to be derived
// from cor_rigid, kModal when the stiffness is given, else kRigid.
Fidelity needed_fidelity(const Design& design);

// How an evaluation is made; none of these changes a number it gives.
struct EvaluationOptions {
  // The hand-held modes' frequencies to this relative error (kModal and above).
  double rel_tol = 1e-6;
  // The frame's modes kept between calls (mode_cache.hpp): a catalogue's rows
  // or a study's points that change only the impact, the ball or the strings
  // then solve no modes. Null: the modes are solved for this call alone.
  ModeCache* modes = nullptr;
  // The design was accepted by validate() and not changed since (a sweep's
  // point after its numbers were set and checked): the rigid model with a
  // given COR and duration does not validate it a second time.
  bool validated = false;
};

// The one front door: every quantity of the model at `fidelity` for a valid
// design (validate() is called and throws std::invalid_argument, a FieldError
// naming the design's path, the same way).
//  * kRigid: Eqs. (1)-(17). A string tension sets the duration; a COR to be
//    derived (cor_rigid) needs kResponse and throws here.
//  * kModal: also the frame's modes, free and hand-held (the hand-held ones
//    to options.rel_tol, the frequency's relative error).
//  * kResponse: also the frame's response to the prescribed pulse: the
//    vibration energy per mode and, with cor_rigid, the derived COR.
//  * kCollision: the collision solved (collision.hpp) with the design's ball
//    law and string bed on the free frame's modes: the COR is derived (Eq. 16
//    inverted with M_eff), the duration is the solved contact time, the peak
//    force, the impulse and the vibration energy are the solved ones, and the
//    peak wrist force is Eq. (11)'s ratio times the solved peak force; the
//    modal outputs as kModal. It needs a string tension and the frame's
//    stiffness, and refuses cor_rigid.
// A design whose COR is to be derived (cor_rigid) needs kResponse: anything
// else throws naming "frame/cor_rigid". An answer that breaks its fidelity's
// invariants (above) is a ModelRefusal. The loop paths that skip parts of
// this for many evaluations of one design are in kernels.hpp.
Evaluation evaluate(const Design& design, Fidelity fidelity = Fidelity::kRigid,
                    const EvaluationOptions& options = {});

// Where a swung racquet (Design::swing) meets the ball: the swing scaled to
// the design's swingweight, the racquet's speed V there and the speed the two
// meet at, v_in + V, at which every number of the impact is solved (the
// collision in the frame moving with the impact point, swing.hpp).
struct Meeting {
  Swing swing;
  double racquet_speed_m_s = 0.0;  // V at the impact point [m/s]
  double speed_m_s = 0.0;          // v_in + V [m/s]
};

// The meeting of a design with a swing at `from_butt_m` from the butt.
// Throws FieldError naming "swing/angular_speed_rad_s" when they meet below
// the model's least speed (kMinSpeed_m_s).
Meeting meeting_at(const Design& design, double from_butt_m);

// A refusal of the impact solved at `meeting`'s speed, said of the design: a
// refusal blaming the ball's speed (which the design did not give, the
// meeting did) is rethrown naming the swing, with the speeds that met; any
// other is rethrown as it is. Call it from the handler that caught `refusal`.
[[noreturn]] void rethrow_at_meeting(const ModelRefusal& refusal, const Design& design,
                                     const Meeting& meeting);

// Throws FieldError naming "support" when the design is on a rig (is_rig()),
// which only the solved collision answers: `what` names what was asked (the
// rigid model, a sweep, ...). Every path that answers a racquet in play
// without evaluate() calls it first.
void require_player(const Design& design, std::string_view what);

}  // namespace sweetspot
