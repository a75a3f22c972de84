#include "io/design_description.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <stdexcept>

#include "io/format.hpp"
#include "io/json_reader.hpp"
#include "sweetspot/rigid_impact.hpp"

namespace sweetspot::io {

double points_head_light_limit(double length_m) { return 0.5 * length_m / kPointHeadLight_m; }

double balance_from_points_head_light(double length_m, double points) {
  return 0.5 * length_m - points * kPointHeadLight_m;
}

double head_radius_from_area(double area_m2) { return std::sqrt(area_m2 / std::numbers::pi); }

bool same_head_area(double a_m2, double b_m2) {
  return std::fabs(a_m2 - b_m2) <= kSameHeadAreaRelTol * std::max(std::fabs(a_m2), std::fabs(b_m2));
}

namespace {

std::string metres(double value) { return brief(value); }

double length_of(const ImplementDescription& d) {
  if (d.form == ImplementDescription::Form::kProfile)
    return d.profile.stations.empty() ? 0.0 : d.profile.stations.back().from_butt_m;
  if (d.form != ImplementDescription::Form::kSections) return d.length_m;
  double total_m = 0.0;
  for (const Section& section : d.sections) total_m += section.length_m;
  return total_m;
}

}  // namespace

std::vector<PointMass> place_point_masses(const std::vector<PointMassDescription>& entries,
                                          double L, const std::optional<HeadShape>& head) {
  std::vector<PointMass> points;
  for (std::size_t i = 0; i < entries.size(); ++i) {
    const PointMassDescription& entry = entries[i];
    if (!(entry.mass_kg >= 0.0 && entry.mass_kg <= kMaxMass_kg)) {
      throw PointMassError(
          i, "mass",
          "must be in [0, " + metres(kMaxMass_kg) + "] kg, got " + metres(entry.mass_kg) + " kg");
    }
    if (entry.handle_from_butt_m) {
      // Under the butt cap (2 cm) or the grip (9 cm): a place on a handle
      // that this implement, shorter, does not have.
      if (!(*entry.handle_from_butt_m <= L)) {
        throw PointMassError(
            i, "clock",
            "places the mass " + significant(*entry.handle_from_butt_m * 100.0, 4) +
                " cm from the butt, beyond the implement's " + significant(L * 100.0, 4) +
                " cm: give its place by from_butt or from_tip");
      }
      points.push_back(PointMass{*entry.handle_from_butt_m, entry.mass_kg, 0.0});
      continue;
    }
    if (!entry.clock_hours.empty()) {
      if (!head) {
        throw PointMassError(
            i, "clock",
            "a clock position needs the head: give /implement/headsize_sq_in (or headsize_cm2)");
      }
      for (const double h : entry.clock_hours) {
        try {
          const FacePoint p = clock_position(*head, L, h);
          points.push_back(PointMass{p.from_butt_m, entry.mass_kg, p.off_axis_m});
        } catch (const std::invalid_argument& error) {
          throw PointMassError(i, "implement", error.what());
        }
      }
      continue;
    }
    const double given = entry.from_butt_m ? *entry.from_butt_m : entry.from_tip_m.value_or(0.0);
    if (!(given >= 0.0 && given <= L)) {
      throw PointMassError(i, "where",
                           "must be in [0, " + metres(L) + "] m, got " + metres(given) + " m");
    }
    // How far off the axis is the outline's to say where the lead sits
    // (the design's validation), in the file's unit.
    if (!std::isfinite(entry.off_axis_m)) {
      throw PointMassError(i, "off_axis",
                           "must be a finite number, got " + metres(entry.off_axis_m));
    }
    const double x = entry.from_butt_m ? *entry.from_butt_m : L - given;
    points.push_back(PointMass{x, entry.mass_kg, entry.off_axis_m});
  }
  return points;
}

double centre_of_strings_from_tip_m(const Design& design) {
  const HeadShape head = racquet_head(design);
  const double length = design.implement.length_m();
  // The string bed's far end is one hoop width below the tip, its centre one
  // semi-length a = sqrt(area aspect / pi) further (string_bed()); a head too
  // long for the implement is put at its middle.
  const double semi_length = std::sqrt(head.area_m2 * head.aspect_ratio / std::numbers::pi);
  if (!(2.0 * (semi_length + head.hoop_width_m) <= length)) return 0.5 * length;
  return length - string_bed(head, length).center_from_butt_m;
}

bool has_racquet_head(const Design& design, ImplementDescription::Form form) {
  return design.head.has_value() || design.strings.has_value() ||
         form == ImplementDescription::Form::kSpecs;
}

ImpactPlace default_impact(const Design& design, ImplementDescription::Form form) {
  return has_racquet_head(design, form) ? ImpactPlace::kCentreOfStrings : ImpactPlace::kFromTip;
}

Implement build_implement(const ImplementDescription& d) {
  const std::vector<PointMass> points = place_point_masses(d.point_masses, length_of(d), d.head);
  switch (d.form) {
    case ImplementDescription::Form::kSections:
      return Implement::from_sections(d.sections, points);
    case ImplementDescription::Form::kProfile:
      return Implement::from_profile(d.profile, points);
    case ImplementDescription::Form::kHeadToHandleRatio:
      return Implement::paper_racquet(d.length_m, d.mass_kg, d.head_to_handle_mass_ratio, points);
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
                               points);
}

std::optional<HeadShape> racquet_head_of(const DesignDescription& d) {
  if (d.implement.head || !d.head_area_m2) return d.implement.head;
  HeadShape head;  // the default aspect ratio and hoop width of head_geometry.hpp
  head.area_m2 = *d.head_area_m2;
  return head;
}

Implement build_implement(const DesignDescription& d) {
  if (d.implement.head || !d.head_area_m2) return build_implement(d.implement);
  ImplementDescription with_head = d.implement;
  with_head.head = racquet_head_of(d);
  return build_implement(with_head);
}

void derive(DesignDescription& d) {
  Design& design = d.design;
  if (const auto& head = d.implement.head) {
    // The reader's bounds on the head (a study may set any number).
    if (!(head->area_m2 > 0.0)) throw std::domain_error("implement/headsize_cm2: must be > 0");
    if (!(head->aspect_ratio >= 1.0 && head->aspect_ratio <= 10.0))
      throw std::domain_error("implement/head_aspect_ratio: must be in [1, 10]");
    if (!(head->hoop_width_m >= 0.0 && head->hoop_width_m <= 1.0))
      throw std::domain_error("implement/hoop_width_m: must be in [0, 1] m");
  }
  design.head = d.implement.head;
  if (d.forearm_from_mass)
    design.forearm_equivalent_mass_kg = forearm_equivalent_mass(d.forearm_mass_kg);
  const double L = design.implement.length_m();
  if (d.head_area_m2) {
    if (!(*d.head_area_m2 > 0)) throw std::domain_error("strings/head_size_cm2: must be > 0");
    if (design.head && !same_head_area(*d.head_area_m2, design.head->area_m2))
      throw std::domain_error("strings/head_size_cm2: contradicts implement/headsize_cm2");
    design.strings->head_radius_m = head_radius_from_area(*d.head_area_m2);
    // One head, one size: the string bed's size given alone is the head's, so
    // the twist, the map and the page take it as they take implement.headsize.
    if (!design.head) design.head = racquet_head_of(d);
  } else if (design.strings && design.head) {
    design.strings->head_radius_m = head_radius_from_area(design.head->area_m2);
  }
  switch (d.impact_place) {
    case ImpactPlace::kFromTip:
      // The reader refuses a given point off the implement; the default 5 cm
      // from the tip of a shorter implement fails validate() instead.
      if (d.impact_given && !(d.impact_m >= 0.0 && d.impact_m <= L))
        throw std::domain_error("impact/from_tip_m: off the implement");
      design.impact_from_butt_m = L - d.impact_m;
      break;
    case ImpactPlace::kFromButt:
      design.impact_from_butt_m = d.impact_m;
      break;
    case ImpactPlace::kCentreOfStrings:
      design.impact_from_butt_m = L - centre_of_strings_from_tip_m(design);
      break;
  }
  validate(design);
}

}  // namespace sweetspot::io
