// The invariant checker (issue 20): a hand-built evaluation that breaks each
// invariant is refused with a ModelRefusal naming an input, and the paper's
// Table I rows, the shipped kinds of design and the solved collision's
// calibrated racquet pass at every fidelity.
#include "sweetspot/invariants.hpp"

#include <catch2/catch.hpp>
#include <cmath>
#include <functional>
#include <limits>
#include <string>
#include <vector>

#include "sweetspot/collision.hpp"
#include "sweetspot/evaluate.hpp"

namespace sweetspot {
namespace {

// Cross (2004) Table I, top row (evaluate_test.cpp has all eight).
Design table_top_row() {
  return Design{Implement::paper_racquet(0.70, 0.25, 0.8),
                0.8,
                0.004,
                Hand{0.5, 0.07},
                0.5,
                Ball{0.057, 50.0},
                0.70 - 0.05};
}

// designs/racquets/tour-100-strung.json: the solved collision's racquet.
Design tour_100_strung() {
  Design d{Implement::from_specs({27.0 * 0.0254, 0.305, 0.325, 0.0320})};
  d.stiffness.fundamental_free_Hz = 155.0;
  d.impact_from_butt_m = d.implement.length_m() - 0.16;
  d.strings = StringBed{};
  d.cor_given = false;
  return d;
}

// Runs check_invariants on `e` and returns the refusal's field ("" if none).
std::string refused_field(const Evaluation& e, const Design& d) {
  try {
    check_invariants(e, d);
  } catch (const ModelRefusal& refusal) {
    CHECK_FALSE(refusal.field().empty());
    CHECK(std::string(refusal.what()).starts_with(refusal.field() + ": "));
    return refusal.field();
  }
  return {};
}

TEST_CASE("Table I's rows and the calibrated strung racquet keep every invariant") {
  const double paper_rows[][3] = {
      {0.25, 0.8, 0.8}, {0.40, 0.8, 0.8}, {0.25, 1.2, 0.8}, {0.25, 0.8, 0.6}, {0.40, 1.2, 0.6}};
  for (const auto& row : paper_rows) {
    Design d = table_top_row();
    d.implement = Implement::paper_racquet(0.70, row[0], row[1]);
    d.cor = row[2];
    CHECK(broken_invariant(evaluate(d), d).empty());
  }
  const Design strung = tour_100_strung();
  const Evaluation e = evaluate(strung, Fidelity::kCollision);
  CHECK(broken_invariant(e, strung).empty());
  Design given = strung;
  given.strings.reset();
  given.cor_given = true;
  given.cor_rigid = 0.85;
  const Evaluation response = evaluate(given, Fidelity::kResponse);
  CHECK(broken_invariant(response, given).empty());
  given.cor_rigid.reset();
  CHECK(broken_invariant(evaluate(given, Fidelity::kModal), given).empty());
}

TEST_CASE("A rim hit's negative apparent COR is inside the rigid-body bound, not refused") {
  Design d = table_top_row();
  d.cor = 0.0;  // the lowest e: e_A = -m / (M_eff + m), the bound itself
  const Evaluation e = evaluate(d);
  CHECK(e.apparent_cor < 0.0);
  CHECK(e.apparent_cor == Approx(-d.ball.mass_kg / (e.effective_mass_kg + d.ball.mass_kg)));
  CHECK(broken_invariant(e, d).empty());
}

TEST_CASE("A hand-built evaluation breaking each invariant is refused, naming an input") {
  const Design d = table_top_row();
  const Evaluation good = evaluate(d);
  REQUIRE(refused_field(good, d).empty());
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const double m = d.ball.mass_kg;
  const std::vector<std::pair<const char*, std::function<void(Evaluation&)>>> breaks = {
      {"COR above 1", [](Evaluation& e) { e.cor = 1.02; }},
      {"COR below 0", [](Evaluation& e) { e.cor = -0.07; }},
      {"apparent COR above the COR", [](Evaluation& e) { e.apparent_cor = e.cor + 0.01; }},
      {"apparent COR below the rigid bound",
       [m](Evaluation& e) { e.apparent_cor = -m / (e.effective_mass_kg + m) - 0.01; }},
      {"negative impulse", [](Evaluation& e) { e.impulse_N_s = -0.1; }},
      {"zero contact time", [](Evaluation& e) { e.impact_duration_s = 0.0; }},
      {"negative contact time", [](Evaluation& e) { e.impact_duration_s = -0.000134; }},
      {"no peak force", [](Evaluation& e) { e.peak_impact_force_N = 0.0; }},
      {"ball out faster than in", [](Evaluation& e) { e.rebound_speed_m_s = 193.0; }},
      {"a NaN output", [nan](Evaluation& e) { e.peak_wrist_force_N = nan; }},
      {"an infinite output", [](Evaluation& e) { e.swingweight_kg_m2 = INFINITY; }},
      {"negative vibration", [](Evaluation& e) { e.vibration_energy_J = -1e-3; }},
      {"vibration beyond the ball's energy", [](Evaluation& e) { e.vibration_energy_J = 2.7e269; }},
      {"a negative mode energy",
       [](Evaluation& e) {
         e.vibration_energy_J = 1.0;
         e.details.emplace();
         e.details->vibration_modes = {{155.0, 1.0014}, {430.0, -1.4e-3}};
       }},
      {"the implement gains more than the ball lost", [](Evaluation& e) { e.impulse_N_s *= 3.0; }},
  };
  for (const auto& [name, apply] : breaks) {
    INFO(name);
    Evaluation e = good;
    apply(e);
    CHECK_FALSE(broken_invariant(e, d).empty());
    CHECK(refused_field(e, d) == "implement");
  }
}

TEST_CASE("A solved collision breaking each ledger invariant is refused, naming an input") {
  const Design d = tour_100_strung();
  const Evaluation good = evaluate(d, Fidelity::kCollision);
  REQUIRE(refused_field(good, d).empty());
  const std::vector<std::pair<const char*, std::function<void(CollisionResult&)>>> breaks = {
      {"negative ball loss (a stiff ball's unresolved step)",
       [](CollisionResult& r) {  // the ledger still closes: the loss moved to the ball's exit
         r.ball_out_J += r.ball_loss_J + 26.5;
         r.ball_loss_J = -26.5;
       }},
      {"negative ball-out energy", [](CollisionResult& r) { r.ball_out_J = -66.5; }},
      {"a ledger that does not close", [](CollisionResult& r) { r.vibration_J += 1.0; }},
      {"negative strings loss", [](CollisionResult& r) { r.strings_loss_J = -0.0129; }},
      {"a negative mode energy", [](CollisionResult& r) { r.mode_energy_J[1] = -1.4e-3; }},
      {"a negative impulse", [](CollisionResult& r) { r.impulse_N_s = -1.0; }},
      {"a negative contact", [](CollisionResult& r) { r.contact_time_s = -0.000134; }},
      {"a rebound faster than elastic", [](CollisionResult& r) { r.apparent_cor = 0.99; }},
  };
  for (const auto& [name, apply] : breaks) {
    INFO(name);
    Evaluation e = good;
    apply(*e.details->collision);
    CHECK_FALSE(broken_invariant(e, d).empty());
    const std::string field = refused_field(e, d);
    CHECK_FALSE(field.empty());
    CHECK(field != "implement");  // a collision input: the ball, strings or frame
  }
  // The input furthest from the calibrated racquet is the one named.
  Design stiff = d;
  stiff.ball_contact.stiffness = 1e15;
  CHECK(collision_suspect(stiff, 155.0).field == "ball/contact/stiffness");
  Design slow = d;
  slow.ball.speed_m_s = 1e-9;
  CHECK(collision_suspect(slow, 155.0).field == "ball/speed_m_s");
  CHECK(collision_suspect(d, 5.0).field == "frame/fundamental_free_Hz");
  // A squeeze names only what squeezes more: a slack bed squeezes less, so a
  // fast ball on it is the speed's; a light ball squeezes less, so a small
  // light one is its diameter's; at the calibrated racquet, the speed.
  Design slack_fast = d;
  slack_fast.strings->tension_N = 20.0;
  slack_fast.ball.speed_m_s = 160.0;
  CHECK(collision_suspect(slack_fast, 155.0).field == "strings/tension_N");
  CHECK(squeeze_suspect(slack_fast).field == "ball/speed_m_s");
  Design small_light = d;
  small_light.ball.mass_kg = 0.010;
  small_light.ball.diameter_m = 0.02;
  CHECK(squeeze_suspect(small_light).field == "ball/diameter_m");
  CHECK(squeeze_suspect(d).field == "ball/speed_m_s");
}

// The refusal of the solved collision of `d`: "field: detail", empty if answered.
std::string collision_refusal(const Design& d) {
  try {
    evaluate(d, Fidelity::kCollision);
  } catch (const ModelRefusal& refusal) {
    return refusal.what();
  }
  return {};
}

TEST_CASE("A ball squeezed past its radius is refused, naming what squeezed it") {
  // The calibrated racquet's ball reaches its radius between 60 and 70 m/s:
  // answered below, refused above, and the answer given a wider ball is the
  // squeeze the refusal saw, past the 6.7 cm ball's radius.
  Design d = tour_100_strung();
  const double radius = 0.5 * kTennisBallDiameter_m;
  d.ball.speed_m_s = 60.0;
  const Evaluation below = evaluate(d, Fidelity::kCollision);
  CHECK(below.details->collision->peak_ball_compression_m < radius);
  d.ball.speed_m_s = 70.0;
  const std::string refused = collision_refusal(d);
  CHECK(refused.starts_with("ball/speed_m_s: "));
  CHECK_THAT(refused, Catch::Contains("more than its radius"));
  Design wide = d;
  wide.ball.diameter_m = 0.1;
  const double squeeze =
      evaluate(wide, Fidelity::kCollision).details->collision->peak_ball_compression_m;
  CHECK(squeeze > radius);
  CHECK(squeeze < 0.5 * wide.ball.diameter_m);
  // A ball far smaller than a tennis ball is the input named.
  Design small = tour_100_strung();
  small.ball.diameter_m = 0.005;
  CHECK(collision_refusal(small).starts_with("ball/diameter_m: "));
}

}  // namespace
}  // namespace sweetspot
