#include "io/design_reader.hpp"

#include <algorithm>
#include <catch2/catch.hpp>
#include <cmath>
#include <cstdio>
#include <map>
#include <numbers>
#include <string>
#include <vector>

#include "io/design_fields.hpp"
#include "io/input_error.hpp"
#include "sweetspot/evaluate.hpp"
#include "sweetspot/head_geometry.hpp"
#include "sweetspot/string_bed.hpp"

namespace sweetspot::io {
namespace {

constexpr double kRoundOff = 1e-12;

DesignFile read(const char* text) {
  return read_design(parse_json(text, "test.json"), "test.json");
}

// The JSON pointer reading `text` fails at, "(no error)" when it reads.
std::string pointer_of(const char* text) {
  try {
    read(text);
  } catch (const InputError& e) {
    return e.pointer();
  }
  return "(no error)";
}

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

TEST_CASE("A lead's clock position is placed on the head the string bed's size gives") {
  // One head, one size: strings.head_size_in2 alone is implement.headsize_sq_in
  // with the default shape, for the lead at 12 and at 3 and 9 as for the twist.
  const Json bed = Json::parse(R"({
    "implement": {"length_in": 27, "mass_g": 300, "balance_cm": 32.5, "swingweight_kg_cm2": 320,
                  "point_masses": [{"clock": 12, "mass_g": 3}, {"clock": [3, 9], "mass_g": 2}]},
    "strings": {"tension_lb": 52, "head_size_in2": 98}})");
  Json implement = bed;
  implement["strings"].erase("head_size_in2");
  implement["implement"]["headsize_sq_in"] = 98;
  const DesignFile a = read_design(bed, "bed.json");
  const DesignFile b = read_design(implement, "implement.json");
  const std::vector<PointMass>& pa = a.design.implement.point_masses();
  const std::vector<PointMass>& pb = b.design.implement.point_masses();
  REQUIRE(pa.size() == 3);
  REQUIRE(pb.size() == 3);
  for (std::size_t k = 0; k < pa.size(); ++k) {
    CHECK(pa[k].from_butt_m == pb[k].from_butt_m);
    CHECK(pa[k].off_axis_m == pb[k].off_axis_m);
    CHECK(pa[k].mass_kg == pb[k].mass_kg);
  }
  CHECK(pa[1].off_axis_m != 0.0);  // 3 o'clock: off the axis, on the hoop
  // The pair as `tune --places` names it, "3/9", is the list [3, 9].
  Json joined = bed;
  joined["implement"]["point_masses"][1]["clock"] = "3/9";
  const std::vector<PointMass> pj =
      read_design(joined, "joined.json").design.implement.point_masses();
  REQUIRE(pj.size() == 3);
  for (std::size_t k = 0; k < pj.size(); ++k) {
    CHECK(pj[k].from_butt_m == pa[k].from_butt_m);
    CHECK(pj[k].off_axis_m == pa[k].off_axis_m);
  }
  for (const char* bad : {"3/13", "3/", "/9", "3//9", "3/nine", "3 / 9"}) {
    INFO(bad);
    joined["implement"]["point_masses"][1]["clock"] = bad;
    CHECK_THROWS_WITH(read_design(joined, "joined.json"),
                      Catch::Contains("/implement/point_masses/1/clock"));
  }
  REQUIRE(polar_inertia_kg_m2(a.design));
  CHECK(*polar_inertia_kg_m2(a.design) == *polar_inertia_kg_m2(b.design));
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

TEST_CASE("A strung design without a COR reads back solving the same collision") {
  // The solved collision's inputs survive design_to_json: no COR (auto keeps
  // choosing collision), the string bed's mass and loss, the ball's law.
  const DesignFile original = read(R"({"implement": {"length_m": 0.7, "mass_kg": 0.25,
      "head_to_handle_mass_ratio": 0.8}, "frame": {"fundamental_free_Hz": 150},
      "strings": {"tension_N": 230, "bed_mass_g": 6, "bed_damping_ratio": 0.01},
      "ball": {"contact": {"stiffness": 3e5, "damping_exponent": 1.0}}})");
  CHECK(original.design.string_bed_mass_kg == Approx(0.006));
  CHECK(original.design.ball_contact.exponent == kTennisBallLaw.exponent);
  CHECK(needed_fidelity(original.design) == Fidelity::kCollision);
  const DesignFile again = read_design(design_to_json(original), "again.json");
  REQUIRE(needed_fidelity(again.design) == Fidelity::kCollision);
  const Evaluation a = evaluate(original.design, Fidelity::kCollision);
  const Evaluation b = evaluate(again.design, Fidelity::kCollision);
  CHECK(b.apparent_cor == Approx(a.apparent_cor).epsilon(kRoundOff));
  CHECK(b.impact_duration_s == Approx(a.impact_duration_s).epsilon(kRoundOff));
}

TEST_CASE("The three implement forms read from files give the same evaluation") {
  const Evaluation paper = evaluate(read(R"({"implement": {"length_m": 0.7, "mass_kg": 0.25,
      "head_to_handle_mass_ratio": 0.8}})")
                                        .design);
  const Evaluation sections = evaluate(read(R"({"implement": {"sections": [
      {"length_m": 0.35, "mass_kg": 0.1388888888888889},
      {"length_m": 0.35, "mass_kg": 0.1111111111111111}]}})")
                                           .design);
  CHECK(sections.peak_wrist_force_N == Approx(paper.peak_wrist_force_N).epsilon(1e-12));
  const std::string specs_text =
      R"({"implement": {"length_m": 0.7, "mass_kg": 0.25, "balance_from_butt_m": )" +
      std::to_string(paper.balance_from_butt_m) + R"(, "swingweight_kg_cm2": )" +
      std::to_string(paper.swingweight_kg_m2 * 1e4) +
      R"(}, "impact": {"from_tip_m": 0.05}})";  // a spec sheet's default is the centre of the
                                                // strings
  const Evaluation specs = evaluate(read(specs_text.c_str()).design);
  // std::to_string keeps 6 decimals: 1e-6 m in balance, 1e-6 kg cm^2 in swingweight.
  CHECK(specs.peak_wrist_force_N == Approx(paper.peak_wrist_force_N).epsilon(1e-5));
}

TEST_CASE("A round profile is read in people's units and gives the uniform rod's modes") {
  // A solid rod 80 cm long, 5 cm across, of wood at 600 kg/m^3 and 10 GPa:
  // free-free, f1 = (4.7300407^2 / (2 pi L^2)) sqrt(EI / mu) with
  // EI = E pi d^4 / 64 and mu = rho pi d^2 / 4 (Euler-Bernoulli).
  const DesignFile d = read(R"({
    "implement": {"profile": [{"from_butt_cm": 0, "diameter_cm": 5}, {"from_butt_in": 31.496062992125985, "diameter_mm": 50}],
                  "density_kg_m3": 600, "youngs_modulus_GPa": 10},
    "strings": {"impact_duration_ms": 1}, "impact": {"from_tip_cm": 15}})");
  CHECK(d.implement_form == "profile");
  constexpr double kPi = 3.14159265358979323846;
  const double L = 0.8, dia = 0.05, mu = 600.0 * kPi * dia * dia / 4.0;
  const double EI = 10e9 * kPi * dia * dia * dia * dia / 64.0;
  CHECK(d.design.implement.mass_properties().mass_kg == Approx(mu * L).epsilon(kRoundOff));
  const double beta = 4.7300407448627040;
  const Evaluation e = evaluate(d.design, Fidelity::kModal);
  CHECK(e.modal->fundamental_free_Hz ==
        Approx(beta * beta / (2 * kPi * L * L) * std::sqrt(EI / mu)).epsilon(1e-6));
  // The node of a uniform free-free beam's fundamental: 0.2242 L from each end.
  CHECK(L - *e.modal->node_free_from_butt_m == Approx(0.22416 * L).epsilon(1e-4));
}

