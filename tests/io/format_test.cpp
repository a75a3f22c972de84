// Writers: numbers for programs read back exactly, numbers for people are
// short, and the text of a cell never breaks its table.
#include "io/format.hpp"

#include <fmt/format.h>

#include <catch2/catch.hpp>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <limits>
#include <random>
#include <string>
#include <vector>

#include "io/outputs.hpp"

namespace sweetspot::io {
namespace {

TEST_CASE("Formats are md, json and csv, nothing else") {
  CHECK(parse_format("md") == Format::kMarkdown);
  CHECK(parse_format("json") == Format::kJson);
  CHECK(parse_format("csv") == Format::kCsv);
  CHECK_FALSE(parse_format("MD"));
  CHECK_FALSE(parse_format(""));
}

TEST_CASE("exact() is the shortest text that reads back to the same double") {
  for (const double value : {0.1, 0.1 + 0.2, 1.0 / 3.0, 1e-300, 5e-324, 123456789.0, -2.5e17}) {
    const std::string text = exact(value);
    CHECK(std::strtod(text.c_str(), nullptr) == value);
  }
  CHECK(exact(0.25) == "0.25");
  CHECK(exact(-0.0) == "0");  // no "-0" in a table
}

TEST_CASE("significant() keeps the digits asked for and never prints -0") {
  CHECK(significant(1117.4321) == "1117.43");
  CHECK(significant(1117.4321, 4) == "1117");
  CHECK(significant(-0.0) == "0");
  // No exponent for an everyday size: rounded to its digits, written whole.
  CHECK(significant(1510.3, 3) == "1510");
  CHECK(significant(60884.2, 4) == "60880");
  CHECK(significant(-60884.2, 4) == "-60880");
  CHECK(significant(999.96, 3) == "1000");
  CHECK(significant(2.5e6, 3) == "2.5e+06");
  CHECK(significant(0.000123, 3) == "0.000123");
}

TEST_CASE(
    "A Markdown cell shows a pipe as the divides sign, never an escape, a CSV field is "
    "quoted only when it must be") {
  CHECK(md_cell("|F_w / F|") == "\u2223F_w / F\u2223");
  CHECK(csv_field("plain") == "plain");
  CHECK(csv_field("a,b") == "\"a,b\"");
  CHECK(csv_field("say \"hi\"") == "\"say \"\"hi\"\"\"");
  CHECK(csv_field("two\nlines") == "\"two\nlines\"");
}

TEST_CASE("A CSV cell a spreadsheet would read as a formula is quoted after a single quote") {
  // The OWASP rule: = + - @ tab CR at the start of a cell.
  CHECK(csv_field("=1+2") == "\"'=1+2\"");
  CHECK(csv_field("=HYPERLINK(\"http://x\")") == "\"'=HYPERLINK(\"\"http://x\"\")\"");
  CHECK(csv_field("+cmd") == "\"'+cmd\"");
  CHECK(csv_field("-2+3") == "\"'-2+3\"");
  CHECK(csv_field("@SUM(A1)") == "\"'@SUM(A1)\"");
  CHECK(csv_field("\t=1") == "\"'\t=1\"");
  CHECK(csv_field("\r=1") == "\"'\r=1\"");
  CHECK(csv_field("+-3") == "\"'+-3\"");
  CHECK(csv_field("-inf") == "\"'-inf\"");
  CHECK(csv_field("-") == "\"'-\"");
  // A formula character elsewhere is text, and a whole number stays a number.
  CHECK(csv_field("a=b") == "a=b");
  CHECK(csv_field("-0.5") == "-0.5");
  CHECK(csv_field("+3") == "+3");
  CHECK(csv_field("-1e-05") == "-1e-05");
  CHECK(csv_plain("-0.5"));
  CHECK_FALSE(csv_plain("-x"));
  CHECK_FALSE(csv_plain("=x"));
}

TEST_CASE("A CSV cell keeps its line breaks inside quotes and shows other control characters") {
  CHECK(csv_field("a\r\nb") == "\"a\r\nb\"");
  CHECK(csv_field(std::string("nul\0here", 8)) == "nul\\x00here");
  CHECK(csv_field("esc\x1b[2J") == "esc\\x1b[2J");
  CHECK(csv_field("tab\tin") == "\"tab\tin\"");
  // Read back by RFC 4180 rules, a multi-line cell is the same cell.
  const std::string cell = csv_field("line one\nline \"two\"");
  CHECK(cell == "\"line one\nline \"\"two\"\"\"");
}

TEST_CASE("Terminal and Markdown text carry no control character") {
  CHECK(terminal_text("a\n# heading") == "a\\n# heading");
  CHECK(terminal_text("\x1b]0;title\x07") == "\\x1b]0;title\\x07");
  CHECK(terminal_text("\x7f") == "\\x7f");
  CHECK(terminal_text("csi \xc2\x9b"
                      "2J") == "csi \\u009b2J");  // U+009B, the C1 CSI
  CHECK(terminal_text("caf\xc3\xa9 \xe2\x80\x94") == "caf\xc3\xa9 \xe2\x80\x94");
  CHECK(terminal_text("bad \xff byte") == "bad \uFFFD byte");
  CHECK(md_cell("x|y\nz") == "x\u2223y\\nz");
  for (const std::string& text : {terminal_text(std::string("\0\x01\x1f\r\t", 5)),
                                  md_cell(std::string("\0\x01\x1f\r\t", 5))}) {
    for (const char c : text) CHECK((static_cast<unsigned char>(c) >= 0x20 && c != 0x7f));
  }
}

TEST_CASE("XML text holds only characters XML 1.0 allows, others as U+FFFD") {
  CHECK(xml_chars("tab\tLF\nCR\r") == "tab\tLF\nCR\r");
  CHECK(xml_chars(std::string("nul\0", 4)) == "nul\uFFFD");
  CHECK(xml_chars("\x01\x1b\x7f") == "\uFFFD\uFFFD\uFFFD");
  CHECK(xml_chars("\xef\xbf\xbe\xef\xbf\xbf") == "\uFFFD\uFFFD");  // U+FFFE, U+FFFF
  CHECK(xml_chars("\xed\xa0\x80") == "\uFFFD\uFFFD\uFFFD");        // a lone surrogate's bytes
  CHECK(xml_chars("\xc2\x85") == "\uFFFD");                        // C1 NEL
  CHECK(xml_chars("\xef\xbf\xbd \xf0\x9f\x8e\xbe \xe2\x88\xa3") ==
        "\xef\xbf\xbd \xf0\x9f\x8e\xbe \xe2\x88\xa3");  // U+FFFD, U+1F3BE, U+2223 stay
  CHECK(xml_chars("cut \xe2\x88") == "cut \uFFFD\uFFFD");
}

TEST_CASE("Every output of an evaluation is in the JSON, null only with a note") {
  DesignFile file{"row1.json",
                  "Table I top row",
                  Design{Implement::paper_racquet(0.70, 0.25, 0.8)},
                  "head_to_handle_mass_ratio",
                  {},
                  Json::object(),
                  {},
                  "auto"};
  const Evaluation e = evaluate(file.design);
  const Json j = evaluation_json(file, e);
  CHECK(j["fidelity"] == "rigid");
  for (const OutputSpec& output : output_specs()) {
    if (output.needs_modes || output.needs_response) continue;
    const Json& value = j["outputs"][std::string(output.name)];
    if (value.is_null()) {
      CHECK(j["notes"].contains(std::string(output.name)));
    } else {
      CHECK(value.get<double>() == output.value(e).value());
    }
  }
}

TEST_CASE("The fidelity note says when the impact barely excites the frame, with its bound") {
  // Cross (2004) Sec. III: a half-sine of duration T excites modes up to about
  // 1.5/T; a mode at f keeps at most 1/(x^2 - 1)^2 of its impulse-limit energy,
  // x = 2 f T. The note is written for the modal and response models only.
  DesignFile file{"stiff.json", "",    Design{Implement::paper_racquet(0.70, 0.25, 0.8)},
                  "",           {},    Json::object(),
                  {},           "auto"};
  const auto note_of = [&](double EI_N_m2, Fidelity fidelity) -> std::string {
    file.design.stiffness.EI_N_m2 = EI_N_m2;
    const Json j = evaluation_json(file, evaluate(file.design, fidelity));
    return j["notes"].contains("fidelity") ? j["notes"]["fidelity"].get<std::string>() : "";
  };
  // A stiff frame: the fundamental is well above 1.5/T.
  file.design.stiffness.EI_N_m2 = 1e4;
  const Evaluation stiff = evaluate(file.design, Fidelity::kModal);
  const double f1 = stiff.modal->fundamental_free_Hz, T = stiff.impact_duration_s;
  REQUIRE(f1 > 1.5 / T);
  const double x = 2.0 * f1 * T;
  const std::string note = note_of(1e4, Fidelity::kModal);
  CHECK_THAT(note, Catch::Contains("is above 1.5/T = " +
                                   std::to_string(static_cast<int>(std::lround(1.5 / T))) + " Hz"));
  const std::size_t at = note.find("at most ") + 8;
  // Printed with six decimals: within half the last digit.
  CHECK(std::abs(std::stod(note.substr(at)) - 1.0 / ((x * x - 1) * (x * x - 1))) <= 5e-7);
  CHECK(note_of(1e4, Fidelity::kRigid).empty());  // no modes, nothing to compare
  // The paper's soft beam: its fundamental is below 1.5/T, the rigid model does not answer.
  file.design.stiffness.EI_N_m2 = 152.0;
  REQUIRE(evaluate(file.design, Fidelity::kModal).modal->fundamental_free_Hz < 1.5 / T);
  CHECK(note_of(152.0, Fidelity::kModal).empty());
}

TEST_CASE(
    "A bat's spec line is a bat's: ounces, and the inertia about the pivot 6 in from the knob") {
  // A uniform rod 80 cm long, 5 cm across, of wood at 600 kg/m^3: M = rho pi d^2 L / 4,
  // balance L / 2, and about the pivot 6 in (0.1524 m) from the knob
  // M L^2 / 12 + M (L / 2 - 0.1524)^2 (the parallel axes).
  constexpr double kPi = 3.14159265358979323846;
  const double L = 0.8, dia = 0.05, M = 600.0 * kPi * dia * dia / 4.0 * L;
  DesignFile file{
      "rod.json", "",    Design{Implement::from_profile({{{0.0, dia}, {L, dia}}, 600.0, 1e10})},
      "",         {},    Json::object(),
      {},         "auto"};
  file.design.impact_from_butt_m = 0.6;
  const std::string md =
      evaluation_report(file, evaluate(file.design, Fidelity::kRigid), Format::kMarkdown);
  const double moi_kg_cm2 = (M * L * L / 12.0 + M * (L / 2 - 0.1524) * (L / 2 - 0.1524)) * 1e4;
  CHECK_THAT(md, Catch::Contains("mass " + significant(M * 1000, 4) + " g (" +
                                 significant(M / 0.028349523125, 4) +
                                 " oz), balance 40 cm "
                                 "(15.75 in) from the knob, moment of inertia " +
                                 significant(moi_kg_cm2, 4) + " kg·cm² about a pivot 6 in"));
  CHECK_THAT(md, !Catch::Contains("pts head-"));
}

TEST_CASE("An evaluation's CSV and Markdown apply their format's rule to a hostile name") {
  DesignFile file{"a\nb.json",
                  "=cmd|x\n# injected\x1b[2J",
                  Design{Implement::paper_racquet(0.70, 0.25, 0.8)},
                  "head_to_handle_mass_ratio",
                  {},
                  Json::object(),
                  {},
                  "auto"};
  const Evaluation e = evaluate(file.design);
  const std::string csv = evaluation_report(file, e, Format::kCsv);
  // The name's cell: neutralised, quoted, the line break kept inside the quotes.
  CHECK(csv.find("\n\"'=cmd|x\n# injected\\x1b[2J\",") != std::string::npos);
  const std::string md = evaluation_report(file, e, Format::kMarkdown);
  CHECK_THAT(md, Catch::StartsWith("# =cmd\u2223x\\n# injected\\x1b[2J\n"));
  CHECK(md.find("source `a\\nb.json`") != std::string::npos);
  CHECK(md.find("\n# injected") == std::string::npos);
  CHECK(md.find('\x1b') == std::string::npos);
}

TEST_CASE("Appending a number writes exactly the text exact() gives, shortest and round-trip") {
  const unsigned seed = 20040622;
  INFO("seed " << seed);
  std::mt19937_64 random(seed);
  std::vector<double> values{0.0,
                             -0.0,
                             1.0,
                             -1.0,
                             0.1,
                             0.3,
                             1e-300,
                             5e-324,
                             -2.2250738585072014e-308,
                             std::numeric_limits<double>::max(),
                             1e21,
                             123456789012345680.0,
                             250.06908906015684,
                             std::numeric_limits<double>::infinity(),
                             -std::numeric_limits<double>::infinity()};
  for (int i = 0; i < 10000; ++i) {
    double value = 0.0;
    const std::uint64_t bits = random();
    std::memcpy(&value, &bits, sizeof value);
    if (!std::isnan(value)) values.push_back(value);
  }
  for (const double value : values) {
    std::string text = "x";
    append_exact(text, value);
    CHECK(text == "x" + exact(value));
    if (std::isfinite(value)) CHECK(std::strtod(exact(value).c_str(), nullptr) == value);
  }
  std::string zero;
  append_exact(zero, -0.0);
  CHECK(zero == "0");
}

}  // namespace
}  // namespace sweetspot::io

