// A design's validation names the field at fault as a design file spells it,
// and the hand-held system is implement plus hand, Cross (2004) Eq. (14).
#include "sweetspot/design.hpp"

#include <catch2/catch.hpp>
#include <stdexcept>
#include <string>

#include "sweetspot/errors.hpp"

namespace sweetspot {
namespace {

Design table1_top_row() { return Design{Implement::paper_racquet(0.70, 0.25, 0.8)}; }

TEST_CASE("The default design is Table I's top row and is valid") {
  const Design d = table1_top_row();
  CHECK(d.cor == 0.8);
  CHECK(d.impact_duration_s == 0.004);
  CHECK(d.hand.mass_kg == 0.5);
  CHECK(d.forearm_equivalent_mass_kg == 0.5);
  CHECK(d.ball.mass_kg == 0.057);
  CHECK(d.ball.speed_m_s == 50.0);
  CHECK(d.impact_from_butt_m == 0.65);  // 5 cm from the 0.70 m tip
  CHECK_NOTHROW(validate(d));
}

TEST_CASE("Each out-of-range field is named by its path in a design file") {
  const auto error = [](auto change) {
    Design d = table1_top_row();
    change(d);
    try {
      validate(d);
    } catch (const std::invalid_argument& e) {
      return std::string(e.what());
    }
    return std::string("accepted");
  };
  CHECK_THAT(error([](Design& d) { d.cor = 1.2; }), Catch::StartsWith("frame/cor:"));
  CHECK_THAT(error([](Design& d) { d.impact_duration_s = 0.0; }),
             Catch::StartsWith("strings/impact_duration_s:"));
  CHECK_THAT(error([](Design& d) { d.hand.mass_kg = -0.5; }), Catch::StartsWith("hand/mass_kg:"));
  CHECK_THAT(error([](Design& d) { d.hand.center_from_butt_m = 0.8; }),
             Catch::StartsWith("hand/center_from_butt_m:"));
  CHECK_THAT(error([](Design& d) { d.forearm_equivalent_mass_kg = -1.0; }),
             Catch::StartsWith("forearm/equivalent_mass_kg:"));
  CHECK_THAT(error([](Design& d) { d.ball.speed_m_s = 0.0; }),
             Catch::StartsWith("ball/speed_m_s:"));
  CHECK_THAT(error([](Design& d) { d.impact_from_butt_m = -0.01; }),
             Catch::StartsWith("impact/from_butt_m:"));
  CHECK_THAT(error([](Design& d) { d.cor_rigid = 1.5; }), Catch::StartsWith("frame/cor_rigid:"));
  CHECK_THAT(error([](Design& d) { d.stiffness.EI_N_m2 = 0.0; }),
             Catch::StartsWith("frame/EI_N_m2:"));
  CHECK_THAT(error([](Design& d) { d.ball.mass_kg = std::nan(""); }),
             Catch::StartsWith("ball/mass_kg:"));
}

TEST_CASE("The hand-held system is implement plus hand at its centre") {
  const Design d = table1_top_row();
  const MassProperties system = hand_held_system(d);
  const MassProperties racquet = d.implement.mass_properties();
  CHECK(system.mass_kg == Approx(racquet.mass_kg + d.hand.mass_kg));
  CHECK(system.com_from_butt_m * system.mass_kg ==
        Approx(racquet.com_from_butt_m * racquet.mass_kg +
               d.hand.center_from_butt_m * d.hand.mass_kg));
}

}  // namespace
}  // namespace sweetspot

namespace sweetspot {

TEST_CASE("The core refuses an input by type: the field it names and what is wrong, apart") {
  Design d{Implement::paper_racquet(0.70, 0.25, 0.8)};
  d.ball.mass_kg = -0.057;
  try {
    validate(d);
    FAIL("a negative ball mass was accepted");
  } catch (const FieldError& e) {
    CHECK(e.field() == "ball/mass_kg");
    CHECK(e.detail() == "must be > 0 kg, got -0.057 kg");
    CHECK(std::string(e.what()) == e.field() + ": " + e.detail());
  }
  // An impact off the implement, likewise.
  d = Design{Implement::paper_racquet(0.70, 0.25, 0.8)};
  d.impact_from_butt_m = 0.9;
  CHECK_THROWS_AS(validate(d), FieldError);
}

}  // namespace sweetspot