TEST_CASE("A profile's errors name the key the file used") {
  CHECK(pointer_of(R"({"implement": {"profile": [{"from_butt_cm": 0, "diameter_cm": 5},
        {"from_butt_cm": 40, "diameter_cm": 5}, {"from_butt_cm": 30, "diameter_cm": 6}],
        "density_kg_m3": 600, "youngs_modulus_GPa": 10}})") == "/implement/profile/2/from_butt_cm");
  CHECK(pointer_of(R"({"implement": {"profile": [{"from_butt_cm": 0, "diameter_cm": 5},
        {"from_butt_cm": 40, "diameter_cm": -1}], "density_kg_m3": 600,
        "youngs_modulus_GPa": 10}})") == "/implement/profile/1/diameter_cm");
  CHECK(pointer_of(R"({"implement": {"profile": [{"from_butt_cm": 0, "diameter_cm": 5},
        {"from_butt_cm": 40, "diameter_cm": 5}], "density_kg_m3": 600,
        "youngs_modulus_GPa": 1e9}})") == "/implement/youngs_modulus_GPa");
  // The profile gives every slice its EI: a frame EI beside it would be read and never used.
  CHECK(pointer_of(R"({"implement": {"profile": [{"from_butt_cm": 0, "diameter_cm": 5},
        {"from_butt_cm": 40, "diameter_cm": 5}], "density_kg_m3": 600,
        "youngs_modulus_GPa": 10}, "frame": {"EI_N_m2": 100}})") == "/frame/EI_N_m2");
  CHECK(pointer_of(R"({"implement": {"sections": [{"length_m": 0.7, "mass_kg": 0.3,
        "EI_N_m2": 150}]}, "frame": {"EI_N_m2": 100}})") == "/frame/EI_N_m2");
  CHECK(pointer_of(R"({"implement": {"sections": [{"length_m": 0.7, "mass_kg": 0.3,
        "EI_N_m2": 150}, {"length_m": 0.1, "mass_kg": 0.1}]}, "frame": {"EI_N_m2": 100}})") ==
        "(no error)");
  CHECK(pointer_of(R"({"implement": {"profile": [{"from_butt_cm": 0, "diameter_cm": 5}],
        "density_kg_m3": 600, "youngs_modulus_GPa": 10}})") == "/implement/profile");
  CHECK(pointer_of(R"({"implement": {"profile": [{"from_butt_cm": 0, "diameter_cm": 5},
        {"from_butt_cm": 40, "diameter_cm": 5}], "youngs_modulus_GPa": 10}})") == "/implement");
}

TEST_CASE("JSON errors name the pointer where they are") {
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

namespace sweetspot::io {
namespace {

TEST_CASE("cor_rigid and a string tension are read, and contradict a given COR or duration") {
  const DesignFile d =
      read(R"({"implement": {"length_m": 0.7, "mass_kg": 0.25, "head_to_handle_mass_ratio": 0.8},
      "frame": {"cor_rigid": 0.85, "fundamental_free_Hz": 150},
      "strings": {"tension_lb": 55, "head_size_in2": 100, "string_spacing_mm": 16.5}})");
  REQUIRE(d.design.cor_rigid);
  CHECK(*d.design.cor_rigid == 0.85);
  REQUIRE(d.design.strings);
  CHECK(d.design.strings->tension_N == Approx(55 * 4.4482216152605).epsilon(1e-12));
  // 100 in^2 as the circle of the same area.
  CHECK(d.design.strings->head_radius_m ==
        Approx(std::sqrt(100 * 0.0254 * 0.0254 / 3.141592653589793)).epsilon(1e-12));
  CHECK(d.design.strings->string_spacing_m == Approx(0.0165).epsilon(1e-12));
  CHECK(d.provenance.at("frame/cor").find("derived") != std::string::npos);
  CHECK_THROWS_WITH(
      read(R"({"implement": {"length_m": 0.7, "mass_kg": 0.25, "head_to_handle_mass_ratio": 0.8},
      "frame": {"cor": 0.8, "cor_rigid": 0.85}})"),
      Catch::Contains("/frame/cor_rigid: contradicts"));
  CHECK_THROWS_WITH(
      read(R"({"implement": {"length_m": 0.7, "mass_kg": 0.25, "head_to_handle_mass_ratio": 0.8},
      "strings": {"impact_duration_ms": 4, "tension_N": 250}})"),
      Catch::Contains("/strings/tension_N: contradicts"));
  CHECK_THROWS_WITH(
      read(R"({"implement": {"length_m": 0.7, "mass_kg": 0.25, "head_to_handle_mass_ratio": 0.8},
      "strings": {"tension_N": -250}})"),
      Catch::Contains("/strings/tension_N"));
}

TEST_CASE(
    "A derived COR is below cor_rigid and the tension sets the duration the evaluation uses") {
  const DesignFile d =
      read(R"({"implement": {"length_m": 0.7, "mass_kg": 0.25, "head_to_handle_mass_ratio": 0.8},
      "frame": {"cor_rigid": 0.85, "fundamental_free_Hz": 150}, "strings": {"tension_N": 250}})");
  CHECK(needed_fidelity(d.design) == Fidelity::kResponse);
  CHECK_THROWS_WITH(evaluate(d.design, Fidelity::kModal), Catch::StartsWith("frame/cor_rigid"));
  const Evaluation e = evaluate(d.design, Fidelity::kResponse);
  CHECK(e.cor_derived);
  CHECK(e.cor < 0.85);
  CHECK(e.cor > 0.0);
  REQUIRE(e.vibration_energy_J);
  CHECK(*e.vibration_energy_J > 0.0);
  // The energy balance of the derived COR: (1 - e^2) = (1 - e_r^2) + 2 E_vib / (mu v1^2).
  const double mu = 0.057 * e.effective_mass_kg / (0.057 + e.effective_mass_kg);
  CHECK(1 - e.cor * e.cor ==
        Approx(1 - 0.85 * 0.85 + 2 * *e.vibration_energy_J / (mu * 50 * 50)).epsilon(1e-9));
  CHECK(e.impact_duration_derived);
  const StringBed bed{250.0};
  CHECK(e.impact_duration_s ==
        Approx(tension_impact_duration(bed, 0.057, e.effective_mass_kg).duration_s).epsilon(1e-12));
}

TEST_CASE("A tension outside the verified range is blamed, at the key the file used") {
  // 1e-9 lb of tension: a string bed so slack that the contact would last
  // minutes. The tension's range (kMinTension_N, issue 20) refuses it when the
  // file is read, at the key and in the unit the file used.
  CHECK_THROWS_WITH(
      read(R"({"implement": {"length_m": 0.7, "mass_kg": 0.25, "head_to_handle_mass_ratio": 0.8},
      "strings": {"tension_lb": 1e-9}})"),
      Catch::StartsWith(
          "test.json: /strings/tension_lb: must be in [4.496, 224.8] lb (20 to 1000 N), got 1e-09 "
          "lb"));
}

