#pragma once

// Writers for one evaluated design: Markdown for people, JSON and CSV for
// programs. All output names come from outputs.hpp.

#include <optional>
#include <string>
#include <string_view>

#include "io/design_reader.hpp"
#include "sweetspot/evaluate.hpp"

namespace sweetspot::io {

enum class Format { kMarkdown, kJson, kCsv };

// "md", "json" or "csv"; std::nullopt otherwise.
std::optional<Format> parse_format(std::string_view text);

// `value` with `digits` significant digits, no exponent for everyday magnitudes.
std::string significant(double value, int digits = 6);
// Shortest text that reads back to exactly `value` (for CSV and JSON).
std::string exact(double value);
// exact(value) appended to `out` (no temporary string: the CSV writers' loop).
void append_exact(std::string& out, double value);
// exact(value) written at `out`, which has room for kMaxExactChars; returns
// the end of the text (no terminating NUL). For rows built in a buffer.
inline constexpr std::size_t kMaxExactChars = 32;
char* write_exact(char* out, double value);
// The escaping rule of each format (docs/command-line.md, "What passes through a writer"), applied
// by the writers to every text that comes from a user's file or command line:
//
// Terminal and Markdown text: no control character reaches the output. C0
// controls, DEL and the C1 controls U+0080..U+009F are written as escapes
// ("\n", "\r", "\t", "\x1b", "\u009b"), as messages on stderr write them, so
// a newline in a name cannot start a Markdown heading and an escape sequence
// cannot drive the terminal. Bytes that are not UTF-8 become U+FFFD.
std::string terminal_text(std::string_view text);
// terminal_text() with pipes, which would end a Markdown table cell, as the
// look-alike U+2223 (its escape "\|" shows where Markdown is read as text).
std::string md_cell(std::string_view text);
// A CSV field (RFC 4180): quoted when it holds a comma, a quote, a line break
// or a tab, quotes written twice; line breaks kept inside the quotes (a
// multi-line cell comes back as the same multi-line cell). Control
// characters other than tab and line breaks are escaped as terminal_text()
// writes them (a NUL is "\x00"). A cell a spreadsheet would read as a
// formula (starting with '=', '+', '-', '@', a tab or a CR: the OWASP rule)
// is neutralised: written quoted, after a single quote, unless the whole cell
// reads as a finite number ("-0.5", "+3", "-1e-05" stay numbers).
std::string csv_field(std::string_view text);
// Whether csv_field(text) is `text` itself, decided without a copy (the
// catalogue writer's loop).
bool csv_plain(std::string_view text);
// `text` holding only characters XML 1.0 allows, and none HTML calls a
// control: C0 controls other than tab, LF and CR, DEL, the C1 controls,
// U+FFFE, U+FFFF, surrogates (lone or not: they are not UTF-8) and bytes that
// are not UTF-8 each become U+FFFD. Nothing else changes (no entities: see
// html_escape for text, render_svg for gnuplot's SVG).
std::string xml_chars(std::string_view text);

// A speed as people read it: km/h and mph per m/s (a mile is 1609.344 m).
// A bat's spec sheet: its mass in avoirdupois ounces, and its moment of
// inertia about the pivot 6 in (15.24 cm) from the knob that the bat
// standards' ASTM F2398 measures it on: I_cm + M (B - 6 in)^2 [kg m^2].
inline constexpr double kOunce_kg = 0.028349523125;
inline constexpr double kBatPivot_m = 6 * kInch_m;
double bat_pivot_inertia_kg_m2(const Evaluation& e);

inline constexpr double kKmHPerMS = 3.6;
inline constexpr double kMphPerMS = 3600.0 / 1609.344;

// An output's unit as people read it: cm for m, g for kg, kg·cm² for kg m²,
// ms for s; the others as they are. value_SI * factor is the value in `unit`.
struct PeopleUnit {
  std::string_view unit;    // "cm"
  double factor = 1.0;      // from the SI unit
  std::string_view suffix;  // the key's suffix in that unit ("_cm"), "" when the SI one stands
};
PeopleUnit people_unit(std::string_view si_unit);
// The same for the output `name`: a string tension in N is read in lb (what a
// stringing machine is set in), a force in N stays in N.
PeopleUnit people_unit(std::string_view si_unit, std::string_view name);
// The output's name in people's units: "cop_hand_from_tip_m" -> "cop_hand_from_tip_cm",
// "string_bed_tension_N" -> "string_bed_tension_lb" (the SI name when its unit stays).
std::string people_name(std::string_view name, std::string_view si_unit);
// A value in people's units for CSV and JSON: six significant digits (the
// conversion's float noise, 30.676100000000002, is not a digit anyone needs).
double people_value(double value_si, std::string_view si_unit, std::string_view name = {});
// The unit a design key is written in, from its suffix: "tension_lb" -> "lb",
// "speed_km_h" -> "km/h", "balance_pts_hl" -> "pts head-light"; "" when none.
std::string_view unit_of_key(std::string_view key);

// {"name", "inputs": {canonical name: {"value", "provenance"}}, "outputs": {...},
//  "notes": {output: why null}}.
Json evaluation_json(const DesignFile& design, const Evaluation& evaluation);

// The whole evaluation in `format`.
// In Markdown, `answer` (a paragraph of plain sentences, reports/summary.hpp)
// comes right after the title, before the tables.
std::string evaluation_report(const DesignFile& design, const Evaluation& evaluation, Format format,
                              std::string_view answer = {}, bool people_units = false);
// With `people_units`, CSV gets a column and JSON a key under "outputs_people"
// for every output whose unit people read otherwise (cm, g, kg·cm², ms),
// after the SI ones, which stay as they are.

}  // namespace sweetspot::io
