#include "sweetspot/evaluate.hpp"

#include <cmath>
#include <stdexcept>
#include <string>

#include "core/check.hpp"
#include "core/collision_evaluation.hpp"
#include "core/kernels_detail.hpp"
#include "sweetspot/errors.hpp"
#include "sweetspot/impact_response.hpp"
#include "sweetspot/invariants.hpp"
#include "sweetspot/kernels.hpp"
#include "sweetspot/mode_cache.hpp"
#include "sweetspot/rigid_impact.hpp"
#include "sweetspot/swing.hpp"

namespace sweetspot {
namespace {

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

// The design with its duration settled (given, or from the string tension),
// validated. A COR to be derived (cor_rigid) needs the response model.
Design settled(const Design& design, Fidelity fidelity) {
  if (design.cor_rigid && fidelity != Fidelity::kResponse) {
    throw FieldError("frame/cor_rigid",
                     "a COR derived from the frame's vibration needs the response model "
                     "(fidelity response or auto)");
  }
  Design resolved = design;
  validate(resolved);
  resolved.impact_duration_s = settled_duration(design);
  return resolved;
}

// The rigid model's evaluation of the settled design, made at `fidelity`.
Evaluation rigid_part(const Design& design, const Design& resolved, Fidelity fidelity) {
  Evaluation e = evaluate_settled(resolved);
  e.fidelity = fidelity;
  e.impact_duration_derived = design.strings.has_value();
  put_string_bed(design, e);
  return e;
}

// Fidelity::kRigid. A design with a given COR and duration (a sweep's or a
// catalogue's every point) has nothing to settle: neither a copy of the
// design nor a second validation; the same checks, in the same order, and the
// same numbers.
Evaluation evaluate_rigid(const Design& design, const EvaluationOptions& options) {
  if (!design.cor_rigid && !design.strings)
    return options.validated ? evaluate_settled_valid(design) : evaluate_settled(design);
  const Design resolved = settled(design, Fidelity::kRigid);
  Evaluation e = rigid_part(design, resolved, Fidelity::kRigid);
  check_invariants(e, resolved);
  return e;
}

// Fidelity::kModal: the rigid model and the frame's modes, free and hand-held.
Evaluation evaluate_modal(const Design& design, double rel_tol, ModeCache& cache) {
  const Design resolved = settled(design, Fidelity::kModal);
  Evaluation e = rigid_part(design, resolved, Fidelity::kModal);
  e.modal = cache.modal_outputs(resolved, rel_tol);
  check_invariants(e, resolved);
  return e;
}

// Fidelity::kResponse: also the energy each free mode keeps, 1/2 J^2 kappa_k,
// with J from the derived COR or, for a given COR, from the rigid model.
Evaluation evaluate_response(const Design& design, double rel_tol, ModeCache& cache) {
  Design resolved = settled(design, Fidelity::kResponse);
  const ResponseModel& model = cache.response_model(resolved, ResponseOptions{});
  if (design.cor_rigid) {
    try {
      resolved.cor = derive_cor(model, resolved.impact_from_butt_m, *design.cor_rigid,
                                resolved.ball, resolved.impact_duration_s)
                         .cor;
    } catch (const std::invalid_argument& error) {
      rethrow_under("frame/", error);
    }
  }
  const std::vector<double> kappa =
      vibration_compliance_per_mode(model, resolved.impact_from_butt_m, resolved.impact_duration_s);
  const Evaluation rigid = evaluate_unchecked(resolved);
  const double J = rigid.impulse_N_s;
  std::vector<std::pair<double, double>> mode_energies;  // frequency [Hz], energy [J]
  double vibration_energy = 0.0;
  for (std::size_t k = 0; k < kappa.size(); ++k) {
    mode_energies.emplace_back(model.modes[k].mode.frequency_Hz, 0.5 * J * J * kappa[k]);
    vibration_energy += mode_energies.back().second;
  }
  // Energy ledger: the frame cannot keep more than the ball loses. A derived
  // COR satisfies it by construction (derive_cor refuses otherwise); a given
  // COR with a frame this compliant contradicts the prescribed pulse.
  const double v1 = resolved.ball.speed_m_s, eA = rigid.apparent_cor;
  const double ball_in_J = 0.5 * resolved.ball.mass_kg * v1 * v1;
  const double ball_loss_J = ball_in_J * (1.0 - eA * eA);
  if (!(vibration_energy <= ball_loss_J * (1.0 + 1e-12))) {
    throw FieldError("frame/cor", "with a COR of " + detail::format_number(resolved.cor) +
                                      " the frame would keep " +
                                      detail::format_significant(vibration_energy) +
                                      " J as vibration, more than the ball loses (" +
                                      detail::format_significant(ball_loss_J) +
                                      " J); the prescribed-pulse model does not hold for this "
                                      "implement");
  }
  Evaluation e = rigid_part(design, resolved, Fidelity::kResponse);
  e.modal = cache.modal_outputs(resolved, rel_tol);
  e.details.emplace();
  e.details->vibration_modes = std::move(mode_energies);
  e.cor_derived = design.cor_rigid.has_value();
  e.vibration_energy_J = vibration_energy;
  e.vibration_share = vibration_energy / ball_in_J;
  check_invariants(e, resolved);
  return e;
}

}  // namespace

Fidelity needed_fidelity(const Design& design) {
  if (is_rig(design.support)) return Fidelity::kCollision;
  if (design.strings && !design.cor_given && !design.cor_rigid && has_stiffness(design))
    return Fidelity::kCollision;
  if (design.cor_rigid) return Fidelity::kResponse;
  return has_stiffness(design) ? Fidelity::kModal : Fidelity::kRigid;
}

namespace {

// The evaluation at `fidelity` of a design without a swing.
Evaluation evaluate_at_rest(const Design& design, Fidelity fidelity,
                            const EvaluationOptions& options) {
  if (fidelity == Fidelity::kRigid) return evaluate_rigid(design, options);
  ModeCache local;
  ModeCache& cache = options.modes ? *options.modes : local;
  switch (fidelity) {
    case Fidelity::kModal:
      return evaluate_modal(design, options.rel_tol, cache);
    case Fidelity::kResponse:
      return evaluate_response(design, options.rel_tol, cache);
    case Fidelity::kCollision:
      return evaluate_collision(design, options.rel_tol, cache);
    case Fidelity::kRigid:
      break;
  }
  return evaluate_rigid(design, options);
}

}  // namespace

void require_player(const Design& design, std::string_view what) {
  if (!is_rig(design.support)) return;
  throw FieldError("support", "a rig (" + std::string(to_string(design.support.kind)) +
                                  ") is answered by the solved collision alone, not " +
                                  std::string(what) +
                                  ": evaluate it with fidelity collision or auto, or give "
                                  "support free or hand");
}

Meeting meeting_at(const Design& design, double from_butt_m) {
  Meeting m;
  m.swing =
      scaled_to_swingweight(*design.swing, swingweight_kg_m2(design.implement.mass_properties()));
  // Scaled to the design's swingweight, the angular speed must stay in the
  // range a swing is accepted over (swing.hpp), or the reference that scaled
  // it is what took it out.
  if (design.swing->reference_swingweight_kg_m2 &&
      !(m.swing.angular_speed_rad_s <= kMaxAngularSpeed_rad_s)) {
    throw FieldError(
        "swing/reference_swingweight_kg_m2",
        "scales the swing's " + detail::format_significant(design.swing->angular_speed_rad_s) +
            " rad/s to this racquet's swingweight as " +
            detail::format_significant(m.swing.angular_speed_rad_s) + " rad/s, above the model's " +
            detail::format_number(kMaxAngularSpeed_rad_s) + " rad/s; got " +
            detail::format_number(*design.swing->reference_swingweight_kg_m2) + " kg m^2");
  }
  m.racquet_speed_m_s = racquet_speed_m_s(m.swing, from_butt_m);
  m.speed_m_s = design.ball.speed_m_s + m.racquet_speed_m_s;
  if (!(m.speed_m_s >= kMinSpeed_m_s && m.speed_m_s <= kMaxSpeed_m_s)) {
    throw FieldError("swing/angular_speed_rad_s",
                     "the ball and the racquet meet at " + detail::format_significant(m.speed_m_s) +
                         " m/s (the ball's " + detail::format_significant(design.ball.speed_m_s) +
                         " and the racquet's " + detail::format_significant(m.racquet_speed_m_s) +
                         "), outside the model's [" + detail::format_number(kMinSpeed_m_s) + ", " +
                         detail::format_number(kMaxSpeed_m_s) + "] m/s");
  }
  return m;
}

void rethrow_at_meeting(const ModelRefusal& refusal, const Design& design, const Meeting& meeting) {
  // The collision saw the meeting speed, which is not the file's ball speed:
  // the swing that added V is the input to name, with the speeds that met.
  if (refusal.field() != "ball/speed_m_s") throw;
  throw ModelRefusal("swing/angular_speed_rad_s", meeting.swing.angular_speed_rad_s,
                     "the solved collision cannot answer this design (" + refusal.reason() +
                         ") at the speed the ball and the racquet meet, " +
                         detail::format_significant(meeting.speed_m_s) + " m/s (the ball's " +
                         detail::format_significant(design.ball.speed_m_s) + " and the racquet's " +
                         detail::format_significant(meeting.racquet_speed_m_s) + ")",
                     refusal.reason());
}

Evaluation evaluate(const Design& design, Fidelity fidelity, const EvaluationOptions& options) {
  if (fidelity != Fidelity::kCollision) {
    require_player(design, "the " + std::string(to_string(fidelity)) + " model");
  }
  if (!design.swing) {
    // The laboratory's impact; the shot the assumed groundstroke would give.
    Evaluation e = evaluate_at_rest(design, fidelity, options);
    put_assumed_shot(design, e);
    return e;
  }
  // The racquet is free during the contact: the collision in the frame moving
  // with the impact point is the one of a ball arriving at v_in + V onto the
  // racquet at rest (swing.hpp).
  validate(design);
  const Meeting meeting = meeting_at(design, design.impact_from_butt_m);
  Design in_play = design;
  in_play.swing.reset();
  in_play.ball.speed_m_s = meeting.speed_m_s;
  Evaluation e;
  try {
    e = evaluate_at_rest(in_play, fidelity,
                         {.rel_tol = options.rel_tol, .modes = options.modes, .validated = false});
  } catch (const ModelRefusal& refusal) {
    rethrow_at_meeting(refusal, design, meeting);
  }
  const Swing& swing = meeting.swing;
  const double V = meeting.racquet_speed_m_s;
  e.swing = swing;
  e.swing_assumed = false;
  e.incoming_speed_m_s = design.ball.speed_m_s;
  e.racquet_speed_m_s = V;
  e.shot_speed_m_s = shot_speed_m_s(e.apparent_cor, e.incoming_speed_m_s, V);
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

}  // namespace sweetspot