TEST_CASE("A lean read gives the same design and the same errors, without provenance or key map") {
  // The oracle is read_design itself: the same evaluation bit for bit, and
  // the same message for a reader error, a core error at a converted key and
  // a core error found only after reading.
  const auto outcome = [](auto&& reader, const char* text) {
    try {
      const DesignFile d = reader(parse_json(text, "test.json"), "test.json");
      return std::to_string(evaluate(d.design).peak_wrist_force_N) + " " + d.name;
    } catch (const InputError& e) {
      return std::string(e.what());
    }
  };
  for (
      const char* text : {
          R"({"name": "specs", "implement": {"length_in": 27, "mass_g": 305, "balance_cm": 32.5,
               "swingweight_kg_cm2": 320}, "impact": {"from_tip_cm": 15}})",
          R"({"implement": {"length_m": 0.7, "mass_kg": 0.25, "head_to_handle_mass_ratio": 0.8},
               "hand": {"mass_g": -5}})",
          R"({"implement": {"length_in": 27, "mass_g": 305, "balance_cm": 80, "swingweight_kg_cm2": 320}})",
          R"({"implement": {"length_m": 0.7, "mass_kg": 0.25, "head_to_handle_mass_ratio": 0.8},
               "impact": {"from_butt_m": 0.9}})"}) {
    INFO(text);
    const std::string full = outcome(read_design, text);
    CHECK(outcome(read_design_lean, text) == full);
  }
  const DesignFile lean =
      read_design_lean(parse_json(R"({"implement": {"length_m": 0.7, "mass_kg": 0.25,
      "head_to_handle_mass_ratio": 0.8}})",
                                  "test.json"),
                       "test.json");
  CHECK(lean.provenance.empty());
  CHECK(lean.keys.empty());
}

}  // namespace
}  // namespace sweetspot::io

namespace sweetspot::io {
namespace {

// The InputError reading (and, with `fidelity`, evaluating) `text` throws.
InputError error_of(const std::string& text, const char* fidelity = nullptr) {
  try {
    const DesignFile d = read_design(parse_json(text, "d.json"), "d.json");
    if (fidelity) evaluate_design_file(d, fidelity, 1e-6);
  } catch (const InputError& e) {
    return e;
  }
  return InputError("d.json", "", "(no error)");
}

TEST_CASE("A core error names the key the file used and quotes the value it gave") {
  const InputError e =
      error_of(R"({"implement": {"sections": [{"length_cm": 5e-324, "mass_kg": 0.1},
                                   {"length_m": 0.7, "mass_kg": 0.2}]}})");
  CHECK(e.pointer() == "/implement/sections/0/length_cm");
  CHECK_THAT(e.detail(), Catch::Contains("length_cm: 5e-324"));
  // In SI the value is printed as the file gave it.
  const InputError si = error_of(R"({"implement": {"length_m": 0.7, "mass_kg": 0.25,
      "head_to_handle_mass_ratio": 0.8}, "hand": {"mass_kg": -1e-300}})");
  CHECK(si.pointer() == "/hand/mass_kg");
  CHECK_THAT(si.detail(), Catch::EndsWith("got -1e-300 kg"));
}

TEST_CASE("A refusal of a quantity the model derived says what it was derived from") {
  // The bed's tension solved from a tap-tone ring, then a ball squeezed past
  // its radius: the ring is the key named, the tension (in N) is not called
  // the ring converted to SI.
  const InputError e = error_of(R"({"implement": {"length_in": 27, "mass_g": 318,
      "balance_cm": 32.5, "swingweight_kg_cm2": 325, "headsize_sq_in": 100},
      "frame": {"RA": 66}, "strings": {"measured_ring_Hz": 1100}, "ball": {"speed_m_s": 62}})",
                                "collision");
  CHECK(e.pointer() == "/strings/measured_ring_Hz");
  CHECK_THAT(e.detail(), Catch::EndsWith("(tension_N, derived from the file's measured_ring_Hz: "
                                         "1100)") &&
                             !Catch::Contains("converted to SI"));
  // The same quantity in another unit is refused in that unit, its range
  // too (the SI range beside it).
  const InputError lb = error_of(R"({"implement": {"length_m": 0.7, "mass_kg": 0.25,
      "head_to_handle_mass_ratio": 0.8}, "strings": {"tension_lb": 1e-9}})");
  CHECK(lb.detail() == "must be in [4.496, 224.8] lb (20 to 1000 N), got 1e-09 lb");
  const InputError g = error_of(R"({"implement": {"length_m": 0.7, "mass_kg": 0.25,
      "head_to_handle_mass_ratio": 0.8}, "hand": {"mass_g": -3}})");
  CHECK(g.pointer() == "/hand/mass_g");
  CHECK_THAT(g.detail(), Catch::StartsWith("must be in [0, ") && Catch::Contains("] g (0 to ") &&
                             Catch::EndsWith(" kg), got -3 g"));
}

// The range [a, b] of a refusal "must be in [a, b] UNIT ...".
std::pair<double, double> range_of(const std::string& detail) {
  double a = 0.0, b = 0.0;
  const std::size_t open = detail.find_first_of("[(");
  REQUIRE(open != std::string::npos);
  REQUIRE(std::sscanf(detail.c_str() + open + 1, "%lf, %lf", &a, &b) == 2);
  return {a, b};
}

TEST_CASE(
    "A place off the head or the strings, or a head too long, is refused in the file's unit") {
  // A 70 cm racquet strung with a 100 sq in head: its bed is an ellipse of
  // aspect 1.35 whose far end is the hoop's 1.5 cm below the tip.
  const std::string racquet = R"({"implement": {"length_cm": 70, "mass_g": 300,
      "balance_cm": 33, "swingweight_kg_cm2": 320}, "strings": {"tension_N": 250,
      "head_size_in2": 100}, "impact": )";
  const double in2 = 0.0254 * 0.0254;
  const HeadEllipse bed = string_bed(HeadShape{100.0 * in2}, 0.70);
  const InputError tip = error_of(racquet + R"({"from_tip_cm": 40}})", "collision");
  const InputError butt = error_of(racquet + R"({"from_butt_cm": 20}})", "collision");
  CHECK(tip.pointer() == "/impact/from_tip_cm");
  CHECK(butt.pointer() == "/impact/from_butt_cm");
  CHECK_THAT(tip.detail(), Catch::Contains("] cm (") && Catch::EndsWith("got 40 cm"));
  CHECK_THAT(butt.detail(), Catch::Contains("] cm (") && Catch::EndsWith("got 20 cm"));
  // From the tip, the range from the butt turned about the tip (4 figures).
  const auto [tip_a, tip_b] = range_of(tip.detail());
  const auto [butt_a, butt_b] = range_of(butt.detail());
  CHECK(tip_a == Approx(70.0 - butt_b).margin(0.01));
  CHECK(tip_b == Approx(70.0 - butt_a).margin(0.01));
  CHECK(tip_a == Approx(1.5).epsilon(1e-3));
  CHECK(tip_b == Approx((0.015 + 2.0 * bed.semi_length_m) * 100.0).epsilon(1e-3));
  // Off the axis on the strings: the ellipse's half-width where the ball lands.
  const InputError off =
      error_of(racquet + R"({"from_butt_cm": 51, "off_axis_cm": 13}})", "collision");
  CHECK(off.pointer() == "/impact/off_axis_cm");
  const double u = (0.51 - bed.center_from_butt_m) / bed.semi_length_m;
  const auto [off_a, off_b] = range_of(off.detail());
  CHECK(off_b == Approx(100.0 * bed.semi_width_m * std::sqrt(1.0 - u * u)).epsilon(1e-3));
  CHECK(off_a == -off_b);
  CHECK_THAT(off.detail(), Catch::EndsWith("got 13 cm"));
  // A head too long: the largest of its aspect whose length and hoop are the
  // implement's, pi (L / 2 - w)^2 / aspect, in the unit the file gave it.
  const double largest_in2 =
      std::numbers::pi * std::pow(0.35 - 0.015, 2) / kDefaultHeadAspectRatio / in2;
  for (const char* key : {R"("strings": {"tension_N": 250, "head_size_in2": 1000})",
                          R"("implement": {"length_cm": 70, "mass_g": 300, "balance_cm": 33,
                               "swingweight_kg_cm2": 320, "headsize_sq_in": 1000})"}) {
    std::string text = std::string(R"({"implement": {"length_cm": 70, "mass_g": 300,
        "balance_cm": 33, "swingweight_kg_cm2": 320}, )") +
                       key + "}";
    if (std::string(key).starts_with(R"("implement")"))
      text = std::string("{") + key + R"(, "frame": {"cor": 0.8}})";
    const InputError head = error_of(text, "collision");
    INFO(head.what());
    CHECK_THAT(head.detail(), Catch::Contains("] sq in ") && Catch::EndsWith("got 1000 sq in"));
    CHECK(range_of(head.detail()).second == Approx(largest_in2).epsilon(1e-3));
  }
}

