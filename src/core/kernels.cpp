#include "sweetspot/kernels.hpp"

#include <cmath>

#include "core/check.hpp"
#include "core/kernels_detail.hpp"
#include "sweetspot/errors.hpp"
#include "sweetspot/head_geometry.hpp"
#include "sweetspot/invariants.hpp"

namespace sweetspot {

bool all_finite(double mass_kg, double I_cm_kg_m2, double swingweight_kg_m2,
                double effective_mass_kg, double apparent_cor, double impulse_N_s,
                double peak_impact_force_N, double system_I_cm_kg_m2, double wrist_force_ratio,
                double peak_wrist_force_N) {
  bool finite = true;
  for (const double value :
       {mass_kg, I_cm_kg_m2, swingweight_kg_m2, effective_mass_kg, apparent_cor, impulse_N_s,
        peak_impact_force_N, system_I_cm_kg_m2, wrist_force_ratio, peak_wrist_force_N}) {
    finite = finite && std::isfinite(value);
  }
  return finite;
}

// The impact duration: given, or derived from the string tension. The
// duration depends on M_eff only (Eq. 17), not on the COR.
double settled_duration(const Design& design) {
  if (!design.strings) return design.impact_duration_s;
  const double duration_s =
      tension_impact_duration(
          *design.strings, design.ball.mass_kg,
          effective_mass(design.implement.mass_properties(), design.impact_from_butt_m,
                         design.impact_off_axis_m, polar_inertia_kg_m2(design).value_or(0.0)))
          .duration_s;
  // Out of range, the tension is to blame: the duration is not the user's.
  if (!(duration_s >= kMinDuration_s && duration_s <= kMaxDuration_s)) {
    throw FieldError("strings/tension_N", "" + detail::format_number(design.strings->tension_N) +
                                              " N gives an impact duration of " +
                                              detail::format_number(duration_s) + " s, outside [" +
                                              detail::format_number(kMinDuration_s) + ", " +
                                              detail::format_number(kMaxDuration_s) + "] s");
  }
  return duration_s;
}

namespace {

// The parts of the rigid evaluation that do not depend on the impact point.
Evaluation design_part(const Design& d, const MassProperties& body, const MassProperties& system) {
  Evaluation e;
  e.cor = d.cor;
  e.impact_duration_s = d.impact_duration_s;
  e.length_m = d.implement.length_m();
  e.mass_kg = body.mass_kg;
  e.balance_from_butt_m = body.com_from_butt_m;
  e.I_cm_kg_m2 = body.I_cm_kg_m2;
  e.swingweight_kg_m2 = swingweight_kg_m2(body);
  e.cop_free_from_butt_m = free_conjugate_from_butt(body, 0.0);
  e.system_mass_kg = system.mass_kg;
  e.system_com_from_butt_m = system.com_from_butt_m;
  e.system_I_cm_kg_m2 = system.I_cm_kg_m2;
  e.cop_hand_from_butt_m = hand_held_cop_from_butt(system);
  e.polar_inertia_kg_m2 = polar_inertia_kg_m2(d);
  e.polar_inertia_estimated = polar_inertia_estimated(d);
  return e;
}

// The design's numbers as the rigid model reads them, unchecked.
RigidCase case_of(const Design& d, double impact_duration_s, double twist_per_kg) {
  return RigidCase{d.implement.mass_properties(),
                   PointMass{d.hand.center_from_butt_m, d.hand.mass_kg},
                   d.forearm_equivalent_mass_kg,
                   d.ball.mass_kg,
                   d.ball.speed_m_s,
                   d.cor,
                   impact_duration_s,
                   d.impact_from_butt_m,
                   twist_per_kg};
}

// y^2 / I_polar for an impact y off the axis; names the input when the polar
// inertia is unknown.
double twist_per_kg(const std::optional<double>& polar_inertia_kg_m2, double off_axis_m) {
  if (off_axis_m != 0.0 && !polar_inertia_kg_m2) {
    throw FieldError("impact/off_axis_m",
                     "an impact off the long axis needs the polar inertia "
                     "(implement/twistweight_kg_cm2 or implement/headsize_sq_in), got " +
                         detail::format_number(off_axis_m) + " m");
  }
  return impact_twist_per_kg(off_axis_m, polar_inertia_kg_m2.value_or(0.0));
}

// What rigid_outcome() gives: Eqs. (11), (15)-(17) and the rebound speed.
void outcome_part(const Design& d, const RigidOutcome& o, Evaluation& e) {
  e.effective_mass_kg = o.effective_mass_kg;
  e.apparent_cor = o.apparent_cor;
  e.rebound_speed_m_s = o.apparent_cor * d.ball.speed_m_s;
  e.impulse_N_s = o.impulse_N_s;
  e.peak_impact_force_N = o.peak_impact_force_N;
  e.wrist_force_ratio = o.wrist_force_ratio;
  e.peak_wrist_force_N = o.peak_wrist_force_N;
}

// The parts that do: Eqs. (5), (11), (12), (15)-(17) at x: rigid_outcome()
// and the rotation axes.
void impact_part(const Design& d, const MassProperties& body, const MassProperties& system,
                 double x, double y, Evaluation& e) {
  RigidCase c = case_of(d, d.impact_duration_s, twist_per_kg(e.polar_inertia_kg_m2, y));
  c.impact_from_butt_m = x;
  const RigidOutcome o = rigid_outcome(c, system);
  e.impact_from_butt_m = x;
  e.impact_from_com_m = x - body.com_from_butt_m;
  e.rotation_axis_free_from_butt_m = free_conjugate_from_butt(body, x);
  outcome_part(d, o, e);
  e.rotation_axis_hand_from_butt_m =
      hand_held_rotation_axis_from_butt(system, d.forearm_equivalent_mass_kg, x);
  e.impact_off_axis_m = y;
  if (y != 0.0) {
    e.twist_rate_rad_s = o.impulse_N_s * y / *e.polar_inertia_kg_m2;
    e.peak_twist_torque_N_m = o.peak_impact_force_N * std::abs(y);
  } else {
    e.twist_rate_rad_s = 0.0;
    e.peak_twist_torque_N_m = 0.0;
  }
}

}  // namespace

Evaluation evaluate_unchecked(const Design& d) {
  const MassProperties& body = d.implement.mass_properties();
  const MassProperties system = hand_held_system(d);
  Evaluation e = design_part(d, body, system);
  impact_part(d, body, system, d.impact_from_butt_m, d.impact_off_axis_m, e);
  return e;
}

bool evaluate_rigid_outcome(const Design& d, Evaluation& e) {
  if (d.cor_rigid || d.strings || d.impact_off_axis_m != 0.0) return false;
  const MassProperties& body = d.implement.mass_properties();
  const MassProperties system = hand_held_system(d);
  // The case impact_part() builds: on the axis, the twist is 0 whatever the polar inertia.
  const RigidOutcome o = rigid_outcome(case_of(d, d.impact_duration_s, 0.0), system);
  if (!all_finite(body.mass_kg, body.I_cm_kg_m2, swingweight_kg_m2(body), o.effective_mass_kg,
                  o.apparent_cor, o.impulse_N_s, o.peak_impact_force_N, system.I_cm_kg_m2,
                  o.wrist_force_ratio, o.peak_wrist_force_N)) {
    return false;
  }
  outcome_part(d, o, e);
  return true;
}

RigidCase rigid_case(const Design& design) {
  if (design.cor_rigid) {
    throw FieldError("frame/cor_rigid",
                     "a COR derived from the frame's vibration needs the response model, not a "
                     "rigid case");
  }
  validate(design);
  return case_of(design, settled_duration(design),
                 twist_per_kg(polar_inertia_kg_m2(design), design.impact_off_axis_m));
}

ImpactSweep::ImpactSweep(const Design& design)
    : design_(design), system_(hand_held_system(design)) {
  if (design.cor_rigid || design.strings) {
    throw FieldError("frame/cor_rigid",
                     "ImpactSweep evaluates the rigid model with a given COR and duration");
  }
  validate(design_);
  base_ = design_part(design_, design_.implement.mass_properties(), system_);
}

Evaluation ImpactSweep::at(double impact_from_butt_m) const {
  return at(impact_from_butt_m, design_.impact_off_axis_m);
}

Evaluation ImpactSweep::at(double impact_from_butt_m, double off_axis_m) const {
  Evaluation e = base_;
  impact_part(design_, design_.implement.mass_properties(), system_, impact_from_butt_m, off_axis_m,
              e);
  check_invariants(e, design_);
  return e;
}

}  // namespace sweetspot
