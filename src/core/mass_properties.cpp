#include "sweetspot/mass_properties.hpp"

#include <cmath>
#include <stdexcept>
#include <string>

#include "core/check.hpp"
#include "core/rigid_kernel.hpp"
#include "sweetspot/errors.hpp"

namespace sweetspot {

double inertia_about(const MassProperties& body, double axis_from_butt_m) {
  const double arm = axis_from_butt_m - body.com_from_butt_m;
  return body.I_cm_kg_m2 + body.mass_kg * arm * arm;
}

double swingweight_kg_m2(const MassProperties& body) {
  return inertia_about(body, kSwingweightAxisFromButt_m);
}

MassProperties with_point_mass(const MassProperties& body, const PointMass& point) {
  detail::require_finite("point mass position", point.from_butt_m);
  detail::require_at_least("point mass", point.mass_kg, 0.0, "kg");
  const kernel::System s = kernel::with_point_mass(
      body.mass_kg, body.com_from_butt_m, body.I_cm_kg_m2, point.from_butt_m, point.mass_kg);
  return MassProperties{s.mass_kg, s.com_from_butt_m, s.I_cm_kg_m2};
}

MassProperties from_swingweight(double mass_kg, double balance_from_butt_m,
                                double swingweight_kg_m2) {
  detail::require_positive("mass", mass_kg, "kg");
  detail::require_finite("balance", balance_from_butt_m);
  detail::require_positive("swingweight", swingweight_kg_m2, "kg m^2");
  const double arm = balance_from_butt_m - kSwingweightAxisFromButt_m;
  const double I_cm = swingweight_kg_m2 - mass_kg * arm * arm;
  if (I_cm < 0.0) {
    throw FieldError("swingweight",
                     "must be >= " + detail::format_number(mass_kg * arm * arm * 1e4) +
                         " kg cm^2 (the mass at its balance point), got " +
                         detail::format_number(swingweight_kg_m2 * 1e4) + " kg cm^2");
  }
  return MassProperties{mass_kg, balance_from_butt_m, I_cm};
}

}  // namespace sweetspot