TEST_CASE("A section error found while evaluating keeps the /implement prefix") {
  // A micrometre stretch of another EI, which finite elements cannot resolve.
  const InputError e = error_of(R"({"implement": {"sections": [
      {"length_m": 0.3, "mass_kg": 0.1, "EI_N_m2": 150},
      {"length_m": 1e-6, "mass_kg": 1e-6, "EI_N_m2": 1e6},
      {"length_m": 0.4, "mass_kg": 0.15, "EI_N_m2": 150}]}})",
                                "modal");
  CHECK(e.pointer() == "/implement/sections/1/length_m");
  CHECK_THAT(e.detail(), Catch::Contains("too short for finite elements"));
}

TEST_CASE("A file name that is not UTF-8 stands in for a missing name as valid UTF-8") {
  const DesignFile d = read_design(parse_json(R"({"implement": {"length_m": 0.7, "mass_kg": 0.25,
      "head_to_handle_mass_ratio": 0.8}})",
                                              "bad\xFF.json"),
                                   "bad\xFF.json");
  CHECK(d.name == "bad\xEF\xBF\xBD.json");
  CHECK(d.source == "bad\xFF.json");
}

}  // namespace
}  // namespace sweetspot::io

namespace sweetspot::io {
namespace {

std::string error_of(const char* text) {
  try {
    read(text);
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

bool has(const std::string& text, const std::string& part) {
  return text.find(part) != std::string::npos;
}

}  // namespace

TEST_CASE("A key of another way of giving the implement is named as that, not as unknown") {
  const std::string sections_and_balance = error_of(R"({"implement": {
      "sections": [{"length_cm": 68.58, "mass_g": 305}], "balance_cm": 32.5}})");
  CHECK(has(sections_and_balance,
            "/implement/balance_cm: belongs to another way of giving the implement than its "
            "sections: give it one way"));
  CHECK_FALSE(has(sections_and_balance, "unknown key"));
  CHECK(has(error_of(R"({"implement": {"length_in": 27, "mass_g": 305, "balance_cm": 32.5,
      "swingweight_kg_cm2": 320, "head_to_handle_mass_ratio": 0.8}})"),
            "/implement/balance_cm: belongs to another way of giving the implement than its "
            "head_to_handle_mass_ratio"));
  CHECK(has(error_of(R"({"implement": {"length_in": 27, "mass_g": 305, "balance_cm": 32.5,
      "swingweight_kg_cm2": 320, "density_kg_m3": 640}})"),
            "/implement/density_kg_m3: belongs to another way of giving the implement than its "
            "balance and swingweight"));
}

TEST_CASE("A place along the implement given in cm or in is refused in that unit") {
  // 27 in = 68.58 cm = 0.6858 m: the range in the key's own unit and in SI.
  const char* const kSpecs =
      R"("length_in": 27, "mass_g": 305, "balance_cm": 32.5, "swingweight_kg_cm2": 320)";
  const auto implement_with = [&](const std::string& rest, const std::string& outside = "") {
    static std::string text;
    text = std::string(R"({"implement": {)") + kSpecs + rest + "}" + outside + "}";
    return error_of(text.c_str());
  };
  CHECK(has(implement_with(R"(, "point_masses": [{"from_tip_cm": -5, "mass_g": 3}])"),
            "/implement/point_masses/0/from_tip_cm: must be in [0, 68.58] cm (0 to 0.6858 m), "
            "got -5 cm"));
  CHECK(has(implement_with(R"(, "point_masses": [{"from_butt_in": 30, "mass_g": 3}])"),
            "/implement/point_masses/0/from_butt_in: must be in [0, 27] in (0 to 0.6858 m), "
            "got 30 in"));
  CHECK(has(implement_with("", R"(, "impact": {"from_tip_cm": 80})"),
            "/impact/from_tip_cm: must be in [0, 68.58] cm (0 to 0.6858 m) on the implement, "
            "got 80 cm"));
  // In metres the core's words stand.
  CHECK(has(implement_with("", R"(, "impact": {"from_tip_m": 0.8})"),
            "/impact/from_tip_m: must be in [0, 0.6858] m (on the implement), got 0.8 m"));
}

TEST_CASE("A bat has no head and no string bed, and a bed's keys need its tension") {
  const char* const kBat = R"("implement": {"profile": [{"from_butt_cm": 0, "diameter_cm": 3},
      {"from_butt_cm": 84, "diameter_cm": 6.6}], "density_kg_m3": 640, "youngs_modulus_GPa": 12.5})";
  const auto bat_with = [&](const std::string& rest) {
    static std::string text;
    text = std::string("{") + kBat + rest + "}";
    return error_of(text.c_str());
  };
  CHECK(bat_with("") == "");
  CHECK(bat_with(R"(, "strings": {"impact_duration_ms": 0.7})") == "");
  CHECK(has(bat_with(R"(, "strings": {"tension_lb": 55})"),
            "/strings/tension_lb: an implement given by its profile is round (a bat, a rod) and "
            "has no string bed"));
  CHECK(has(bat_with(R"(, "strings": {"head_size_in2": 100, "tension_lb": 55})"),
            "/strings/head_size_in2: an implement given by its profile is round (a bat, a rod) "
            "and has no head"));
  // Without a tension, a string bed's keys are not read: each says what it lacks.
  for (const char* key : {"string_spacing_cm", "contact_radius_mm"}) {
    CHECK(has(bat_with(std::string(R"(, "strings": {")") + key + R"(": 1.6})"),
              std::string("/strings/") + key +
                  ": describes a string bed: give its tension (strings.tension_lb)"));
  }
  const std::string bed_size = error_of(R"({"implement": {"length_in": 27, "mass_g": 305,
      "balance_cm": 32.5, "swingweight_kg_cm2": 320}, "strings": {"head_size_in2": 100}})");
  CHECK(has(bed_size, "/strings/head_size_in2: is the string bed's size: give its tension"));
  CHECK_FALSE(has(bed_size, "unknown"));
}

