#pragma once

// Where the sweet spots of a design held in the hand are and what the wrist
// and the ball feel at each: the design evaluated at its centre of
// percussion, the node of its hand-held fundamental, the point of best
// rebound and the centre of the strings. Plain data; reports/summary.hpp says
// it in sentences.

#include <optional>
#include <string>
#include <vector>

#include "io/design_reader.hpp"
#include "sweetspot/evaluate.hpp"
#include "sweetspot/head_geometry.hpp"

namespace sweetspot::studies {

// One point on the implement the answer speaks about, and the design
// evaluated with the ball there (same fidelity as the impact asked about).
struct SpotOutcome {
  double from_tip_m = 0.0;
  Evaluation evaluation;
};

// A sweet spot the model cannot answer a hit at: what it is ("node"), where,
// and the model's reason (the refusal's text after its JSON path).
struct UnansweredSpot {
  std::string what;
  double from_tip_m = 0.0;
  std::string why;
};

// The sweet spots of a design held in the hand.
struct SweetSpots {
  // The hand-held centre of percussion (Eq. 13): the least jolt to the wrist
  // (the rigid model's wrist force is zero there). Absent when it is at
  // infinity or off the implement.
  std::optional<SpotOutcome> cop_hand;
  // The node of the hand-held fundamental nearest the tip: the least
  // vibration. Needs the frame's stiffness (modal fidelity).
  std::optional<SpotOutcome> node_hand;
  // The free frame's node [m from the tip], for comparison (modal fidelity).
  std::optional<double> node_free_from_tip_m;
  // When there is no node: the input that would give it.
  std::string node_missing;
  // The point on the long axis of the string bed where the ball rebounds
  // fastest (the "power point", best_rebound_on_axis()), evaluated by the
  // solved collision; set when `asked` is at the collision fidelity.
  std::optional<SpotOutcome> best_rebound;
  // The point on the long axis of the string bed where the shot off the
  // swinging racquet is fastest (power_point_on_axis()), at the asked
  // fidelity; set for a racquet with a head.
  std::optional<SpotOutcome> power_point;
  // The centre of the strings, for a racquet (centre_of_strings_from_tip_m).
  std::optional<SpotOutcome> centre_of_strings;
  // The impact the design asks about (its own, or the default).
  SpotOutcome asked;
  // How that impact was chosen: "given", or what the default was.
  std::string asked_provenance = "given";
  // The sweet spots the model cannot answer a hit at (a refusal there is
  // that spot's, never the design's: the asked impact was answered).
  std::vector<UnansweredSpot> unanswered;
  // Where the centre of percussion and the node are [m from the tip], a hit
  // there answered or not (cop_hand, node_hand: its answer).
  std::optional<double> cop_from_tip_m, node_from_tip_m;
};

// Whether a design is a racquet with a head (io::has_racquet_head()): it
// gives a head, a string tension, or a spec sheet (length, mass, balance,
// swingweight).
bool is_racquet(const io::DesignFile& design);

// The centre of the string bed [m from the tip] of a racquet: the centre of
// head_geometry.hpp's string bed (string_bed()), one hoop width plus the
// ellipse's semi-length below the tip. The head is the design's own
// (implement.headsize_sq_in, head_aspect_ratio, hoop_width_*) or else an ellipse
// of the string bed's area (strings.head_size, 100 sq in by default) with the
// default aspect ratio (1.35) and hoop width (1.5 cm): 18.15 cm from the tip
// for 100 sq in. A stated assumption of shape, not a measurement: real heads
// differ by about a centimetre. Half the length when the head would not fit.
// The impact a racquet is hit at when its file gives none
// (io::default_impact()).
double centre_of_strings_from_tip_m(const io::DesignFile& design);

// The head of a racquet design: implement.headsize_sq_in (with its aspect
// ratio and hoop width) when given, else the default shape with the string
// bed's area (pi strings.head_radius_m^2), else 100 sq in.
HeadShape head_shape_of(const io::DesignFile& design);

// How closely best_rebound is located [m]: the 0.5 cm the sentences round to.
inline constexpr double kBestReboundTolerance_m = 0.005;

// The impact point on the long axis of the string bed (head_shape_of(): from
// one hoop width below the tip to the throat end of the ellipse) where the
// solved collision (Fidelity::kCollision) returns the ball fastest, i.e. the
// largest apparent COR e_A: the best of a scan every 3 cm or closer (e_A can
// have two humps along a soft frame), then a golden-section search between
// its neighbours until the bracket is at most `tolerance_m` wide (> 0, else
// std::invalid_argument naming "tolerance_m"); the midpoint of the bracket,
// within tolerance_m / 2 of the maximiser when e_A has one hump there. The frame's COR e peaks at
// the fundamental's node (Cross, Am. J. Phys. 68, 1025 (2000)), but e_A = (e M_eff
// - m) / (M_eff + m) also grows with M_eff towards the handle, so the point is
// throat-side of the node (5.5 cm on designs/racquets/tour-100-strung.json,
// 17.7 cm from the tip; the node is 12.2 cm). std::nullopt when the
// design lacks what the collision needs (a string tension, the frame's
// stiffness, no cor_rigid). A point the model refuses (io::InputError) is
// left out of the search: where it ends on one, the best point it answered
// (std::nullopt if none).
std::optional<SpotOutcome> best_rebound_on_axis(const io::DesignFile& design, double rel_tol,
                                                double tolerance_m = kBestReboundTolerance_m);

// The impact point on the long axis of the string bed (the range of
// best_rebound_on_axis()) where the shot off the swinging racquet, e_A v_in +
// (1 + e_A) V (swing.hpp: the design's swing or the assumed groundstroke), is
// fastest: the power point, at `fidelity` ("rigid", ..., "collision"; empty:
// the file's), found by golden-section search to `tolerance_m` as
// best_rebound_on_axis() is. Its racquet speed V grows towards the tip while
// e_A falls there, so it lies tip-side of the best rebound; the rigid model
// with a given COR has its best rebound at the centre of mass. std::nullopt
// for a design without a racquet head (is_racquet()). Points the model refuses
// are left out as there.
std::optional<SpotOutcome> power_point_on_axis(const io::DesignFile& design,
                                               std::string_view fidelity, double rel_tol,
                                               double tolerance_m = kBestReboundTolerance_m);

// `evaluation` with its power point (power_point_from_butt_m and the shot
// speed there) from power_point_on_axis(), when the design has a head and
// is held by a player (a rig has no shot: the evaluation as it is).
Evaluation with_power_point(const io::DesignFile& design, Evaluation evaluation, double rel_tol);

// Evaluates `design` at its sweet spots at the fidelity of `asked` (the
// design's own evaluation), the hand-held modes to `rel_tol`. Throws like
// io::evaluate_design_file.
SweetSpots find_sweet_spots(const io::DesignFile& design, const Evaluation& asked, double rel_tol);

}  // namespace sweetspot::studies
