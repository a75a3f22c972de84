// compare names every input that differs, on the designs as read, before it
// compares any output (issue 20, item 7), and says "the same implement" only
// when no field of the implement, its frame or its strings differs.
#include "reports/comparison.hpp"

#include <catch2/catch.hpp>
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include "io/design_reader.hpp"

namespace sweetspot::reports {
namespace {

// A strung racquet with a head and one point mass: every part of a design given.
const char* const kBase = R"({
  "name": "A",
  "implement": {"length_in": 27.0, "mass_g": 305, "balance_cm": 32.5, "swingweight_kg_cm2": 320,
                "headsize_sq_in": 100,
                "point_masses": [{"from_butt_m": 0.6, "mass_g": 2}]},
  "frame": {"fundamental_free_Hz": 155},
  "strings": {"tension_N": 250},
  "hand": {"mass_kg": 0.5},
  "forearm": {"equivalent_mass_kg": 0.5},
  "ball": {"mass_kg": 0.057, "speed_m_s": 50},
  "impact": {"from_tip_m": 0.16}
})";

ComparedDesign compared(const io::Json& document) {
  return studies::compare_one(
      io::read_design(document, document["name"].get<std::string>() + ".json"), "rigid", 1e-6);
}

// The first sentence of `compare A B`: what differs in the inputs.
std::string inputs_sentence(const io::Json& b) {
  const io::Json a = io::Json::parse(kBase);
  return differences(compared(a), compared(b)).front();
}

io::Json with(const std::string& pointer, const io::Json& value) {
  io::Json b = io::Json::parse(kBase);
  b["name"] = "B";
  b[io::Json::json_pointer(pointer)] = value;
  return b;
}

TEST_CASE("compare says the same implement, held and hit the same way, for the same design") {
  io::Json b = io::Json::parse(kBase);
  b["name"] = "B";
  CHECK(inputs_sentence(b) == "B against A: the same implement, held and hit the same way.");
}

TEST_CASE("compare says only the ball differs when only the ball differs") {
  CHECK(inputs_sentence(with("/ball/speed_m_s", 40)) ==
        "B against A: the same implement; only the ball differs: speed 50 → 40 m/s.");
  io::Json b = with("/ball/speed_m_s", 40);
  b["ball"]["mass_kg"] = 0.058;
  CHECK(inputs_sentence(b) ==
        "B against A: the same implement; only the ball differs: mass 57 → 58 g and speed 50 → "
        "40 m/s.");
}

TEST_CASE("compare says only the hand differs when only the hand differs") {
  CHECK(inputs_sentence(with("/hand/mass_kg", 0.4)) ==
        "B against A: the same implement; only the hand differs: mass 500 → 400 g.");
  // The hand and the ball: each named with its part.
  io::Json b = with("/hand/mass_kg", 0.4);
  b["ball"]["speed_m_s"] = 40;
  CHECK(inputs_sentence(b) ==
        "B against A: the same implement; the hand and the ball differ: the hand's mass 500 → "
        "400 g and the ball's speed 50 → 40 m/s.");
}

TEST_CASE("compare names what differs in the implement, never calling it the same") {
  // In a player's words where they apply.
  const std::string heavier = inputs_sentence(with("/implement/swingweight_kg_cm2", 330));
  CHECK(heavier.find("a swingweight 10 kg·cm² higher") != std::string::npos);
  CHECK(heavier.find("the same implement") == std::string::npos);
  // Below what a player would notice, the field is still named, with the
  // digits that tell the two apart.
  CHECK(inputs_sentence(with("/implement/mass_g", 305.0001)) ==
        "B against A: frame mass 305 → 305.0001 g.");
  // A head on one and not the other: its size, not the shape of a head that is not there.
  io::Json headless = with("/implement/mass_g", 305);
  headless["implement"].erase("headsize_sq_in");
  CHECK(inputs_sentence(headless) == "B against A: head size 100 sq in → none.");
  // The implement and the ball at once.
  io::Json b = with("/implement/headsize_sq_in", 110);
  b["ball"]["speed_m_s"] = 40;
  CHECK(inputs_sentence(b) ==
        "B against A: head size 100 → 110 sq in; and the ball differs: speed 50 → 40 m/s.");
}