TEST_CASE("A mass too small for its digits is refused in SI, not in a unit its ratio garbles") {
  // 1e-320 g is a subnormal 1e-323 kg: the ratio of the two is 0.000988, not 0.001.
  const std::string tiny = error_of(R"({"implement": {"length_in": 27, "mass_g": 1e-320,
      "balance_cm": 32.5, "swingweight_kg_cm2": 320}})");
  CHECK(has(tiny, "/implement/mass_g: must be in [0.001, 1e+06] kg"));
  CHECK(has(error_of(R"({"implement": {"length_in": 27, "mass_g": 0.5, "balance_cm": 32.5,
      "swingweight_kg_cm2": 320}})"),
            "/implement/mass_g: must be in [1, 1e+09] g (0.001 to 1e+06 kg), got 0.5 g"));
}

TEST_CASE(
    "A misspelt key is named with the keys it may have meant, before any missing key is "
    "complained of") {
  const auto implement_with = [](const std::string& key) {
    static std::string text;
    text = R"({"implement": {")" + key + R"(": 1, "length_in": 27}})";
    return error_of(text.c_str());
  };
  const std::string weight = implement_with("weight_oz");
  CHECK(has(weight, "/implement/weight_oz: unknown key; the mass is given as mass_kg or mass_g"));
  CHECK_FALSE(has(weight, "missing"));
  CHECK(has(implement_with("length_inch"),
            "/implement/length_inch: unknown key; the length is given as length_m, length_cm, "
            "length_mm or length_in"));
  CHECK(has(implement_with("balance_in"),
            "/implement/balance_in: unknown key; the balance is given as balance_from_butt_m, "
            "balance_cm or balance_pts_hl"));
  CHECK(has(implement_with("swingweight"),
            "/implement/swingweight: unknown key; the swingweight is given as swingweight_kg_m2 "
            "or swingweight_kg_cm2"));
  CHECK(has(implement_with("mas_g"), "did you mean mass_g?"));
  // No near key: the list alone, with every spelling the reader accepts.
  const std::string colour = implement_with("colour");
  CHECK(has(colour, "/implement/colour: unknown key (expected one of: length_m, length_cm,"));
  CHECK(has(error_of(R"({"implement": {"length_m": 0.7, "mass_kg": 0.25,
      "head_to_handle_mass_ratio": 0.8}, "ball": {"speed_kph": 50}})"),
            "/ball/speed_kph: unknown key; the speed is given as speed_m_s, speed_km_h or "
            "speed_mph"));
  CHECK(has(error_of(R"({"implement": {"length_m": 0.7, "mass_kg": 0.25,
      "head_to_handle_mass_ratio": 0.8}, "hand": {"colour": 1}})"),
            "speed_km_h") == false);
  CHECK(has(error_of(R"({"implement": {"length_m": 0.7, "mass_kg": 0.25,
      "head_to_handle_mass_ratio": 0.8, "point_masses": [{"weight_g": 5, "clock": 12}]}})"),
            "/implement/point_masses/0/weight_g: unknown key; the mass is given as mass_kg or "
            "mass_g"));
}

TEST_CASE("Every accepted spelling is in the expected keys of its object, and is accepted") {
  // Each spelling of every field of the table that needs no other, written
  // alone into its object, is read (or refused for its value), never unknown.
  for (const DesignField& field : design_fields()) {
    if (field.object.empty() || field.object.find('/') != std::string_view::npos) continue;
    for (const std::string& key : spellings_of(field)) {
      const std::vector<std::string>& keys = design_keys(field.object);
      CHECK(std::find(keys.begin(), keys.end(), key) != keys.end());
      // A field that needs another (a balance needs a spec sheet's swingweight,
      // a string spacing a tension) is another form's key alone.
      if (!field.depends_on.empty()) continue;
      std::string text = R"({"implement": {"length_m": 0.7, "mass_kg": 0.25,
          "head_to_handle_mass_ratio": 0.8}})";
      Json document = Json::parse(text);
      document[std::string(field.object)][key] = 1;
      INFO(field.object << "/" << key);
      try {
        read_design(document, "test.json");
      } catch (const InputError& e) {
        CHECK_FALSE(has(e.what(), "unknown key"));
      }
    }
  }
}

TEST_CASE(
    "A racquet with a head is hit at the centre of its strings when no impact is given, the "
    "paper's designs 5 cm from the tip, and the provenance says so") {
  const DesignFile racquet = read(R"({"implement": {"length_in": 27, "mass_g": 318,
      "balance_cm": 32.5, "swingweight_kg_cm2": 325, "headsize_sq_in": 100},
      "frame": {"RA": 66}, "strings": {"tension_lb": 52}})");
  CHECK(racquet.design.implement.length_m() - racquet.design.impact_from_butt_m ==
        centre_of_strings_from_tip_m(racquet.design));
  CHECK(racquet.provenance.at("impact/from_butt_m") ==
        "default for a racquet: the centre of the strings, 18 cm from the tip");
  // The paper's racquet with a head is a racquet with a head.
  const DesignFile headed = read(R"({"implement": {"length_m": 0.7, "mass_kg": 0.25,
      "head_to_handle_mass_ratio": 0.8, "headsize_cm2": 600}})");
  CHECK(headed.design.impact_from_butt_m == 0.7 - centre_of_strings_from_tip_m(headed.design));
  const DesignFile paper = read(R"({"implement": {"length_m": 0.7, "mass_kg": 0.25,
      "head_to_handle_mass_ratio": 0.8}})");
  CHECK(paper.design.impact_from_butt_m == 0.7 - 0.05);
  CHECK(paper.provenance.at("impact/from_butt_m") ==
        "default: 5 cm from the tip, as in the paper's Table I");
}

TEST_CASE("The implement's head size is the string bed's, a second, different one is refused") {
  const auto collision = [](int sq_in) {
    const std::string text = R"({"implement": {"length_in": 27, "mass_g": 318, "balance_cm": 32.5,
        "swingweight_kg_cm2": 325, "headsize_sq_in": )" +
                             std::to_string(sq_in) +
                             R"(}, "frame": {"RA": 66}, "strings": {"tension_lb": 52},
        "impact": {"from_tip_cm": 18}})";
    const DesignFile d = read(text.c_str());
    REQUIRE(d.design.strings);
    CHECK(d.design.strings->head_radius_m ==
          Approx(std::sqrt(sq_in * 0.0254 * 0.0254 / 3.141592653589793)).epsilon(1e-12));
    return evaluate(d.design, Fidelity::kCollision);
  };
  const Evaluation small = collision(95), large = collision(110);
  CHECK(small.apparent_cor != large.apparent_cor);
  CHECK(small.impact_duration_s != large.impact_duration_s);
  const std::string both = error_of(R"({"implement": {"length_in": 27, "mass_g": 318,
      "balance_cm": 32.5, "swingweight_kg_cm2": 325, "headsize_sq_in": 95},
      "strings": {"tension_lb": 52, "head_size_in2": 110}})");
  CHECK(has(both, "/strings/head_size_in2: contradicts /implement/headsize_sq_in"));
  // The same size in the two keys is one head.
  CHECK_NOTHROW(read(R"({"implement": {"length_in": 27, "mass_g": 318, "balance_cm": 32.5,
      "swingweight_kg_cm2": 325, "headsize_sq_in": 100},
      "strings": {"tension_lb": 52, "head_size_in2": 100}})"));
}

