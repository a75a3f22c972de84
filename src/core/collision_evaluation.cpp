#include "core/collision_evaluation.hpp"

#include <algorithm>
#include <cmath>
#include <optional>
#include <stdexcept>
#include <string>

#include "core/check.hpp"
#include "core/kernels_detail.hpp"
#include "sweetspot/collision.hpp"
#include "sweetspot/errors.hpp"
#include "sweetspot/frame_modes.hpp"
#include "sweetspot/impact_response.hpp"
#include "sweetspot/invariants.hpp"
#include "sweetspot/mode_cache.hpp"
#include "sweetspot/rigid_impact.hpp"

namespace sweetspot {

DesignCollision::DesignCollision(const Design& design, double rel_tol) : design_(design) {
  ModeCache cache;
  init(rel_tol, cache);
}

DesignCollision::DesignCollision(const Design& design, double rel_tol, ModeCache& cache)
    : design_(design) {
  init(rel_tol, cache);
}

void DesignCollision::init(double rel_tol, ModeCache& cache) {
  const Design& design = design_;
  const Support::Kind support = design.support.kind;
  if (is_round(design) && support != Support::Kind::kRigidSurface) {
    throw FieldError("implement/profile",
                     "the solved collision is a ball on a string bed, and an implement given by "
                     "its profile (a bat, a rod) has none: evaluate it with --fidelity modal (its "
                     "frame cor and impact duration) or response (its frame cor_rigid)");
  }
  if (design.cor_rigid) {
    throw FieldError("frame/cor_rigid",
                     "the solved collision derives the COR itself; give neither cor nor "
                     "cor_rigid (or evaluate with --fidelity response)");
  }
  if (design.cor_given) {
    throw FieldError("frame/cor",
                     "the solved collision derives the COR itself; give no frame cor (or "
                     "evaluate with --fidelity modal), got " +
                         detail::format_number(design.cor));
  }
  validate(design);
  // A ball given by its COR on a rigid surface: the law's loss set to match it.
  if (design.ball.cor_on_rigid_surface) {
    design_.ball_contact = with_rigid_surface_cor(design.ball_contact, design.ball.mass_kg,
                                                  *design.ball.cor_on_rigid_surface);
  }
  immovable_ = support == Support::Kind::kHeadClamped || support == Support::Kind::kRigidSurface;
  if (support == Support::Kind::kRigidSurface) return;  // the ball alone on a plate
  if (!design.strings) {
    throw FieldError("strings/tension_N",
                     "the solved collision needs the string tension (the string bed's "
                     "stiffness), not a given impact duration");
  }
  bed_ = string_bed_dynamics(*design.strings, design.string_bed_mass_kg,
                             design.string_bed_damping_ratio);
  polar_inertia_kg_m2_ = polar_inertia_kg_m2(design);
  if (immovable_) return;  // the strings on a frame that does not move
  if (!has_stiffness(design)) {
    throw FieldError("frame/EI_N_m2",
                     "the solved collision needs the frame's stiffness (EI_N_m2, RA or "
                     "fundamental_free_Hz)");
  }
  ResponseOptions options;
  options.modes = kCollisionModes;
  options.rel_tol = rel_tol;
  if (support == Support::Kind::kHand) {
    options.support = ResponseOptions::Support::kHandHeld;
  } else if (const std::optional<BeamSupport> rig = beam_support(design)) {
    options.support = ResponseOptions::Support::kRig;  // the vice or the pivot
    options.rig = *rig;
  }
  try {
    model_ = cache.response_model(design, options);
  } catch (const std::invalid_argument& error) {
    if (support != Support::Kind::kHandleClamped) throw;
    throw FieldError("hand/grip_length_m",
                     "the vice holds the handle where the hand would (hand center_from_butt and "
                     "grip_length): " +
                         std::string(error.what()));
  }
}

FrameAtImpact DesignCollision::frame_at(double from_butt_m, double off_axis_m) const {
  if (immovable_) return rigid_frame();  // an off-axis impact moves it no more
  FrameAtImpact frame = frame_at_impact(model_, from_butt_m);
  if (off_axis_m != 0.0 && is_rig(design_.support)) {
    throw FieldError("impact/off_axis_m",
                     "an impact off the long axis would twist the implement in its " +
                         std::string(to_string(design_.support.kind)) +
                         " support, which the model does not hold: give 0, got " +
                         detail::format_number(off_axis_m) + " m");
  }
  if (off_axis_m != 0.0) {
    if (!polar_inertia_kg_m2_) {
      throw FieldError("impact/off_axis_m",
                       "an impact off the long axis needs the polar inertia "
                       "(implement/twistweight_kg_cm2 or implement/headsize_sq_in), got " +
                           detail::format_number(off_axis_m) + " m");
    }
    frame.inverse_effective_mass_per_kg += impact_twist_per_kg(off_axis_m, *polar_inertia_kg_m2_);
  }
  return frame;
}

CollisionResult DesignCollision::at(double from_butt_m, double off_axis_m,
                                    const CollisionOptions& options) const {
  return at_speed(from_butt_m, off_axis_m, design_.ball.speed_m_s, options);
}

CollisionResult DesignCollision::at_speed(double from_butt_m, double off_axis_m, double speed_m_s,
                                          const CollisionOptions& options) const {
  const FrameAtImpact frame = frame_at(from_butt_m, off_axis_m);
  CollisionResult r =
      collide(frame, bed_, design_.ball.mass_kg, design_.ball_contact, speed_m_s, options);
  // The design as hit, for the refusals' blame: its ball at this speed.
  std::optional<Design> hit;
  const auto as_hit = [&]() -> const Design& {
    if (speed_m_s == design_.ball.speed_m_s) return design_;
    hit.emplace(design_);
    hit->ball.speed_m_s = speed_m_s;
    return *hit;
  };
  const Design& design = design_;
  const double f1 = model_.modes.empty() ? 155.0 : model_.modes.front().mode.frequency_Hz;
  const auto refuse = [&](const Suspect& blame, const std::string& why) {
    throw ModelRefusal(blame.field, blame.value,
                       "the solved collision cannot answer this design (" + why + "); " +
                           detail::format_number(blame.value) +
                           " is the input furthest from the racquet it was verified on",
                       why);
  };
  if (!r.separated && r.steps == 0) {
    // Not stepped at all (step_mesh.hpp): the contact alone would take more
    // steps than a run may, its fastest motion far shorter than the contact.
    refuse(collision_suspect(as_hit(), f1),
           "the contact is too stiff to step through: its fastest motion rings in a step of " +
               detail::format_significant(r.step_s) +
               " s, more than the 2e7 steps a contact may take; a ball or strings this stiff "
               "take the solved collision past what it resolves in bounded time");
  }
  if (!r.separated) {
    // A ball given dead (a COR on a rigid surface near 0) comes back off what
    // it hits at a crawl, or (plastic) stops there: it is still there when
    // the run ends.
    const std::optional<double> dead = design.ball.cor_on_rigid_surface;
    refuse(collision_suspect(as_hit(), f1),
           std::string("the ball has not left ") +
               (bed_                                                  ? "the strings"
                : design.support.kind == Support::Kind::kRigidSurface ? "the surface"
                                                                      : "the frame") +
               " for good within the run's " + detail::format_number(options.max_time_s) +
               " s (or its bound on steps) and " + std::to_string(r.contacts) +
               (r.contacts == 1 ? " contact" : " contacts") +
               (dead && *dead < 0.1
                    ? "; a ball as dead as cor_on_rigid_surface " + detail::format_number(*dead) +
                          " comes off it too slowly, or stops: give a livelier one"
                    : ""));
  }
  if (!(r.step_error <= kMaxStepError)) {
    refuse(collision_suspect(as_hit(), f1),
           "the step does not resolve the contact: the apparent COR changes by " +
               detail::format_significant(r.step_error) + " when the step halves, more than " +
               detail::format_number(kMaxStepError));
  }
  if (!(r.contact_time_s >= kMinDuration_s && r.contact_time_s <= kMaxDuration_s)) {
    refuse(collision_suspect(as_hit(), f1),
           "the contact lasts " + detail::format_significant(r.contact_time_s) + " s, outside [" +
               detail::format_number(kMinDuration_s) + ", " +
               detail::format_number(kMaxDuration_s) + "] s");
  }
  // Squeezed by more than its radius, the ball's centre would have passed what
  // it hits: the contact law has been taken beyond any ball.
  if (const double radius = 0.5 * design.ball.diameter_m; !(r.peak_ball_compression_m < radius)) {
    refuse(squeeze_suspect(as_hit()),
           "the ball is squeezed by " + detail::format_significant(r.peak_ball_compression_m) +
               " m, more than its radius of " + detail::format_number(radius) +
               " m: its centre would have passed what it hits" +
               (design.ball_contact.form == BallLawForm::kPower
                    ? "; the hysteretic ball (ball.contact.law \"hysteretic\"), which stiffens "
                      "as it squeezes, may answer"
                    : ""));
  }
  const double M_eff = 1.0 / frame.inverse_effective_mass_per_kg;  // inf: immovable
  if (const std::string why =
          broken_invariant(r, design.ball.mass_kg, M_eff, bed_ ? design.string_bed_mass_kg : 0.0);
      !why.empty()) {
    refuse(collision_suspect(as_hit(), f1), why);
  }
  return r;
}

namespace {

// The solved collision `r` into `e`, with the COR `cor` it implies: the
// contact, the ball's numbers, the vibration and the record.
void put_collision(const Design& design, const DesignCollision& collision, double cor,
                   CollisionResult r, Evaluation& e) {
  e.fidelity = Fidelity::kCollision;
  e.support = design.support;
  e.cor = cor;
  e.cor_derived = true;
  e.impact_duration_s = r.contact_time_s;
  e.impact_duration_derived = true;
  put_string_bed(design, e);
  e.apparent_cor = r.apparent_cor;
  e.rebound_speed_m_s = r.apparent_cor * design.ball.speed_m_s;
  e.impulse_N_s = r.impulse_N_s;
  e.peak_impact_force_N = r.peak_force_N;
  e.vibration_energy_J = r.vibration_J;
  e.vibration_share = r.vibration_J / r.ball_in_J;
  if (!e.details) e.details.emplace();
  e.details->vibration_modes.clear();
  for (std::size_t k = 0; k < r.mode_energy_J.size(); ++k) {
    e.details->vibration_modes.emplace_back(collision.model().modes[k].mode.frequency_Hz,
                                            r.mode_energy_J[k]);
  }
  e.details->collision = std::move(r);
}

// A rig's evaluation (is_rig()): the solved collision on the rig, the
// implement's mass properties beside it (none on a rigid surface), nothing of
// the player (Evaluation::support).
Evaluation evaluate_rig(const Design& design, double rel_tol, ModeCache& cache) {
  const DesignCollision collision(design, rel_tol, cache);
  CollisionOptions collision_options;
  collision_options.record_history = true;
  CollisionResult r =
      collision.at(design.impact_from_butt_m, design.impact_off_axis_m, collision_options);
  const double inverse_mass =
      collision.frame_at(design.impact_from_butt_m, design.impact_off_axis_m)
          .inverse_effective_mass_per_kg;
  // Eq. (16) inverted where the impact point moves; e = e_A where it cannot.
  const double cor = inverse_mass > 0.0 ? cor_from_apparent(r.apparent_cor, design.ball.mass_kg,
                                                            1.0 / inverse_mass)
                                        : r.apparent_cor;
  // The implement's numbers from the rigid model of the same implement free,
  // at the solved COR and contact time; then everything of the impact is the
  // rig's and nothing of the player is kept.
  Design free = design;
  free.support = {};
  free.strings.reset();
  free.impact_off_axis_m = 0.0;
  free.cor = std::clamp(cor, 0.0, 1.0);
  free.impact_duration_s = r.contact_time_s;
  Evaluation e = evaluate(free, Fidelity::kRigid, {.rel_tol = rel_tol, .modes = &cache});
  const Evaluation player{};
  e.cop_free_from_butt_m = player.cop_free_from_butt_m;
  e.rotation_axis_free_from_butt_m = player.rotation_axis_free_from_butt_m;
  e.system_mass_kg = player.system_mass_kg;
  e.system_com_from_butt_m = player.system_com_from_butt_m;
  e.system_I_cm_kg_m2 = player.system_I_cm_kg_m2;
  e.cop_hand_from_butt_m = player.cop_hand_from_butt_m;
  e.rotation_axis_hand_from_butt_m = player.rotation_axis_hand_from_butt_m;
  e.wrist_force_ratio = player.wrist_force_ratio;
  e.peak_wrist_force_N = player.peak_wrist_force_N;
  e.impact_off_axis_m = design.impact_off_axis_m;
  e.twist_rate_rad_s = player.twist_rate_rad_s;
  e.peak_twist_torque_N_m = player.peak_twist_torque_N_m;
  e.effective_mass_kg = inverse_mass > 0.0 ? 1.0 / inverse_mass : INFINITY;
  if (design.support.kind == Support::Kind::kRigidSurface) {
    const StaticLoop loop = static_loop(collision.ball_law());
    e.static_forward_deformation_m = loop.forward_deformation_m;
    e.static_return_deformation_m = loop.return_deformation_m;
  }
  put_collision(design, collision, cor, std::move(r), e);
  check_invariants(e, design);
  return e;
}

}  // namespace

Evaluation evaluate_collision(const Design& design, double rel_tol, ModeCache& cache) {
  if (is_rig(design.support)) return evaluate_rig(design, rel_tol, cache);
  const DesignCollision collision(design, rel_tol, cache);
  CollisionOptions collision_options;
  collision_options.record_history = true;
  CollisionResult r =
      collision.at(design.impact_from_butt_m, design.impact_off_axis_m, collision_options);
  const double M_eff = 1.0 / collision.frame_at(design.impact_from_butt_m, design.impact_off_axis_m)
                                 .inverse_effective_mass_per_kg;
  // The rigid model's quantities at the COR that Eq. (16) maps to the solved
  // apparent COR; then the solved numbers replace the prescribed ones.
  const double cor = cor_from_apparent(r.apparent_cor, design.ball.mass_kg, M_eff);
  Design resolved = design;
  resolved.strings.reset();
  resolved.cor = std::clamp(cor, 0.0, 1.0);
  resolved.impact_duration_s = r.contact_time_s;
  Evaluation e = evaluate(resolved, Fidelity::kModal, {.rel_tol = rel_tol, .modes = &cache});
  put_collision(design, collision, cor, std::move(r), e);
  e.peak_wrist_force_N = peak_wrist_force(e.wrist_force_ratio, e.peak_impact_force_N);
  // Held in the hand, the impact moves implement and hand (the rigid model's
  // M_eff is the implement's alone, Eq. 17).
  if (design.support.kind == Support::Kind::kHand) e.effective_mass_kg = M_eff;
  if (const double y = design.impact_off_axis_m; y != 0.0) {
    // The twist of the solved impulse and force (evaluate()'s formulas).
    e.twist_rate_rad_s = e.impulse_N_s * y / *e.polar_inertia_kg_m2;
    e.peak_twist_torque_N_m = e.peak_impact_force_N * std::abs(y);
  }
  check_invariants(e, design);
  return e;
}

}  // namespace sweetspot
