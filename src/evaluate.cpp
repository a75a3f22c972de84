#include "sweetspot/evaluate.hpp"

#include <cmath>
#include <stdexcept>

#include "sweetspot/rigid_impact.hpp"

namespace sweetspot {

Evaluation evaluate(const Design& design) {
  validate(design);
  Evaluation e = evaluate_unchecked(design);
  // validate() bounds every input, so this is a backstop: never hand out inf or NaN.
  for (const double value : {e.mass_kg, e.I_cm_kg_m2, e.swingweight_kg_m2, e.effective_mass_kg,
                             e.apparent_cor, e.impulse_N_s, e.peak_impact_force_N,
                             e.system_I_cm_kg_m2, e.wrist_force_ratio, e.peak_wrist_force_N}) {
    if (!std::isfinite(value)) {
      throw std::invalid_argument("implement: the inputs are outside the range the model can represent "
                                  "(a result is not finite)");
    }
  }
  return e;
}

Evaluation evaluate(const Design& design, Fidelity fidelity, double rel_tol) {
  Evaluation e = evaluate(design);
  if (fidelity == Fidelity::kModal) e.modal = evaluate_modes(design, rel_tol);
  return e;
}

Evaluation evaluate_unchecked(const Design& d) {
  const MassProperties& body = d.implement.mass_properties();
  const double x = d.impact_from_butt_m;
  Evaluation e;
  e.length_m = d.implement.length_m();
  e.mass_kg = body.mass_kg;
  e.balance_from_butt_m = body.com_from_butt_m;
  e.I_cm_kg_m2 = body.I_cm_kg_m2;
  e.swingweight_kg_m2 = swingweight_kg_m2(body);
  e.impact_from_butt_m = x;
  e.impact_from_com_m = x - body.com_from_butt_m;
  e.cop_free_from_butt_m = free_conjugate_from_butt(body, 0.0);
  e.rotation_axis_free_from_butt_m = free_conjugate_from_butt(body, x);

  e.effective_mass_kg = effective_mass(body, x);
  e.apparent_cor = apparent_cor(d.cor, e.effective_mass_kg, d.ball.mass_kg);
  e.rebound_speed_m_s = e.apparent_cor * d.ball.speed_m_s;
  e.impulse_N_s = d.ball.mass_kg * (1.0 + e.apparent_cor) * d.ball.speed_m_s;
  e.peak_impact_force_N =
      peak_impact_force(d.ball.mass_kg, d.ball.speed_m_s, e.apparent_cor, d.impact_duration_s);

  const MassProperties system = hand_held_system(d);
  e.system_mass_kg = system.mass_kg;
  e.system_com_from_butt_m = system.com_from_butt_m;
  e.system_I_cm_kg_m2 = system.I_cm_kg_m2;
  e.cop_hand_from_butt_m = hand_held_cop_from_butt(system);
  e.rotation_axis_hand_from_butt_m =
      hand_held_rotation_axis_from_butt(system, d.forearm_equivalent_mass_kg, x);
  e.wrist_force_ratio = wrist_force_ratio(system, d.forearm_equivalent_mass_kg, x);
  e.peak_wrist_force_N = std::abs(e.wrist_force_ratio) * e.peak_impact_force_N;
  return e;
}

}  // namespace sweetspot