TEST_CASE("A unit that is a power of ten keeps the digits the user gave: 282 g is 0.282 kg") {
  const DesignFile d = read(R"({"implement": {"length_cm": 68.5, "mass_g": 282,
      "balance_cm": 32.5, "swingweight_kg_cm2": 325}})");
  CHECK(d.design.implement.mass_properties().mass_kg == 0.282);
  CHECK(d.design.implement.length_m() == 0.685);
  CHECK(d.design.implement.mass_properties().com_from_butt_m == 0.325);
}

}  // namespace sweetspot::io

namespace sweetspot::io {
namespace {

std::string source_file(const std::string& path) {
  return read_input_file(std::string(SWEETSPOT_SOURCE_DIR) + "/" + path, kMaxInputFileBytes);
}

// The schema's "properties" of the table's object ("implement/sections/N" ->
// properties.implement.properties.sections.items.properties); nullptr when
// the schema does not describe it.
const Json* schema_properties(const Json& schema, const std::string& object) {
  const Json* node = &schema;
  std::size_t start = 0;
  while (start < object.size()) {
    const std::size_t slash = std::min(object.find('/', start), object.size());
    const std::string token = object.substr(start, slash - start);
    if (token == "N") {
      if (!node->contains("items")) return nullptr;
      node = &(*node)["items"];
    } else {
      if (!node->contains("properties") || !(*node)["properties"].contains(token)) return nullptr;
      node = &(*node)["properties"][token];
    }
    start = slash + 1;
  }
  return node->contains("properties") ? &(*node)["properties"] : nullptr;
}

}  // namespace

TEST_CASE("The schema accepts exactly the keys of the field table, every spelling included") {
  const Json schema = parse_json(source_file("schema/design.schema.json"), "design.schema.json");
  std::vector<std::string> objects;
  for (const DesignField& field : design_fields()) {
    if (std::find(objects.begin(), objects.end(), field.object) == objects.end())
      objects.emplace_back(field.object);
  }
  CHECK(objects.size() == 17);
  for (const std::string& object : objects) {
    INFO("object '" << object << "'");
    const Json* properties = schema_properties(schema, object);
    REQUIRE(properties);
    std::vector<std::string> in_schema;
    for (const auto& [key, value] : properties->items()) in_schema.push_back(key);
    std::vector<std::string> in_table = design_keys(object);
    std::sort(in_schema.begin(), in_schema.end());
    std::sort(in_table.begin(), in_table.end());
    CHECK(in_schema == in_table);
  }
}

TEST_CASE("The design-file page's table of keys names every field of the field table") {
  const std::string page = source_file("docs/design-files.md");
  const std::size_t section = page.find("## Every key");
  REQUIRE(section != std::string::npos);
  const std::size_t table = page.find("| key | meaning", section);
  REQUIRE(table != std::string::npos);
  const std::size_t end = page.find("\n\n", table);
  const std::string rows = page.substr(table, end - table);
  for (const DesignField& field : design_fields()) {
    INFO(field.object << " " << field.stem);
    CHECK(rows.find(std::string(field.stem)) != std::string::npos);
  }
}

}  // namespace sweetspot::io

namespace sweetspot::io {

TEST_CASE("Each field's default in the table is the reader's and the schema's") {
  const DesignFile plain = read(R"({"implement": {"length_m": 0.7, "mass_kg": 0.25,
      "head_to_handle_mass_ratio": 0.8, "point_masses": [{"from_butt_m": 0.1, "mass_g": 1}]}})");
  const DesignFile strung = read(R"({"implement": {"length_m": 0.7, "mass_kg": 0.25,
      "head_to_handle_mass_ratio": 0.8, "headsize_cm2": 600}, "strings": {"tension_N": 250}})");
  const DesignFile round = read(R"({"implement": {"length_m": 0.7, "mass_kg": 0.25,
      "head_to_handle_mass_ratio": 0.8}, "frame": {"EI_N_m2": 300, "cross_section":
      {"shear_modulus_Pa": 1e9, "shape": "circle", "diameter_mm": 64}}})");
  const Design& a = plain.design;
  const Design& b = strung.design;
  REQUIRE(b.strings);
  REQUIRE(b.head);
  // What the reader gives each field when the file leaves it out (the oracle).
  const std::map<std::string, double> read_default{
      {"implement/head_aspect_ratio", b.head->aspect_ratio},
      {"implement/hoop_width_m", b.head->hoop_width_m},
      {"implement/point_masses/N/off_axis_m", a.implement.point_masses().at(0).off_axis_m},
      {"frame/cor", a.cor},
      {"strings/impact_duration_s", a.impact_duration_s},
      {"strings/string_spacing_m", b.strings->string_spacing_m},
      {"strings/contact_radius_m", b.strings->contact_radius_m},
      {"strings/bed_mass_kg", a.string_bed_mass_kg},
      {"strings/bed_damping_ratio", a.string_bed_damping_ratio},
      {"hand/mass_kg", a.hand.mass_kg},
      {"hand/center_from_butt_m", a.hand.center_from_butt_m},
      {"hand/grip_length_m", a.hand.grip_length_m},
      {"hand/grip_stiffness_N_m2", a.hand.grip_stiffness_N_m2},
      {"hand/grip_damping_N_s_m2", a.hand.grip_damping_N_s_m2},
      {"forearm/equivalent_mass_kg", a.forearm_equivalent_mass_kg},
      {"ball/mass_kg", a.ball.mass_kg},
      {"ball/speed_m_s", a.ball.speed_m_s},
      {"ball/diameter_m", a.ball.diameter_m},
      {"ball/contact/stiffness", a.ball_contact.stiffness},
      {"ball/contact/exponent", a.ball_contact.exponent},
      {"ball/contact/damping", a.ball_contact.damping},
      {"ball/contact/damping_exponent", a.ball_contact.damping_exponent},
      {"impact/off_axis_m", a.impact_off_axis_m},
      {"frame/cross_section/poisson_ratio", round.design.stiffness.cross_section.poisson_ratio}};
  const Json schema = parse_json(source_file("schema/design.schema.json"), "design.schema.json");
  std::size_t numbers = 0;
  for (const DesignField& field : design_fields()) {
    const std::string name = std::string(field.object) + "/" + std::string(field.si_key);
    const Json* properties = schema_properties(schema, std::string(field.object));
    REQUIRE(properties);
    INFO(name);
    const auto found = properties->find(std::string(field.si_key));
    REQUIRE(found != properties->end());
    const Json& property = *found;
    CHECK((property.contains("default") && property["default"].is_number()) ==
          field.default_si.has_value());
    if (!field.default_si) continue;
    ++numbers;
    CHECK(property["default"].get<double>() == *field.default_si);
    REQUIRE(read_default.count(name) == 1);
    CHECK(read_default.at(name) == *field.default_si);
  }
  CHECK(numbers == read_default.size());
}

}  // namespace sweetspot::io