TEST_CASE("compare names a COR the solved collision derived against one given") {
  // At the rigid fidelity the default 0.8 is the COR used; solved, the
  // collision derives its own, and a given 0.8 is then a difference.
  const io::Json a = io::Json::parse(kBase);
  const io::Json b = with("/frame/cor", 0.8);
  const auto at = [](const io::Json& document, const char* fidelity) {
    return studies::compare_one(
        io::read_design(document, document["name"].get<std::string>() + ".json"), fidelity, 1e-6);
  };
  CHECK(differences(at(a, "rigid"), at(b, "rigid")).front() ==
        "B against A: the same implement, held and hit the same way.");
  CHECK(differences(at(a, "auto"), at(b, "auto")).front() ==
        "B against A: the frame's COR derived → 0.8.");
}

TEST_CASE("compare names every input of the read design that differs, by its part") {
  struct Change {
    const char* pointer;
    io::Json value;
    const char* named;  // in the first sentence
  };
  const std::vector<Change> changes{
      {"/implement/length_in", 27.5, "length 68.58 → 69.85 cm"},
      {"/implement/balance_cm", 32.6, "frame balance from the butt 32.5 → 32.6 cm"},
      {"/implement/headsize_sq_in", 110, "head size 100 → 110 sq in"},
      {"/implement/head_aspect_ratio", 1.5, "head's aspect ratio 1.35 → 1.5"},
      {"/implement/hoop_width_m", 0.02, "hoop width 1.5 → 2 cm"},
      {"/implement/twistweight_kg_cm2", 15, "twistweight none → 15 kg·cm²"},
      {"/implement/point_masses/0/mass_g", 3, "1 g heavier"},
      {"/implement/point_masses/0/off_axis_m", 0.01,
       "point mass 1's distance off the axis 0 → 1 cm"},
      {"/frame/fundamental_free_Hz", 170, "the frame's free fundamental 155 → 170 Hz"},
      {"/frame/cor", 0.85, "the frame's COR 0.8 → 0.85"},
      {"/strings/tension_N", 260, "strings at 58.5 lb instead of 56.2 lb"},
      {"/strings/string_spacing_m", 0.017, "the strings' spacing 16.5 → 17 mm"},
      {"/strings/contact_radius_m", 0.035, "the strings' contact radius 3 → 3.5 cm"},
      // (The strung radius follows the head size above: a different
      // strings.head_size_in2 beside the implement's is refused by the reader.)
      {"/strings/bed_mass_kg", 0.005, "the strings' moving mass 4 → 5 g"},
      {"/strings/bed_damping_ratio", 0.01, "the strings' damping ratio 0.008 → 0.01"},
      {"/hand/center_from_butt_m", 0.08, "only the hand differs: centre from the butt 7 → 8 cm"},
      {"/hand/grip_length_m", 0.12, "only the hand differs: grip length 10 → 12 cm"},
      {"/hand/grip_stiffness_N_m2", 3e5, "only the hand differs: grip stiffness"},
      {"/hand/grip_damping_N_s_m2", 2000, "only the hand differs: grip damping"},
      {"/forearm/equivalent_mass_kg", 0.6, "only the forearm differs: equivalent mass 500 → 600 g"},
      {"/ball/contact", io::Json{{"stiffness", 1e6}}, "only the ball differs: contact stiffness"},
      {"/impact/from_tip_m", 0.18, "only the impact differs: distance from the tip 16 → 18 cm"},
      {"/impact/off_axis_m", 0.02, "only the impact differs: distance off the axis 0 → 2 cm"},
      // What is named, not numbered: the ball's law, what holds the implement
      // (a player's: compare refuses a rig).
      {"/ball/contact", io::Json{{"law", "hysteretic"}},
       "only the ball differs: contact law power → hysteretic"},
      {"/support", "hand", "only the support differs: free → hand"},
      {"/swing", io::Json{{"angular_speed_rad_s", 15}, {"pivot_beyond_butt_m", 0.6}},
       "only the swing differs: angular speed none → 15 rad/s and pivot beyond the butt none → "
       "60 cm"},
  };
  for (const Change& change : changes) {
    INFO(change.pointer);
    const std::string sentence = inputs_sentence(with(change.pointer, change.value));
    INFO(sentence);
    CHECK(sentence.find(change.named) != std::string::npos);
    CHECK(sentence.find("held and hit the same way") == std::string::npos);
    const bool player = std::string(change.pointer).starts_with("/hand") ||
                        std::string(change.pointer).starts_with("/forearm") ||
                        std::string(change.pointer).starts_with("/ball") ||
                        std::string(change.pointer).starts_with("/impact") ||
                        std::string(change.pointer).starts_with("/support") ||
                        std::string(change.pointer).starts_with("/swing");
    CHECK((sentence.find("the same implement") != std::string::npos) == player);
  }
}

