#include "studies/comparison.hpp"

#include <utility>

namespace sweetspot::studies {

ComparedDesign compare_one(io::DesignFile design, std::string_view fidelity, double rel_tol,
                           bool along_frame) {
  io::DesignFile placed = std::move(design);
  const Evaluation asked = io::evaluate_design_file(placed, fidelity, rel_tol);
  SweetSpots spots = find_sweet_spots(placed, asked, rel_tol);
  std::vector<FramePoint> curve;
  if (along_frame)
    curve = frame_curves(placed.design, kFrameCurveStep_m, frame_curve_fidelity(asked));
  return ComparedDesign{std::move(placed), std::move(spots), std::move(curve)};
}

}  // namespace sweetspot::studies