namespace sweetspot::io {

TEST_CASE("exact() writes what fmt's \"{}\" writes for every double, shortest and round-trip") {
  // The oracle is fmt::format("{}", x), the text every CSV and JSON number had
  // before exact() laid out the shortest digits itself: random bit patterns,
  // everyday magnitudes, and both sides of every place the layout changes
  // (the decimal exponents -5/-4 and 15/16, integers, three-digit exponents).
  const unsigned seed = 20261130;
  INFO("seed " << seed);
  std::mt19937_64 random(seed);
  std::vector<double> values;
  for (int i = 0; i < 200000; ++i) {
    double value = 0.0;
    const std::uint64_t bits = random();
    std::memcpy(&value, &bits, sizeof value);
    values.push_back(value);
  }
  std::uniform_real_distribution<double> mantissa(-10.0, 10.0);
  std::uniform_int_distribution<int> decade(-12, 20);
  for (int i = 0; i < 200000; ++i)
    values.push_back(mantissa(random) * std::pow(10.0, decade(random)));
  for (int e = -324; e <= 308; ++e) {
    const double power = std::pow(10.0, e);
    for (const double v : {power, std::nextafter(power, 0.0), std::nextafter(power, 1e308),
                           3.0 * power, 1.5 * power, -power, 123456789.0 * power}) {
      values.push_back(v);
    }
  }
  for (std::int64_t k = -2000; k <= 2000; ++k) values.push_back(static_cast<double>(k));
  values.push_back(std::numeric_limits<double>::denorm_min());
  values.push_back(std::numeric_limits<double>::min());
  values.push_back(std::numeric_limits<double>::max());
  values.push_back(9007199254740993.0);
  values.push_back(1e16 - 2.0);
  std::size_t differ = 0;
  for (const double value : values) {
    if (value == 0.0 || std::isnan(value)) continue;  // "0" for both zeros, tested above
    const std::string expected = fmt::format("{}", value);
    if (exact(value) != expected) {
      if (++differ <= 10) FAIL_CHECK(exact(value) << " != " << expected);
    }
  }
  CHECK(differ == 0);
}

TEST_CASE("People's units: cm, g, kg cm^2 and ms, with the key's suffix changed to match") {
  CHECK(people_unit("m").unit == "cm");
  CHECK(people_unit("m").factor == 100.0);
  CHECK(people_unit("kg").unit == "g");
  CHECK(people_unit("kg m^2").factor == 1e4);
  CHECK(people_unit("s").unit == "ms");
  CHECK(people_unit("Hz").unit == "Hz");
  CHECK(people_unit("Hz").suffix.empty());
  CHECK(people_name("cop_hand_from_tip_m", "m") == "cop_hand_from_tip_cm");
  CHECK(people_name("mass_kg", "kg") == "mass_g");
  CHECK(people_name("I_cm_kg_m2", "kg m^2") == "I_cm_kg_cm2");
  CHECK(people_name("impact_duration_s", "s") == "impact_duration_ms");
  CHECK(people_name("rebound_speed_m_s", "m/s") == "rebound_speed_m_s");
  // 0.306761 m * 100 is 30.676100000000002 in binary: six digits are what a person reads.
  CHECK(exact(people_value(0.306761, "m")) == "30.6761");
}

TEST_CASE("A string tension is in pounds for people, a force stays in newtons") {
  // 1 lbf = 4.4482216152605 N exactly (0.45359237 kg x 9.80665 m/s^2).
  CHECK(people_unit("N", "string_bed_tension_N").unit == "lb");
  CHECK(people_name("string_bed_tension_N", "N") == "string_bed_tension_lb");
  CHECK(people_value(0.45359237 * 9.80665 * 52.0, "N", "string_bed_tension_N") == 52.0);
  CHECK(people_unit("N", "peak_wrist_force_N").unit == "N");
  CHECK(people_unit("N", "peak_wrist_force_N").suffix.empty());
  CHECK(people_name("peak_wrist_force_N", "N") == "peak_wrist_force_N");
  CHECK(people_value(300.0, "N", "peak_wrist_force_N") == 300.0);
}

TEST_CASE("A design key's unit is read from its suffix, the longest first") {
  CHECK(unit_of_key("tension_lb") == "lb");
  CHECK(unit_of_key("speed_km_h") == "km/h");
  CHECK(unit_of_key("speed_m_s") == "m/s");
  CHECK(unit_of_key("balance_pts_hl") == "pts head-light");
  CHECK(unit_of_key("swingweight_kg_cm2") == "kg\u00b7cm\u00b2");
  CHECK(unit_of_key("from_tip_cm") == "cm");
  CHECK(unit_of_key("headsize_sq_in") == "sq in");  // an area, not the inch of "_in"
  CHECK(unit_of_key("length_in") == "in");
  CHECK(unit_of_key("head_to_handle_mass_ratio").empty());
  // "_N_m2" is a bending stiffness (N m^2) only as EI; the grip's stiffness
  // per metre of grip is N/m^2, its damping N s/m^2.
  CHECK(unit_of_key("EI_N_m2") == "N\u00b7m\u00b2");
  CHECK(unit_of_key("grip_stiffness_N_m2") == "N/m\u00b2");
  CHECK(unit_of_key("grip_damping_N_s_m2") == "N\u00b7s/m\u00b2");
  CHECK(unit_of_key("impulse_N_s") == "N\u00b7s");
  CHECK(unit_of_key("vibration_energy_J") == "J");
}

}  // namespace sweetspot::io
