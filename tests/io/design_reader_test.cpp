#include "sweetspot/io/design_reader.hpp"

#include <catch2/catch.hpp>

#include "sweetspot/evaluate.hpp"
#include "sweetspot/io/input_error.hpp"

namespace sweetspot::io {
namespace {

constexpr double kRoundOff = 1e-12;

DesignFile read(const char* text) { return read_design(parse_json(text, "test.json"), "test.json"); }

TEST_CASE("Industry units are converted to SI by their key suffix") {
  const DesignFile d = read(R"({
    "implement": {"length_in": 27, "mass_g": 300, "balance_cm": 32, "swingweight_kg_cm2": 320},
    "strings": {"impact_duration_ms": 5}, "hand": {"mass_g": 400, "center_from_butt_cm": 8},
    "ball": {"mass_g": 57, "speed_km_h": 180}, "impact": {"from_tip_cm": 10}})");
  const MassProperties& body = d.design.implement.mass_properties();
  CHECK(d.design.implement.length_m() == Approx(0.6858).epsilon(kRoundOff));
  CHECK(body.mass_kg == Approx(0.300).epsilon(kRoundOff));
  CHECK(body.com_from_butt_m == Approx(0.32).epsilon(kRoundOff));
  CHECK(swingweight_kg_m2(body) == Approx(0.0320).epsilon(kRoundOff));
  CHECK(d.design.impact_duration_s == Approx(0.005).epsilon(kRoundOff));
  CHECK(d.design.hand.mass_kg == Approx(0.4).epsilon(kRoundOff));
  CHECK(d.design.hand.center_from_butt_m == Approx(0.08).epsilon(kRoundOff));
  CHECK(d.design.ball.speed_m_s == Approx(50.0).epsilon(kRoundOff));
  CHECK(d.design.impact_from_butt_m == Approx(0.6858 - 0.10).epsilon(kRoundOff));
  CHECK(d.implement_form == "specs");
}

TEST_CASE("Points head-light count eighths of an inch from the middle towards the butt") {
  const DesignFile d = read(R"({"implement": {"length_in": 27, "mass_g": 300,
                                "balance_pts_hl": 4, "swingweight_kg_cm2": 320}})");
  // 27 in racquet, 4 pts HL: balance at 13.5 in - 0.5 in = 13 in = 33.02 cm.
  CHECK(d.design.implement.mass_properties().com_from_butt_m == Approx(0.3302).epsilon(kRoundOff));
}

TEST_CASE("Absent parts take the Table I top-row values and say so") {
  const DesignFile d = read(R"({"implement": {"length_m": 0.7, "mass_kg": 0.25,
                                "head_to_handle_mass_ratio": 0.8}})");
  CHECK(d.design.cor == 0.8);
  CHECK(d.design.impact_duration_s == 0.004);
  CHECK(d.design.hand.mass_kg == 0.5);
  CHECK(d.design.hand.center_from_butt_m == 0.07);
  CHECK(d.design.forearm_equivalent_mass_kg == 0.5);
  CHECK(d.design.ball.mass_kg == 0.057);
  CHECK(d.design.ball.speed_m_s == 50.0);
  CHECK(d.design.impact_from_butt_m == Approx(0.65).epsilon(kRoundOff));
  CHECK(d.provenance.at("hand/mass_kg") == "default");
  CHECK(d.name == "test.json");
}

TEST_CASE("A forearm given by its mass acts as a third of it at the wrist (Eq. 7)") {
  const DesignFile d = read(R"({"implement": {"length_m": 0.7, "mass_kg": 0.25,
      "head_to_handle_mass_ratio": 0.8}, "forearm": {"mass_kg": 1.5}})");
  CHECK(d.design.forearm_equivalent_mass_kg == 0.5);
}

TEST_CASE("A design written by design_to_json reads back to the same evaluation") {
  for (const char* text : {
           R"({"name": "specs + tape", "implement": {"length_in": 27, "mass_g": 305,
               "balance_pts_hl": 6, "swingweight_kg_cm2": 325,
               "point_masses": [{"from_butt_cm": 66, "mass_g": 4}]}, "impact": {"from_tip_m": 0.2}})",
           R"({"implement": {"sections": [{"length_m": 0.3, "mass_kg": 0.12, "EI_N_m2": 300},
               {"length_m": 0.4, "mass_kg": 0.16}]}, "hand": {"mass_kg": 0}})"}) {
    const DesignFile original = read(text);
    const DesignFile again = read_design(design_to_json(original), "again.json");
    const Evaluation a = evaluate(original.design);
    const Evaluation b = evaluate(again.design);
    CHECK(b.swingweight_kg_m2 == Approx(a.swingweight_kg_m2).epsilon(kRoundOff));
    CHECK(b.peak_impact_force_N == Approx(a.peak_impact_force_N).epsilon(kRoundOff));
    CHECK(b.peak_wrist_force_N == Approx(a.peak_wrist_force_N).epsilon(kRoundOff));
    CHECK(again.design.implement.sections().size() == original.design.implement.sections().size());
  }
}

TEST_CASE("The three implement forms read from files give the same evaluation") {
  const Evaluation paper = evaluate(read(R"({"implement": {"length_m": 0.7, "mass_kg": 0.25,
      "head_to_handle_mass_ratio": 0.8}})").design);
  const Evaluation sections = evaluate(read(R"({"implement": {"sections": [
      {"length_m": 0.35, "mass_kg": 0.1388888888888889},
      {"length_m": 0.35, "mass_kg": 0.1111111111111111}]}})").design);
  CHECK(sections.peak_wrist_force_N == Approx(paper.peak_wrist_force_N).epsilon(1e-12));
  const std::string specs_text =
      R"({"implement": {"length_m": 0.7, "mass_kg": 0.25, "balance_from_butt_m": )" +
      std::to_string(paper.balance_from_butt_m) + R"(, "swingweight_kg_cm2": )" +
      std::to_string(paper.swingweight_kg_m2 * 1e4) + "}}";
  const Evaluation specs = evaluate(read(specs_text.c_str()).design);
  // std::to_string keeps 6 decimals: 1e-6 m in balance, 1e-6 kg cm^2 in swingweight.
  CHECK(specs.peak_wrist_force_N == Approx(paper.peak_wrist_force_N).epsilon(1e-5));
}

TEST_CASE("JSON errors name the pointer where they are") {
  const auto pointer_of = [](const char* text) {
    try {
      read(text);
    } catch (const InputError& e) {
      return e.pointer();
    }
    return std::string("(no error)");
  };
  CHECK(pointer_of(R"({"implement": {"sections": [{"length_m": 0.7, "mass_kg": 0.3,
                      "mass_kg": 0.2}]}})") == "/implement/sections/0/mass_kg");
  CHECK(pointer_of(R"({"implement": {"sections": [{"length_m": 0.7, "mass_kg": 0.3},
                      {"length_m": 0.1, "mass_g": -1}]}})") == "/implement/sections/1/mass_g");
  CHECK(pointer_of(R"({"implement": {"length_m": 0.7, "mass_kg": 0.3,
                      "head_to_handle_mass_ratio": 1}, "hand": {"center_from_butt_in": 30}})") ==
        "/hand/center_from_butt_in");
}

}  // namespace
}  // namespace sweetspot::io
