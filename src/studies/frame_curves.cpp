#include "studies/frame_curves.hpp"

#include <algorithm>
#include <cmath>
#include <optional>
#include <stdexcept>

#include "io/format.hpp"
#include "sweetspot/collision.hpp"
#include "sweetspot/rigid_impact.hpp"

namespace sweetspot::studies {
namespace {

Evaluation evaluate_at(const Design& design, double from_butt_m) {
  Design at = design;
  at.impact_from_butt_m = std::clamp(from_butt_m, 0.0, design.implement.length_m());
  at.impact_off_axis_m = 0.0;  // the curves run along the long axis
  return evaluate(at, Fidelity::kRigid);
}

}  // namespace

Fidelity frame_curve_fidelity(const Evaluation& evaluation) {
  return fidelity_of(evaluation) == Fidelity::kCollision ? Fidelity::kCollision : Fidelity::kRigid;
}

std::vector<FramePoint> frame_curves(const Design& design, double step_m, Fidelity fidelity) {
  if (!(step_m > 0)) throw std::invalid_argument("step_m: must be > 0 m, got " + io::exact(step_m));
  const double L = design.implement.length_m();
  std::optional<DesignCollision> collision;
  if (fidelity == Fidelity::kCollision) collision.emplace(design);
  std::vector<FramePoint> points;
  const auto steps = static_cast<std::size_t>(std::ceil(L / step_m - 1e-9));
  for (std::size_t i = 0; i <= steps; ++i) {
    const double d = std::min(L, static_cast<double>(i) * step_m);
    const Evaluation e = evaluate_at(design, L - d);
    if (!collision) {
      points.push_back({d, e.wrist_force_ratio, e.apparent_cor, e.peak_wrist_force_N});
      continue;
    }
    try {
      const CollisionResult r = collision->at(e.impact_from_butt_m, 0.0);
      points.push_back({d, e.wrist_force_ratio, r.apparent_cor,
                        peak_wrist_force(e.wrist_force_ratio, r.peak_force_N)});
    } catch (const std::invalid_argument&) {
      // No solved collision here (its contact time out of range): no point.
    }
  }
  return points;
}

}  // namespace sweetspot::studies
