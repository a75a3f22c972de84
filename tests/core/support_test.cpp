// Oracles for a design's support (Design::support): each rig's solved
// collision against collide() on the frame it stands for, built here from the
// pieces the rig is made of; the pinned rigid body against the free body's
// centre of percussion (a pivot at the conjugate point of the impact takes no
// impulse, Cross 2004 Eq. 5, so the two effective masses agree); the clamped
// and pinned modes against supported_modes(); and the refusals.
#include <catch2/catch.hpp>
#include <cmath>
#include <optional>
#include <string>

#include "sweetspot/collision.hpp"
#include "sweetspot/errors.hpp"
#include "sweetspot/evaluate.hpp"
#include "sweetspot/frame_modes.hpp"
#include "sweetspot/impact_response.hpp"
#include "sweetspot/rigid_impact.hpp"

namespace sweetspot {
namespace {

// designs/racquets/tour-100.json's racquet, strung at 250 N, hit 16 cm from the tip.
Design strung_racquet() {
  Design d{Implement::from_specs({27.0 * 0.0254, 0.305, 0.325, 0.0320})};
  d.stiffness.fundamental_free_Hz = 155.0;
  d.impact_from_butt_m = d.implement.length_m() - 0.16;
  d.strings.emplace();
  d.strings->tension_N = 250.0;
  d.cor_given = false;
  return d;
}

Design on(Design d, Support::Kind kind, double pivot_from_butt_m = 0.0) {
  d.support = {kind, pivot_from_butt_m};
  return d;
}

std::string field_of(const Design& d, Fidelity fidelity) {
  try {
    evaluate(d, fidelity);
  } catch (const FieldError& e) {
    return e.field();
  }
  return "";
}

// The drop tests' rigs (the ITF's drop onto a plate, the string-bed drop test)
// at the drop's 7.06 m/s.
Design dropped_on(Support::Kind kind) {
  Design d = on(strung_racquet(), kind);
  d.ball.speed_m_s = kDropTestSpeed_m_s;
  return d;
}

TEST_CASE("A lossless ball on a rigid surface comes back at its speed, never above it") {
  // The sums of the run's steps and their extrapolation give 1 to about 1e-15
  // either way; above 1 would be energy from nowhere.
  for (const double stiffness : {3e5, 1e6}) {
    for (const double exponent : {1.0, 1.5}) {
      for (const double speed : {2.0, kDropTestSpeed_m_s, 20.0}) {
        Design d = dropped_on(Support::Kind::kRigidSurface);
        d.ball_contact = BallContactLaw{stiffness, exponent, 0.0, 0.0};
        d.ball.speed_m_s = speed;
        const Evaluation e = evaluate(d, Fidelity::kCollision);
        INFO("k " << stiffness << ", n " << exponent << ", v " << speed);
        CHECK(e.apparent_cor <= 1.0);
        CHECK(e.apparent_cor == Approx(1.0).epsilon(1e-9));
        CHECK(e.cor <= 1.0);
        CHECK(e.rebound_speed_m_s <= speed);
        REQUIRE(e.details);
        REQUIRE(e.details->collision);
        CHECK(e.details->collision->ball_out_J <= e.details->collision->ball_in_J);
        CHECK(e.details->collision->ball_loss_J >= 0.0);
      }
    }
  }
}

TEST_CASE("On a rigid surface the ball's own collision is the answer, bit for bit") {
  const Design d = dropped_on(Support::Kind::kRigidSurface);
  const Evaluation e = evaluate(d, needed_fidelity(d));
  const CollisionResult wall =
      collide(rigid_frame(), std::nullopt, d.ball.mass_kg, d.ball_contact, d.ball.speed_m_s);
  CHECK(e.fidelity == Fidelity::kCollision);
  CHECK(e.apparent_cor == wall.apparent_cor);
  CHECK(e.cor == wall.apparent_cor);  // nothing moves: e = e_A
  CHECK(e.impact_duration_s == wall.contact_time_s);
  CHECK(e.peak_impact_force_N == wall.peak_force_N);
  CHECK(e.impulse_N_s == wall.impulse_N_s);
  REQUIRE(e.details);
  REQUIRE(e.details->collision);
  CHECK(e.details->collision->peak_ball_compression_m == wall.peak_ball_compression_m);
  CHECK(e.details->collision->vibration_J == 0.0);
  CHECK(std::isinf(e.effective_mass_kg));
  CHECK(e.peak_wrist_force_N == 0.0);
  CHECK(!e.cop_hand_from_butt_m);
  // The ITF's slow test of the same ball beside its drop: static_loop()'s,
  // for the law as given and for a law whose loss was solved to a COR.
  const StaticLoop loop = static_loop(d.ball_contact);
  CHECK(e.static_forward_deformation_m == loop.forward_deformation_m);
  CHECK(e.static_return_deformation_m == loop.return_deformation_m);
  Design dead = d;
  dead.ball_contact = kHystereticTennisBallLaw;
  dead.ball.cor_on_rigid_surface = 0.5;
  const Evaluation d_e = evaluate(dead, needed_fidelity(dead));
  const StaticLoop solved = static_loop(with_rigid_surface_cor(dead.ball_contact, 0.057, 0.5));
  CHECK(d_e.static_return_deformation_m == solved.return_deformation_m);
  CHECK(*d_e.static_return_deformation_m >
        static_loop(kHystereticTennisBallLaw).return_deformation_m);  // deader: a wider loop
  // Not a number of any other support.
  CHECK(!evaluate(strung_racquet(), Fidelity::kCollision).static_forward_deformation_m);
}

TEST_CASE("Head clamped, the ball meets the strings of an immovable frame, bit for bit") {
  const Design d = dropped_on(Support::Kind::kHeadClamped);
  const Evaluation e = evaluate(d, needed_fidelity(d));
  const CollisionResult bed = collide(rigid_frame(), string_bed_dynamics(*d.strings),
                                      d.ball.mass_kg, d.ball_contact, d.ball.speed_m_s);
  CHECK(e.apparent_cor == bed.apparent_cor);
  CHECK(e.cor == bed.apparent_cor);
  CHECK(e.impact_duration_s == bed.contact_time_s);
  CHECK(e.peak_impact_force_N == bed.peak_force_N);
  // The frame neither recoils nor vibrates: more comes back than off the free racquet.
  Design free = strung_racquet();
  free.ball.speed_m_s = d.ball.speed_m_s;
  CHECK(e.apparent_cor > evaluate(free, Fidelity::kCollision).apparent_cor);
  // The strings share the squeeze: the ball compresses less than on the plate.
  const CollisionResult wall =
      collide(rigid_frame(), std::nullopt, d.ball.mass_kg, d.ball_contact, d.ball.speed_m_s);
  CHECK(bed.peak_ball_compression_m < wall.peak_ball_compression_m);
}

TEST_CASE("A pivot at the impact's conjugate point takes no impulse: M_eff is the free body's") {
  // Cross (2004) Eq. (5): an impact at x turns the free body about the
  // conjugate point p = x_cm + I_cm / (M (x_cm - x))... measured from the
  // butt; pinned there, the pivot exerts nothing, and (x - p)^2 / I_p =
  // 1/M + b^2/I_cm.
  const Design racquet = strung_racquet();
  const MassProperties body = racquet.implement.mass_properties();
  const double x = racquet.impact_from_butt_m;
  const std::optional<double> p = free_conjugate_from_butt(body, x);
  REQUIRE(p);
  REQUIRE(*p > 0.0);
  const DesignCollision pinned(on(racquet, Support::Kind::kPivot, *p));
  const DesignCollision free(racquet);
  const double inverse_pinned = pinned.frame_at(x, 0.0).inverse_effective_mass_per_kg;
  const double inverse_free = free.frame_at(x, 0.0).inverse_effective_mass_per_kg;
  CHECK(inverse_pinned == Approx(inverse_free).epsilon(1e-12));
  // At the pivot itself the rigid body does not move.
  CHECK(pinned.frame_at(*p, 0.0).inverse_effective_mass_per_kg == 0.0);
}

TEST_CASE("Pivoted or clamped at the handle, the collision runs on supported_modes()") {
  const Design racquet = strung_racquet();
  const double pivot = 0.1524;  // the bat standards' 6 in from the knob
  const FlexibleFrame frame = flexible_frame(racquet);
  ModeOptions options = frame.options;
  options.method = ModeOptions::Method::kFiniteElement;
  options.modes = kCollisionModes;
  options.shape_samples = 0;
  const double grip_from = racquet.hand.center_from_butt_m - 0.5 * racquet.hand.grip_length_m;
  const double grip_to = racquet.hand.center_from_butt_m + 0.5 * racquet.hand.grip_length_m;
  struct Rig {
    Support::Kind kind;
    BeamSupport beam;
  };
  for (const Rig& rig :
       {Rig{Support::Kind::kPivot, {BeamSupport::Kind::kPinned, pivot, pivot}},
        Rig{Support::Kind::kHandleClamped, {BeamSupport::Kind::kClamped, grip_from, grip_to}}}) {
    INFO(to_string(rig.kind));
    const Design d = on(racquet, rig.kind, pivot);
    const DesignCollision collision(d);
    const ModalResult modes =
        supported_modes(frame.sections, frame.point_masses, rig.beam, options);
    REQUIRE(collision.model().modes.size() == modes.modes.size());
    for (std::size_t k = 0; k < modes.modes.size(); ++k)
      CHECK(collision.model().modes[k].mode.frequency_Hz == modes.modes[k].frequency_Hz);
    const Evaluation e = evaluate(d, Fidelity::kCollision);
    const FrameAtImpact at = collision.frame_at(d.impact_from_butt_m, 0.0);
    const CollisionResult r = collide(at, string_bed_dynamics(*d.strings), d.ball.mass_kg,
                                      d.ball_contact, d.ball.speed_m_s);
    CHECK(e.apparent_cor == r.apparent_cor);
    CHECK(e.impact_duration_s == r.contact_time_s);
    if (rig.kind == Support::Kind::kHandleClamped) {
      CHECK(at.inverse_effective_mass_per_kg == 0.0);
      CHECK(std::isinf(e.effective_mass_kg));
      CHECK(e.cor == r.apparent_cor);
    } else {
      const MassProperties body = racquet.implement.mass_properties();
      const double arm = body.com_from_butt_m - pivot;
      const double I_p = body.I_cm_kg_m2 + body.mass_kg * arm * arm;
      const double b = d.impact_from_butt_m - pivot;
      // The model's body is the sections fitted to the specs: their mass,
      // balance and inertia are the specs' to round-off.
      CHECK(at.inverse_effective_mass_per_kg == Approx(b * b / I_p).epsilon(1e-12));
      CHECK(e.effective_mass_kg == 1.0 / at.inverse_effective_mass_per_kg);
    }
    CHECK(e.vibration_energy_J == r.vibration_J);
    CHECK(e.peak_wrist_force_N == 0.0);
  }
}

TEST_CASE("Held in the hand, the collision runs on the hand-held frame") {
  const Design d = on(strung_racquet(), Support::Kind::kHand);
  ResponseOptions options;
  options.support = ResponseOptions::Support::kHandHeld;
  options.modes = kCollisionModes;
  const FrameAtImpact at = frame_at_impact(response_model(d, options), d.impact_from_butt_m);
  const CollisionResult r = collide(at, string_bed_dynamics(*d.strings), d.ball.mass_kg,
                                    d.ball_contact, d.ball.speed_m_s);
  const Evaluation e = evaluate(d, Fidelity::kCollision);
  CHECK(e.apparent_cor == r.apparent_cor);
  CHECK(e.effective_mass_kg == 1.0 / at.inverse_effective_mass_per_kg);
  // Implement and hand move together: heavier at the impact than the implement alone.
  CHECK(e.effective_mass_kg > evaluate(strung_racquet(), Fidelity::kCollision).effective_mass_kg);
  // A player: the wrist force is given.
  CHECK(e.peak_wrist_force_N > 0.0);
}

TEST_CASE("A rig is answered by the solved collision alone, and refuses what it cannot hold") {
  Design rig = on(strung_racquet(), Support::Kind::kHeadClamped);
  CHECK(needed_fidelity(rig) == Fidelity::kCollision);
  for (const Fidelity f : {Fidelity::kRigid, Fidelity::kModal, Fidelity::kResponse})
    CHECK(field_of(rig, f) == "support");
  rig.swing = kTypicalGroundstroke;
  CHECK(field_of(rig, Fidelity::kCollision) == "swing");
  Design pivot = on(strung_racquet(), Support::Kind::kPivot, 2.0);
  CHECK(field_of(pivot, Fidelity::kCollision) == "support/pivot_from_butt_m");
  pivot.support.pivot_from_butt_m = 0.15;
  pivot.impact_off_axis_m = 0.03;
  pivot.twistweight_kg_m2 = 0.0015;
  CHECK(field_of(pivot, Fidelity::kCollision) == "impact/off_axis_m");
  // A rigid surface needs no strings and no frame; the head clamped no frame.
  Design wall = on(Design{Implement::paper_racquet(0.7, 0.25, 0.8)}, Support::Kind::kRigidSurface);
  wall.cor_given = false;
  wall.ball.speed_m_s = kDropTestSpeed_m_s;
  CHECK_NOTHROW(evaluate(wall, Fidelity::kCollision));
  Design head = dropped_on(Support::Kind::kHeadClamped);
  head.stiffness = {};
  CHECK_NOTHROW(evaluate(head, Fidelity::kCollision));
  head.strings.reset();
  CHECK(field_of(head, Fidelity::kCollision) == "strings/tension_N");
}

}  // namespace
}  // namespace sweetspot
