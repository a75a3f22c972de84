#include "studies/sweet_spots.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <numbers>
#include <stdexcept>
#include <string>
#include <utility>

#include "io/input_error.hpp"
#include "io/json_reader.hpp"
#include "studies/frame_curves.hpp"
#include "sweetspot/frame_modes.hpp"

namespace sweetspot::studies {
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
  // The file's impact is not this one: a refusal here is the spot's, not the
  // file's key's.
  for (const char* key : {"impact/from_butt_m", "impact/from_tip_m", "impact/off_axis_m"})
    moved.keys.erase(key);
  return io::evaluate_design_file(moved, fidelity, rel_tol);
}

std::optional<double> on_implement_from_tip(const Evaluation& e, std::optional<double> from_butt) {
  if (!from_butt || !(*from_butt >= 0.0 && *from_butt <= e.length_m)) return std::nullopt;
  return e.length_m - *from_butt;
}

// The string bed's long axis [m from the tip] (hit_span(), as the curves are drawn over).
std::pair<double, double> string_bed_axis(const io::DesignFile& design) {
  const AxisSpan span = hit_span(design);
  return {span.from_tip_m, span.to_tip_m};
}

// Golden-section search for the largest value of `f` over [lo, hi] [m from
// the tip]: each step keeps the part that holds the maximum of a unimodal
// function and shrinks it by 1/phi, reusing one interior point; the midpoint
// of the last bracket, at most `tolerance_m` wide.
template <class F>
double golden_section_max(F&& f, double lo, double hi, double tolerance_m) {
  const double inv_phi = (std::sqrt(5.0) - 1.0) / 2.0;
  double x1 = hi - inv_phi * (hi - lo), x2 = lo + inv_phi * (hi - lo);
  double f1 = f(x1), f2 = f(x2);
  while (hi - lo > tolerance_m) {
    if (f1 >= f2) {
      hi = x2, x2 = x1, f2 = f1;
      x1 = hi - inv_phi * (hi - lo);
      f1 = f(x1);
    } else {
      lo = x1, x1 = x2, f1 = f2;
      x2 = lo + inv_phi * (hi - lo);
      f2 = f(x2);
    }
  }
  return 0.5 * (lo + hi);
}

// The spacing of the scan that brackets the largest value before the
// golden-section search: the rebound along a soft frame can have two humps
// (one each side of the fundamental's antinode), and a search that assumes
// one finds either.
inline constexpr double kScanSpacing_m = 0.03;
inline constexpr int kMinScanIntervals = 6;

// The scan's evaluations, shared by the searches of one design at one
// fidelity: the best rebound and the power point scan the same points.
struct ScanCache {
  std::string fidelity;
  std::map<double, std::optional<Evaluation>> at;  // std::nullopt: refused there
};

// The point of the string bed's long axis [m from the tip] where `value` of
// the evaluation there is largest, and that evaluation: the best of a scan
// every kScanSpacing_m or closer, then a golden-section search to
// `tolerance_m` between its neighbours. A point the model refuses (a ball
// squeezed past its radius where the frame gives less) counts as -infinity, so
// the search keeps to the points it answers; where it ends on one it refuses,
// the best point it answered is the answer (std::nullopt when it answered
// none). `cache`, when given at this fidelity, holds and keeps the scan's.
template <class Value>
std::optional<SpotOutcome> max_along_axis(const io::DesignFile& design, std::string_view fidelity,
                                          double rel_tol, double tolerance_m, Value value,
                                          ScanCache* cache = nullptr) {
  const auto [lo, hi] = string_bed_axis(design);
  std::optional<SpotOutcome> best_answered;
  const auto evaluation_at = [&](double from_tip, bool scanned) -> std::optional<Evaluation> {
    if (scanned && cache && cache->fidelity == fidelity) {
      if (const auto it = cache->at.find(from_tip); it != cache->at.end()) return it->second;
    }
    std::optional<Evaluation> e;
    try {
      e = evaluate_at(design, from_tip, fidelity, rel_tol);
    } catch (const io::InputError&) {
    }
    if (scanned && cache && cache->fidelity == fidelity) cache->at.emplace(from_tip, e);
    return e;
  };
  const auto value_of = [&](double from_tip, bool scanned) {
    const std::optional<Evaluation> e = evaluation_at(from_tip, scanned);
    if (!e) return -std::numeric_limits<double>::infinity();
    const double v = value(*e);
    if (!best_answered || v > value(best_answered->evaluation))
      best_answered = SpotOutcome{from_tip, *e};
    return v;
  };
  const int intervals =
      std::max(kMinScanIntervals, static_cast<int>(std::ceil((hi - lo) / kScanSpacing_m)));
  const double step = (hi - lo) / intervals;
  int best_k = 0;
  double best_value = -std::numeric_limits<double>::infinity();
  for (int k = 0; k <= intervals; ++k) {
    const double v = value_of(k == intervals ? hi : lo + k * step, true);
    if (v > best_value) best_value = v, best_k = k;
  }
  const double best = golden_section_max(
      [&](double x) { return value_of(x, false); }, lo + std::max(0, best_k - 1) * step,
      best_k + 1 >= intervals ? hi : lo + (best_k + 1) * step, tolerance_m);
  if (const std::optional<Evaluation> e = evaluation_at(best, false)) return SpotOutcome{best, *e};
  return best_answered;
}