TEST_CASE("compare compares the designs as read, not the files' text") {
  // The same racquet in other units, other forms and another key order is the
  // same implement, held and hit the same way.
  io::Json b = io::Json::parse(R"({
    "name": "B",
    "impact": {"from_tip_cm": 16},
    "ball": {"speed_m_s": 50, "mass_g": 57},
    "forearm": {"equivalent_mass_g": 500},
    "hand": {"mass_g": 500},
    "strings": {"tension_N": 250},
    "frame": {"fundamental_free_Hz": 155},
    "implement": {"length_m": 0.6858, "mass_kg": 0.305, "balance_from_butt_m": 0.325,
                  "swingweight_kg_cm2": 320, "headsize_cm2": 645.16,
                  "point_masses": [{"from_tip_m": 0.0858, "mass_kg": 0.002}]}
  })");
  CHECK(inputs_sentence(b) == "B against A: the same implement, held and hit the same way.");
  // An impact 52.58 cm from the butt of a 68.58 cm racquet is not, to the
  // last bit, the one 16 cm from the tip: the difference is named, not hidden.
  b["impact"] = io::Json{{"from_butt_m", 0.5258}};
  CHECK(inputs_sentence(b) ==
        "B against A: the same implement; only the impact differs: distance from the tip 16 → "
        "15.99999999999999 cm.");
}

TEST_CASE("a change's two values are printed so that they differ and show the percentage") {
  // Two figures would say 280 N -> 280 N for a 2 % fall: a third figure tells them apart.
  CHECK(change_sentence(283.0, 277.3, 0.02, "N") == "falls by 2 % (283 N → 277 N)");
  // Two figures suffice where they differ and show the percentage.
  CHECK(change_sentence(250.0, 230.0, 0.02, "N") == "falls by 8 % (250 N → 230 N)");
  // Two figures that differ but overstate it (280 -> 270 is 3.6 %): a third.
  CHECK(change_sentence(280.4, 274.6, 0.02, "N") == "falls by 2 % (280 N → 275 N)");
  CHECK(change_sentence(0.95, 0.99, 0.02, "N·m") == "rises by 4 % (0.95 N·m → 0.99 N·m)");
  // Below the threshold, or rounding to 0 %: about the same, the pair still apart.
  CHECK(change_sentence(100.0, 101.0, 0.02, "N") == "is about the same (100 N → 101 N)");
  CHECK(change_sentence(238.45, 238.45, 0.02, "N") == "is about the same (240 N → 240 N)");
  CHECK(change_sentence(0.0, 43.01, 0.02, "N·m") == "goes from 0 N·m to 43 N·m");
  CHECK(change_sentence(280.0, 280.1, 0.0, "N") == "is about the same (280 N → 280 N)");
  // Two figures apart that overstate a change below the threshold (270 -> 280 reads as 4 %).
  CHECK(change_sentence(273.1, 276.1, 0.02, "N") == "is about the same (273 N → 276 N)");
}