namespace sweetspot::io {

// Checks that every key of `node` (a JSON object of the table's `object`) is
// the SI key of one of the table's fields there, recursing into the objects
// and lists the table describes.
void check_si_keys(const Json& node, const std::string& object) {
  for (const auto& [key, value] : node.items()) {
    INFO(object << "/" << key);
    bool si = false;
    for (const DesignField& field : design_fields())
      si = si || (field.object == object && field.si_key == key);
    CHECK(si);
    const std::string inner = object.empty() ? key : object + "/" + key;
    if (value.is_object()) check_si_keys(value, inner);
    if (value.is_array()) {
      for (const Json& item : value) {
        if (item.is_object()) check_si_keys(item, inner + "/N");
      }
    }
  }
}

TEST_CASE("design_to_json writes only the field table's SI keys, and they read back exactly") {
  for (const char* text : {
           R"({"name": "specs + tape + head", "implement": {"length_in": 27, "mass_g": 305,
               "balance_cm": 32, "swingweight_kg_cm2": 325, "headsize_sq_in": 100,
               "twistweight_kg_cm2": 14,
               "point_masses": [{"clock": [3, 9], "mass_g": 2}, {"from_tip_cm": 1, "mass_g": 4,
               "off_axis_cm": 1}]}, "impact": {"from_tip_cm": 17, "off_axis_cm": 2}})",
           R"({"implement": {"sections": [{"length_m": 0.3, "mass_kg": 0.12, "EI_N_m2": 300},
               {"length_m": 0.4, "mass_kg": 0.16, "EI_N_m2": 400}]},
               "frame": {"cor_rigid": 0.85, "cross_section": {"shear_modulus_Pa": 3e9,
               "width_cm": 2, "thickness_cm": 1}}})",
           R"({"implement": {"length_m": 0.7, "mass_kg": 0.25, "head_to_handle_mass_ratio": 0.8},
               "frame": {"EI_N_m2": 300, "cross_section": {"shear_modulus_Pa": 3e9,
               "shape": "ellipse", "width_mm": 24, "thickness_mm": 15, "poisson_ratio": 0.3}}})",
           R"({"implement": {"length_m": 0.7, "mass_kg": 0.25, "head_to_handle_mass_ratio": 0.8},
               "frame": {"EI_N_m2": 300, "cross_section": {"shear_modulus_Pa": 3e9,
               "shape": "box", "width_mm": 24, "thickness_mm": 15, "wall_mm": 2}}})",
           R"({"implement": {"length_m": 0.7, "mass_kg": 0.25,
               "head_to_handle_mass_ratio": 0.8}, "frame": {"RA": 65},
               "strings": {"tension_lb": 55, "bed_mass_g": 6, "bed_damping_ratio": 0.01},
               "ball": {"speed_km_h": 100, "contact": {"stiffness": 3e5}},
               "forearm": {"mass_kg": 1.2}})"}) {
    const DesignFile original = read(text);
    const Json written = design_to_json(original);
    check_si_keys(written, "");
    // In SI the numbers read back as written: the same design, bit for bit.
    const DesignFile again = read_design(written, "again.json");
    CHECK(design_to_json(again) == written);
  }
}

}  // namespace sweetspot::io

namespace sweetspot::io {

TEST_CASE("A support is read by name or as a pivot, written back, and refused with its path") {
  const auto support_of = [](const std::string& value) {
    const std::string text = R"({"implement": {"length_m": 0.7, "mass_kg": 0.25,
        "head_to_handle_mass_ratio": 0.8}, "support": )" +
                             value + "}";
    return read(text.c_str()).design.support;
  };
  CHECK(support_of(R"("free")").kind == Support::Kind::kFree);
  CHECK(support_of(R"("hand")").kind == Support::Kind::kHand);
  CHECK(support_of(R"("head_clamped")").kind == Support::Kind::kHeadClamped);
  CHECK(support_of(R"("handle_clamped")").kind == Support::Kind::kHandleClamped);
  CHECK(support_of(R"("rigid_surface")").kind == Support::Kind::kRigidSurface);
  const Support pivot = support_of(R"({"pivot_from_butt_cm": 15.24})");
  CHECK(pivot.kind == Support::Kind::kPivot);
  CHECK(pivot.pivot_from_butt_m == 0.1524);
  CHECK(read(R"({"implement": {"length_m": 0.7, "mass_kg": 0.25,
      "head_to_handle_mass_ratio": 0.8}})")
            .design.support.kind == Support::Kind::kFree);
  // Written back as read.
  for (const char* value : {R"("hand")", R"("rigid_surface")", R"({"pivot_from_butt_m": 0.2})"}) {
    INFO(value);
    const std::string text = R"({"implement": {"length_m": 0.7, "mass_kg": 0.25,
        "head_to_handle_mass_ratio": 0.8}, "support": )" +
                             std::string(value) + "}";
    const DesignFile once = read(text.c_str());
    const DesignFile twice = read_design(design_to_json(once), "again.json");
    CHECK(twice.design.support.kind == once.design.support.kind);
    CHECK(twice.design.support.pivot_from_butt_m == once.design.support.pivot_from_butt_m);
  }
  // A plate needs no implement.
  CHECK(read(R"({"support": "rigid_surface", "ball": {"speed_m_s": 7.06}})").design.support.kind ==
        Support::Kind::kRigidSurface);
  CHECK(has(error_of(R"({"support": "head_clamped"})"), "/implement: missing"));
  const std::string racquet = R"({"implement": {"length_m": 0.7, "mass_kg": 0.25,
      "head_to_handle_mass_ratio": 0.8}, "support": )";
  const auto error = [&](const std::string& value) {
    return error_of((racquet + value + "}").c_str());
  };
  CHECK(has(error(R"("pivot")"), "/support: a pivot needs its place"));
  CHECK(has(error(R"("vice")"), "/support: expected \"free\""));
  CHECK(has(error("3"), "/support: expected"));
  CHECK(has(error("{}"), "/support: a pivot needs its place"));
  CHECK(has(error(R"({"pivot_from_butt_cm": 15, "at": 1})"), "/support/at"));
  CHECK(has(error(R"({"pivot_from_butt_cm": 90})"), "/support/pivot_from_butt_cm"));
  CHECK(has(error(R"({"pivot_from_butt_cm": "nan"})"), "/support/pivot_from_butt_cm"));
}

TEST_CASE("A ball's law is read by name and its rigid-surface COR as given, both written back") {
  const std::string racquet = R"({"implement": {"length_m": 0.7, "mass_kg": 0.25,
      "head_to_handle_mass_ratio": 0.8}, "ball": )";
  const auto ball = [&](const std::string& value) { return read((racquet + value + "}").c_str()); };
  CHECK(ball("{}").design.ball_contact.form == BallLawForm::kPower);
  CHECK(ball(R"({"contact": {"law": "power", "damping": 50}})").design.ball_contact.damping == 50);
  const DesignFile hysteretic =
      ball(R"({"contact": {"law": "hysteretic"}, "cor_on_rigid_surface": 0.3})");
  CHECK(hysteretic.design.ball_contact.form == BallLawForm::kHysteretic);
  CHECK(hysteretic.design.ball_contact.hysteretic.shell_stiffness ==
        kHystereticTennisBallLaw.hysteretic.shell_stiffness);
  CHECK(hysteretic.design.ball.cor_on_rigid_surface == 0.3);
  const DesignFile twice = read_design(design_to_json(hysteretic), "again.json");
  CHECK(twice.design.ball_contact.form == BallLawForm::kHysteretic);
  CHECK(twice.design.ball.cor_on_rigid_surface == 0.3);
  CHECK(!ball("{}").design.ball.cor_on_rigid_surface);
  // The two-mass ball by name, its body with it, and back under its name.
  const DesignFile two = ball(R"({"contact": {"law": "two_mass"}})");
  CHECK(two.design.ball_contact.form == BallLawForm::kTwoMass);
  CHECK(two.design.ball_contact.body.front_mass_fraction ==
        kTwoMassTennisBallLaw.body.front_mass_fraction);
  CHECK(design_to_json(two).dump().find("\"two_mass\"") != std::string::npos);
  CHECK(read_design(design_to_json(two), "again.json").design.ball_contact.form ==
        BallLawForm::kTwoMass);
  const auto error = [&](const std::string& value) {
    return error_of((racquet + value + "}").c_str());
  };
  CHECK(has(error(R"({"contact": {"law": "maxwell"}})"), "/ball/contact/law: expected \"power\""));
  CHECK(has(error(R"({"contact": {"law": "hysteretic", "damping": 5}})"),
            "/ball/contact/damping: is a coefficient of the power law"));
  CHECK(has(error(R"({"contact": {"law": 1}})"), "/ball/contact/law"));
  CHECK(has(error(R"({"contact": {"law": "two_mass", "exponent": 2}})"),
            "/ball/contact/exponent: is a coefficient of the power law, not of the two_mass ball"));
  CHECK(has(error(R"({"cor_on_rigid_surface": "high"})"), "/ball/cor_on_rigid_surface"));
}

