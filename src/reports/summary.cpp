#include "reports/summary.hpp"

#include <fmt/format.h>

#include <cmath>
#include <regex>
#include <string>

#include "io/format.hpp"

namespace sweetspot::reports {
namespace {

// "the wrist feels a jolt of 470 N and the ball comes back at 0.42 of its speed"; the
// first time with "(apparent COR)". Off a swinging implement, the speed is the one the
// ball and the strings (a racquet's) meet at (the implement is free during the contact:
// swing.hpp).
std::string feel(const Evaluation& e, bool first = false, bool swinging = false,
                 bool racquet = true) {
  const std::string wrist =
      e.peak_wrist_force_N == 0.0 || newton_text(e.peak_wrist_force_N) == "0 N"
          ? std::string("the wrist feels no jolt")
          : "the wrist feels a jolt of " + newton_text(e.peak_wrist_force_N);
  const char* speed = !swinging ? "its speed"
                      : racquet ? "the speed it meets the strings at"
                                : "the speed it meets the implement at";
  if (ratio_text(e.apparent_cor).starts_with("-")) {
    // e_A < 0: the racquet gives way faster than the ball is pushed back.
    return fmt::format("{} and the ball does not come back: it goes on at {} of {}{}", wrist,
                       ratio_text(-e.apparent_cor), speed,
                       first ? " (an apparent COR of " + ratio_text(e.apparent_cor) + ")" : "");
  }
  return fmt::format("{} and the ball comes back at {} of {}{}", wrist, ratio_text(e.apparent_cor),
                     speed, first ? " (the apparent COR)" : "");
}

// The model's reason in a coach's units: its lengths in metres ("0.015 to
// 0.348009 m", "got 0.415369 m") as the rest of the paragraph gives them, in
// cm to 0.5 cm. A speed (m/s), an area or an inertia (m^2, m²) stays as it is.
std::string in_centimetres(const std::string& why) {
  static const std::regex kLength(
      R"((-?\d+(?:\.\d+)?(?:e[-+]?\d+)?)(?: to (-?\d+(?:\.\d+)?(?:e[-+]?\d+)?))? m(?![\w/^\xC2]))");
  std::string out;
  auto from = why.cbegin();
  for (std::sregex_iterator it(why.begin(), why.end(), kLength), end; it != end; ++it) {
    const std::smatch& m = *it;
    out.append(from, m[0].first);
    std::string text = cm_text(std::stod(m[1].str()));  // "1.5 cm"
    if (m[2].matched)
      text = text.substr(0, text.size() - 3) + " to " + cm_text(std::stod(m[2].str()));
    out += text;
    from = m[0].second;
  }
  out.append(from, why.cend());
  return out;
}

}  // namespace

std::string rig_paragraph(const io::DesignFile& design, const Evaluation& e) {
  const Support::Kind kind = e.support.kind;
  const std::string where =
      kind == Support::Kind::kRigidSurface  ? "On a rigid surface"
      : kind == Support::Kind::kHeadClamped ? "On the strings of the head-clamped frame"
      : kind == Support::Kind::kHandleClamped
          ? "With the handle clamped"
          : "On the pivot " + cm_text(design.design.support.pivot_from_butt_m) + " from the butt";
  const double squeeze_mm =
      e.details && e.details->collision ? e.details->collision->peak_ball_compression_m * 1e3 : 0.0;
  return fmt::format(
      "{}, the ball comes back at {} of its {:.3g} m/s (the apparent COR) after {:.2f} ms of "
      "contact; the force peaks at {} and the ball squeezes {:.1f} mm. A rig holds the "
      "implement still: nothing of a player (wrist force, sweet spots, the shot) is given.",
      where, ratio_text(e.apparent_cor), design.design.ball.speed_m_s, e.impact_duration_s * 1e3,
      newton_text(e.peak_impact_force_N), squeeze_mm);
}

std::string cm_text(double metres) {
  const double half_cm = std::round(metres * 200.0) / 2.0;
  if (half_cm == std::floor(half_cm)) return fmt::format("{:.0f} cm", half_cm == 0 ? 0.0 : half_cm);
  return fmt::format("{:.1f} cm", half_cm);
}

std::string newton_text(double newtons) {
  const double magnitude = std::fabs(newtons);
  if (magnitude < 0.5) return "0 N";
  const int digits = static_cast<int>(std::floor(std::log10(magnitude)));
  const double scale = std::pow(10.0, digits - 1);
  const double rounded = std::round(newtons / scale) * scale;
  return fmt::format("{:.{}f} N", rounded, std::max(0, 1 - digits));
}

std::string ratio_text(double ratio) {
  const double hundredths = std::round(ratio * 100.0);
  return fmt::format("{:.2f}", hundredths == 0.0 ? 0.0 : hundredths / 100.0);  // no "-0.00"
}

std::vector<std::string> sweet_spot_sentences(const io::DesignFile& design,
                                              const studies::SweetSpots& spots) {
  std::vector<std::string> sentences;
  const Evaluation& asked = spots.asked.evaluation;
  const bool racquet = studies::is_racquet(design);
  const char* thing = racquet ? "racquet" : "implement";
  // 1. Where the sweet spots are, and how far apart.
  if (spots.cop_from_tip_m && spots.node_from_tip_m) {
    sentences.push_back(fmt::format(
        "Held in the hand, this {} has two sweet spots: the centre of percussion, {} from the "
        "tip, where the wrist feels the least jolt, and the node of its fundamental vibration "
        "({:.0f} Hz in the hand), {} from the tip, where the frame vibrates least.",
        thing, cm_text(*spots.cop_from_tip_m), asked.modal->fundamental_hand_Hz,
        cm_text(*spots.node_from_tip_m)));
    const double gap = std::fabs(*spots.cop_from_tip_m - *spots.node_from_tip_m);
    sentences.push_back(cm_text(gap) == "0 cm"
                            ? std::string("The two coincide.")
                            : fmt::format("They are {} apart, the {} nearer the tip.", cm_text(gap),
                                          *spots.node_from_tip_m < *spots.cop_from_tip_m
                                              ? "node"
                                              : "centre of percussion"));
  } else if (spots.cop_from_tip_m) {
    sentences.push_back(fmt::format(
        "Held in the hand, this {}'s centre of percussion, where the wrist feels the least jolt, "
        "is {} from the tip.",
        thing, cm_text(*spots.cop_from_tip_m)));
    sentences.push_back("The node of least vibration is not located: " + spots.node_missing + ".");
  } else {
    sentences.push_back(
        "Held in the hand, this implement has no centre of percussion on its length (implement "
        "and hand balance at the wrist), so every impact jolts the wrist.");
    if (spots.node_from_tip_m) {
      sentences.push_back(fmt::format("The node of least vibration is {} from the tip.",
                                      cm_text(*spots.node_from_tip_m)));
    }
  }
  for (const studies::UnansweredSpot& spot : spots.unanswered)
    sentences.push_back(fmt::format("The model cannot answer a hit at the {}, {} from the tip: {}.",
                                    spot.what, cm_text(spot.from_tip_m), in_centimetres(spot.why)));
  // 2. What the arm and the ball feel at each.
  const bool swinging = design.design.swing.has_value();
  const std::string speed = fmt::format("{:.3g} m/s", design.design.ball.speed_m_s);
  if (spots.cop_hand) {
    const Evaluation& cop = spots.cop_hand->evaluation;
    const std::string ball =
        swinging ? fmt::format(
                       "a ball coming at {} onto the swinging {} (they meet at {:.3g} "
                       "m/s there)",
                       speed, thing, cop.incoming_speed_m_s + cop.racquet_speed_m_s)
                 : "a ball at " + speed;
    sentences.push_back(fmt::format("For {}, at the centre of percussion {}.", ball,
                                    feel(cop, true, swinging, racquet)));
  }
  if (spots.node_hand) {
    sentences.push_back(fmt::format(
        "At the node {}.", feel(spots.node_hand->evaluation, !spots.cop_hand, swinging, racquet)));
  }
  // 3. The point of best rebound (the collision fidelity) slots in here.
  if (spots.best_rebound) {
    const Evaluation& best = spots.best_rebound->evaluation;
    sentences.push_back(
        ratio_text(best.apparent_cor).starts_with("-") || ratio_text(best.apparent_cor) == "0.00"
            // e_A <= 0 everywhere: the best is where the ball goes on slowest.
            ? fmt::format("Nowhere along the strings does the ball come back{}; it goes on "
                          "slowest {} from the tip, where {}.",
                          swinging ? " relative to the racquet" : "",
                          cm_text(spots.best_rebound->from_tip_m),
                          feel(best, false, swinging, racquet))
            : fmt::format(
                  "The ball comes back fastest{}, at {:.2g} m/s, {} from the tip, where {}.",
                  swinging ? " relative to the racquet" : "", best.rebound_speed_m_s,
                  cm_text(spots.best_rebound->from_tip_m), feel(best, false, swinging, racquet)));
  }
  // The impact the tables are for, by its name: the one asked about, or the
  // default (the centre of the strings, or where the paper's Table I hits).
  const bool asked_is_centre =
      spots.centre_of_strings &&
      cm_text(spots.centre_of_strings->from_tip_m) == cm_text(spots.asked.from_tip_m);
  const std::string asked_name =
      spots.asked_provenance == "given" ? "the impact asked about"
      : asked_is_centre                 ? "the centre of the strings"
                        : "the impact " + cm_text(spots.asked.from_tip_m) + " from the tip";
  // 3b. The shot off the swinging racquet (swing.hpp), at its power point.
  if (spots.power_point) {
    const Evaluation& power = spots.power_point->evaluation;
    const std::string swing =
        asked.swing_assumed
            ? std::string(
                  "an assumed groundstroke (no swing given: 15.4 m/s 50 cm from the butt, "
                  "turning about a pivot 60 cm beyond it; Kwon et al. 2017)")
            : fmt::format("its swing ({:.3g} rad/s about a pivot {} beyond the butt)",
                          asked.swing.angular_speed_rad_s,
                          cm_text(asked.swing.pivot_beyond_butt_m));
    std::string than_rebound;
    if (spots.best_rebound) {
      const double gap = spots.best_rebound->from_tip_m - spots.power_point->from_tip_m;
      than_rebound = cm_text(std::fabs(gap)) == "0 cm"
                         ? std::string(
                               ", where the ball also rebounds best off the racquet "
                               "at rest")
                         : fmt::format(
                               ", {} {} the tip than the best rebound off the racquet "
                               "at rest",
                               cm_text(std::fabs(gap)), gap > 0.0 ? "nearer" : "farther from");
    }
    sentences.push_back(fmt::format(
        "Swung as {} at a ball coming at {:.3g} m/s, the shot is fastest, {:.0f} km/h ({:.0f} "
        "mph), {} from the tip (the power point){}; {}.",
        swing, asked.incoming_speed_m_s, power.shot_speed_m_s * io::kKmHPerMS,
        power.shot_speed_m_s * io::kMphPerMS, cm_text(spots.power_point->from_tip_m), than_rebound,
        std::lround(asked.shot_speed_m_s * io::kKmHPerMS) < 0
            ? fmt::format("from {} the racquet does not turn it back: it goes on past the "
                          "racquet at {:.0f} km/h",
                          asked_name, -asked.shot_speed_m_s * io::kKmHPerMS)
            : fmt::format("from {} it leaves at {:.0f} km/h", asked_name,
                          asked.shot_speed_m_s * io::kKmHPerMS)));
    if (power.fidelity != Fidelity::kCollision) {
      // A COR given for the frame is the same at every point: the rebound does not fall
      // towards the tip as a string bed's does, so the power point sits near the balance.
      sentences.push_back(
          "That power point takes the frame's COR as the same at every point; the solved "
          "collision of ball, strings and frame (a string tension and a stiffness, no COR) "
          "places it on the strings, nearer the tip than the best rebound.");
    }
  }
  // 4. The centre of the strings and the impact asked about.
  if (spots.centre_of_strings && !asked_is_centre) {
    sentences.push_back(
        fmt::format("At the centre of the strings, about {} from the tip, {}.",
                    cm_text(spots.centre_of_strings->from_tip_m),
                    feel(spots.centre_of_strings->evaluation, false, swinging, racquet)));
  }
  // An impact given off the axis alone is placed along it by default.
  const double off_axis_m = asked.impact_off_axis_m;
  const std::string off_axis =
      off_axis_m == 0.0 ? "" : fmt::format(" and {} off the axis", cm_text(std::fabs(off_axis_m)));
  const auto off_axis_note = design.provenance.find("impact/off_axis_m");
  const bool off_axis_given =
      off_axis_note != design.provenance.end() && off_axis_note->second == "given";
  const char* not_given = off_axis_m == 0.0 && !off_axis_given
                              ? "no impact was given"
                              : "the impact's distance from the tip was not given";
  const std::string where =
      spots.asked_provenance == "given"
          ? fmt::format("At the impact asked about, {} from the tip{},",
                        cm_text(spots.asked.from_tip_m), off_axis)
      : asked_is_centre
          ? fmt::format(
                "At the centre of the strings, about {} from the tip{} ({}, so the tables below "
                "are for this one),",
                cm_text(spots.asked.from_tip_m), off_axis, not_given)
          : fmt::format(
                "At {} from the tip{}, where the paper's Table I hits ({}, so the "
                "tables below are for this one),",
                cm_text(spots.asked.from_tip_m), off_axis, not_given);
  sentences.push_back(fmt::format("{} {}.", where, feel(asked, false, swinging, racquet)));
  sentences.push_back(
      "Positions are rounded to 0.5 cm and forces to two figures: the hand's place and the "
      "arm's mass are assumed, not measured.");
  return sentences;
}

std::string sweet_spot_paragraph(const io::DesignFile& design, const studies::SweetSpots& spots) {
  std::string paragraph;
  for (const std::string& sentence : sweet_spot_sentences(design, spots)) {
    paragraph += (paragraph.empty() ? "" : " ") + sentence;
  }
  return paragraph;
}

}  // namespace sweetspot::reports
