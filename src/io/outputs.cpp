#include "io/outputs.hpp"

#include <algorithm>
#include <array>
#include <cmath>

#include "io/format.hpp"
#include "io/json_reader.hpp"

namespace sweetspot::io {
namespace {

constexpr double kCm2PerM2 = 1e4;
// Standard gravity [m/s^2], the g of the customisers' MgR/I.
constexpr double kStandardGravity_m_s2 = 9.80665;

constexpr std::string_view kAxisAtInfinity =
    "at infinity: the impact is through the centre of mass, so the body translates without "
    "rotating";

constexpr std::string_view kNeedsModes =
    "needs the modal model: give the frame's stiffness (frame EI_N_m2, RA or fundamental_free_Hz) "
    "and evaluate with --fidelity modal or auto";

constexpr std::string_view kNoPolarInertia =
    "no polar inertia: give implement/twistweight_kg_cm2 (or a racquet's "
    "implement/headsize_sq_in)";
constexpr std::string_view kNeedsResponse =
    "needs the response model: give the frame's stiffness and evaluate with --fidelity response "
    "(or auto with frame cor_rigid)";

constexpr std::string_view kNeedsCollision =
    "needs the solved collision: give the string tension and the frame's stiffness and evaluate "
    "with --fidelity collision (or auto without frame cor)";

constexpr std::string_view kOnRigidSurface =
    "the ball's own slow test: given for a ball on a rigid surface (support rigid_surface)";

constexpr std::string_view kNeedsStrings =
    "needs a string bed: give strings.tension (or a stringer's ticket: pattern, mains, crosses)";
// lbf per inch in N/m.
constexpr double kLbInPerNM = 0.0254 / kPoundForce_N;

std::optional<double> from_tip(const Evaluation& e, const std::optional<double>& from_butt) {
  if (!from_butt) return std::nullopt;
  return e.length_m - *from_butt;
}

// A number of the modal outputs, absent without them.
template <double ModalOutputs::*Field>
std::optional<double> modal(const Evaluation& e) {
  if (!e.modal) return std::nullopt;
  return (*e.modal).*Field;
}

// A node of the modal outputs, measured from the tip.
template <std::optional<double> ModalOutputs::*Field>
std::optional<double> modal_from_tip(const Evaluation& e) {
  if (!e.modal) return std::nullopt;
  return from_tip(e, (*e.modal).*Field);
}

// A number of the solved collision's record (collision.hpp).
template <double CollisionResult::*Field>
std::optional<double> collision(const Evaluation& e) {
  if (!e.details || !e.details->collision) return std::nullopt;
  return (*e.details->collision).*Field;
}

const std::array kOutputs{
    OutputSpec{"length_m", "m", "length, butt to tip",
               [](const Evaluation& e) -> std::optional<double> { return e.length_m; }, ""},
    OutputSpec{"mass_kg", "kg", "mass with point masses",
               [](const Evaluation& e) -> std::optional<double> { return e.mass_kg; }, ""},
    OutputSpec{"balance_from_butt_m", "m", "balance point (centre of mass) from the butt",
               [](const Evaluation& e) -> std::optional<double> { return e.balance_from_butt_m; },
               ""},
    OutputSpec{"I_cm_kg_m2", "kg m^2", "moment of inertia about the centre of mass, I_0",
               [](const Evaluation& e) -> std::optional<double> { return e.I_cm_kg_m2; }, ""},
    OutputSpec{"swingweight_kg_cm2", "kg cm^2", "inertia about the axis 10 cm from the butt",
               [](const Evaluation& e) -> std::optional<double> {
                 return e.swingweight_kg_m2 * kCm2PerM2;
               },
               ""},
    OutputSpec{
        "recoil_weight_kg_cm2", "kg cm^2", "inertia about the centre of mass",
        [](const Evaluation& e) -> std::optional<double> { return e.I_cm_kg_m2 * kCm2PerM2; }, ""},
    OutputSpec{"impact_from_tip_m", "m", "impact point from the tip",
               [](const Evaluation& e) -> std::optional<double> {
                 return e.length_m - e.impact_from_butt_m;
               },
               ""},
    OutputSpec{"impact_from_com_m", "m", "impact point from the centre of mass, b (Eq. 17)",
               [](const Evaluation& e) -> std::optional<double> { return e.impact_from_com_m; },
               ""},
    OutputSpec{"cor", "", "COR e used at the impact point (given, or derived from cor_rigid)",
               [](const Evaluation& e) -> std::optional<double> { return e.cor; }, ""},
    OutputSpec{
        "impact_duration_s", "s", "impact duration T used (given, or derived from the tension)",
        [](const Evaluation& e) -> std::optional<double> { return e.impact_duration_s; }, ""},
    // The string bed (string_bed.hpp), when the design gives one.
    OutputSpec{"string_bed_tension_N", "N",
               "tension of each main in the bed (the pull less strings.tension_loss; the crosses "
               "in proportion)",
               [](const Evaluation& e) { return e.string_bed_tension_N; }, kNeedsStrings},
    OutputSpec{"string_bed_stiffness_N_m", "N/m",
               "string bed's stiffness at its centre, 2 pi sqrt(N_m N_c) / ln(R / r0) (the "
               "membrane; not an RDC or ERT reading)",
               [](const Evaluation& e) { return e.string_bed_stiffness_N_m; }, kNeedsStrings},
    OutputSpec{"string_bed_stiffness_lb_in", "lb/in", "the same in lb/in",
               [](const Evaluation& e) -> std::optional<double> {
                 if (!e.string_bed_stiffness_N_m) return std::nullopt;
                 return *e.string_bed_stiffness_N_m * kLbInPerNM;
               },
               kNeedsStrings},
    OutputSpec{"string_bed_ring_Hz", "Hz",
               "string bed's ring (its membrane's fundamental, what tap-tone apps hear)",
               [](const Evaluation& e) { return e.string_bed_ring_Hz; }, kNeedsStrings},
    OutputSpec{"effective_mass_kg", "kg", "effective mass at the impact point, M_eff (Eq. 17)",
               [](const Evaluation& e) -> std::optional<double> { return e.effective_mass_kg; },
               ""},
    OutputSpec{"apparent_cor", "", "apparent COR e_A, rebound over incident speed (Eq. 16)",
               [](const Evaluation& e) -> std::optional<double> { return e.apparent_cor; }, ""},
    OutputSpec{"rebound_speed_m_s", "m/s", "ball rebound speed e_A v1",
               [](const Evaluation& e) -> std::optional<double> { return e.rebound_speed_m_s; },
               ""},
    OutputSpec{"impulse_N_s", "N s", "impulse on the implement, m v1 (1 + e_A)",
               [](const Evaluation& e) -> std::optional<double> { return e.impulse_N_s; }, ""},
    OutputSpec{"peak_impact_force_N", "N",
               "peak force between ball and implement (on a racquet's strings), F0 (Eq. 15)",
               [](const Evaluation& e) -> std::optional<double> { return e.peak_impact_force_N; },
               ""},
    OutputSpec{"wrist_force_ratio", "",
               "F_w / F (Eq. 11); > 0 jerks the forearm towards the outgoing ball, < 0 away",
               [](const Evaluation& e) -> std::optional<double> { return e.wrist_force_ratio; },
               ""},
    OutputSpec{"peak_wrist_force_N", "N", "peak shock force on the wrist, |F_w / F| F0",
               [](const Evaluation& e) -> std::optional<double> { return e.peak_wrist_force_N; },
               "", true},
    OutputSpec{"cop_free_from_tip_m", "m",
               "COP of the free implement for an axis through the butt (Eq. 5)",
               [](const Evaluation& e) { return from_tip(e, e.cop_free_from_butt_m); },
               "at infinity: the centre of mass is at the butt"},
    OutputSpec{"cop_hand_from_tip_m", "m", "COP of the hand-held implement (Eq. 13)",
               [](const Evaluation& e) { return from_tip(e, e.cop_hand_from_butt_m); },
               "at infinity: implement and hand have their centre of mass at the wrist"},
    OutputSpec{"rotation_axis_free_from_butt_m", "m",
               "rotation axis of the free implement for this impact (Eq. 5); < 0 beyond the butt",
               [](const Evaluation& e) { return e.rotation_axis_free_from_butt_m; },
               kAxisAtInfinity},
    OutputSpec{"rotation_axis_hand_from_butt_m", "m",
               "rotation axis of the hand-held implement, s = h - A (Eq. 12); < 0 beyond the butt",
               [](const Evaluation& e) { return e.rotation_axis_hand_from_butt_m; },
               "at infinity: implement, hand and forearm translate without rotating"},
    OutputSpec{"fundamental_free_Hz", "Hz", "fundamental bending frequency of the free implement",
               &modal<&ModalOutputs::fundamental_free_Hz>, kNeedsModes, false, true},
    OutputSpec{"node_free_from_tip_m", "m", "node of the free fundamental nearest the tip",
               &modal_from_tip<&ModalOutputs::node_free_from_butt_m>, kNeedsModes, false, true},
    OutputSpec{"fundamental_hand_Hz", "Hz", "damped fundamental of the hand-held implement",
               &modal<&ModalOutputs::fundamental_hand_Hz>, kNeedsModes, false, true},
    OutputSpec{"hand_damping_ratio", "", "damping ratio of the hand-held fundamental",
               &modal<&ModalOutputs::hand_damping_ratio>, kNeedsModes, false, true},
    OutputSpec{"node_hand_from_tip_m", "m", "node of the hand-held fundamental nearest the tip",
               &modal_from_tip<&ModalOutputs::node_hand_from_butt_m>, kNeedsModes, false, true},
    OutputSpec{"cop_node_gap_m", "m",
               "hand-held COP minus node, both from the tip (> 0: the COP is nearer the hand)",
               [](const Evaluation& e) -> std::optional<double> {
                 if (!e.modal || !e.modal->node_hand_from_butt_m || !e.cop_hand_from_butt_m)
                   return std::nullopt;
                 return *e.modal->node_hand_from_butt_m - *e.cop_hand_from_butt_m;
               },
               kNeedsModes, false, true},
    OutputSpec{"vibration_energy_J", "J",
               "energy the impact puts into vibration: the frame's modes after it (and, solved, "
               "the string bed's and what damping took during the contact)",
               [](const Evaluation& e) { return e.vibration_energy_J; }, kNeedsResponse, false,
               true, true},
    OutputSpec{"vibration_share", "", "vibration energy over the ball's incident kinetic energy",
               [](const Evaluation& e) { return e.vibration_share; }, kNeedsResponse, false, true,
               true},
    OutputSpec{"contact_time_s", "s",
               "contact time of the solved collision, first touch to the ball's last separation",
               &collision<&CollisionResult::contact_time_s>, kNeedsCollision, false, true, true},
    OutputSpec{"peak_ball_compression_m", "m",
               "largest compression of the ball in the solved collision: how far its centre "
               "came towards what it hit (one mass: its law's x)",
               &collision<&CollisionResult::peak_ball_compression_m>, kNeedsCollision, false, true,
               true},
    OutputSpec{"static_forward_deformation_m", "m",
               "the ITF's slow test of the ball alone: its deformation loaded to 18 lbf (80 N)",
               [](const Evaluation& e) { return e.static_forward_deformation_m; }, kOnRigidSurface,
               false, true, true},
    OutputSpec{"static_return_deformation_m", "m",
               "the same, unloaded to 18 lbf after 1 in (25.4 mm) of compression",
               [](const Evaluation& e) { return e.static_return_deformation_m; }, kOnRigidSurface,
               false, true, true},
    OutputSpec{"peak_string_deflection_m", "m",
               "largest deflection of the string bed from the frame under the ball in the solved "
               "collision",
               &collision<&CollisionResult::peak_string_deflection_m>, kNeedsCollision, false, true,
               true},
    // The shot off a swinging racquet (swing.hpp; Brody; Cross 1999).
    OutputSpec{"racquet_speed_m_s", "m/s",
               "speed of the implement at the impact point, omega (pivot + from butt): the "
               "design's swing, or the assumed tennis groundstroke",
               [](const Evaluation& e) -> std::optional<double> { return e.racquet_speed_m_s; },
               ""},
    OutputSpec{"shot_speed_m_s", "m/s",
               "outgoing ball speed off the swinging implement, e_A v_in + (1 + e_A) V",
               [](const Evaluation& e) -> std::optional<double> { return e.shot_speed_m_s; }, ""},
    OutputSpec{
        "shot_speed_km_h", "km/h", "the same in km/h",
        [](const Evaluation& e) -> std::optional<double> { return e.shot_speed_m_s * kKmHPerMS; },
        ""},
    OutputSpec{
        "shot_speed_mph", "mph", "the same in mph",
        [](const Evaluation& e) -> std::optional<double> { return e.shot_speed_m_s * kMphPerMS; },
        ""},
    // The customisers' numbers (docs/model.md, "Customisers' numbers").
    OutputSpec{"maneuverability_index_s2", "1/s^2",
               "MgR/I: mass x g x balance over the inertia about the butt (a pendulum hung at the "
               "butt)",
               [](const Evaluation& e) -> std::optional<double> {
                 const double R = e.balance_from_butt_m;
                 return e.mass_kg * kStandardGravity_m_s2 * R / (e.I_cm_kg_m2 + e.mass_kg * R * R);
               },
               ""},
    OutputSpec{"polarization", "",
               "I_cm / (M L^2 / 12): the inertia about the centre of mass over a uniform rod's",
               [](const Evaluation& e) -> std::optional<double> {
                 return e.I_cm_kg_m2 / (e.mass_kg * e.length_m * e.length_m / 12.0);
               },
               ""},
    OutputSpec{"system_mass_kg", "kg", "implement plus hand, M",
               [](const Evaluation& e) -> std::optional<double> { return e.system_mass_kg; }, ""},
    OutputSpec{
        "system_com_from_butt_m", "m", "centre of mass of implement plus hand, h (Eq. 14)",
        [](const Evaluation& e) -> std::optional<double> { return e.system_com_from_butt_m; }, ""},
    OutputSpec{"system_I_cm_kg_m2", "kg m^2", "inertia of implement plus hand about h, I_cm",
               [](const Evaluation& e) -> std::optional<double> { return e.system_I_cm_kg_m2; },
               ""},
    // The second dimension: twist about the long axis (head_geometry.hpp).
    OutputSpec{"twistweight_kg_cm2", "kg cm^2",
               "polar inertia about the long axis with point masses (twistweight): measured, or "
               "estimated from the head's size (about +-15 %)",
               [](const Evaluation& e) -> std::optional<double> {
                 if (!e.polar_inertia_kg_m2) return std::nullopt;
                 return *e.polar_inertia_kg_m2 * kCm2PerM2;
               },
               kNoPolarInertia},
    OutputSpec{"polar_inertia_kg_m2", "kg m^2",
               "I_polar, the twistweight again (in kg m^2 in JSON and CSV)",
               [](const Evaluation& e) { return e.polar_inertia_kg_m2; }, kNoPolarInertia},
    OutputSpec{"impact_off_axis_m", "m",
               "impact point off the long axis, y (> 0 towards 3 o'clock)",
               [](const Evaluation& e) -> std::optional<double> {
                 if (!e.polar_inertia_kg_m2) return std::nullopt;
                 return e.impact_off_axis_m;
               },
               kNoPolarInertia},
    OutputSpec{
        "twist_rate_rad_s", "rad/s",
        "roll rate of the free implement about its long axis after the impact, J y / I_polar",
        [](const Evaluation& e) -> std::optional<double> {
          if (!e.polar_inertia_kg_m2) return std::nullopt;
          return e.twist_rate_rad_s;
        },
        kNoPolarInertia},
    OutputSpec{"peak_twist_torque_N_m", "N m",
               "peak torque about the long axis, F0 |y|: what a grip that lets no roll through "
               "takes",
               [](const Evaluation& e) -> std::optional<double> {
                 if (!e.polar_inertia_kg_m2) return std::nullopt;
                 return e.peak_twist_torque_N_m;
               },
               kNoPolarInertia, true},
};

// On a rig: every output but the player's and the free or hand-held frame's
// modes (the rig's own are the collision's vibration modes). On a rigid
// surface only the ball's: there is no implement.
constexpr std::string_view kPlayerOutputs[] = {"wrist_force_ratio",
                                               "peak_wrist_force_N",
                                               "cop_free_from_tip_m",
                                               "cop_hand_from_tip_m",
                                               "rotation_axis_free_from_butt_m",
                                               "rotation_axis_hand_from_butt_m",
                                               "cop_node_gap_m",
                                               "racquet_speed_m_s",
                                               "shot_speed_m_s",
                                               "shot_speed_km_h",
                                               "shot_speed_mph",
                                               "system_mass_kg",
                                               "system_I_cm_kg_m2",
                                               "twist_rate_rad_s",
                                               "peak_twist_torque_N_m",
                                               "fundamental_hand_Hz",
                                               "hand_damping_ratio",
                                               "node_hand_from_tip_m",
                                               "fundamental_free_Hz",
                                               "node_free_from_tip_m"};
constexpr std::string_view kBallOutputs[] = {"cor",
                                             "impact_duration_s",
                                             "apparent_cor",
                                             "rebound_speed_m_s",
                                             "impulse_N_s",
                                             "peak_impact_force_N",
                                             "vibration_energy_J",
                                             "vibration_share",
                                             "contact_time_s",
                                             "peak_ball_compression_m",
                                             "static_forward_deformation_m",
                                             "static_return_deformation_m",
                                             "effective_mass_kg"};

}  // namespace

std::span<const std::string_view> player_outputs() { return kPlayerOutputs; }
std::span<const std::string_view> ball_outputs() { return kBallOutputs; }

bool given_on_rig(std::string_view name, Support::Kind kind) {
  if (std::ranges::find(kPlayerOutputs, name) != std::end(kPlayerOutputs)) return false;
  if (kind != Support::Kind::kRigidSurface) return true;
  return std::ranges::find(kBallOutputs, name) != std::end(kBallOutputs);
}

std::optional<double> OutputSpec::value(const Evaluation& e) const {
  if (!is_rig(e.support)) [[likely]]
    return compute(e);
  if (!given_on_rig(name, e.support.kind)) return std::nullopt;
  const std::optional<double> v = compute(e);
  if (v && std::isinf(*v)) return std::nullopt;  // the effective mass of a point held still
  return v;
}

std::string_view OutputSpec::absent_because(const Evaluation& e) const {
  if (!is_rig(e.support)) return when_absent;
  if (!given_on_rig(name, e.support.kind)) return kAbsentOnRig;
  if (const std::optional<double> v = compute(e); v && std::isinf(*v)) return kHeldStill;
  return when_absent;
}

std::span<const OutputSpec> output_specs() { return kOutputs; }

const OutputSpec* find_output(std::string_view name) {
  for (const OutputSpec& output : kOutputs) {
    if (output.name == name) return &output;
  }
  return nullptr;
}

bool of_the_string_bed(const OutputSpec& output) {
  return output.name.starts_with("string_bed_") || output.name.starts_with("peak_string_");
}

bool can_be_strung(const Design& design) {
  return design.head || design.strings || !design.implement.profile();
}

}  // namespace sweetspot::io
