#include "io/format.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <bit>
#include <charconv>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <string>
#include <utility>

#include "core/check.hpp"
#include "io/evaluation_tree.hpp"
#include "io/json_reader.hpp"
#include "io/outputs.hpp"

namespace sweetspot::io {

std::optional<Format> parse_format(std::string_view text) {
  if (text == "md") return Format::kMarkdown;
  if (text == "json") return Format::kJson;
  if (text == "csv") return Format::kCsv;
  return std::nullopt;
}

double bat_pivot_inertia_kg_m2(const Evaluation& e) {
  const double arm = e.balance_from_butt_m - kBatPivot_m;
  return e.I_cm_kg_m2 + e.mass_kg * arm * arm;
}

std::string significant(double value, int digits) {
  return detail::format_significant(value, digits);
}

std::string exact(double value) {
  std::string text;
  append_exact(text, value);
  return text;
}

namespace {

// "00" .. "99": two digits at a time.
constexpr char kDigitPairs[] =
    "0001020304050607080910111213141516171819"
    "2021222324252627282930313233343536373839"
    "4041424344454647484950515253545556575859"
    "6061626364656667686970717273747576777879"
    "8081828384858687888990919293949596979899";

// Two digits of `pair` (< 100) at `at`.
void write_pair(char* at, std::uint32_t pair) {
  at[0] = kDigitPairs[pair * 2];
  at[1] = kDigitPairs[pair * 2 + 1];
}

// The decimal digits of `value` (> 0) ending at `end`: eight at a time, in
// two independent halves, so that the divisions do not wait on each other.
void digits_before(char* end, std::uint64_t value) {
  while (value >= 100000000) {
    const auto low = static_cast<std::uint32_t>(value % 100000000);
    value /= 100000000;
    end -= 8;
    const std::uint32_t high4 = low / 10000, low4 = low % 10000;
    write_pair(end, high4 / 100);
    write_pair(end + 2, high4 % 100);
    write_pair(end + 4, low4 / 100);
    write_pair(end + 6, low4 % 100);
  }
  auto rest = static_cast<std::uint32_t>(value);
  while (rest >= 100) {
    end -= 2;
    write_pair(end, rest % 100);
    rest /= 100;
  }
  if (rest >= 10) {
    write_pair(end - 2, rest);
  } else {
    *--end = static_cast<char>('0' + rest);
  }
}

// How many decimal digits `value` (> 0) has: log10(2) ~ 1233 / 4096 from its
// bit width guesses the count or one more, which one power of ten settles.
int digit_count(std::uint64_t value) {
  static constexpr std::uint64_t kPowers[20] = {1ull,
                                                10ull,
                                                100ull,
                                                1000ull,
                                                10000ull,
                                                100000ull,
                                                1000000ull,
                                                10000000ull,
                                                100000000ull,
                                                1000000000ull,
                                                10000000000ull,
                                                100000000000ull,
                                                1000000000000ull,
                                                10000000000000ull,
                                                100000000000000ull,
                                                1000000000000000ull,
                                                10000000000000000ull,
                                                100000000000000000ull,
                                                1000000000000000000ull,
                                                10000000000000000000ull};
  const int guess = static_cast<int>((std::bit_width(value) * 1233) >> 12);
  return guess + 1 - (value < kPowers[guess] ? 1 : 0);
}

}  // namespace

char* write_exact(char* out, double value) {
  if (value == 0.0) {
    *out = '0';
    return out + 1;
  }
  if (!std::isfinite(value)) return fmt::format_to(out, "{}", value);
  // fmt's "{}" for a double, written here from the same shortest round-trip
  // digits (fmt's Dragonbox) without its general formatting machinery, which
  // costs twice the digits themselves: tests/io/format_test.cpp compares the
  // two on hundreds of thousands of doubles. The layout is fmt's: fixed
  // notation for a decimal exponent in [-4, 16), without a trailing ".0";
  // else d.ddde+XX. The digits are written where they end up.
  char* p = out;
  if (std::signbit(value)) {
    *p++ = '-';
    value = -value;
  }
  const auto decimal = fmt::detail::dragonbox::to_decimal(value);
  const int count = digit_count(decimal.significand);
  const int exponent = decimal.exponent;  // value = significand * 10^exponent
  const int output_exponent = exponent + count - 1;
  if (output_exponent < -4 || output_exponent >= 16) {
    digits_before(p + 1 + count, decimal.significand);  // d ddd, then d.ddd
    p[0] = p[1];
    if (count > 1) {
      p[1] = '.';
      p += count + 1;
    } else {
      p += 1;
    }
    *p++ = 'e';
    int e = output_exponent;
    *p++ = e < 0 ? '-' : '+';
    if (e < 0) e = -e;
    if (e >= 100) {
      *p++ = static_cast<char>('0' + e / 100);
      e %= 100;
    }
    *p++ = kDigitPairs[e * 2];
    *p++ = kDigitPairs[e * 2 + 1];
    return p;
  }
  if (exponent >= 0) {
    p += count;
    digits_before(p, decimal.significand);
    for (int k = 0; k < exponent; ++k) *p++ = '0';
    return p;
  }
  const int whole = count + exponent;  // digits before the point
  if (whole > 0) {
    digits_before(p + 1 + count, decimal.significand);  // the digits, then the point in place
    for (int k = 0; k < whole; ++k) p[k] = p[k + 1];
    p[whole] = '.';
    return p + 1 + count;
  }
  *p++ = '0';
  *p++ = '.';
  for (int k = 0; k < -whole; ++k) *p++ = '0';
  p += count;
  digits_before(p, decimal.significand);
  return p;
}

void append_exact(std::string& out, double value) {
  char buffer[kMaxExactChars];
  out.append(buffer, static_cast<std::size_t>(write_exact(buffer, value) - buffer));
}

namespace {

constexpr std::string_view kReplacement = "\uFFFD";

// The length of the UTF-8 sequence starting at `text[at]` and its code point;
// 0 when the bytes there are not UTF-8 (overlong forms, surrogates, past
// U+10FFFF, a sequence cut short).
std::size_t utf8_sequence(std::string_view text, std::size_t at, char32_t& code) {
  const auto byte = [&](std::size_t k) { return static_cast<unsigned char>(text[at + k]); };
  const unsigned char lead = byte(0);
  std::size_t length = 0;
  if (lead < 0x80) {
    code = lead;
    return 1;
  }
  if (lead >= 0xC2 && lead <= 0xDF) {
    length = 2;
    code = lead & 0x1F;
  } else if (lead >= 0xE0 && lead <= 0xEF) {
    length = 3;
    code = lead & 0x0F;
  } else if (lead >= 0xF0 && lead <= 0xF4) {
    length = 4;
    code = lead & 0x07;
  } else {
    return 0;
  }
  if (at + length > text.size()) return 0;
  for (std::size_t k = 1; k < length; ++k) {
    if ((byte(k) & 0xC0) != 0x80) return 0;
    code = (code << 6) | (byte(k) & 0x3F);
  }
  const bool overlong = (length == 3 && code < 0x800) || (length == 4 && code < 0x10000);
  if (overlong || code > 0x10FFFF || (code >= 0xD800 && code <= 0xDFFF)) return 0;
  return length;
}

// "\n", "\r", "\t", "\x1b" for a C0 control or DEL, as messages write them.
void append_escaped_control(std::string& out, unsigned char byte) {
  constexpr char kHex[] = "0123456789abcdef";
  if (byte == '\n') {
    out += "\\n";
  } else if (byte == '\r') {
    out += "\\r";
  } else if (byte == '\t') {
    out += "\\t";
  } else {
    out += "\\x";
    out += kHex[byte >> 4];
    out += kHex[byte & 0xf];
  }
}

bool is_c0_or_del(unsigned char byte) { return byte < 0x20 || byte == 0x7f; }

// terminal_text(), and with `pipes` each '|' as U+2223.
std::string visible(std::string_view text, bool pipes) {
  std::string out;
  out.reserve(text.size());
  for (std::size_t at = 0; at < text.size();) {
    const auto byte = static_cast<unsigned char>(text[at]);
    if (byte < 0x80) {
      if (is_c0_or_del(byte)) {
        append_escaped_control(out, byte);
      } else if (pipes && byte == '|') {
        out += "\u2223";
      } else {
        out += text[at];
      }
      ++at;
      continue;
    }
    char32_t code = 0;
    const std::size_t length = utf8_sequence(text, at, code);
    if (length == 0) {
      out += kReplacement;
      ++at;
    } else if (code >= 0x80 && code <= 0x9f) {
      out += fmt::format("\\u{:04x}", static_cast<unsigned>(code));
      at += length;
    } else {
      out.append(text, at, length);
      at += length;
    }
  }
  return out;
}

// Whether a spreadsheet would read `text` as a formula: it starts with one
// of = + - @, a tab or a CR, and is not a number as a whole.
bool reads_as_formula(std::string_view text) {
  if (text.empty()) return false;
  const char first = text.front();
  if (first != '=' && first != '+' && first != '-' && first != '@' && first != '\t' &&
      first != '\r')
    return false;
  if (first != '+' && first != '-') return true;
  std::string_view number = text;
  if (first == '+') number.remove_prefix(1);  // from_chars takes a '-' only
  if (number.empty() || number.front() == '+' || (first == '+' && number.front() == '-'))
    return true;
  double value = 0.0;
  const auto [end, error] = std::from_chars(number.data(), number.data() + number.size(), value);
  return error != std::errc() || end != number.data() + number.size() || !std::isfinite(value);
}

}  // namespace

std::string terminal_text(std::string_view text) { return visible(text, false); }

std::string md_cell(std::string_view text) {
  // A pipe would end the cell, and its escape shows as "\|" wherever Markdown
  // is read as text: the divides sign looks the same and needs none.
  return visible(text, true);
}

bool csv_plain(std::string_view text) {
  for (const char c : text) {
    const auto byte = static_cast<unsigned char>(c);
    if (is_c0_or_del(byte) || c == ',' || c == '"') return false;
  }
  return !reads_as_formula(text);
}

std::string csv_field(std::string_view text) {
  if (csv_plain(text)) return std::string(text);
  const bool formula = reads_as_formula(text);
  std::string field;
  bool quote = formula;
  for (const char c : text) {
    const auto byte = static_cast<unsigned char>(c);
    if (c == ',' || c == '"' || c == '\n' || c == '\r' || c == '\t') quote = true;
    if (is_c0_or_del(byte) && c != '\n' && c != '\r' && c != '\t') {
      append_escaped_control(field, byte);
    } else {
      field += c;
      if (c == '"') field += '"';
    }
  }
  if (formula) field.insert(0, 1, '\'');
  return quote ? "\"" + field + "\"" : field;
}

std::string xml_chars(std::string_view text) {
  std::string out;
  out.reserve(text.size());
  for (std::size_t at = 0; at < text.size();) {
    const auto byte = static_cast<unsigned char>(text[at]);
    if (byte < 0x80) {
      const bool allowed = !is_c0_or_del(byte) || byte == '\t' || byte == '\n' || byte == '\r';
      if (allowed) {
        out += text[at];
      } else {
        out += kReplacement;
      }
      ++at;
      continue;
    }
    char32_t code = 0;
    const std::size_t length = utf8_sequence(text, at, code);
    if (length == 0) {
      out += kReplacement;
      ++at;
      continue;
    }
    if ((code >= 0x80 && code <= 0x9f) || code == 0xFFFE || code == 0xFFFF) {
      out += kReplacement;
    } else {
      out.append(text, at, length);
    }
    at += length;
  }
  return out;
}

PeopleUnit people_unit(std::string_view si_unit) {
  if (si_unit == "m") return {"cm", 100.0, "_cm"};
  if (si_unit == "kg") return {"g", 1000.0, "_g"};
  if (si_unit == "kg m^2") return {"kg·cm²", 1e4, "_kg_cm2"};
  if (si_unit == "kg cm^2") return {"kg·cm²", 1.0, ""};
  if (si_unit == "s") return {"ms", 1000.0, "_ms"};
  if (si_unit == "m/s") return {"m/s", 1.0, ""};
  if (si_unit == "N s") return {"N·s", 1.0, ""};
  if (si_unit == "N m") return {"N·m", 1.0, ""};
  if (si_unit == "1/s^2") return {"1/s²", 1.0, ""};
  return {si_unit, 1.0, ""};
}

PeopleUnit people_unit(std::string_view si_unit, std::string_view name) {
  if (si_unit == "N" && name.ends_with("tension_N")) return {"lb", 1.0 / kPoundForce_N, "_lb"};
  return people_unit(si_unit);
}

std::string people_name(std::string_view name, std::string_view si_unit) {
  const PeopleUnit unit = people_unit(si_unit, name);
  if (unit.suffix.empty()) return std::string(name);
  for (const std::string_view si_suffix : {"_kg_m2", "_m", "_kg", "_s", "_N"}) {
    if (name.ends_with(si_suffix))
      return std::string(name.substr(0, name.size() - si_suffix.size())) + std::string(unit.suffix);
  }
  return std::string(name) + std::string(unit.suffix);
}

double people_value(double value_si, std::string_view si_unit, std::string_view name) {
  const double value = value_si * people_unit(si_unit, name).factor;
  if (!std::isfinite(value) || value == 0.0) return value;
  return std::strtod(fmt::format("{:.6g}", value).c_str(), nullptr);
}

std::string_view unit_of_key(std::string_view key) {
  // The first suffix that ends the key wins: longer ones first. "_N_m2" is
  // N/m² (the grip's stiffness per metre of grip) except in a bending
  // stiffness EI, N·m².
  static constexpr std::pair<std::string_view, std::string_view> kSuffixes[] = {
      {"EI_N_m2", "N·m²"},
      {"_rad_s", "rad/s"},
      {"_rpm", "rpm"},
      {"_km_h", "km/h"},
      {"_m_s", "m/s"},
      {"_mph", "mph"},
      {"_kg_cm2", "kg·cm²"},
      {"_kg_m2", "kg·m²"},
      {"_N_s_m2", "N·s/m²"},
      {"_N_m2", "N/m²"},
      {"_N_m", "N/m"},
      {"_lb_in", "lb/in"},
      {"_g_m", "g/m"},
      {"_kg_m", "kg/m"},
      {"_N_s", "N·s"},
      {"_in2", "sq in"},
      {"_sq_in", "sq in"},
      {"_cm2", "cm²"},
      {"_pts_hl", "pts head-light"},
      {"_pts", "points"},
      {"_Hz", "Hz"},
      {"_Pa", "Pa"},
      {"_ms", "ms"},
      {"_mm", "mm"},
      {"_cm", "cm"},
      {"_in", "in"},
      {"_lb", "lb"},
      {"_oz", "oz"},
      {"_kg", "kg"},
      {"_g", "g"},
      {"_J", "J"},
      {"_N", "N"},
      {"_s", "s"},
      {"_m", "m"}};
  for (const auto& [suffix, unit] : kSuffixes) {
    if (key.ends_with(suffix)) return unit;
  }
  return {};
}

namespace {

// A number for people: four significant digits, no exponent for everyday sizes.
std::string people_text(double value) { return significant(value, 4); }

// Every input of the design as people read it: what the file gave, in the unit
// and words it used ("/strings/tension_lb = 52 lb, 231.3 N"), then what was
// left to its default or derived, in people's units.
std::string inputs_markdown(const DesignFile& file, const Evaluation& e) {
  std::string md = "\nInputs as given in the file:\n\n";
  std::vector<std::string> shown;  // a key recorded under two canonical names is shown once
  for (const auto& [canonical, origin] : file.keys) {
    if (std::find(shown.begin(), shown.end(), origin.pointer) != shown.end()) continue;
    shown.push_back(origin.pointer);
    const std::string_view key =
        std::string_view(origin.pointer).substr(origin.pointer.rfind('/') + 1);
    const std::string_view unit = unit_of_key(key);
    md += fmt::format("- `{}` = {}{}{}\n", origin.pointer, md_cell(given_text(origin)),
                      unit.empty() ? "" : " ", unit);
  }
  const Design& d = file.design;
  const auto line = [&](const char* name, const char* what, double si, std::string_view si_unit) {
    const auto it = file.provenance.find(name);
    if (it == file.provenance.end() || it->second == "given" || it->second.starts_with("given"))
      return std::string();
    const PeopleUnit unit = people_unit(si_unit);
    const std::string_view solved = evaluation_tree_detail::solved_provenance(name, e);
    return fmt::format("- {}: {}{}{} ({})\n", what, people_text(si * unit.factor),
                       unit.unit.empty() ? "" : " ", unit.unit,
                       md_cell(solved.empty() ? it->second : std::string(solved)));
  };
  // On a rig nothing of the player is used (the vice sits where the hand
  // would), on a rigid surface no implement.
  const bool plate = e.support.kind == Support::Kind::kRigidSurface;
  const bool player = !is_rig(e.support);
  std::string rest;
  if (!plate) {
    rest +=
        line("impact/from_butt_m", "impact from the tip", e.length_m - d.impact_from_butt_m, "m");
  }
  rest += line("strings/impact_duration_s", "impact duration", e.impact_duration_s, "s");
  rest += line("frame/cor", "frame COR", e.cor, "");
  if (player) rest += line("hand/mass_kg", "hand mass", d.hand.mass_kg, "kg");
  if (player || e.support.kind == Support::Kind::kHandleClamped) {
    rest += line("hand/center_from_butt_m", "hand centre from the butt", d.hand.center_from_butt_m,
                 "m");
  }
  if (player) {
    rest += line("forearm/equivalent_mass_kg", "forearm equivalent mass",
                 d.forearm_equivalent_mass_kg, "kg");
  }
  rest += line("ball/mass_kg", "ball mass", d.ball.mass_kg, "kg");
  rest += line("ball/speed_m_s", "ball speed", d.ball.speed_m_s, "m/s");
  if (e.details && e.details->collision)
    rest += line("ball/diameter_m", "ball diameter", d.ball.diameter_m, "m");
  if (!rest.empty())
    md += "\nDefaulted or derived (defaults are Cross (2004) Table I, top row):\n\n" + rest;
  if (plate) return md + "\nNo implement: the ball meets a rigid plate.\n";
  // The implement in a spec sheet's words: a bat's (ounces, and its moment of
  // inertia about the pivot 6 in from the knob that ASTM F2398 measures it
  // on), or a racquet's (points head-light, the swingweight 10 cm from the butt).
  if (is_round(d)) {
    md += fmt::format(
        "\nThe implement as a bat's spec sheet says it: length {} cm ({} in), mass {} g ({} oz), "
        "balance {} cm ({} in) from the knob, moment of inertia {} kg·cm² about a pivot 6 in "
        "(15.24 cm) from the knob (the bat standards' ASTM F2398).\n",
        people_text(e.length_m * 100), people_text(e.length_m / kInch_m),
        people_text(e.mass_kg * 1000), people_text(e.mass_kg / kOunce_kg),
        people_text(e.balance_from_butt_m * 100), people_text(e.balance_from_butt_m / kInch_m),
        people_text(bat_pivot_inertia_kg_m2(e) * 1e4));
  } else {
    const double points_head_light = (0.5 * e.length_m - e.balance_from_butt_m) / kPointHeadLight_m;
    md += fmt::format(
        "\nThe implement as a spec sheet says it: length {} cm ({} in), mass {} g, balance {} cm "
        "from the butt ({} pts {}), swingweight {} kg·cm².\n",
        people_text(e.length_m * 100), people_text(e.length_m / 0.0254),
        people_text(e.mass_kg * 1000), people_text(e.balance_from_butt_m * 100),
        people_text(std::fabs(points_head_light)),
        points_head_light >= 0 ? "head-light" : "head-heavy",
        people_text(e.swingweight_kg_m2 * 1e4));
  }
  if (d.strings) {
    const StringBed& bed = *d.strings;
    const std::string pull =
        bed.cross_tension_ratio == 1.0
            ? people_text(bed.pull_tension_N() / kPoundForce_N) + " lb"
            : people_text(bed.pull_tension_N() / kPoundForce_N) + " lb mains, " +
                  people_text(bed.pull_tension_N() * bed.cross_tension_ratio / kPoundForce_N) +
                  " lb crosses";
    if (bed.tension_loss > 0.0) {
      md += fmt::format(
          "String tension {} on the machine; the bed holds {} % less ({} N in each "
          "main).\n",
          pull, people_text(bed.tension_loss * 100.0), people_text(bed.tension_N));
    } else {
      md +=
          fmt::format("String tension {} ({} N in each main).\n", pull, people_text(bed.tension_N));
    }
  }
  return md;
}

}  // namespace

namespace evaluation_tree_detail {

std::string_view solved_provenance(std::string_view name, const Evaluation& e) {
  if (!(e.details && e.details->collision)) return {};
  if (name == "frame/cor") return "derived from the solved collision (Eq. 16 inverted)";
  if (name == "strings/impact_duration_s") return "the solved collision's contact time";
  return {};
}

// The modal and response models on a frame whose free fundamental is above
// 1.5/T, which a half-sine of duration T barely excites (Cross 2004, Sec.
// III); every mode keeps at most 1/(x^2 - 1)^2 of its impulse-limit energy,
// x = 2 f1 T.
std::string fidelity_note(const Evaluation& e) {
  if (!e.modal || (e.fidelity != Fidelity::kModal && e.fidelity != Fidelity::kResponse)) return {};
  const double limit_Hz = 1.5 / e.impact_duration_s;
  const double f1 = e.modal->fundamental_free_Hz;
  if (!(f1 > limit_Hz)) return {};
  const double x = 2.0 * f1 * e.impact_duration_s;
  return "the free fundamental (" + std::to_string(static_cast<int>(std::lround(f1))) +
         " Hz) is above 1.5/T = " + std::to_string(static_cast<int>(std::lround(limit_Hz))) +
         " Hz: the impact barely excites the frame (every mode keeps at most " +
         std::to_string(1.0 / ((x * x - 1) * (x * x - 1))) +
         " of its impulse-limit energy), so the rigid model answers this design";
}

std::optional<std::pair<std::string, Json>> given_elsewhere(const DesignFile& file,
                                                            std::string_view name) {
  const auto origin = file.keys.find(std::string(name));
  if (origin == file.keys.end()) return std::nullopt;
  const std::string& pointer = origin->second.pointer;
  if (std::string_view(pointer).substr(pointer.rfind('/') + 1) == name.substr(name.rfind('/') + 1))
    return std::nullopt;
  const Json& given = origin->second.given;
  if (!given.is_number()) return std::nullopt;
  return std::pair{pointer, given};
}

}  // namespace evaluation_tree_detail

namespace {

// write_evaluation()'s node for a JSON document.
class JsonNode {
 public:
  explicit JsonNode(Json& json) : json_(&json) {}
  void number(std::string_view key, double value) { at(key) = value; }
  void integer(std::string_view key, std::int64_t value) { at(key) = value; }
  void text(std::string_view key, std::string_view value) { at(key) = value; }
  void null(std::string_view key) { at(key) = nullptr; }
  void numbers(std::string_view key, const std::vector<double>& values) { at(key) = values; }
  void json_number(std::string_view key, const Json& value) { at(key) = value; }
  JsonNode object(std::string_view key) {
    Json& child = at(key);
    child = Json::object();
    return JsonNode(child);
  }
  class List {
   public:
    explicit List(Json& json) : json_(&json) {}
    JsonNode object() { return JsonNode(json_->emplace_back(Json::object())); }

