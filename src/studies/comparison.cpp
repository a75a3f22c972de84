#include "studies/comparison.hpp"

#include <cmath>
#include <utility>

#include "sweetspot/head_geometry.hpp"

namespace sweetspot::studies {
namespace {

// The whole hour on the hoop each point mass sits at, if any.
std::vector<std::optional<int>> clock_hours_of(const io::DesignFile& design) {
  const auto& masses = design.design.implement.point_masses();
  std::vector<std::optional<int>> hours(masses.size());
  if (!is_racquet(design)) return hours;
  const HeadShape head = head_shape_of(design);
  const double length = design.design.implement.length_m();
  constexpr double kSame_m = 1e-9;
  for (std::size_t k = 0; k < masses.size(); ++k) {
    for (int hour = 1; hour <= 12 && !hours[k]; ++hour) {
      try {
        const FacePoint p = clock_position(head, length, hour);
        if (std::fabs(p.from_butt_m - masses[k].from_butt_m) < kSame_m &&
            std::fabs(p.off_axis_m - masses[k].off_axis_m) < kSame_m)
          hours[k] = hour;
      } catch (const std::invalid_argument&) {
        return hours;  // a head that does not fit: no clock
      }
    }
  }
  return hours;
}

}  // namespace

ComparedDesign compare_one(io::DesignFile design, std::string_view fidelity, double rel_tol,
                           bool along_frame) {
  io::DesignFile placed = std::move(design);
  require_player_file(placed, "a comparison for the player and the arm");
  const Evaluation asked = io::evaluate_design_file(placed, fidelity, rel_tol);
  SweetSpots spots = find_sweet_spots(placed, asked, rel_tol);
  std::vector<FramePoint> curve;
  // Along the frame; a string bed's hits along its strings alone (design_page()'s span).
  if (along_frame) {
    curve = placed.design.strings
                ? frame_curves(placed.design, kFrameCurveStep_m, frame_curve_fidelity(asked),
                               hit_span(placed))
                : frame_curves(placed.design, kFrameCurveStep_m, frame_curve_fidelity(asked));
  }
  const FreeFrame frame = free_frame_of(placed, asked);
  std::optional<double> centre;
  if (is_racquet(placed)) centre = centre_of_strings_from_tip_m(placed);
  ArmLoad arm = arm_load(placed, asked, spots.asked.from_tip_m, centre, frame, rel_tol);
  std::optional<HandVibration> vibration;
  std::string vibration_why = frame.why;
  if (frame.model) {
    try {
      vibration = hand_vibration(*frame.model, placed.design.hand.center_from_butt_m, asked);
    } catch (const std::invalid_argument& refusal) {
      vibration_why = refusal.what();
    }
  }
  std::vector<std::optional<int>> hours = clock_hours_of(placed);
  return ComparedDesign{std::move(placed), std::move(spots),     std::move(curve),
                        std::move(arm),    std::move(vibration), std::move(vibration_why),
                        std::move(hours)};
}

}  // namespace sweetspot::studies