// The differences of kBase against a variant, as one paragraph, at `fidelity`.
std::string paragraph(const io::Json& b, const char* fidelity = "rigid") {
  const io::Json a = io::Json::parse(kBase);
  const auto at = [&](const io::Json& d) {
    return studies::compare_one(io::read_design(d, d["name"].get<std::string>() + ".json"),
                                fidelity, 1e-6);
  };
  std::string text;
  for (const std::string& s : differences(at(a), at(b))) text += s + " ";
  return text;
}

TEST_CASE("compare's move of a sweet spot is the difference of the places it prints") {
  // Lead at the tip moves the hand-held COP by a distance whose half-centimetre
  // rounding is not the difference of the rounded places: say it to the millimetre.
  for (const double grams : {4.0, 6.0, 10.0, 16.0}) {
    io::Json b = io::Json::parse(kBase);
    b["name"] = "B";
    b["implement"]["point_masses"].push_back({{"clock", 12}, {"mass_g", grams}});
    const std::string text = paragraph(b);
    INFO(text);
    const std::size_t at = text.find("centre of percussion moves ");
    REQUIRE(at != std::string::npos);
    double move = 0.0, from = 0.0, to = 0.0;
    char unit_a[8], unit_b[8];
    REQUIRE(std::sscanf(text.c_str() + at,
                        "centre of percussion moves %lf %7s toward the %*s (%lf cm → %lf %7s",
                        &move, unit_a, &from, &to, unit_b) == 5);
    CHECK(std::abs(std::abs(to - from) - move) < 1e-9);
  }
}

TEST_CASE("compare says mains and crosses apart when a bed has them apart") {
  io::Json a = io::Json::parse(kBase);
  a["strings"] = io::Json::parse(R"({"mains": {"tension_lb": 52}, "crosses": {"tension_lb": 54}})");
  io::Json b = a;
  b["name"] = "B";
  b["strings"]["mains"]["tension_lb"] = 48;
  std::string text;
  for (const std::string& s : differences(compared(a), compared(b))) text += s + " ";
  INFO(text);
  CHECK(text.find("mains at 48 lb and crosses at 54 lb instead of 52 lb and 54 lb") !=
        std::string::npos);
  CHECK(text.find("strings at 48 lb") == std::string::npos);
  // The crosses alone, by less than a pound: a difference, in pounds.
  io::Json c = a;
  c["name"] = "C";
  c["strings"]["crosses"]["tension_lb"] = 54.4;
  text.clear();
  for (const std::string& s : differences(compared(a), compared(c))) text += s + " ";
  INFO(text);
  CHECK(text.find("mains at 52 lb and crosses at 54.4 lb instead of 52 lb and 54 lb") !=
        std::string::npos);
  CHECK(text.find("the same implement") == std::string::npos);
}

TEST_CASE("compare says a pair of pieces on the hoop is at 3 and 9 o'clock") {
  io::Json b = io::Json::parse(kBase);
  b["name"] = "B";
  b["implement"]["point_masses"].push_back(io::Json::parse(R"({"clock": [3, 9], "mass_g": 5})"));
  const std::string text = paragraph(b);
  INFO(text);
  CHECK(text.find("10 g of added mass at 3 and 9 o'clock (5 g each)") != std::string::npos);
}

TEST_CASE("compare says an off-axis hit is off the axis, with its twist") {
  const std::string text = paragraph(with("/impact/off_axis_cm", 3));
  INFO(text);
  // From none to F0 x 3 cm.
  CHECK(text.find("the twist of a hit 16 cm from the tip, on the axis and 3 cm off the axis "
                  "toward 3 o'clock (peak torque about the long axis) goes from 0 N·m to ") !=
        std::string::npos);
}

