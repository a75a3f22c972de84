#include "reports/summary.hpp"

#include <fmt/format.h>

#include <cmath>
#include <numbers>
#include <stdexcept>

#include "io/input_error.hpp"
#include "io/json_reader.hpp"
#include "sweetspot/frame_modes.hpp"

namespace sweetspot::reports {
namespace {

// The design with the ball at `from_tip_m`, evaluated at `fidelity`.
Evaluation evaluate_at(const io::DesignFile& design, double from_tip_m, std::string_view fidelity,
                       double rel_tol) {
  io::DesignFile moved = design;
  moved.design.impact_from_butt_m = design.design.implement.length_m() - from_tip_m;
  // The sweet spots (the COP, the node, the centre of the strings, the best
  // rebound) lie on the long axis: an off-axis miss is the asked impact's
  // alone, and may not be on the head at another point along the frame.
  moved.design.impact_off_axis_m = 0.0;
  return io::evaluate_design_file(moved, fidelity, rel_tol);
}

std::optional<double> on_implement_from_tip(const Evaluation& e, std::optional<double> from_butt) {
  if (!from_butt || !(*from_butt >= 0.0 && *from_butt <= e.length_m)) return std::nullopt;
  return e.length_m - *from_butt;
}

// "the wrist feels a jolt of 470 N and the ball comes back at 0.42 of its speed"; the
// first time with "(apparent COR)".
std::string feel(const Evaluation& e, bool first = false) {
  const std::string wrist =
      e.peak_wrist_force_N == 0.0 || newton_text(e.peak_wrist_force_N) == "0 N"
          ? std::string("the wrist feels no jolt")
          : "the wrist feels a jolt of " + newton_text(e.peak_wrist_force_N);
  return fmt::format("{} and the ball comes back at {} of its speed{}", wrist,
                     ratio_text(e.apparent_cor), first ? " (the apparent COR)" : "");
}

}  // namespace

std::optional<SpotOutcome> best_rebound_on_axis(const io::DesignFile& design, double rel_tol,
                                                double tolerance_m) {
  if (!(tolerance_m > 0.0)) {
    throw std::invalid_argument("tolerance_m: must be > 0 m, got " + std::to_string(tolerance_m));
  }
  if (!design.design.strings || !has_stiffness(design.design) || design.design.cor_rigid)
    return std::nullopt;
  const double length = design.design.implement.length_m();
  const HeadShape head = head_shape_of(design);
  const double semi_length = std::sqrt(head.area_m2 * head.aspect_ratio / std::numbers::pi);
  double lo = std::min(head.hoop_width_m, length);  // from the tip
  double hi = std::min(head.hoop_width_m + 2.0 * semi_length, length);
  auto cor_at = [&](double from_tip) {
    return evaluate_at(design, from_tip, "collision", rel_tol).apparent_cor;
  };
  // Golden-section search for the largest apparent COR: each step keeps the
  // part of [lo, hi] that holds the maximum of a unimodal function and
  // shrinks it by 1/phi, reusing one interior point.
  const double inv_phi = (std::sqrt(5.0) - 1.0) / 2.0;
  double x1 = hi - inv_phi * (hi - lo), x2 = lo + inv_phi * (hi - lo);
  double f1 = cor_at(x1), f2 = cor_at(x2);
  while (hi - lo > tolerance_m) {
    if (f1 >= f2) {
      hi = x2, x2 = x1, f2 = f1;
      x1 = hi - inv_phi * (hi - lo);
      f1 = cor_at(x1);
    } else {
      lo = x1, x1 = x2, f1 = f2;
      x2 = lo + inv_phi * (hi - lo);
      f2 = cor_at(x2);
    }
  }
  const double best = 0.5 * (lo + hi);
  return SpotOutcome{best, evaluate_at(design, best, "collision", rel_tol)};
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

bool is_racquet(const io::DesignFile& design) {
  return io::has_racquet_head(design.design, design.implement_form == "specs"
                                                 ? io::ImplementDescription::Form::kSpecs
                                                 : io::ImplementDescription::Form::kSections);
}

HeadShape head_shape_of(const io::DesignFile& design) { return io::racquet_head(design.design); }

double centre_of_strings_from_tip_m(const io::DesignFile& design) {
  return io::centre_of_strings_from_tip_m(design.design);
}

SweetSpots find_sweet_spots(const io::DesignFile& design, const Evaluation& asked, double rel_tol) {
  const std::string_view fidelity = to_string(fidelity_of(asked));
  SweetSpots spots;
  spots.asked = SpotOutcome{asked.length_m - asked.impact_from_butt_m, asked};
  if (const auto it = design.provenance.find("impact/from_butt_m");
      it != design.provenance.end() && it->second.starts_with("default"))
    spots.asked_provenance = it->second;
  // A hit at a sweet spot the model refuses leaves that spot out, said why.
  const auto at = [&](double from_tip, const char* what) -> std::optional<SpotOutcome> {
    try {
      return SpotOutcome{from_tip, evaluate_at(design, from_tip, fidelity, rel_tol)};
    } catch (const io::InputError& refusal) {
      std::string why = refusal.what();
      if (const auto colon = why.find(": "); colon != std::string::npos)
        why = why.substr(colon + 2);
      spots.unanswered.push_back(
          fmt::format("The model cannot answer a hit at the {}, {} from "
                      "the tip: {}.",
                      what, cm_text(from_tip), why));
      return std::nullopt;
    }
  };
  spots.cop_from_tip_m = on_implement_from_tip(asked, asked.cop_hand_from_butt_m);
  if (spots.cop_from_tip_m) spots.cop_hand = at(*spots.cop_from_tip_m, "centre of percussion");
  if (asked.modal) {
    const auto node = on_implement_from_tip(asked, asked.modal->node_hand_from_butt_m);
    spots.node_from_tip_m = node;
    if (node) spots.node_hand = at(*node, "node");
    spots.node_free_from_tip_m = on_implement_from_tip(asked, asked.modal->node_free_from_butt_m);
    if (!spots.node_hand) {
      spots.node_missing = node ? "the model cannot answer a hit at it"
                                : "the hand-held fundamental has no node on the frame";
    }
  } else {
    spots.node_missing =
        "give the frame's stiffness (frame.fundamental_free_Hz, the free frame's fundamental "
        "frequency, or frame.EI_N_m2) to locate the node of least vibration";
  }
  if (fidelity_of(asked) == Fidelity::kCollision)
    spots.best_rebound = best_rebound_on_axis(design, rel_tol, kBestReboundTolerance_m);
  if (is_racquet(design)) {
    const double centre = centre_of_strings_from_tip_m(design);
    spots.centre_of_strings = at(centre, "centre of the strings");
  }
  return spots;
}

std::vector<std::string> sweet_spot_sentences(const io::DesignFile& design,
                                              const SweetSpots& spots) {
  std::vector<std::string> sentences;
  const Evaluation& asked = spots.asked.evaluation;
  // 1. Where the sweet spots are, and how far apart.
  if (spots.cop_from_tip_m && spots.node_from_tip_m) {
    sentences.push_back(fmt::format(
        "Held in the hand, this {} has two sweet spots: the centre of percussion, {} from the "
        "tip, where the wrist feels the least jolt, and the node of its fundamental vibration "
        "({:.0f} Hz in the hand), {} from the tip, where the frame vibrates least.",
        is_racquet(design) ? "racquet" : "implement", cm_text(*spots.cop_from_tip_m),
        asked.modal->fundamental_hand_Hz, cm_text(*spots.node_from_tip_m)));
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
        is_racquet(design) ? "racquet" : "implement", cm_text(*spots.cop_from_tip_m)));
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
  sentences.insert(sentences.end(), spots.unanswered.begin(), spots.unanswered.end());
  // 2. What the arm and the ball feel at each.
  const std::string speed = fmt::format("{:.3g} m/s", design.design.ball.speed_m_s);
  if (spots.cop_hand) {
    sentences.push_back(fmt::format("For a ball at {}, at the centre of percussion {}.", speed,
                                    feel(spots.cop_hand->evaluation, true)));
  }
  if (spots.node_hand) {
    sentences.push_back(
        fmt::format("At the node {}.", feel(spots.node_hand->evaluation, !spots.cop_hand)));
  }
  // 3. The point of best rebound (the collision fidelity) slots in here.
  if (spots.best_rebound) {
    sentences.push_back(
        fmt::format("The ball comes back fastest, at {:.2g} m/s, {} from the tip, where {}.",
                    spots.best_rebound->evaluation.rebound_speed_m_s,
                    cm_text(spots.best_rebound->from_tip_m), feel(spots.best_rebound->evaluation)));
  }
  // 4. The centre of the strings and the impact asked about.
  const bool asked_is_centre =
      spots.centre_of_strings &&
      cm_text(spots.centre_of_strings->from_tip_m) == cm_text(spots.asked.from_tip_m);
  if (spots.centre_of_strings && !asked_is_centre) {
    sentences.push_back(fmt::format("At the centre of the strings, about {} from the tip, {}.",
                                    cm_text(spots.centre_of_strings->from_tip_m),
                                    feel(spots.centre_of_strings->evaluation)));
  }
  const std::string where =
      spots.asked_provenance == "given" ? fmt::format("At the impact asked about, {} from the tip,",
                                                      cm_text(spots.asked.from_tip_m))
      : asked_is_centre
          ? fmt::format(
                "At the centre of the strings, about {} from the tip (no impact was given, "
                "so the tables below are for this one),",
                cm_text(spots.asked.from_tip_m))
          : fmt::format(
                "At {} from the tip (no impact was given: {}; the tables below are for "
                "this one),",
                cm_text(spots.asked.from_tip_m), spots.asked_provenance);
  sentences.push_back(fmt::format("{} {}.", where, feel(asked)));
  sentences.push_back(
      "Positions are rounded to 0.5 cm and forces to two figures: the hand's place and the "
      "arm's mass are assumed, not measured.");
  return sentences;
}

std::string sweet_spot_paragraph(const io::DesignFile& design, const SweetSpots& spots) {
  std::string paragraph;
  for (const std::string& sentence : sweet_spot_sentences(design, spots)) {
    paragraph += (paragraph.empty() ? "" : " ") + sentence;
  }
  return paragraph;
}

}  // namespace sweetspot::reports