   private:
    Json* json_;
  };
  List list(std::string_view key) {
    Json& child = at(key);
    child = Json::array();
    return List(child);
  }

 private:
  Json& at(std::string_view key) { return (*json_)[std::string(key)]; }
  Json* json_;
};

}  // namespace

Json evaluation_json(const DesignFile& file, const Evaluation& e) {
  Json j = Json::object();
  JsonNode root(j);
  write_evaluation(root, file, e);
  return j;
}

std::string evaluation_report(const DesignFile& file, const Evaluation& e, Format format,
                              std::string_view answer, bool people_units) {
  if (format == Format::kJson) {
    Json j = evaluation_json(file, e);
    if (people_units) {
      Json& people = j["outputs_people"];
      people = Json::object();
      for (const OutputSpec& output : output_specs()) {
        if (people_unit(output.unit, output.name).suffix.empty()) continue;
        const auto value = output.value(e);
        people[people_name(output.name, output.unit)] =
            value ? Json(people_value(*value, output.unit, output.name)) : Json(nullptr);
      }
    }
    return j.dump(2, ' ', false, Json::error_handler_t::replace) + "\n";
  }
  if (format == Format::kCsv) {
    std::string header = "name";
    std::string row = csv_field(file.name);
    for (const OutputSpec& output : output_specs()) {
      header += "," + std::string(output.name);
      const auto value = output.value(e);
      row += "," + (value ? exact(*value) : std::string());
    }
    if (people_units) {
      for (const OutputSpec& output : output_specs()) {
        if (people_unit(output.unit, output.name).suffix.empty()) continue;
        header += "," + people_name(output.name, output.unit);
        const auto value = output.value(e);
        row +=
            "," + (value ? exact(people_value(*value, output.unit, output.name)) : std::string());
      }
    }
    return header + "\n" + row + "\n";
  }
  std::string md = fmt::format("# {}\n\n", md_cell(file.name));
  if (!answer.empty()) md += terminal_text(answer) + "\n\n";
  md += fmt::format(
      "{} of Cross (2004); source `{}`.{}\n\n",
      is_rig(e.support) ? "The solved collision on a rig (support " +
                              std::string(to_string(e.support.kind)) + "), beyond the model"
      : e.vibration_energy_J ? "Rigid-body model, vibration modes and impact response"
      : e.modal              ? "Rigid-body model and vibration modes"
                             : "Rigid-body model",
      md_cell(file.source),
      e.modal && e.modal->mass_distribution_fitted
          ? " The mass distribution for the modes was fitted to the specs (quadratic density)."
          : "");
  md += "| quantity | value | unit | output (SI in JSON and CSV) |\n|---|---:|---|---|\n";
  // A bat has no string bed to ask for.
  const bool strung = can_be_strung(file.design);
  for (const OutputSpec& output : output_specs()) {
    if (output.needs_modes && !output.value(e)) continue;
    if (!strung && of_the_string_bed(output) && !output.value(e)) continue;
    // A rig's table holds what the rig gives (the rest is the player's).
    if (is_rig(e.support) && !given_on_rig(output.name, e.support.kind)) continue;
    const auto value = output.value(e);
    const PeopleUnit unit = people_unit(output.unit, output.name);
    md += fmt::format("| {} | {} | {} | `{}` |\n",
                      md_cell(value ? std::string(output.description)
                                    : std::string(output.description) + "; " +
                                          std::string(output.absent_because(e))),
                      value ? people_text(*value * unit.factor) : std::string("—"), unit.unit,
                      output.name);
  }
  if (!e.modal && !is_rig(e.support)) {
    md += "\nVibration modes: not evaluated (rigid fidelity; they need the frame's stiffness).\n";
  }
  const Evaluation::Details details = e.details.value_or(Evaluation::Details{});
  if (!details.vibration_modes.empty()) {
    md += fmt::format(
        "\nEnergy each mode of the {} frame keeps after the impact:\n\n| mode | frequency (Hz) | "
        "energy (J) |\n|---:|---:|---:|\n",
        e.support.kind == Support::Kind::kHandleClamped ? "clamped"
        : e.support.kind == Support::Kind::kPivot       ? "pivoted"
        : e.support.kind == Support::Kind::kHand        ? "hand-held"
                                                        : "free");
    for (std::size_t k = 0; k < details.vibration_modes.size(); ++k) {
      md += fmt::format("| {} | {:.1f} | {} |\n", k + 1, details.vibration_modes[k].first,
                        significant(details.vibration_modes[k].second, 4));
    }
    if (details.collision && e.vibration_energy_J) {
      // The ledger's vibration is more than the modes keep: say what else.
      double modes_J = 0.0;
      for (const auto& mode : details.vibration_modes) modes_J += mode.second;
      md += fmt::format(
          "\nThe modes keep {} J of the {} J the impact put into vibration; the string bed keeps "
          "{} J and the frame's damping took {} J during the contact.\n",
          significant(modes_J, 4), significant(*e.vibration_energy_J, 4),
          significant(details.collision->string_bed_energy_J, 4),
          significant(details.collision->modal_damping_loss_J, 4));
    }
  }
  if (const std::string note = evaluation_tree_detail::fidelity_note(e); !note.empty())
    md += "\nNote: " + note + ".\n";
  md += inputs_markdown(file, e);
  return md;
}

}  // namespace sweetspot::io
