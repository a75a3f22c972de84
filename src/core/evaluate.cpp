#include "sweetspot/evaluate.hpp"

#include <cmath>
#include <stdexcept>
#include <string>

#include "core/check.hpp"
#include "core/collision_evaluation.hpp"
#include "sweetspot/errors.hpp"
#include "sweetspot/impact_response.hpp"
#include "sweetspot/invariants.hpp"
#include "sweetspot/mode_cache.hpp"
#include "sweetspot/rigid_impact.hpp"

namespace sweetspot {
namespace {

// validate() bounds every input, so this is a backstop: never hand out inf or
// NaN. Whether these numbers of an evaluation are all finite.
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

// The rigid evaluation of a validated design whose COR and duration are settled.
Evaluation evaluate_settled_valid(const Design& design) {
  Evaluation e = evaluate_unchecked(design);
  if (!all_finite(e.mass_kg, e.I_cm_kg_m2, e.swingweight_kg_m2, e.effective_mass_kg, e.apparent_cor,
                  e.impulse_N_s, e.peak_impact_force_N, e.system_I_cm_kg_m2, e.wrist_force_ratio,
                  e.peak_wrist_force_N)) {
    throw FieldError("implement",
                     "the inputs are outside the range the model can represent "
                     "(a result is not finite)");
  }
  check_invariants(e, design);
  return e;
}

// The rigid evaluation of a design whose COR and duration are settled.
Evaluation evaluate_settled(const Design& design) {
  validate(design);
  return evaluate_settled_valid(design);
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

}  // namespace

Evaluation evaluate(const Design& design) { return evaluate(design, Fidelity::kRigid); }

Evaluation evaluate_validated(const Design& design, Fidelity fidelity, double rel_tol) {
  ModeCache cache;
  return evaluate_validated(design, fidelity, rel_tol, cache);
}

Evaluation evaluate_validated(const Design& design, Fidelity fidelity, double rel_tol,
                              ModeCache& cache) {
  if (fidelity == Fidelity::kRigid && !design.cor_rigid && !design.strings)
    return evaluate_settled_valid(design);
  return evaluate(design, fidelity, rel_tol, cache);
}

Fidelity needed_fidelity(const Design& design) {
  if (design.strings && !design.cor_given && !design.cor_rigid && has_stiffness(design))
    return Fidelity::kCollision;
  if (design.cor_rigid) return Fidelity::kResponse;
  return has_stiffness(design) ? Fidelity::kModal : Fidelity::kRigid;
}

Evaluation evaluate(const Design& design, Fidelity fidelity, double rel_tol) {
  ModeCache cache;
  return evaluate(design, fidelity, rel_tol, cache);
}

Evaluation evaluate(const Design& design, Fidelity fidelity, double rel_tol, ModeCache& cache) {
  if (fidelity == Fidelity::kCollision) return evaluate_collision(design, rel_tol, cache);
  // The rigid model with a given COR and duration (a sweep's or a catalogue's
  // every point): nothing to settle, so neither a copy of the design nor a
  // second validation; the same checks, in the same order, and the same numbers.
  if (fidelity == Fidelity::kRigid && !design.cor_rigid && !design.strings)
    return evaluate_settled(design);
  if (design.cor_rigid && fidelity != Fidelity::kResponse) {
    throw FieldError("frame/cor_rigid",
                     "a COR derived from the frame's vibration needs the response model "
                     "(fidelity response or auto)");
  }
  Design resolved = design;
  validate(resolved);
  const bool duration_derived = design.strings.has_value();
  resolved.impact_duration_s = settled_duration(design);
  // Response: the energy each mode keeps, 1/2 J^2 kappa_k, with J from the
  // derived COR or, for a given COR, from the rigid model.
  std::vector<std::pair<double, double>> mode_energies;  // frequency [Hz], energy [J]
  std::optional<double> vibration_energy;
  if (fidelity == Fidelity::kResponse) {
    const ResponseModel& model = cache.response_model(resolved, ResponseOptions{});
    std::vector<double> kappa;
    if (design.cor_rigid) {
      try {
        const DerivedCor derived = derive_cor(model, resolved.impact_from_butt_m, *design.cor_rigid,
                                              resolved.ball, resolved.impact_duration_s);
        resolved.cor = derived.cor;
      } catch (const std::invalid_argument& error) {
        rethrow_under("frame/", error);
      }
    }
    kappa = vibration_compliance_per_mode(model, resolved.impact_from_butt_m,
                                          resolved.impact_duration_s);
    const Evaluation rigid = evaluate_unchecked(resolved);
    const double J = rigid.impulse_N_s;
    vibration_energy = 0.0;
    for (std::size_t k = 0; k < kappa.size(); ++k) {
      mode_energies.emplace_back(model.modes[k].mode.frequency_Hz, 0.5 * J * J * kappa[k]);
      *vibration_energy += mode_energies.back().second;
    }
    // Energy ledger: the frame cannot keep more than the ball loses. A derived
    // COR satisfies it by construction (derive_cor refuses otherwise); a given
    // COR with a frame this compliant contradicts the prescribed pulse.
    const double v1 = resolved.ball.speed_m_s, eA = rigid.apparent_cor;
    const double ball_loss_J = 0.5 * resolved.ball.mass_kg * v1 * v1 * (1.0 - eA * eA);
    if (!(*vibration_energy <= ball_loss_J * (1.0 + 1e-12))) {
      throw FieldError("frame/cor",
                       "with a COR of " + detail::format_number(resolved.cor) +
                           " the frame would keep " +
                           detail::format_significant(*vibration_energy) +
                           " J as vibration, more than the ball loses (" +
                           detail::format_significant(ball_loss_J) +
                           " J); the prescribed-pulse model does not hold for this implement");
    }
  }
  Evaluation e = evaluate_settled(resolved);
  e.fidelity = fidelity;
  e.impact_duration_derived = duration_derived;
  if (fidelity != Fidelity::kRigid) e.modal = cache.modal_outputs(resolved, rel_tol);
  if (e.modal) {
    // Cross (2004) Sec. III: a half-sine of duration T excites modes up to about 1.5/T.
    const double limit_Hz = 1.5 / resolved.impact_duration_s;
    const double f1 = e.modal->fundamental_free_Hz;
    if (f1 > limit_Hz) {
      const double x = 2.0 * f1 * resolved.impact_duration_s;
      if (!e.details) e.details.emplace();
      e.details->fidelity_note =
          "the free fundamental (" + std::to_string(static_cast<int>(std::lround(f1))) +
          " Hz) is above 1.5/T = " + std::to_string(static_cast<int>(std::lround(limit_Hz))) +
          " Hz: the impact barely excites the frame (every mode keeps at most " +
          std::to_string(1.0 / ((x * x - 1) * (x * x - 1))) +
          " of its impulse-limit energy), so the rigid model answers this design";
    }
  }
  if (vibration_energy) {
    if (!e.details) e.details.emplace();
    e.details->vibration_modes = std::move(mode_energies);
    e.cor_derived = design.cor_rigid.has_value();
    e.vibration_energy_J = *vibration_energy;
    const double v1 = resolved.ball.speed_m_s;
    e.vibration_share = *vibration_energy / (0.5 * resolved.ball.mass_kg * v1 * v1);
  }
  check_invariants(e, resolved);
  return e;
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

std::string_view to_string(Fidelity fidelity) {
  switch (fidelity) {
    case Fidelity::kRigid:
      return "rigid";
    case Fidelity::kModal:
      return "modal";
    case Fidelity::kResponse:
      return "response";
    case Fidelity::kCollision:
      return "collision";
  }
  return "rigid";
}

std::optional<Fidelity> parse_fidelity(std::string_view name) {
  for (const Fidelity f :
       {Fidelity::kRigid, Fidelity::kModal, Fidelity::kResponse, Fidelity::kCollision}) {
    if (name == to_string(f)) return f;
  }
  if (name == "auto") return std::nullopt;
  throw std::invalid_argument(
      "expected \"rigid\", \"modal\", \"response\", \"collision\" or \"auto\", got \"" +
      std::string(name) + "\"");
}

Fidelity resolve_fidelity(std::string_view name, const Design& design) {
  return parse_fidelity(name).value_or(needed_fidelity(design));
}

Fidelity fidelity_of(const Evaluation& evaluation) { return evaluation.fidelity; }

}  // namespace sweetspot