TEST_CASE("A grip is read by its tightness, its stiffness and damping unless they are given") {
  const std::string racquet = R"({"implement": {"length_m": 0.7, "mass_kg": 0.25,
      "head_to_handle_mass_ratio": 0.8}, "hand": )";
  const auto hand = [&](const std::string& value) {
    return read((racquet + value + "}").c_str()).design.hand;
  };
  CHECK(hand("{}").grip_stiffness_N_m2 == kCalibratedGripStiffness_N_m2);
  CHECK(hand(R"({"grip": "paper"})").grip_damping_N_s_m2 == kCalibratedGripDamping_N_s_m2);
  for (const auto& [name, grip] : {std::pair{"light", kLightGrip}, std::pair{"medium", kMediumGrip},
                                   std::pair{"tight", kTightGrip}}) {
    const Hand h = hand(std::string(R"({"grip": ")") + name + "\"}");
    CHECK(h.grip_stiffness_N_m2 == grip.stiffness_N_m2);
    CHECK(h.grip_damping_N_s_m2 == grip.damping_N_s_m2);
  }
  // Written back as the numbers it set, read again as the same hand.
  const DesignFile tight = read((racquet + R"({"grip": "tight"}})").c_str());
  CHECK(read_design(design_to_json(tight), "again.json").design.hand.grip_stiffness_N_m2 ==
        kTightGrip.stiffness_N_m2);
  const auto error = [&](const std::string& value) {
    return error_of((racquet + value + "}").c_str());
  };
  CHECK(has(error(R"({"grip": "firm"})"), "/hand/grip: expected \"paper\", \"light\""));
  CHECK(has(error(R"({"grip": 0.5})"), "/hand/grip: expected a string"));
  // A stiffness or damping given beside the grip replaces that one of the grip's.
  const Hand swept = hand(R"({"grip": "light", "grip_stiffness_N_m2": 1e5})");
  CHECK(swept.grip_stiffness_N_m2 == 1e5);
  CHECK(swept.grip_damping_N_s_m2 == kLightGrip.damping_N_s_m2);
  CHECK(hand(R"({"grip": "tight", "grip_damping_N_s_m2": 10})").grip_stiffness_N_m2 ==
        kTightGrip.stiffness_N_m2);
}

}  // namespace sweetspot::io

namespace sweetspot::io {

TEST_CASE(
    "An ellipse and a box are read with their sizes, and a size of another shape is refused") {
  const std::string frame = R"({"implement": {"length_m": 0.7, "mass_kg": 0.25,
      "head_to_handle_mass_ratio": 0.8}, "frame": {"EI_N_m2": 300, "cross_section":
      {"shear_modulus_Pa": 3e9, )";
  const auto section_of = [&](const std::string& rest) {
    return read((frame + rest + "}}}").c_str()).design.stiffness.cross_section;
  };
  const CrossSection e = section_of(R"("shape": "ellipse", "width_mm": 24, "thickness_mm": 15)");
  CHECK(e.shape == CrossSection::Shape::kEllipse);
  CHECK(e.width_m == 0.024);
  CHECK(e.thickness_m == 0.015);
  const CrossSection b =
      section_of(R"("shape": "box", "width_in": 1, "thickness_cm": 2, "wall_mm": 2)");
  CHECK(b.shape == CrossSection::Shape::kBox);
  CHECK(b.width_m == 0.0254);
  CHECK(b.thickness_m == 0.02);
  CHECK(b.wall_m == 0.002);
  const auto error = [&](const std::string& rest) {
    return error_of((frame + rest + "}}}").c_str());
  };
  CHECK(has(error(R"("shape": "box", "width_mm": 24, "thickness_mm": 15)"),
            "/frame/cross_section: a box needs wall_m"));
  CHECK(has(error(R"("shape": "box", "width_mm": 24, "thickness_mm": 15, "wall_mm": 7.5)"),
            "/frame/cross_section/wall_mm"));
  CHECK(has(error(R"("shape": "box", "width_mm": 24, "thickness_mm": 15, "wall_mm": 7.5)"),
            "give shape rectangle"));
  CHECK(has(error(R"("shape": "ellipse", "width_mm": 24, "thickness_mm": 15, "wall_mm": 2)"),
            "/frame/cross_section/wall_mm"));
  CHECK(has(error(R"("shape": "ellipse", "diameter_mm": 24)"), "/frame/cross_section/diameter_mm"));
  CHECK(has(error(R"("shape": "ellipse", "width_mm": 24)"),
            "/frame/cross_section: an ellipse needs width_m and thickness_m"));
  CHECK(has(error(R"("shape": "oval", "width_mm": 24)"), "ellipse, box or profile"));
}

}  // namespace sweetspot::io

namespace sweetspot::io {

TEST_CASE("A profile's cross-section has no sizes, is written back, and needs a profile") {
  const std::string bat = R"({"implement": {"profile": [{"from_butt_cm": 0, "diameter_cm": 2.5},
      {"from_butt_cm": 84, "diameter_cm": 6.6}], "density_kg_m3": 650, "youngs_modulus_GPa": 12},
      "frame": {"cross_section": {"shear_modulus_Pa": 9e8, "shape": "profile", )";
  const DesignFile read_once = read((bat + R"("poisson_ratio": 0.35}}})").c_str());
  CHECK(read_once.design.stiffness.cross_section.shape == CrossSection::Shape::kProfile);
  const Json written = design_to_json(read_once);
  CHECK(written["frame"]["cross_section"] ==
        Json::parse(R"({"shear_modulus_Pa": 9e8, "shape": "profile", "poisson_ratio": 0.35})"));
  CHECK(design_to_json(read_design(written, "again.json")) == written);
  CHECK(has(error_of((bat + R"("diameter_mm": 60}}})").c_str()),
            "/frame/cross_section/diameter_mm: is one section's size"));
  CHECK(has(error_of((bat + R"("wall_mm": 2}}})").c_str()), "/frame/cross_section/wall_mm"));
  CHECK(has(error_of(R"({"implement": {"length_m": 0.7, "mass_kg": 0.25,
      "head_to_handle_mass_ratio": 0.8}, "frame": {"EI_N_m2": 300, "cross_section":
      {"shear_modulus_Pa": 9e8, "shape": "profile"}}})"),
            "/frame/cross_section/shape: profile takes each section's circle or tube"));
}

}  // namespace sweetspot::io
