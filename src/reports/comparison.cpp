#include "reports/comparison.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstdint>
#include <functional>
#include <map>
#include <optional>
#include <tuple>

#include "io/json_reader.hpp"
#include "io/plot.hpp"
#include "reports/html_page.hpp"
#include "reports/html_report.hpp"
#include "reports/summary.hpp"

namespace sweetspot::reports {
namespace {

constexpr double kNewtonsPerPound = io::kPoundForce_N;
// What a player would notice (the model's own rounding, summary.hpp).
constexpr double kPositionThreshold_m = 0.005;
constexpr double kForceThreshold = 0.02;  // relative
constexpr double kCorThreshold = 0.01;
// A factor of the arm's load that changes by less is "about the same".
constexpr double kArmThreshold = 0.02;  // relative

// One line of the side-by-side table: a number of a compared design in SI.
struct Row {
  const char* label;  // for people
  const char* key;    // JSON and CSV, SI
  const char* unit;   // SI unit, as outputs.hpp writes it
  std::function<std::optional<double>(const ComparedDesign&)> value;
};

std::optional<double> node_of(const ComparedDesign& c) { return c.spots.node_from_tip_m; }

std::optional<double> cop_of(const ComparedDesign& c) { return c.spots.cop_from_tip_m; }

const std::vector<Row>& rows() {
  static const std::vector<Row> kRows{
      {"mass", "mass_kg", "kg",
       [](const ComparedDesign& c) -> std::optional<double> {
         return c.spots.asked.evaluation.mass_kg;
       }},
      {"balance from the butt", "balance_from_butt_m", "m",
       [](const ComparedDesign& c) -> std::optional<double> {
         return c.spots.asked.evaluation.balance_from_butt_m;
       }},
      {"swingweight", "swingweight_kg_cm2", "kg cm^2",
       [](const ComparedDesign& c) -> std::optional<double> {
         return c.spots.asked.evaluation.swingweight_kg_m2 * 1e4;
       }},
      {"string tension", "string_tension_N", "N",
       [](const ComparedDesign& c) -> std::optional<double> {
         if (!c.design.design.strings) return std::nullopt;
         return c.design.design.strings->tension_N;
       }},
      {"free fundamental", "fundamental_free_Hz", "Hz",
       [](const ComparedDesign& c) -> std::optional<double> {
         if (!c.spots.asked.evaluation.modal) return std::nullopt;
         return c.spots.asked.evaluation.modal->fundamental_free_Hz;
       }},
      {"hand-held centre of percussion from the tip (least jolt)", "cop_hand_from_tip_m", "m",
       cop_of},
      {"hand-held node from the tip (least vibration)", "node_hand_from_tip_m", "m", node_of},
      {"distance between them", "cop_node_distance_m", "m",
       [](const ComparedDesign& c) -> std::optional<double> {
         if (!cop_of(c) || !node_of(c)) return std::nullopt;
         return std::fabs(*cop_of(c) - *node_of(c));
       }},
      {"impact from the tip", "impact_from_tip_m", "m",
       [](const ComparedDesign& c) -> std::optional<double> { return c.spots.asked.from_tip_m; }},
      {"peak wrist force at the impact", "peak_wrist_force_N", "N",
       [](const ComparedDesign& c) -> std::optional<double> {
         return c.spots.asked.evaluation.peak_wrist_force_N;
       }},
      {"apparent COR at the impact (rebound / incoming speed)", "apparent_cor", "",
       [](const ComparedDesign& c) -> std::optional<double> {
         return c.spots.asked.evaluation.apparent_cor;
       }},
      {"impact off the axis (toward 3 o'clock when > 0)", "impact_off_axis_m", "m",
       [](const ComparedDesign& c) -> std::optional<double> {
         // As evaluate's outputs: known where the polar inertia is.
         if (!c.spots.asked.evaluation.polar_inertia_kg_m2) return std::nullopt;
         return c.spots.asked.evaluation.impact_off_axis_m;
       }},
      {"contact time at the impact", "impact_duration_s", "s",
       [](const ComparedDesign& c) -> std::optional<double> {
         return c.spots.asked.evaluation.impact_duration_s;
       }},
      {"peak twist torque at the impact (about the long axis)", "peak_twist_torque_N_m", "N m",
       [](const ComparedDesign& c) -> std::optional<double> {
         if (!c.spots.asked.evaluation.polar_inertia_kg_m2) return std::nullopt;
         return c.spots.asked.evaluation.peak_twist_torque_N_m;
       }},
      {"vibration at the hand after the impact (W_h-weighted acceleration)",
       "hand_vibration_weighted_m_s2", "m/s^2",
       [](const ComparedDesign& c) -> std::optional<double> {
         if (!c.asked_vibration) return std::nullopt;
         return c.asked_vibration->weighted_acceleration_m_s2;
       }},
      {"vibration at the hand after the impact (velocity amplitude)", "hand_vibration_velocity_m_s",
       "m/s",
       [](const ComparedDesign& c) -> std::optional<double> {
         if (!c.asked_vibration) return std::nullopt;
         return c.asked_vibration->velocity_m_s;
       }},
      {"frequency of the vibration at the hand", "hand_vibration_frequency_Hz", "Hz",
       [](const ComparedDesign& c) -> std::optional<double> {
         if (!c.asked_vibration) return std::nullopt;
         return c.asked_vibration->frequency_Hz;
       }},
      // Shot speed off a swinging racquet (shot_speed_m_s) is to join here.
      {"arm, nine hits: mean peak wrist force (the shock)", "arm_peak_wrist_force_N", "N",
       [](const ComparedDesign& c) { return c.arm.peak_wrist_force_N.value; }},
      {"arm, nine hits: mean W_h-weighted vibration at the hand",
       "arm_hand_vibration_weighted_m_s2", "m/s^2",
       [](const ComparedDesign& c) { return c.arm.hand_weighted_acceleration_m_s2.value; }},
      {"arm, nine hits: mean vibration velocity at the hand", "arm_hand_vibration_velocity_m_s",
       "m/s", [](const ComparedDesign& c) { return c.arm.hand_velocity_m_s.value; }},
      {"arm, nine hits: frequency of the most vibration at the hand",
       "arm_hand_vibration_frequency_Hz", "Hz",
       [](const ComparedDesign& c) { return c.arm.hand_frequency_Hz.value; }},
      {"arm, nine hits: mean peak twist torque (the twist)", "arm_peak_twist_torque_N_m", "N m",
       [](const ComparedDesign& c) { return c.arm.peak_twist_torque_N_m.value; }},
      {"peak wrist force at the node", "peak_wrist_force_at_node_N", "N",
       [](const ComparedDesign& c) -> std::optional<double> {
         if (!c.spots.node_hand) return std::nullopt;
         return c.spots.node_hand->evaluation.peak_wrist_force_N;
       }},
      {"apparent COR at the node", "apparent_cor_at_node", "",
       [](const ComparedDesign& c) -> std::optional<double> {
         if (!c.spots.node_hand) return std::nullopt;
         return c.spots.node_hand->evaluation.apparent_cor;
       }},
      {"apparent COR at the centre of percussion", "apparent_cor_at_cop", "",
       [](const ComparedDesign& c) -> std::optional<double> {
         if (!c.spots.cop_hand) return std::nullopt;
         return c.spots.cop_hand->evaluation.apparent_cor;
       }},
  };
  return kRows;
}

std::string toward(double delta_from_tip_m) {
  return delta_from_tip_m < 0 ? "toward the tip" : "toward the handle";
}

// "moves 1.4 cm toward the tip (30.7 cm -> 29.3 cm from the tip)", or std::nullopt when it does
// not.
std::optional<std::string> moved(std::optional<double> before, std::optional<double> after) {
  if (!before || !after || std::fabs(*after - *before) < kPositionThreshold_m) return std::nullopt;
  // The move is the difference of the printed places, to the millimetre as
  // the table beside the words prints them (30.68 -> 29.94 reads 30.7 -> 29.9,
  // not the half centimetres 30.5 -> 30).
  const double a = std::round(*before * 1000.0) / 10.0, b = std::round(*after * 1000.0) / 10.0;
  return fmt::format("moves {:.1f} cm {} ({:.1f} cm → {:.1f} cm from the tip)", std::fabs(b - a),
                     toward(*after - *before), a, b);
}

// `value` to `digits` significant figures in fixed notation ("274", "0.95").
std::string to_figures(double value, int digits) {
  if (value == 0.0 || !std::isfinite(value)) return "0";
  const int exponent = static_cast<int>(std::floor(std::log10(std::fabs(value))));
  const double scale = std::pow(10.0, exponent - digits + 1);
  const double rounded = std::round(value / scale) * scale;
  return fmt::format("{:.{}f}", rounded == 0.0 ? 0.0 : rounded, std::max(0, digits - 1 - exponent));
}

}  // namespace

std::string change_sentence(double before, double after, double threshold, std::string_view unit) {
  const std::string with_unit = unit.empty() ? "" : " " + std::string(unit);
  if (before == 0.0 && after != 0.0) {
    return fmt::format("goes from 0{} to {}{}", with_unit, to_figures(after, 2), with_unit);
  }
  const double scale = std::fabs(before) > 0.0 ? std::fabs(before) : 1.0;
  const double percent = 100.0 * (after - before) / scale;
  const bool same = std::fabs(after - before) / scale < threshold || std::lround(percent) == 0;
  // Two significant figures (what the model can claim), more only as it
  // takes for the printed pair to differ and to show the percentage stated;
  // about the same, a third figure at most to tell them apart, and never a
  // pair whose own change is another (273 -> 276, not 270 -> 280).
  const auto shows = [&](int d) {
    const std::string a = to_figures(before, d), b = to_figures(after, d);
    if (same && (d >= 3 || before == after)) return true;
    if (a == b) return false;
    const double pa = std::stod(a), pb = std::stod(b);
    const double shown = 100.0 * (pb - pa) / (std::fabs(pa) > 0.0 ? std::fabs(pa) : 1.0);
    return std::lround(std::fabs(shown)) == std::lround(std::fabs(percent));
  };
  int digits = 2;
  while (digits < 6 && !shows(digits)) ++digits;
  const std::string pair = fmt::format("({}{} → {}{})", to_figures(before, digits), with_unit,
                                       to_figures(after, digits), with_unit);
  if (same) return "is about the same " + pair;
  return fmt::format("{} by {} % {}", percent < 0 ? "falls" : "rises",
                     std::lround(std::fabs(percent)), pair);
}

namespace {

// "falls by 7 % (250 N → 230 N)", or std::nullopt below the threshold.
std::optional<std::string> force_change(double before, double after) {
  const double scale = std::max(std::fabs(before), 1.0);
  if (std::fabs(after - before) / scale < kForceThreshold) return std::nullopt;
  return change_sentence(before, after, kForceThreshold, "N");
}

bool on_centre(const ComparedDesign& c) {
  return c.spots.centre_of_strings &&
         cm_text(c.spots.centre_of_strings->from_tip_m) == cm_text(c.spots.asked.from_tip_m);
}

// "3 cm off the axis toward 3 o'clock", or "" for a hit on the axis.
std::string off_axis_text(const ComparedDesign& c) {
  const double y = c.spots.asked.evaluation.impact_off_axis_m;
  if (cm_text(std::fabs(y)) == "0 cm") return "";
  return fmt::format("{} off the axis toward {} o'clock", cm_text(std::fabs(y)), y > 0 ? 3 : 9);
}

std::string along_text(const ComparedDesign& c) {
  return on_centre(c) ? fmt::format("at the centre of the strings ({} from the tip)",
                                    cm_text(c.spots.asked.from_tip_m))
                      : fmt::format("{} from the tip", cm_text(c.spots.asked.from_tip_m));
}

std::string where_hit(const ComparedDesign& c) {
  const std::string off = off_axis_text(c);
  return off.empty() ? along_text(c) : along_text(c) + ", " + off;
}

bool off_axis(const ComparedDesign& c) { return !off_axis_text(c).empty(); }

// "a hit at the centre of the strings (18 cm from the tip)", each design's
// own when they differ, told as its default when neither file gives one.
std::string impact_words(const ComparedDesign& a, const ComparedDesign& b) {
  if (where_hit(a) == where_hit(b)) return "a hit " + where_hit(a);
  if (along_text(a) == along_text(b)) {  // the same place along the axis, not across it
    const auto across = [](const ComparedDesign& c) {
      return off_axis(c) ? off_axis_text(c) : std::string("on the axis");
    };
    return fmt::format("a hit {}, {} and {}", along_text(a), across(a), across(b));
  }
  const bool defaults = a.spots.asked_provenance != "given" && b.spots.asked_provenance != "given";
  if (defaults && on_centre(a) && on_centre(b) && !off_axis(a) && !off_axis(b)) {
    return fmt::format(
        "a hit at each one's own default point, the centre of its strings ({} and {} from the "
        "tip)",
        cm_text(a.spots.asked.from_tip_m), cm_text(b.spots.asked.from_tip_m));
  }
  const bool asked_a = a.spots.asked_provenance == "given";
  const bool asked_b = b.spots.asked_provenance == "given";
  if (asked_a != asked_b) {
    // One file asks about an impact, the other takes its default.
    const auto told = [](const ComparedDesign& c) {
      return where_hit(c) +
             (c.spots.asked_provenance == "given" ? " as the file asks" : " by default");
    };
    return fmt::format("a hit at each one's own impact ({}; {})", told(a), told(b));
  }
  return fmt::format("a hit at the impact each {} ({} and {})",
                     defaults ? "is given by default" : "asks about", where_hit(a), where_hit(b));
}

// Where a design's spread of hits on the arm is centred: the centre of its
// strings, the impact its file asks about, or the default impact.
// Without its article: "centre of the strings".
std::string around_words(const ComparedDesign& c) {
  if (c.arm.around_centre_of_strings) return "centre of the strings";
  if (c.spots.asked_provenance == "given") return "impact asked about";
  return "default impact, " + cm_text(c.spots.asked.from_tip_m) + " from the tip";
}

// The inputs that differ, in a player's words, and which differences of the
// read designs those words describe.
struct PlayerWords {
  std::vector<std::string> changes;
  bool mass_distribution = false;  // lead, mass, balance or swingweight
  bool tension = false;
};

PlayerWords input_changes(const ComparedDesign& a, const ComparedDesign& b) {
  PlayerWords words;
  std::vector<std::string>& changes = words.changes;
  const Evaluation& ea = a.spots.asked.evaluation;
  const Evaluation& eb = b.spots.asked.evaluation;
  const auto& pa = a.design.design.implement.point_masses();
  const auto& pb = b.design.design.implement.point_masses();
  // Lead added on top of the first design's: each extra point mass by where it sits.
  bool lead_described = false;
  if (pb.size() > pa.size() && std::equal(pa.begin(), pa.end(), pb.begin(), [](auto& x, auto& y) {
        return x.mass_kg == y.mass_kg && x.from_butt_m == y.from_butt_m;
      })) {
    const auto hour = [&](std::size_t k) {
      return k < b.clock_hours.size() ? b.clock_hours[k] : std::nullopt;
    };
    for (std::size_t k = pa.size(); k < pb.size(); ++k) {
      // A pair of equal pieces on the hoop, one each side ("at 3 and 9 o'clock").
      if (k + 1 < pb.size() && hour(k) && hour(k + 1) && pb[k].mass_kg == pb[k + 1].mass_kg &&
          *hour(k) + *hour(k + 1) == 12) {
        changes.push_back(fmt::format(
            "{} g of added mass at {} and {} o'clock ({} g each)",
            io::significant(2.0 * pb[k].mass_kg * 1000, 3), std::min(*hour(k), *hour(k + 1)),
            std::max(*hour(k), *hour(k + 1)), io::significant(pb[k].mass_kg * 1000, 3)));
        ++k;
        continue;
      }
      changes.push_back(fmt::format("{} g of added mass {} from the tip",
                                    io::significant(pb[k].mass_kg * 1000, 3),
                                    cm_text(eb.length_m - pb[k].from_butt_m)));
    }
    lead_described = true;
  }
  const double dm = eb.mass_kg - ea.mass_kg;
  if (!lead_described && std::fabs(dm) >= 0.0005)
    changes.push_back(fmt::format("{} g {}", io::significant(std::fabs(dm) * 1000, 3),
                                  dm > 0 ? "heavier" : "lighter"));
  const double db = eb.balance_from_butt_m - ea.balance_from_butt_m;
  if (std::fabs(db) >= 0.001)
    changes.push_back(fmt::format("the balance {:.2g} cm {}", std::fabs(db) * 100,
                                  db > 0 ? "nearer the tip" : "nearer the handle"));
  const double ds = (eb.swingweight_kg_m2 - ea.swingweight_kg_m2) * 1e4;
  if (std::fabs(ds) >= 0.5)
    changes.push_back(
        fmt::format("a swingweight {:.0f} kg·cm² {}", std::fabs(ds), ds > 0 ? "higher" : "lower"));
  words.mass_distribution = !changes.empty();
  const auto& sa = a.design.design.strings;
  const auto& sb = b.design.design.strings;
  if (sa && sb &&
      (sa->tension_N != sb->tension_N || sa->cross_tension_N() != sb->cross_tension_N())) {
    // The tension in the bed (the pull less its loss) in pounds, to three
    // figures (52.4 lb), mains and crosses apart when either bed has them apart.
    const auto lb = [](double N) { return io::significant(N / kNewtonsPerPound, 3) + " lb"; };
    const std::string in_bed =
        sa->tension_loss > 0.0 || sb->tension_loss > 0.0 ? " in the bed" : "";
    if (sa->cross_tension_ratio == 1.0 && sb->cross_tension_ratio == 1.0) {
      changes.push_back(fmt::format("strings at {}{} instead of {}", lb(sb->tension_N), in_bed,
                                    lb(sa->tension_N)));
    } else {
      changes.push_back(fmt::format("mains at {} and crosses at {}{} instead of {} and {}",
                                    lb(sb->tension_N), lb(sb->cross_tension_N()), in_bed,
                                    lb(sa->tension_N), lb(sa->cross_tension_N())));
    }
    words.tension = true;
  }
  if (ea.modal && eb.modal &&
      std::fabs(ea.modal->fundamental_free_Hz - eb.modal->fundamental_free_Hz) >= 1.0)
    // The frequency falls with added mass as well as with a softer frame:
    // say what changed, not why.
    changes.push_back(fmt::format("a frame vibrating at {:.0f} Hz instead of {:.0f} Hz (free)",
                                  eb.modal->fundamental_free_Hz, ea.modal->fundamental_free_Hz));
  return words;
}

// Every input of a read design, by the part of the design it belongs to:
// what `compare` checks field by field before it compares any output.
enum class Part {
  kImplementShape,
  kMassDistribution,
  kFrame,
  kStrings,
  kHand,
  kForearm,
  kBall,
  kImpact,
  kSupport,
  kSwing
};

constexpr const char* kPartNames[] = {"the implement", "the implement", "the frame", "the strings",
                                      "the hand",      "the forearm",   "the ball",  "the impact",
                                      "the support",   "the swing"};
// What goes before a field's name in a list of several parts' fields ("the
// ball's speed"); the implement's own fields read on their own ("head size").
constexpr const char* kPossessives[] = {"",
                                        "",
                                        "the frame's ",
                                        "the strings' ",
                                        "the hand's ",
                                        "the forearm's ",
                                        "the ball's ",
                                        "the impact's ",
                                        "the support: ",
                                        "the swing's "};

// The players' side of a comparison: the hand, the forearm, the ball and
// the impact. The rest is the implement (its frame and strings included).
bool is_racquet(Part part) {
  return part == Part::kImplementShape || part == Part::kMassDistribution || part == Part::kFrame ||
         part == Part::kStrings;
}

// What a field belongs to when it is not always there: a head's shape is no
// input of a design without a head, nor a string bed's of one without strings.
enum class Within { kDesign, kHead, kStrings };

struct InputField {
  Part part;
  const char* name;                                           // "speed", read after the part's name
  const char* unit;                                           // as people read it: "m/s", "g", "cm"
  double factor;                                              // from SI to `unit`
  std::function<std::optional<double>(const Design&)> value;  // std::nullopt: not given
  // Where one design has the head (or the strings) and the other not, only
  // the first field of it is named.
  Within within = Within::kDesign;
  bool first = true;
  // Derived from the head's size when the file gives one: not named again
  // when the head size itself differs.
  bool follows_head = false;
  // What a design without the value has instead ("none"; the COR the solved
  // collision derives is "derived").
  const char* absent = "none";
  // The evaluation derived it (the COR of the solved collision): no input.
  bool derived_by_evaluation = false;
};

template <typename T>
std::optional<double> given(const std::optional<T>& value) {
  if (!value) return std::nullopt;
  return static_cast<double>(*value);
}

const std::vector<InputField>& input_fields() {
  using D = const Design&;
  static const std::vector<InputField> kFields{
      {Part::kImplementShape, "length", "cm", 100.0,
       [](D d) -> std::optional<double> { return d.implement.length_m(); }},
      {Part::kMassDistribution, "frame mass", "g", 1000.0,
       [](D d) -> std::optional<double> { return d.implement.frame_mass_properties().mass_kg; }},
      {Part::kMassDistribution, "frame balance from the butt", "cm", 100.0,
       [](D d) -> std::optional<double> {
         return d.implement.frame_mass_properties().com_from_butt_m;
       }},
      {Part::kMassDistribution, "frame swingweight", "kg·cm²", 1e4,
       [](D d) -> std::optional<double> {
         return swingweight_kg_m2(d.implement.frame_mass_properties());
       }},
      {Part::kImplementShape, "head size", "sq in", 1.0 / io::kSquareInch_m2,
       [](D d) { return d.head ? std::optional(d.head->area_m2) : std::nullopt; }, Within::kHead},
      {Part::kImplementShape, "head's aspect ratio", "", 1.0,
       [](D d) { return d.head ? std::optional(d.head->aspect_ratio) : std::nullopt; },
       Within::kHead, false},
      {Part::kImplementShape, "hoop width", "cm", 100.0,
       [](D d) { return d.head ? std::optional(d.head->hoop_width_m) : std::nullopt; },
       Within::kHead, false},
      {Part::kImplementShape, "twistweight", "kg·cm²", 1e4,
       [](D d) { return given(d.twistweight_kg_m2); }},
      {Part::kFrame, "COR", "", 1.0, [](D d) -> std::optional<double> { return d.cor; },
       Within::kDesign, true, false, "derived", true},
      {Part::kFrame, "COR on a rigid frame", "", 1.0, [](D d) { return given(d.cor_rigid); }},
      {Part::kFrame, "EI", "N·m²", 1.0, [](D d) { return given(d.stiffness.EI_N_m2); }},
      {Part::kFrame, "free fundamental", "Hz", 1.0,
       [](D d) { return given(d.stiffness.fundamental_free_Hz); }},
      {Part::kFrame, "RA", "", 1.0, [](D d) { return given(d.stiffness.RA); }},
      {Part::kFrame, "shear modulus", "Pa", 1.0,
       [](D d) { return given(d.stiffness.shear_modulus_Pa); }},
      {Part::kFrame, "cross-section's width", "mm", 1000.0,
       [](D d) -> std::optional<double> {
         if (!sized_by_width(d.stiffness.cross_section.shape)) return std::nullopt;
         return d.stiffness.cross_section.width_m;
       }},
      {Part::kFrame, "cross-section's thickness", "mm", 1000.0,
       [](D d) -> std::optional<double> {
         if (!sized_by_width(d.stiffness.cross_section.shape)) return std::nullopt;
         return d.stiffness.cross_section.thickness_m;
       }},
      {Part::kFrame, "cross-section's diameter", "mm", 1000.0,
       [](D d) -> std::optional<double> {
         if (!sized_by_diameter(d.stiffness.cross_section.shape)) return std::nullopt;
         return d.stiffness.cross_section.diameter_m;
       }},
      {Part::kFrame, "cross-section's wall", "mm", 1000.0,
       [](D d) -> std::optional<double> {
         const CrossSection& c = d.stiffness.cross_section;
         return has_wall(c.shape) ? std::optional(c.wall_m) : std::nullopt;
       }},
      {Part::kStrings, "tension", "lb", 1.0 / kNewtonsPerPound,
       [](D d) { return d.strings ? std::optional(d.strings->tension_N) : std::nullopt; },
       Within::kStrings},
      {Part::kStrings, "tension of the crosses", "lb", 1.0 / kNewtonsPerPound,
       [](D d) { return d.strings ? std::optional(d.strings->cross_tension_N()) : std::nullopt; },
       Within::kStrings, false},
      {Part::kStrings, "spacing", "mm", 1000.0,
       [](D d) { return d.strings ? std::optional(d.strings->string_spacing_m) : std::nullopt; },
       Within::kStrings, false},
      {Part::kStrings, "strung radius", "cm", 100.0,
       [](D d) { return d.strings ? std::optional(d.strings->head_radius_m) : std::nullopt; },
       Within::kStrings, false, true},
      {Part::kStrings, "contact radius", "cm", 100.0,
       [](D d) { return d.strings ? std::optional(d.strings->contact_radius_m) : std::nullopt; },
       Within::kStrings, false},
      // An input only without a string bed: a bed's tension gives its own.
      {Part::kStrings, "impact duration", "ms", 1000.0,
       [](D d) { return d.strings ? std::nullopt : std::optional(d.impact_duration_s); }},
      {Part::kStrings, "moving mass", "g", 1000.0,
       [](D d) -> std::optional<double> { return d.string_bed_mass_kg; }},
      {Part::kStrings, "damping ratio", "", 1.0,
       [](D d) -> std::optional<double> { return d.string_bed_damping_ratio; }},
      {Part::kHand, "mass", "g", 1000.0,
       [](D d) -> std::optional<double> { return d.hand.mass_kg; }},
      {Part::kHand, "centre from the butt", "cm", 100.0,
       [](D d) -> std::optional<double> { return d.hand.center_from_butt_m; }},
      {Part::kHand, "grip length", "cm", 100.0,
       [](D d) -> std::optional<double> { return d.hand.grip_length_m; }},
      {Part::kHand, "grip stiffness", "N/m²", 1.0,
       [](D d) -> std::optional<double> { return d.hand.grip_stiffness_N_m2; }},
      {Part::kHand, "grip damping", "N·s/m²", 1.0,
       [](D d) -> std::optional<double> { return d.hand.grip_damping_N_s_m2; }},
      {Part::kForearm, "equivalent mass", "g", 1000.0,
       [](D d) -> std::optional<double> { return d.forearm_equivalent_mass_kg; }},
      {Part::kBall, "mass", "g", 1000.0,
       [](D d) -> std::optional<double> { return d.ball.mass_kg; }},
      {Part::kBall, "speed", "m/s", 1.0,
       [](D d) -> std::optional<double> { return d.ball.speed_m_s; }},
      {Part::kBall, "diameter", "cm", 100.0,
       [](D d) -> std::optional<double> { return d.ball.diameter_m; }},
      {Part::kBall, "COR on a rigid surface", "", 1.0,
       [](D d) -> std::optional<double> { return d.ball.cor_on_rigid_surface; }},
      {Part::kBall, "contact stiffness", "", 1.0,
       [](D d) -> std::optional<double> { return d.ball_contact.stiffness; }},
      {Part::kBall, "contact exponent", "", 1.0,
       [](D d) -> std::optional<double> { return d.ball_contact.exponent; }},
      {Part::kBall, "contact damping", "", 1.0,
       [](D d) -> std::optional<double> { return d.ball_contact.damping; }},
      {Part::kBall, "contact damping exponent", "", 1.0,
       [](D d) -> std::optional<double> { return d.ball_contact.damping_exponent; }},
      {Part::kImpact, "distance from the tip", "cm", 100.0,
       [](D d) -> std::optional<double> { return d.implement.length_m() - d.impact_from_butt_m; }},
      {Part::kImpact, "distance off the axis", "cm", 100.0,
       [](D d) -> std::optional<double> { return d.impact_off_axis_m; }},
      {Part::kSwing, "angular speed", "rad/s", 1.0,
       [](D d) { return d.swing ? std::optional(d.swing->angular_speed_rad_s) : std::nullopt; }},
      {Part::kSwing, "pivot beyond the butt", "cm", 100.0,
       [](D d) { return d.swing ? std::optional(d.swing->pivot_beyond_butt_m) : std::nullopt; }},
      {Part::kSwing, "reference swingweight", "kg·cm²", 1e4,
       [](D d) { return d.swing ? given(d.swing->reference_swingweight_kg_m2) : std::nullopt; }},
  };
  return kFields;
}

bool same_number(std::optional<double> a, std::optional<double> b) {
  if (!a || !b) return a.has_value() == b.has_value();
  return std::bit_cast<std::uint64_t>(*a) == std::bit_cast<std::uint64_t>(*b) ||
         (*a == 0.0 && *b == 0.0);  // -0 is 0
}

// "50 → 40 m/s": as many digits as it takes to tell the two apart.
std::string from_to(std::optional<double> a, std::optional<double> b, double factor,
                    std::string_view unit, std::string_view absent = "none") {
  int digits = 4;
  const auto text = [&](std::optional<double> v) {
    return v ? io::significant(*v * factor, digits) : std::string(absent);
  };
  while (digits < 17 && text(a) == text(b)) ++digits;
  const std::string with_unit = unit.empty() ? "" : " " + std::string(unit);
  // "645.2 cm² → none": the unit goes with the number.
  if (a && !b) return fmt::format("{}{} → {}", text(a), with_unit, absent);
  return fmt::format("{} → {}{}", text(a), text(b), b ? with_unit : "");
}

// What differs in a list of parts (sections, point masses), entry by entry.
template <typename T>
void list_differences(
    Part part, const char* what, const char* plural, const std::vector<T>& a,
    const std::vector<T>& b,
    const std::vector<std::tuple<const char*, const char*, double,
                                 std::function<std::optional<double>(const T&)>>>& fields,
    std::vector<std::pair<Part, std::string>>& out) {
  if (a.size() != b.size())
    out.emplace_back(part, fmt::format("number of {} {} → {}", plural, a.size(), b.size()));
  for (std::size_t k = 0; k < std::max(a.size(), b.size()); ++k) {
    for (const auto& [name, unit, factor, value] : fields) {
      const auto va = k < a.size() ? value(a[k]) : std::nullopt;
      const auto vb = k < b.size() ? value(b[k]) : std::nullopt;
      if (!same_number(va, vb))
        out.emplace_back(
            part, fmt::format("{} {}'s {} {}", what, k + 1, name, from_to(va, vb, factor, unit)));
    }
  }
}

// Every input that differs between the two read designs, field by field, by part.
// `a_derived`, `b_derived`: whether each evaluation derived its COR.
std::vector<std::pair<Part, std::string>> field_differences(const Design& a, const Design& b,
                                                            bool a_derived, bool b_derived) {
  std::vector<std::pair<Part, std::string>> out;
  const auto one_has = [&](Within within) {
    return within == Within::kHead      ? a.head.has_value() != b.head.has_value()
           : within == Within::kStrings ? a.strings.has_value() != b.strings.has_value()
                                        : false;
  };
  const auto head_area = [](const Design& d) {
    return d.head ? std::optional(d.head->area_m2) : std::nullopt;
  };
  const bool head_differs = !same_number(head_area(a), head_area(b));
  for (const InputField& f : input_fields()) {
    if (!f.first && one_has(f.within)) continue;
    if (f.follows_head && head_differs) continue;
    const auto va = f.derived_by_evaluation && a_derived ? std::nullopt : f.value(a);
    const auto vb = f.derived_by_evaluation && b_derived ? std::nullopt : f.value(b);
    if (!same_number(va, vb))
      out.emplace_back(f.part,
                       fmt::format("{} {}", f.name, from_to(va, vb, f.factor, f.unit, f.absent)));
  }
  // What is named, not numbered: what holds the implement (free or the hand:
  // compare refuses a rig) and the ball's law.
  if (a.support.kind != b.support.kind)
    out.emplace_back(Part::kSupport,
                     fmt::format("{} → {}", to_string(a.support.kind), to_string(b.support.kind)));
  if (a.ball_contact.form != b.ball_contact.form)
    out.emplace_back(Part::kBall, fmt::format("contact law {} → {}", to_string(a.ball_contact.form),
                                              to_string(b.ball_contact.form)));
  using SectionField = std::function<std::optional<double>(const Section&)>;
  list_differences<Section>(
      Part::kMassDistribution, "section", "sections", a.implement.sections(),
      b.implement.sections(),
      {{"length", "cm", 100.0,
        SectionField([](const Section& s) -> std::optional<double> { return s.length_m; })},
       {"mass", "g", 1000.0,
        SectionField([](const Section& s) -> std::optional<double> { return s.mass_kg; })},
       {"EI", "N·m²", 1.0, SectionField([](const Section& s) { return given(s.EI_N_m2); })}},
      out);
  using PointField = std::function<std::optional<double>(const PointMass&)>;
  list_differences<PointMass>(
      Part::kMassDistribution, "point mass", "point masses", a.implement.point_masses(),
      b.implement.point_masses(),
      {{"mass", "g", 1000.0,
        PointField([](const PointMass& p) -> std::optional<double> { return p.mass_kg; })},
       {"distance from the butt", "cm", 100.0,
        PointField([](const PointMass& p) -> std::optional<double> { return p.from_butt_m; })},
       {"distance off the axis", "cm", 100.0,
        PointField([](const PointMass& p) -> std::optional<double> { return p.off_axis_m; })}},
      out);
  return out;
}

std::string joined(const std::vector<std::string>& parts) {
  std::string text;
  for (std::size_t k = 0; k < parts.size(); ++k) {
    text += (k == 0 ? "" : k + 1 == parts.size() ? " and " : ", ") + parts[k];
  }
  return text;
}

// What differs between the inputs of the two designs, before any output: the
// implement in a player's words where they say it (lead, mass, balance,
// swingweight, tension, the frame's frequency), every other field of the
// read designs that differs by name, and "the same implement" only when no
// field of the implement, its frame or its strings differs.
std::string inputs_sentence(const ComparedDesign& a, const ComparedDesign& b) {
  const PlayerWords words = input_changes(a, b);
  std::vector<std::string> racquet = words.changes;
  std::vector<Part> players_parts;
  std::map<Part, std::vector<std::string>> by_part;
  bool racquet_differs = false;
  for (const auto& [part, text] :
       field_differences(a.design.design, b.design.design, a.spots.asked.evaluation.cor_derived,
                         b.spots.asked.evaluation.cor_derived)) {
    if (is_racquet(part)) {
      racquet_differs = true;
      const bool said = (part == Part::kMassDistribution && words.mass_distribution) ||
                        (part == Part::kStrings && words.tension && text.starts_with("tension "));
      if (!said) racquet.push_back(kPossessives[static_cast<int>(part)] + text);
      continue;
    }
    if (!by_part.count(part)) players_parts.push_back(part);
    by_part[part].push_back(text);
  }
  racquet_differs = racquet_differs || !words.changes.empty();
  std::string others;
  if (players_parts.size() == 1) {
    const Part part = players_parts.front();
    others = fmt::format("{} {} differs: {}", racquet_differs ? "and" : "only",
                         kPartNames[static_cast<int>(part)], joined(by_part[part]));
  } else if (!players_parts.empty()) {
    std::vector<std::string> names, details;
    for (const Part part : players_parts) {
      names.emplace_back(kPartNames[static_cast<int>(part)]);
      for (const std::string& text : by_part[part])
        details.push_back(kPossessives[static_cast<int>(part)] + text);
    }
    others = fmt::format("{}{} differ: {}", racquet_differs ? "and " : "", joined(names),
                         joined(details));
  }
  if (!racquet_differs) {
    return "the same implement" +
           (others.empty() ? std::string(", held and hit the same way") : "; " + others);
  }
  // A difference too small for the player's words is still named.
  return joined(racquet) + (others.empty() ? "" : "; " + others);
}

}  // namespace

namespace {

// One factor of the arm's load as a sentence's clause, and which way it points.
struct ArmClause {
  std::string text;
  int points = 0;  // -1: the first design is kinder by it, +1: the second, 0: no difference
  bool known = true;
  std::string why;  // when not known
};

ArmClause arm_clause(const std::string& what, const std::string& detail, const char* unit,
                     double factor, const studies::ArmFactor& a, const studies::ArmFactor& b,
                     const ComparedDesign& da, const ComparedDesign& db) {
  ArmClause clause;
  if (!a.value || !b.value) {
    clause.known = false;
    const bool neither = !a.value && !b.value;
    const std::string& why = !a.value ? a.unknown_why : b.unknown_why;
    clause.text =
        fmt::format("{} is not known for {}", what,
                    neither ? std::string("either") : (!a.value ? da.design.name : db.design.name));
    clause.why = (neither && a.unknown_why != b.unknown_why)
                     ? fmt::format("{}: {}; {}: {}", da.design.name, a.unknown_why, db.design.name,
                                   b.unknown_why)
                     : why;
    return clause;
  }
  const double before = *a.value * factor, after = *b.value * factor;
  const double scale = std::fabs(before) > 0.0 ? std::fabs(before) : 1.0;
  const bool differs =
      std::fabs(after - before) / scale >= kArmThreshold && std::fabs(after - before) > 0.0;
  clause.points = !differs ? 0 : after < before ? 1 : -1;
  clause.text =
      fmt::format("{} ({}) {}", what, detail, change_sentence(before, after, kArmThreshold, unit));
  return clause;
}

// What the two designs do to the arm over the spread of hits: each factor's
// number and the way it points, then the verdict (docs/model.md, "The arm").
std::vector<std::string> arm_sentences(const ComparedDesign& a, const ComparedDesign& b) {
  const studies::ArmLoad& la = a.arm;
  const studies::ArmLoad& lb = b.arm;
  std::string frequency;
  if (la.hand_frequency_Hz.value && lb.hand_frequency_Hz.value) {
    const std::string fa = fmt::format("{:.0f} Hz", *la.hand_frequency_Hz.value);
    const std::string fb = fmt::format("{:.0f} Hz", *lb.hand_frequency_Hz.value);
    frequency =
        fa == fb ? ", mostly at " + fa : fmt::format(", mostly at {} instead of {}", fb, fa);
  }
  const std::vector<std::pair<const char*, ArmClause>> clauses{
      {"the shock", arm_clause("the shock at the wrist", "mean peak wrist force", "N", 1.0,
                               la.peak_wrist_force_N, lb.peak_wrist_force_N, a, b)},
      {"the vibration",
       arm_clause("the vibration at the hand",
                  "mean weighted acceleration, ISO 5349-1's W_h" + frequency, "m/s²", 1.0,
                  la.hand_weighted_acceleration_m_s2, lb.hand_weighted_acceleration_m_s2, a, b)},
      {"the twist", arm_clause("the twist", "mean peak torque about the long axis", "N·m", 1.0,
                               la.peak_twist_torque_N_m, lb.peak_twist_torque_N_m, a, b)},
  };
  std::vector<std::string> parts, for_a, for_b, unknown, reasons;
  for (const auto& [name, clause] : clauses) {
    parts.push_back(clause.text);
    if (!clause.known && std::find(reasons.begin(), reasons.end(), clause.why) == reasons.end())
      reasons.push_back(clause.why);
    if (!clause.known) unknown.emplace_back(name);
    if (clause.points > 0) for_b.emplace_back(name);
    if (clause.points < 0) for_a.emplace_back(name);
  }
  const std::string where = around_words(a) == around_words(b)
                                ? "around the " + around_words(a)
                                : fmt::format("around the first's {}, and the second's {}",
                                              around_words(a), around_words(b));
  std::vector<std::string> out;
  const bool grid = la.spread.size() == 9 && lb.spread.size() == 9;
  out.push_back(fmt::format(
      "On the arm, over {} hits {} ({} apart along {}): {}.", grid ? "nine" : "the", where,
      cm_text(studies::kArmSpreadStep_m),
      grid ? "and across the axis" : "the axis, and across it where it can twist", joined(parts)));
  if (!reasons.empty()) {
    std::string why;
    for (const std::string& r : reasons) why += (why.empty() ? "" : "; ") + r;
    out.push_back("Not known: " + why + ".");
  }
  const std::string of_known = unknown.empty() ? "" : " of those known";
  if (!for_a.empty() && !for_b.empty()) {
    out.push_back(fmt::format(
        "The factors disagree: {} {} to {}, {} to {}; the model weighs none against another.",
        joined(for_b), for_b.size() == 1 ? "points" : "point", b.design.name, joined(for_a),
        a.design.name));
  } else if (!for_a.empty() || !for_b.empty()) {
    const bool second = !for_b.empty();
    const auto& agree = second ? for_b : for_a;
    const ComparedDesign& kinder = second ? b : a;
    out.push_back(
        fmt::format("For the arm, {} is the kinder: {} {} to it and no factor{} the other way.",
                    kinder.design.name, joined(agree), agree.size() == 1 ? "points" : "point",
                    of_known + " points"));
  } else {
    out.push_back(
        fmt::format("Neither is kinder to the arm: no factor{} changes by {:.0f} % or more.",
                    of_known, 100.0 * kArmThreshold));
  }
  return out;
}

}  // namespace

std::vector<std::string> differences(const ComparedDesign& a, const ComparedDesign& b) {
  std::vector<std::string> sentences;
  sentences.push_back(
      fmt::format("{} against {}: {}.", b.design.name, a.design.name, inputs_sentence(a, b)));
  std::vector<std::string> effects;
  if (const auto m = moved(cop_of(a), cop_of(b)))
    effects.push_back("the hand-held centre of percussion " + *m);
  if (const auto m = moved(node_of(a), node_of(b))) effects.push_back("the node " + *m);
  const Evaluation& ea = a.spots.asked.evaluation;
  const Evaluation& eb = b.spots.asked.evaluation;
  const std::string impact = impact_words(a, b);
  if (const auto f = force_change(ea.peak_wrist_force_N, eb.peak_wrist_force_N))
    effects.push_back("the wrist force of " + impact + " " + *f);
  if (std::fabs(eb.apparent_cor - ea.apparent_cor) >= kCorThreshold)
    effects.push_back(fmt::format("its rebound goes from {} to {} of the ball's speed",
                                  ratio_text(ea.apparent_cor), ratio_text(eb.apparent_cor)));
  // Shot speed off a swinging racquet joins here when the evaluation gives it.
  if (std::fabs(eb.impact_duration_s - ea.impact_duration_s) >=
      kForceThreshold * std::fabs(ea.impact_duration_s))
    effects.push_back("its contact time " + change_sentence(ea.impact_duration_s * 1e3,
                                                            eb.impact_duration_s * 1e3,
                                                            kForceThreshold, "ms"));
  if (a.asked_vibration && b.asked_vibration) {
    const double va = a.asked_vibration->weighted_acceleration_m_s2;
    const double vb = b.asked_vibration->weighted_acceleration_m_s2;
    if (std::fabs(vb - va) >= kArmThreshold * std::fabs(va))
      effects.push_back("the vibration it leaves at the hand (weighted acceleration) " +
                        change_sentence(va, vb, kArmThreshold, "m/s²"));
  }
  // Lead at 3 and 9 o'clock is there for this: the head's resistance to
  // twisting, whichever hit is asked about.
  if (ea.polar_inertia_kg_m2 && eb.polar_inertia_kg_m2 &&
      std::fabs(*eb.polar_inertia_kg_m2 - *ea.polar_inertia_kg_m2) >=
          kForceThreshold * std::fabs(*ea.polar_inertia_kg_m2)) {
    effects.push_back("its twistweight (how it resists twisting on a hit off the axis) " +
                      change_sentence(*ea.polar_inertia_kg_m2 * 1e4, *eb.polar_inertia_kg_m2 * 1e4,
                                      kForceThreshold, "kg·cm²"));
  }
  if (off_axis(a) || off_axis(b)) {
    effects.push_back(fmt::format(
        "the twist of {} (peak torque about the long axis) {}", impact,
        change_sentence(ea.peak_twist_torque_N_m, eb.peak_twist_torque_N_m, kArmThreshold, "N·m")));
  }
  if (a.spots.node_hand && b.spots.node_hand) {
    if (const auto f = force_change(a.spots.node_hand->evaluation.peak_wrist_force_N,
                                    b.spots.node_hand->evaluation.peak_wrist_force_N))
      effects.push_back("the wrist force of a hit on the node " + *f);
  }
  if (effects.empty()) {
    sentences.push_back(
        "No difference that matters at the impact: the sweet spots move less than 0.5 cm, the "
        "wrist force, the contact time, the twistweight and the vibration at the hand change less "
        "than 2 % and "
        "the rebound less than 0.01.");
  } else {
    std::string first = joined(effects);
    first[0] = static_cast<char>(std::toupper(static_cast<unsigned char>(first[0])));
    sentences.push_back(first + ".");
  }
  for (std::string& s : arm_sentences(a, b)) sentences.push_back(std::move(s));
  return sentences;
}

std::string comparison_report(const std::vector<ComparedDesign>& designs, io::Format format) {
  if (format == io::Format::kJson) {
    io::Json j;
    j["designs"] = io::Json::array();
    for (const ComparedDesign& c : designs) {
      io::Json d;
      d["name"] = c.design.name;
      d["source"] = c.design.source;
      d["fidelity"] = to_string(fidelity_of(c.spots.asked.evaluation));
      d["impact_provenance"] = c.spots.asked_provenance;
      io::Json& values = d["values"];
      values = io::Json::object();
      for (const Row& row : rows()) {
        const auto v = row.value(c);
        values[row.key] = v ? io::Json(*v) : io::Json(nullptr);
      }
      d["sweet_spots"] = sweet_spot_sentences(c.design, c.spots);
      io::Json& arm = d["arm"];
      arm["spread"] = io::Json::array();
      for (const studies::SpreadPoint& p : c.arm.spread)
        arm["spread"].push_back({{"from_tip_m", p.from_tip_m}, {"off_axis_m", p.off_axis_m}});
      arm["around"] = "the " + around_words(c);
      const std::pair<const char*, const studies::ArmFactor*> factors[] = {
          {"peak_wrist_force_N", &c.arm.peak_wrist_force_N},
          {"hand_vibration_weighted_m_s2", &c.arm.hand_weighted_acceleration_m_s2},
          {"hand_vibration_velocity_m_s", &c.arm.hand_velocity_m_s},
          {"hand_vibration_frequency_Hz", &c.arm.hand_frequency_Hz},
          {"peak_twist_torque_N_m", &c.arm.peak_twist_torque_N_m}};
      for (const auto& [key, factor] : factors) {
        arm[key] = factor->value ? io::Json(*factor->value) : io::Json(nullptr);
        if (!factor->value) arm["unknown"][key] = factor->unknown_why;
      }
      j["designs"].push_back(d);
    }
    j["differences"] = io::Json::array();
    for (std::size_t k = 1; k < designs.size(); ++k) {
      j["differences"].push_back({{"from", designs[0].design.name},
                                  {"to", designs[k].design.name},
                                  {"sentences", differences(designs[0], designs[k])}});
    }
    return j.dump(2, ' ', false, io::Json::error_handler_t::replace) + "\n";
  }
  if (format == io::Format::kCsv) {
    std::string csv = "name,source";
    for (const Row& row : rows()) csv += std::string(",") + row.key;
    csv += "\n";
    for (const ComparedDesign& c : designs) {
      csv += io::csv_field(c.design.name) + "," + io::csv_field(c.design.source);
      for (const Row& row : rows()) {
        csv += ",";
        if (const auto v = row.value(c)) io::append_exact(csv, *v);
      }
      csv += "\n";
    }
    return csv;
  }
  std::string md = "# Compared";
  for (std::size_t k = 0; k < designs.size(); ++k)
    md += (k == 0                    ? ": "
           : k + 1 == designs.size() ? " and "
                                     : ", ") +
          io::md_cell(designs[k].design.name);
  md += "\n\n";
  for (std::size_t k = 1; k < designs.size(); ++k) {
    std::string paragraph;
    for (const std::string& s : differences(designs[0], designs[k]))
      paragraph += (paragraph.empty() ? "" : " ") + s;
    md += io::terminal_text(paragraph) + "\n\n";
  }
  md += "| | unit";
  for (const ComparedDesign& c : designs) md += " | " + io::md_cell(c.design.name);
  md += " |\n|---|---";
  for (std::size_t k = 0; k < designs.size(); ++k) md += "|---:";
  md += "|\n";
  for (const Row& row : rows()) {
    bool any = false;
    for (const ComparedDesign& c : designs) any = any || row.value(c).has_value();
    if (!any) continue;
    const io::PeopleUnit unit = io::people_unit(row.unit, row.key);
    md += fmt::format("| {} | {}", row.label, unit.unit);
    for (const ComparedDesign& c : designs) {
      const auto v = row.value(c);
      md += " | " + (v ? io::significant(*v * unit.factor, 4) : std::string("—"));
    }
    md += " |\n";
  }
  md += "\nEach design alone, as `sweetspot evaluate` says it:\n\n";
  for (const ComparedDesign& c : designs) {
    md += "- **" + io::md_cell(c.design.name) + "** (`" + io::md_cell(c.design.source) +
          "`): " + io::terminal_text(sweet_spot_paragraph(c.design, c.spots)) + "\n";
  }
  return md;
}

namespace {

// The curve along the frame is drawn and tabulated in steps of this much.

std::string title_of(const std::vector<ComparedDesign>& designs) {
  std::string title = "Compared";
  for (std::size_t k = 0; k < designs.size(); ++k)
    title += (k == 0 ? ": " : k + 1 == designs.size() ? " and " : ", ") + designs[k].design.name;
  return title;
}

// The side-by-side table: each value in people's units, the SI value under it.
std::string side_by_side_html(const std::vector<ComparedDesign>& designs) {
  std::string html =
      "<div class=\"table-wrap\"><table id=\"compared\" class=\"side-by-side\"><thead><tr>"
      "<th>quantity (unit)</th>";
  for (const ComparedDesign& c : designs)
    html += "<th class=\"num\">" + reports::html_escape(c.design.name) + "</th>";
  html += "</tr></thead><tbody>\n";
  for (const Row& row : rows()) {
    bool any = false;
    for (const ComparedDesign& c : designs) any = any || row.value(c).has_value();
    if (!any) continue;
    const io::PeopleUnit unit = io::people_unit(row.unit, row.key);
    const std::string shown_unit(unit.unit);
    html += fmt::format("<tr id=\"cmp-{}\"><td>{}{}<div class=\"means\"><code>{}</code></div></td>",
                        row.key, reports::html_escape(row.label),
                        shown_unit.empty() ? "" : " (" + reports::html_escape(shown_unit) + ")",
                        row.key);
    for (const ComparedDesign& c : designs) {
      const auto v = row.value(c);
      if (!v) {
        html += "<td class=\"num\">—</td>";
        continue;
      }
      const double people = *v * unit.factor;
      html += fmt::format("<td class=\"num\">{}<span class=\"si\">{}{}</span></td>",
                          io::significant(people, 4), io::significant(*v, 6),
                          *row.unit ? " " + reports::html_escape(row.unit) : std::string());
    }
    html += "</tr>\n";
  }
  return html + "</tbody></table></div>\n";
}

// The peak wrist force for a hit anywhere along each frame, overlaid, and
// the numbers behind it (one row per centimetre from the tip).
std::string wrist_along_frame_html(const std::vector<ComparedDesign>& designs) {
  io::Plot plot{"The wrist force for a hit along the frame",
                "impact point from the tip (cm)",
                "peak wrist force (N)",
                std::nullopt,
                std::nullopt,
                {},
                {},
                {}};
  // Rows by position from the tip in tenths of a millimetre, so that the
  // designs' points on the same centimetre share a row.
  std::map<long, std::vector<std::optional<double>>> table;
  double longest_cm = 0.0;
  for (std::size_t k = 0; k < designs.size(); ++k) {
    const std::vector<studies::FramePoint>& curve = designs[k].curve;
    // The key numbers the lines (a name would not fit a phone's layout);
    // the caption names them.
    io::PlotSeries series{std::to_string(k + 1), {}, {}, "lines lw 2.5"};
    series.color = io::plot_color(k);
    for (const studies::FramePoint& p : curve) {
      series.x.push_back(p.from_tip_m * 100.0);
      series.y.push_back(p.peak_wrist_force_N);
      auto& cells = table[std::lround(p.from_tip_m * 1e4)];
      cells.resize(designs.size());
      cells[k] = p.peak_wrist_force_N;
    }
    longest_cm = std::max(longest_cm, designs[k].design.design.implement.length_m() * 100.0);
    plot.series.push_back(std::move(series));
  }
  plot.x_range = std::pair{0.0, longest_cm};
  // Above the hand-held COP, where the curves are least.
  plot.key_position = "top center";
  std::string lines;
  for (std::size_t k = 0; k < designs.size(); ++k)
    lines += fmt::format("{}<span class=\"swatch\" style=\"background: {}\"></span> {}: {}",
                         k == 0 ? "" : "; ", io::plot_color(k), k + 1,
                         reports::html_escape(designs[k].design.name));
  std::string html = reports::html_figure(
      plot, "plot-wrist",
      "The peak force on the wrist for a hit at each point along the frame, one line per "
      "design (" +
          lines +
          "): the share of the peak force of the impact that reaches the wrist (Cross 2004, Eq. "
          "11), of the rigid model's force (Eqs. 15-17) or, where a design solves the collision, "
          "the solved one; least at each design's hand-held COP.");
  html +=
      "<details><summary>The numbers behind this plot</summary><div class=\"table-wrap\">"
      "<table id=\"curve\"><thead><tr><th class=\"num\">impact from the tip (cm)</th>";
  for (std::size_t k = 0; k < designs.size(); ++k)
    html += fmt::format("<th class=\"num\">{}: {} (N)</th>", k + 1,
                        reports::html_escape(designs[k].design.name));
  html += "</tr></thead><tbody>\n";
  for (const auto& [at, cells] : table) {
    html += fmt::format("<tr><td class=\"num\">{:.1f}</td>", static_cast<double>(at) / 100.0);
    for (const auto& cell : cells)
      html += cell ? fmt::format("<td class=\"num\">{:.0f}</td>", *cell)
                   : std::string("<td class=\"num\">—</td>");
    html += "</tr>\n";
  }
  return html + "</tbody></table></div></details>\n";
}

}  // namespace

std::string comparison_html(const std::vector<ComparedDesign>& designs) {
  std::string html = reports::html_page_open(
      title_of(designs),
      "The designs side by side, each at its own impact and at its sweet spots.");
  html += "<section id=\"answer\"><h2>The answer</h2>\n<div class=\"answer\">\n";
  for (std::size_t k = 1; k < designs.size(); ++k) {
    std::string paragraph;
    for (const std::string& s : differences(designs[0], designs[k]))
      paragraph += (paragraph.empty() ? "" : " ") + reports::html_escape(s);
    html += "<p>" + paragraph + "</p>\n";
  }
  html +=
      "</div>\n<details><summary>Each design alone, as <code>sweetspot evaluate</code> says it"
      "</summary>\n<ul>\n";
  for (const ComparedDesign& c : designs) {
    html += "<li><strong>" + reports::html_escape(c.design.name) +
            "</strong>: " + reports::html_escape(sweet_spot_paragraph(c.design, c.spots)) +
            "</li>\n";
  }
  html += "</ul></details></section>\n";

  html +=
      "<section id=\"numbers\"><h2>Side by side</h2>\n"
      "<p>Each value in a player's units, the SI value under it (as <code>--format json"
      "</code> gives it).</p>\n" +
      side_by_side_html(designs) + "</section>\n";

  // Racquets, bats (given by a profile), or implements when both.
  const auto round_count = std::count_if(designs.begin(), designs.end(),
                                         [](const auto& c) { return is_round(c.design.design); });
  const std::string things = round_count == 0 ? "racquets"
                             : round_count == static_cast<std::ptrdiff_t>(designs.size())
                                 ? "bats"
                                 : "implements";
  html += "<section id=\"racquets\"><h2>The " + things + ", to one scale</h2>\n<p>" +
          (things == "racquets" ? "Each from above"
           : things == "bats"   ? "Each from the side"
                                : "Each racquet from above and each bat from the side") +
          ", tip "
          "on the left: the balance point (triangle), the hand-held COP (red dot), the node (blue "
          "diamond, when the frame's stiffness is known), the lead (orange) and the ball at the "
          "impact (off the axis where the hit is, 3 o'clock up).</p>\n";
  std::vector<reports::DrawnRacquet> drawn;
  for (const ComparedDesign& c : designs)
    drawn.push_back({&c.design, &c.spots.asked.evaluation, reports::html_escape(c.design.name)});
  html += reports::racquets_to_scale_html(drawn, "drawing") + "</section>\n";

  html += "<section id=\"frame\"><h2>Along the frame</h2>\n" + wrist_along_frame_html(designs) +
          "</section>\n";

  std::string sources;
  for (const ComparedDesign& c : designs)
    sources += (sources.empty() ? "" : ", ") +
               ("<code>" + reports::html_escape(c.design.source) + "</code>");
  return html + reports::html_page_close(
                    "Computed by sweetspot from " + sources +
                    ", after R. Cross, \"Center of percussion of hand-held implements\", Am. J. "
                    "Phys. 72 (2004). Positions are measured from the tip of each of the " +
                    things + ".");
}

}  // namespace sweetspot::reports
