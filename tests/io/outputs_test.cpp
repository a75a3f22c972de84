// The table of named outputs: one name, one unit, one meaning, used by every
// writer, report and objective.
#include "io/outputs.hpp"

#include <catch2/catch.hpp>
#include <set>
#include <string>

#include "sweetspot/collision.hpp"

namespace sweetspot::io {
namespace {

TEST_CASE("Output names are unique, found by name, and carry their SI unit in the name") {
  std::set<std::string_view> names;
  for (const OutputSpec& output : output_specs()) {
    CHECK(names.insert(output.name).second);
    CHECK(find_output(output.name) == &output);
    CHECK_FALSE(output.description.empty());
    REQUIRE(output.compute != nullptr);
    // "_N" names are in N, "_m" in m, "_Hz" in Hz: the unit is the name's suffix.
    if (!output.unit.empty() && output.unit.find(' ') == std::string_view::npos &&
        output.unit.find('/') == std::string_view::npos) {
      const std::string suffix = "_" + std::string(output.unit);
      CHECK(std::string(output.name).ends_with(suffix));
    }
  }
  CHECK(find_output("no_such_output") == nullptr);
}

TEST_CASE("On a rig the player's outputs are absent, on a rigid surface all but the ball's") {
  for (const std::string_view name : player_outputs()) CHECK(find_output(name));
  for (const std::string_view name : ball_outputs()) CHECK(find_output(name));
  Design d{Implement::from_specs({0.6858, 0.305, 0.325, 0.0320})};
  d.stiffness.fundamental_free_Hz = 155.0;
  d.strings.emplace();
  d.strings->tension_N = 250.0;
  d.cor_given = false;
  d.impact_from_butt_m = 0.5;
  d.ball.speed_m_s = kDropTestSpeed_m_s;  // the drop tests' rigs
  for (const Support::Kind kind : {Support::Kind::kHeadClamped, Support::Kind::kRigidSurface}) {
    d.support.kind = kind;
    const Evaluation e = evaluate(d, Fidelity::kCollision);
    INFO(to_string(kind));
    for (const OutputSpec& output : output_specs()) {
      INFO(output.name);
      const bool given = given_on_rig(output.name, kind);
      if (!given) CHECK_FALSE(output.value(e).has_value());
    }
    // Held still, the impact point's effective mass is infinite: not given.
    CHECK_FALSE(find_output("effective_mass_kg")->value(e).has_value());
    CHECK_FALSE(find_output("peak_wrist_force_N")->value(e).has_value());
    CHECK(find_output("apparent_cor")->value(e).has_value());
    CHECK(find_output("peak_ball_compression_m")->value(e).has_value());
    CHECK(find_output("mass_kg")->value(e).has_value() == (kind == Support::Kind::kHeadClamped));
  }
}

TEST_CASE("Outputs that need the modes are absent from a rigid evaluation, the rest present") {
  const Evaluation e = evaluate(Design{Implement::paper_racquet(0.70, 0.25, 0.8)});
  for (const OutputSpec& output : output_specs()) {
    if (output.needs_modes || output.needs_response) {
      CHECK_FALSE(output.value(e).has_value());
    } else if (output.when_absent.empty()) {
      CHECK(output.value(e).has_value());
    }
  }
  CHECK(find_output("peak_wrist_force_N")->value(e).value() ==
        Approx(568).margin(0.5));  // Table I, row 1
}

}  // namespace
}  // namespace sweetspot::io

namespace sweetspot::io {
namespace {

TEST_CASE("MgR/I and polarization: closed forms on a uniform rod and on the paper's racquet") {
  // A uniform rod (equal halves): I_cm = M L^2 / 12, so polarization = 1; R =
  // L / 2, the inertia about the butt M L^2 / 3, MgR/I = 3 g / (2 L).
  const double L = 0.70, M = 0.30, g = 9.80665;
  const Evaluation rod = evaluate(Design{Implement::paper_racquet(L, M, 1.0)});
  CHECK(find_output("polarization")->value(rod).value() == Approx(1.0).epsilon(1e-12));
  CHECK(find_output("maneuverability_index_s2")->value(rod).value() ==
        Approx(1.5 * g / L).epsilon(1e-12));
  // The paper's racquet, head 0.8 of the handle: two halves of M/1.8 and
  // 0.8 M/1.8 centred at L/4 and 3L/4.
  const double m1 = 0.8 * M / 1.8, m2 = M / 1.8;  // head, handle
  const double x_cm = (m2 * L / 4 + m1 * 3 * L / 4) / M;
  const double I_butt = m2 * L * L / 12 + m1 * (L * L / 48 + 9 * L * L / 16);
  const double I_cm = I_butt - M * x_cm * x_cm;
  const Evaluation racquet = evaluate(Design{Implement::paper_racquet(L, M, 0.8)});
  CHECK(find_output("maneuverability_index_s2")->value(racquet).value() ==
        Approx(M * g * x_cm / I_butt).epsilon(1e-12));
  CHECK(find_output("polarization")->value(racquet).value() ==
        Approx(I_cm / (M * L * L / 12)).epsilon(1e-12));
  // People's units of the shot speed.
  CHECK(find_output("shot_speed_km_h")->value(racquet).value() ==
        Approx(3.6 * racquet.shot_speed_m_s).epsilon(1e-12));
  CHECK(find_output("shot_speed_mph")->value(racquet).value() ==
        Approx(racquet.shot_speed_m_s / 0.44704).epsilon(1e-12));
}

}  // namespace
}  // namespace sweetspot::io
