#pragma once

// The impact moved along the frame: what the wrist feels and how the ball
// comes back for a hit at each point from the tip to the butt. Plain data,
// drawn by the HTML page and `compare --html`.

#include <vector>

#include "io/design_reader.hpp"
#include "sweetspot/design.hpp"
#include "sweetspot/evaluate.hpp"

namespace sweetspot::studies {

// One impact point along the frame: the rigid model (Eqs. 11, 15-17) or the
// solved collision.
struct FramePoint {
  double from_tip_m = 0.0;
  double wrist_force_ratio = 0.0;  // F_w / F (Eq. 11), signed
  double apparent_cor = 0.0;       // e_A (Eq. 16, or the solved rebound)
  double peak_wrist_force_N = 0.0;
};

// Steps along the frame of the curves on a page [m].
inline constexpr double kFrameCurveStep_m = 0.01;

// The impact moved along the frame from the tip to the butt in steps of
// `step_m` (> 0; the butt itself always included). At Fidelity::kCollision
// each point is the solved collision there (DesignCollision: e_A its rebound,
// the wrist its share |F_w / F| of the solved peak force, as evaluate() does);
// a point whose collision cannot be solved (a contact time out of range near
// the butt) is left out. Any other fidelity: the rigid model at the design's
// COR, or with cor_rigid at the COR the response model derives at each point
// (as evaluate() answers it). Throws std::invalid_argument for a step <= 0,
// or as DesignCollision.
// A stretch of the long axis [m from the tip], from_tip_m <= to_tip_m.
struct AxisSpan {
  double from_tip_m = 0.0;
  double to_tip_m = 0.0;
  bool string_bed = false;  // the stretch is a racquet's string bed
};

// Where a ball can hit along the long axis: a racquet's string bed (from one
// hoop width below the tip to the throat end of its ellipse, the stretch the
// best rebound is searched over), else the whole implement.
AxisSpan hit_span(const io::DesignFile& file);

// frame_curves() over `span` only: the points of the step grid inside it and
// both its ends, so a curve reaches the edges of the head.
std::vector<FramePoint> frame_curves(const Design& design, double step_m, Fidelity fidelity,
                                     AxisSpan span);
std::vector<FramePoint> frame_curves(const Design& design, double step_m,
                                     Fidelity fidelity = Fidelity::kRigid);

// The fidelity of the curves drawn beside an evaluation: the solved collision
// when it was solved, else the rigid model.
Fidelity frame_curve_fidelity(const Evaluation& evaluation);

}  // namespace sweetspot::studies