TEST_CASE("compare tells two racquets hit at their own default points as such") {
  io::Json a = io::Json::parse(kBase);
  a.erase("impact");
  io::Json b = a;
  b["name"] = "B";
  b["implement"]["headsize_sq_in"] = 115;
  const auto at = [&](const io::Json& d) {
    return studies::compare_one(io::read_design(d, d["name"].get<std::string>() + ".json"), "rigid",
                                1e-6);
  };
  std::string text;
  for (const std::string& s : differences(at(a), at(b))) text += s + " ";
  INFO(text);
  CHECK(text.find("at each one's own default point, the centre of its strings (") !=
        std::string::npos);
}

TEST_CASE("compare tells an impact asked about from another file's default, each by its name") {
  // The first asks about 16 cm from the tip; the second gives none and is
  // hit at the centre of its strings; a paper beam without one, 5 cm from the tip.
  io::Json b = io::Json::parse(kBase);
  b["name"] = "B";
  b.erase("impact");
  const std::string text = paragraph(b);
  INFO(text);
  CHECK(text.find("a hit at each one's own impact (16 cm from the tip as the file asks; at the "
                  "centre of the strings (") != std::string::npos);
  CHECK(text.find(") by default)") != std::string::npos);
  CHECK(text.find("asks about") == std::string::npos);
  io::Json beam = io::Json::parse(R"({"name": "beam", "implement": {"length_m": 0.7,
      "mass_kg": 0.3, "head_to_handle_mass_ratio": 0.8}})");
  const std::string arm = paragraph(beam);
  INFO(arm);
  CHECK(arm.find("around the first's centre of the strings, and the second's default impact, "
                 "5 cm from the tip") != std::string::npos);
  CHECK(arm.find("impact asked about") == std::string::npos);
}

TEST_CASE("compare's arm verdict names each factor's number and which way it points") {
  // A softer frame at the modal fidelity: the rigid body's numbers do not
  // change, the vibration at the hand grows (tests/studies/arm_load_test.cpp).
  const std::string text = paragraph(with("/frame/fundamental_free_Hz", 125), "modal");
  INFO(text);
  CHECK(text.find("On the arm, over nine hits around the centre of the strings (3 cm apart") !=
        std::string::npos);
  CHECK(text.find("the shock at the wrist (mean peak wrist force) is about the same (") !=
        std::string::npos);
  CHECK(text.find("mostly at 125 Hz instead of 155 Hz) rises by") != std::string::npos);
  CHECK(text.find("For the arm, A is the kinder: the vibration points to it") != std::string::npos);
  // A rigid comparison: the vibration is not known, and said so.
  const std::string rigid = paragraph(with("/ball/speed_m_s", 40));
  INFO(rigid);
  CHECK(rigid.find("the vibration at the hand is not known for either") != std::string::npos);
  CHECK(rigid.find("Not known: the rigid model has no vibration.") != std::string::npos);
  CHECK(rigid.find("no factor of those known") != std::string::npos);
}
}  // namespace
}  // namespace sweetspot::reports

namespace sweetspot::reports {

TEST_CASE("compare says a string tension in lb, and no impact duration a string bed does not use") {
  // B has no strings: its impact duration (the default 4 ms) is its input,
  // A's comes from its tension (250 N = 56.2 lb: 250 / 4.4482216152605).
  io::Json b = with("/strings/impact_duration_ms", 6);
  b["strings"].erase("tension_N");
  const std::string sentence = inputs_sentence(b);
  INFO(sentence);
  CHECK(sentence.find("the strings' tension 56.2 lb → none") != std::string::npos);
  CHECK(sentence.find("impact duration none → 6 ms") != std::string::npos);
  CHECK(sentence.find(" N →") == std::string::npos);
}

}  // namespace sweetspot::reports
