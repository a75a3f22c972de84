#include "sweetspot/swing.hpp"

#include <cmath>

#include "core/check.hpp"

namespace sweetspot {

void validate(const Swing& swing) {
  detail::require_positive("swing/angular_speed_rad_s", swing.angular_speed_rad_s, "rad/s");
  detail::require_in_range("swing/angular_speed_rad_s", swing.angular_speed_rad_s, 0.0,
                           kMaxAngularSpeed_rad_s, "rad/s");
  detail::require_in_range("swing/pivot_beyond_butt_m", swing.pivot_beyond_butt_m, 0.0,
                           kMaxPivotBeyondButt_m, "m");
  if (swing.reference_swingweight_kg_m2)
    detail::require_positive("swing/reference_swingweight_kg_m2",
                             *swing.reference_swingweight_kg_m2, "kg m^2");
}

double racquet_speed_m_s(const Swing& swing, double from_butt_m) {
  return swing.angular_speed_rad_s * (swing.pivot_beyond_butt_m + from_butt_m);
}

double shot_speed_m_s(double apparent_cor, double incoming_speed_m_s, double racquet_speed_m_s) {
  return apparent_cor * incoming_speed_m_s + (1.0 + apparent_cor) * racquet_speed_m_s;
}

Swing scaled_to_swingweight(const Swing& swing, double swingweight_kg_m2) {
  detail::require_positive("swingweight_kg_m2", swingweight_kg_m2, "kg m^2");
  if (!swing.reference_swingweight_kg_m2) return swing;
  Swing scaled = swing;
  scaled.angular_speed_rad_s *=
      std::pow(*swing.reference_swingweight_kg_m2 / swingweight_kg_m2, kSwingweightExponent);
  return scaled;
}

}  // namespace sweetspot