void require_tolerance(double tolerance_m) {
  if (!(tolerance_m > 0.0)) {
    throw std::invalid_argument("tolerance_m: must be > 0 m, got " + std::to_string(tolerance_m));
  }
}

std::optional<SpotOutcome> best_rebound_searched(const io::DesignFile& design, double rel_tol,
                                                 double tolerance_m, ScanCache* cache) {
  require_tolerance(tolerance_m);
  if (!design.design.strings || !has_stiffness(design.design) || design.design.cor_rigid)
    return std::nullopt;
  return max_along_axis(
      design, "collision", rel_tol, tolerance_m, [](const Evaluation& e) { return e.apparent_cor; },
      cache);
}

std::optional<SpotOutcome> power_point_searched(const io::DesignFile& design,
                                                std::string_view fidelity, double rel_tol,
                                                double tolerance_m, ScanCache* cache) {
  require_tolerance(tolerance_m);
  if (!is_racquet(design)) return std::nullopt;
  return max_along_axis(
      design, fidelity, rel_tol, tolerance_m, [](const Evaluation& e) { return e.shot_speed_m_s; },
      cache);
}

}  // namespace

std::optional<SpotOutcome> best_rebound_on_axis(const io::DesignFile& design, double rel_tol,
                                                double tolerance_m) {
  return best_rebound_searched(design, rel_tol, tolerance_m, nullptr);
}

std::optional<SpotOutcome> power_point_on_axis(const io::DesignFile& design,
                                               std::string_view fidelity, double rel_tol,
                                               double tolerance_m) {
  return power_point_searched(design, fidelity, rel_tol, tolerance_m, nullptr);
}

Evaluation with_power_point(const io::DesignFile& design, Evaluation evaluation, double rel_tol) {
  if (is_rig(evaluation.support)) return evaluation;  // the shot is a player's
  if (const auto power = power_point_on_axis(design, to_string(fidelity_of(evaluation)), rel_tol)) {
    evaluation.power_point_from_butt_m = evaluation.length_m - power->from_tip_m;
    evaluation.power_point_shot_speed_m_s = power->evaluation.shot_speed_m_s;
  }
  return evaluation;
}

bool is_racquet(const io::DesignFile& design) {
  return io::has_racquet_head(design.design, design.implement_form == "specs"
                                                 ? io::ImplementDescription::Form::kSpecs
                                                 : io::ImplementDescription::Form::kSections);
}

HeadShape head_shape_of(const io::DesignFile& design) { return racquet_head(design.design); }

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
      // The reason alone: not the file, nor the JSON path of a point the
      // file did not ask about.
      std::string why = refusal.what();
      if (const auto colon = why.find(": "); colon != std::string::npos)
        why = why.substr(colon + 2);
      if (const auto colon = why.find(": "); why.starts_with("/") && colon != std::string::npos)
        why = why.substr(colon + 2);
      spots.unanswered.push_back({what, from_tip, std::move(why)});
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
        "give the frame's stiffness (frame.RA, the spec sheet's rating; "
        "frame.fundamental_free_Hz, the free frame's fundamental frequency; or frame.EI_N_m2) "
        "to locate the node of least vibration";
  }
  // Both searches scan the same points: at the same fidelity, once.
  ScanCache scan{std::string(fidelity), {}};
  if (fidelity_of(asked) == Fidelity::kCollision)
    spots.best_rebound = best_rebound_searched(design, rel_tol, kBestReboundTolerance_m, &scan);
  spots.power_point =
      power_point_searched(design, fidelity, rel_tol, kBestReboundTolerance_m, &scan);
  if (is_racquet(design)) {
    const double centre = centre_of_strings_from_tip_m(design);
    spots.centre_of_strings = at(centre, "centre of the strings");
  }
  return spots;
}

}  // namespace sweetspot::studies
