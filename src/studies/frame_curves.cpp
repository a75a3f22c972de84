#include "studies/frame_curves.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <optional>
#include <stdexcept>

#include "io/format.hpp"
#include "studies/sweet_spots.hpp"
#include "sweetspot/collision.hpp"
#include "sweetspot/evaluate.hpp"
#include "sweetspot/mode_cache.hpp"
#include "sweetspot/rigid_impact.hpp"

namespace sweetspot::studies {
namespace {

// The rigid model at a point of the long axis: at the frame's COR, or at
// the COR the response model derives there from cor_rigid (which the rigid
// model alone cannot answer), as evaluate() answers that design.
Evaluation evaluate_at(const Design& design, double from_butt_m, ModeCache& modes) {
  Design at = design;
  at.impact_from_butt_m = std::clamp(from_butt_m, 0.0, design.implement.length_m());
  at.impact_off_axis_m = 0.0;  // the curves run along the long axis
  return evaluate(at, design.cor_rigid ? Fidelity::kResponse : Fidelity::kRigid, {.modes = &modes});
}

}  // namespace

Fidelity frame_curve_fidelity(const Evaluation& evaluation) {
  return fidelity_of(evaluation) == Fidelity::kCollision ? Fidelity::kCollision : Fidelity::kRigid;
}

AxisSpan hit_span(const io::DesignFile& file) {
  const double L = file.design.implement.length_m();
  if (!is_racquet(file)) return {0.0, L, false};
  const HeadShape head = head_shape_of(file);
  const double semi_length = std::sqrt(head.area_m2 * head.aspect_ratio / std::numbers::pi);
  return {std::min(head.hoop_width_m, L), std::min(head.hoop_width_m + 2.0 * semi_length, L), true};
}

std::vector<FramePoint> frame_curves(const Design& design, double step_m, Fidelity fidelity) {
  return frame_curves(design, step_m, fidelity, {0.0, design.implement.length_m(), false});
}

std::vector<FramePoint> frame_curves(const Design& design, double step_m, Fidelity fidelity,
                                     AxisSpan span) {
  if (!(step_m > 0)) throw std::invalid_argument("step_m: must be > 0 m, got " + io::exact(step_m));
  const double L = design.implement.length_m();
  const double lo = std::clamp(span.from_tip_m, 0.0, L), hi = std::clamp(span.to_tip_m, lo, L);
  std::optional<DesignCollision> collision;
  if (fidelity == Fidelity::kCollision) collision.emplace(design);
  // The span's ends and every step of the grid between them.
  std::vector<double> at{lo};
  for (auto i = static_cast<long>(std::floor(lo / step_m + 1e-9)) + 1;
       static_cast<double>(i) * step_m < hi - 1e-9; ++i)
    at.push_back(static_cast<double>(i) * step_m);
  if (hi > lo) at.push_back(hi);
  std::vector<FramePoint> points;
  ModeCache modes;
  for (const double d : at) {
    const Evaluation e = evaluate_at(design, L - d, modes);
    if (!collision) {
      points.push_back({d, e.wrist_force_ratio, e.apparent_cor, e.peak_wrist_force_N});
      continue;
    }
    try {
      // A swung racquet meets the ball at v_in + V there, as evaluate() solves it.
      const double speed_m_s =
          design.swing ? meeting_at(design, e.impact_from_butt_m).speed_m_s : design.ball.speed_m_s;
      const CollisionResult r = collision->at_speed(e.impact_from_butt_m, 0.0, speed_m_s);
      points.push_back({d, e.wrist_force_ratio, r.apparent_cor,
                        peak_wrist_force(e.wrist_force_ratio, r.peak_force_N)});
    } catch (const std::invalid_argument&) {
      // No solved collision here (its contact time out of range): no point.
    }
  }
  return points;
}

}  // namespace sweetspot::studies
