#include "io/design_description.hpp"

#include <cmath>
#include <numbers>
#include <stdexcept>

#include "sweetspot/rigid_impact.hpp"

namespace sweetspot::io {

double points_head_light_limit(double length_m) { return 0.5 * length_m / kPointHeadLight_m; }

double balance_from_points_head_light(double length_m, double points) {
  return 0.5 * length_m - points * kPointHeadLight_m;
}

double head_radius_from_area(double area_m2) { return std::sqrt(area_m2 / std::numbers::pi); }

Implement build_implement(const ImplementDescription& d) {
  switch (d.form) {
    case ImplementDescription::Form::kSections:
      return Implement::from_sections(d.sections, d.point_masses);
    case ImplementDescription::Form::kHeadToHandleRatio:
      return Implement::paper_racquet(d.length_m, d.mass_kg, d.head_to_handle_mass_ratio,
                                      d.point_masses);
    case ImplementDescription::Form::kSpecs:
      break;
  }
  double balance = d.balance;
  if (d.balance_in_points) {
    const double limit = points_head_light_limit(d.length_m);
    if (!(balance > -limit && balance < limit))
      throw std::domain_error("balance_pts_hl: outside the length");
    balance = balance_from_points_head_light(d.length_m, balance);
  }
  return Implement::from_specs(IndustrySpecs{d.length_m, d.mass_kg, balance, d.swingweight_kg_m2},
                               d.point_masses);
}

void derive(DesignDescription& d) {
  Design& design = d.design;
  if (d.forearm_from_mass)
    design.forearm_equivalent_mass_kg = forearm_equivalent_mass(d.forearm_mass_kg);
  const double L = design.implement.length_m();
  if (d.impact_from_tip) {
    // The reader refuses a given point off the implement; the default 5 cm
    // from the tip of a shorter implement fails validate() instead.
    if (!(d.impact_m >= 0.0 && d.impact_m <= L))
      throw std::domain_error("impact/from_tip_m: off the implement");
    design.impact_from_butt_m = L - d.impact_m;
  } else {
    design.impact_from_butt_m = d.impact_m;
  }
  if (d.head_area_m2) {
    if (!(*d.head_area_m2 > 0)) throw std::domain_error("strings/head_size_cm2: must be > 0");
    design.strings->head_radius_m = head_radius_from_area(*d.head_area_m2);
  }
  validate(design);
}

}  // namespace sweetspot::io
