#include "sweetspot/design.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <optional>
#include <stdexcept>
#include <string>

#include "core/check.hpp"
#include "sweetspot/errors.hpp"
#include "sweetspot/frame_specs.hpp"

namespace sweetspot {

std::string_view to_string(Support::Kind kind) {
  switch (kind) {
    case Support::Kind::kFree:
      return "free";
    case Support::Kind::kHand:
      return "hand";
    case Support::Kind::kHeadClamped:
      return "head_clamped";
    case Support::Kind::kHandleClamped:
      return "handle_clamped";
    case Support::Kind::kPivot:
      return "pivot";
    case Support::Kind::kRigidSurface:
      return "rigid_surface";
  }
  return "free";
}

void validate(const Design& d) {
  const double L = d.implement.length_m();
  detail::require_in_range("frame/cor", d.cor, 0.0, 1.0, "");
  detail::require_in_range("strings/impact_duration_s", d.impact_duration_s, kMinDuration_s,
                           kMaxDuration_s, "s");
  detail::require_in_range("hand/mass_kg", d.hand.mass_kg, 0.0, kMaxMass_kg, "kg");
  detail::require_in_range("hand/center_from_butt_m", d.hand.center_from_butt_m, 0.0, L, "m");
  detail::require_in_range("forearm/equivalent_mass_kg", d.forearm_equivalent_mass_kg, 0.0,
                           kMaxForearmMass_kg, "kg");
  detail::require_positive("ball/mass_kg", d.ball.mass_kg, "kg");
  detail::require_in_range("ball/mass_kg", d.ball.mass_kg, kMinBallMass_kg, kMaxMass_kg, "kg");
  detail::require_positive("ball/diameter_m", d.ball.diameter_m, "m");
  detail::require_in_range("ball/diameter_m", d.ball.diameter_m, kMinBallDiameter_m, kMaxLength_m,
                           "m");
  // The implement's own parts are bounded where they are built; in all it
  // weighs at least kMinImplementMass_kg.
  if (!(d.implement.mass_properties().mass_kg >= kMinImplementMass_kg)) {
    throw FieldError("implement/mass_kg",
                     "must be >= " + detail::format_number(kMinImplementMass_kg) + " kg, got " +
                         detail::format_number(d.implement.mass_properties().mass_kg) + " kg");
  }
  if (d.swing) {
    // The incoming ball's speed over the ground: 0 for a serve; the racquet's
    // own speed at the impact makes the relative speed (checked by evaluate()).
    validate(*d.swing);
    detail::require_in_range("ball/speed_m_s", d.ball.speed_m_s, 0.0, kMaxSpeed_m_s, "m/s");
  } else {
    detail::require_positive("ball/speed_m_s", d.ball.speed_m_s, "m/s");
    detail::require_in_range("ball/speed_m_s", d.ball.speed_m_s, kMinSpeed_m_s, kMaxSpeed_m_s,
                             "m/s");
  }
  detail::require_in_range("impact/from_butt_m", d.impact_from_butt_m, 0.0, L, "m");
  if (d.support.kind == Support::Kind::kPivot) {
    detail::require_in_range("support/pivot_from_butt_m", d.support.pivot_from_butt_m, 0.0, L, "m");
  }
  if (is_rig(d.support) && d.swing) {
    throw FieldError("swing", "a rig holds the implement still (support " +
                                  std::string(to_string(d.support.kind)) +
                                  "): give no swing, or support free or hand");
  }
  detail::require_positive("hand/grip_length_m", d.hand.grip_length_m, "m");
  detail::require_in_range("hand/grip_stiffness_N_m2", d.hand.grip_stiffness_N_m2, 0.0,
                           kMaxGripStiffness_N_m2, "N/m^2");
  detail::require_in_range("hand/grip_damping_N_s_m2", d.hand.grip_damping_N_s_m2, 0.0,
                           kMaxGripDamping_N_s_m2, "N s/m^2");
  if (d.cor_rigid) detail::require_in_range("frame/cor_rigid", *d.cor_rigid, 0.0, 1.0, "");
  if (d.strings) {
    if (const std::string why = d.strings->validate(); !why.empty()) {
      throw std::invalid_argument("strings/" + why);
    }
    detail::require_in_range("strings/tension_N", d.strings->tension_N, kMinTension_N,
                             kMaxTension_N, "N");
    detail::require_in_range("strings/crosses/tension_N", d.strings->cross_tension_N(),
                             kMinTension_N, kMaxTension_N, "N");
    detail::require_in_range("strings/mains/linear_density_kg_m",
                             d.strings->main_linear_density_kg_m, kMinStringLinearDensity_kg_m,
                             kMaxStringLinearDensity_kg_m, "kg/m");
    detail::require_in_range("strings/crosses/linear_density_kg_m",
                             d.strings->cross_linear_density_kg_m, kMinStringLinearDensity_kg_m,
                             kMaxStringLinearDensity_kg_m, "kg/m");
  }
  if (const std::string why = d.ball_contact.validate(); !why.empty()) {
    throw std::invalid_argument("ball/contact/" + why);
  }
  if (d.ball.cor_on_rigid_surface &&
      !(*d.ball.cor_on_rigid_surface >= 0.0 && *d.ball.cor_on_rigid_surface < 1.0)) {
    throw FieldError("ball/cor_on_rigid_surface",
                     "must be in [0, 1) (0: a dead ball), got " +
                         detail::format_number(*d.ball.cor_on_rigid_surface));
  }
  detail::require_in_range("strings/bed_mass_kg", d.string_bed_mass_kg, kMinStringBedMass_kg,
                           kMaxStringBedMass_kg, "kg");
  if (!(d.string_bed_damping_ratio >= 0.0 && d.string_bed_damping_ratio < 1.0)) {
    detail::fail_in_range("strings/bed_damping_ratio", d.string_bed_damping_ratio, 0.0, 1.0, "");
  }
  const FrameStiffness& k = d.stiffness;
  if (k.EI_N_m2) {
    detail::require_positive("frame/EI_N_m2", *k.EI_N_m2, "N m^2");
    detail::require_in_range("frame/EI_N_m2", *k.EI_N_m2, 0.0, kMaxEI_N_m2, "N m^2");
  }
  if (k.fundamental_free_Hz)
    detail::require_positive("frame/fundamental_free_Hz", *k.fundamental_free_Hz, "Hz");
  if (k.RA) {
    if (k.EI_N_m2 || k.fundamental_free_Hz) {
      throw FieldError("frame/RA",
                       "contradicts the frame's EI_N_m2 or fundamental_free_Hz: give the stiffness "
                       "once");
    }
    fundamental_free_Hz_from_RA(*k.RA, d.implement.frame_mass_properties().mass_kg,
                                d.implement.length_m());  // its range
  }
  if (k.shear_modulus_Pa) {
    detail::require_positive("frame/cross_section/shear_modulus_Pa", *k.shear_modulus_Pa, "Pa");
    detail::require_in_range("frame/cross_section/shear_modulus_Pa", *k.shear_modulus_Pa, 0.0,
                             kMaxShearModulus_Pa, "Pa");
    const CrossSection& c = k.cross_section;
    const auto size = [](const char* name, double value) {
      detail::require_positive(name, value, "m");
      detail::require_in_range(name, value, 0.0, kMaxLength_m, "m");
    };
    using Shape = CrossSection::Shape;
    if (sized_by_width(c.shape)) {
      size("frame/cross_section/width_m", c.width_m);
      size("frame/cross_section/thickness_m", c.thickness_m);
    } else if (sized_by_diameter(c.shape)) {
      size("frame/cross_section/diameter_m", c.diameter_m);
    }
    if (c.shape == Shape::kProfile && !d.implement.profile()) {
      throw FieldError("frame/cross_section/shape",
                       "profile takes each section's circle or tube from implement.profile: "
                       "give the implement by its profile, or the section's own shape and sizes");
    }
    detail::require_in_range("frame/cross_section/poisson_ratio", c.poisson_ratio, 0.0,
                             kMaxPoissonRatio, "");
    if (has_wall(c.shape)) size("frame/cross_section/wall_m", c.wall_m);
    // The shape's own rules (a wall inside its section): shear_coefficient()'s,
    // named under this path.
    if (c.shape != Shape::kProfile) {
      try {
        shear_coefficient(c);
      } catch (const std::invalid_argument& error) {
        rethrow_under("frame/cross_section/", error);
      }
    }
  }
  // How far off the axis the ball may land is the head's to say, below.
  detail::require_finite("impact/off_axis_m", d.impact_off_axis_m);
  // A profile is a round implement's: a bat is hit on its barrel, not on a
  // head's strings, and a string bed would take the hit's stiffness and
  // duration from strings it does not have.
  if (is_round(d) && d.head) {
    throw FieldError("implement/headsize",
                     "an implement given by its profile is round (a bat, a rod) and has no head: "
                     "give a racquet by its sections or its spec sheet, or give no head size");
  }
  if (is_round(d) && d.strings) {
    throw FieldError("strings/tension_N",
                     "an implement given by its profile is round (a bat, a rod) and has no string "
                     "bed: give the ball's contact by strings.impact_duration_ms, or a racquet by "
                     "its sections or its spec sheet");
  }
  std::optional<HeadEllipse> outline;  // the head to the hoop's outer edge
  if (d.head) {
    try {
      outline = hoop_outline(*d.head, L);
    } catch (const std::invalid_argument& error) {
      rethrow_under("implement/", error);
    }
    // The hand holds the handle, not the head: the hoop's outer edge ends
    // beyond where the hand is (a head of this aspect that fills the length
    // beyond it, pi (a - w)^2 / aspect with 2 a = L - hand, is the largest).
    const double bottom_m = outline->center_from_butt_m - outline->semi_length_m;
    const double hand_m = d.hand.center_from_butt_m;
    if (d.hand.mass_kg > 0.0 && !(bottom_m > hand_m)) {
      const double longest_a = 0.5 * (L - hand_m) - d.head->hoop_width_m;
      std::optional<FieldError::Range> range;
      if (longest_a > 0.0) {
        range = FieldError::Range{
            0.0, head_area_m2(longest_a, d.head->aspect_ratio), true, d.head->area_m2,
            "for the head of its aspect, with its hoop, to end beyond the hand"};
      }
      throw FieldError("implement/headsize",
                       "a head of " + detail::format_significant(d.head->area_m2) +
                           " m^2 reaches " + detail::format_significant(bottom_m) +
                           " m from the butt with its hoop, over the hand at " +
                           detail::format_significant(hand_m) + " m",
                       range);
    }
  }
  // A round implement given by its profile (a bat) is as wide as its
  // diameter: its widest bounds the twistweight.
  const std::optional<RoundProfile>& profile = d.implement.profile();
  const bool round = is_round(d);
  double widest_radius_m = 0.0;
  if (round) {
    for (const ProfileStation& s : profile->stations)
      widest_radius_m = std::max(widest_radius_m, 0.5 * s.diameter_m);
  }
  const double half_width_m = outline ? outline->semi_width_m
                              : round ? widest_radius_m
                                      : kMaxHeadHalfWidth_m;
  if (d.twistweight_kg_m2) {
    // All the frame's mass at the head's edge: the largest polar inertia it can have.
    const double frame_mass_kg = d.implement.frame_mass_properties().mass_kg;
    const double most_kg_m2 = frame_mass_kg * half_width_m * half_width_m;
    const double twistweight = *d.twistweight_kg_m2;
    if (!(twistweight >= kMinTwistweight_kg_m2 && twistweight <= most_kg_m2)) {
      throw FieldError("implement/twistweight_kg_m2",
                       "must be in [" + detail::format_number(kMinTwistweight_kg_m2) + ", " +
                           detail::format_significant(most_kg_m2) +
                           "] kg m^2 (at most the frame's " +
                           detail::format_significant(frame_mass_kg) + " kg all " +
                           detail::format_significant(half_width_m) + " m off the axis), got " +
                           detail::format_number(twistweight) + " kg m^2",
                       FieldError::Range{kMinTwistweight_kg_m2, most_kg_m2, false, twistweight,
                                         "(at most the frame's mass all at its half-width off "
                                         "the axis)"});
    }
  }
  // Lead sits on the implement where it is put: within a racquet's outline
  // there (its handle, throat or hoop), a round implement's radius there, or
  // the widest head the rules allow when no head is given.
  const std::vector<PointMass>& points = d.implement.point_masses();
  const std::optional<HeadShape> legal_head =
      !round && !d.head ? largest_legal_head(L) : std::nullopt;
  const bool legal_head_fits = legal_head.has_value();
  for (std::size_t i = 0; i < points.size(); ++i) {
    const double x = points[i].from_butt_m;
    const double here_m = round             ? 0.5 * profile_diameter_m(*profile, x)
                          : d.head          ? face_half_width_m(*d.head, L, x)
                          : legal_head_fits ? face_half_width_m(*legal_head, L, x)
                                            : grip_half_width_m();
    if (!(std::abs(points[i].off_axis_m) <= here_m)) {
      const char* const edge =
          round    ? "to sit on the implement where it is put (its radius there)"
          : d.head ? "to sit on the racquet where it is put (its handle, as wide as the largest "
                     "grip, the throat from the handle to the hoop, or the hoop's outer edge)"
          : legal_head_fits
              ? "to sit on the racquet where it is put (its handle, as wide as the largest grip, "
                "the throat, or the largest hoop the rules allow that fits beyond the handle: "
                "give the head's size for its own)"
              : "to sit on the implement (as wide as the largest grip, too short for a head)";
      throw FieldError(detail::indexed("implement/point_masses", i, "off_axis_m"),
                       "must be in [" + detail::format_significant(-here_m) + ", " +
                           detail::format_significant(here_m) + "] m " + edge + ", got " +
                           detail::format_number(points[i].off_axis_m) + " m",
                       FieldError::Range{-here_m, here_m, false, points[i].off_axis_m, edge});
    }
  }
  if (const double y = d.impact_off_axis_m; y != 0.0 && round) {
    // A round surface's normal passes through its axis: a ball hitting it off
    // the axis is pushed through the axis, and is deflected (G. S. Sawicki,
    // M. Hubbard and W. J. Stronge, Am. J. Phys. 71, 1152, 2003; R. Cross and
    // A. M. Nathan, Am. J. Phys. 74, 896, 2006), where the twist model turns a
    // flat face by F0 |y|. Only friction would roll it, which is not modelled.
    throw FieldError("impact/off_axis_m",
                     "must be 0 on a round implement (given by its profile, without a head): "
                     "its surface pushes the ball through its axis, so a hit off the axis "
                     "deflects the ball rather than twisting the implement, which this model "
                     "of a flat face does not solve; got " +
                         detail::format_number(y) + " m");
  } else if (y != 0.0 && !d.strings) {
    // On the head: inside the hoop's outer edge where the ball lands along the
    // axis; without a head given, inside the largest the rules allow. (A ball
    // on the strings must land on them, which is checked below.)
    std::optional<HeadEllipse> legal_outline;
    if (!outline) {
      if (const std::optional<HeadShape> legal = largest_legal_head(L))
        legal_outline = hoop_outline(*legal, L);
    }
    const HeadEllipse* const edge = outline ? &*outline : legal_outline ? &*legal_outline : nullptr;
    const bool on_head =
        edge ? on_string_bed(*edge, d.impact_from_butt_m, y) : std::abs(y) <= grip_half_width_m();
    if (!on_head) {
      const double here_m = edge ? half_width_at(*edge, d.impact_from_butt_m) : grip_half_width_m();
      const char* const why =
          outline ? "to land on the head (inside the hoop's outer edge where the ball lands "
                    "along the axis)"
          : edge  ? "to land on the head (inside the largest hoop the rules allow where the ball "
                    "lands along the axis: give the head's size for its own)"
                  : "to land on the implement (as wide as the largest grip, too short for a "
                    "head)";
      throw FieldError("impact/off_axis_m",
                       "must be in [" + detail::format_significant(-here_m) + ", " +
                           detail::format_significant(here_m) + "] m " + why + ", got " +
                           detail::format_number(y) + " m",
                       FieldError::Range{-here_m, here_m, false, y, why});
    }
  }
  // A string bed's impact lands on the strings: not on the hoop, the throat
  // or the handle, where the contact is the frame's (the head's string bed,
  // or the default head of the bed's size, as the centre of the strings is
  // placed; none when that head does not fit). To round-off of the length.
  if (d.strings) {
    std::optional<HeadEllipse> bed;
    try {
      bed = string_bed(racquet_head(d), L);
    } catch (const std::invalid_argument&) {
    }
    const double slack = 1e-9;
    if (bed) {
      const double u = (d.impact_from_butt_m - bed->center_from_butt_m) / bed->semi_length_m;
      const double v = d.impact_off_axis_m / bed->semi_width_m;
      const double from_tip_m = L - d.impact_from_butt_m;
      const double bed_from_tip_m = L - bed->center_from_butt_m - bed->semi_length_m;
      const double bed_to_tip_m = L - bed->center_from_butt_m + bed->semi_length_m;
      if (std::abs(u) > 1.0 + slack) {
        throw FieldError(
            "impact/from_butt_m",
            "a ball on the strings must land on them, " +
                detail::format_significant(bed_from_tip_m) + " to " +
                detail::format_significant(bed_to_tip_m) + " m from the tip along the axis, got " +
                detail::format_significant(from_tip_m) +
                " m from the tip: a hit on the hoop, the throat or the handle is "
                "the frame's, not the string bed's",
            FieldError::Range{L - bed_to_tip_m, L - bed_from_tip_m, false, d.impact_from_butt_m,
                              "to land on the strings (a hit on the hoop, the throat "
                              "or the handle is the frame's, not the string bed's)"});
      }
      if (u * u + v * v > 1.0 + slack) {
        const double here_m = half_width_at(*bed, d.impact_from_butt_m);
        throw FieldError("impact/off_axis_m",
                         "a ball on the strings must land on them, within " +
                             detail::format_significant(here_m) + " m either side of the axis " +
                             detail::format_significant(from_tip_m) + " m from the tip, got " +
                             detail::format_number(d.impact_off_axis_m) +
                             " m: a hit on the hoop is the frame's, not the string bed's",
                         FieldError::Range{-here_m, here_m, false, d.impact_off_axis_m,
                                           "to land on the strings where the ball lands along "
                                           "the axis (a hit on the hoop is the frame's, not the "
                                           "string bed's)"});
      }
    }
  }
  if (d.impact_off_axis_m != 0.0 && !d.twistweight_kg_m2 && !d.head) {
    throw FieldError(
        "impact/off_axis_m",
        "an impact off the long axis twists the implement, which needs its "
        "polar inertia: give implement/twistweight_kg_cm2 or implement/headsize_sq_in, got " +
            detail::format_number(d.impact_off_axis_m) + " m");
  }
  if (!(hand_held_system(d).com_from_butt_m > 0.0)) {
    throw FieldError("hand/center_from_butt_m",
                     "implement and hand have all their mass at the butt; the wrist "
                     "force (Cross 2004 Eq. 11) needs a centre of mass beyond the wrist");
  }
}

std::optional<double> polar_inertia_kg_m2(const Design& d) {
  std::optional<double> frame = d.twistweight_kg_m2;
  if (!frame && d.head) {
    frame = estimated_polar_inertia_kg_m2(*d.head, d.implement.length_m(),
                                          d.implement.frame_mass_properties().mass_kg);
  }
  if (!frame) return std::nullopt;
  return polar_inertia_with_point_masses(*frame, d.implement.point_masses());
}

bool polar_inertia_estimated(const Design& d) { return !d.twistweight_kg_m2 && d.head; }

bool is_round(const Design& d) {
  const std::optional<RoundProfile>& profile = d.implement.profile();
  return profile && !profile->stations.empty();
}

HeadShape racquet_head(const Design& d) {
  if (d.head) return *d.head;
  HeadShape head;  // the default aspect ratio and hoop width, kDefaultHeadArea_m2
  if (d.strings)
    head.area_m2 = std::numbers::pi * d.strings->head_radius_m * d.strings->head_radius_m;
  return head;
}

MassProperties hand_held_system(const Design& d) {
  return with_point_mass(d.implement.mass_properties(),
                         PointMass{d.hand.center_from_butt_m, d.hand.mass_kg});
}

}  // namespace sweetspot
