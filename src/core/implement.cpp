#include "sweetspot/implement.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <stdexcept>
#include <string>
#include <utility>

#include "core/check.hpp"
#include "core/rigid_kernel.hpp"
#include "sweetspot/design.hpp"
#include "sweetspot/errors.hpp"

namespace sweetspot {

namespace {

MassProperties add_all(MassProperties body, const std::vector<PointMass>& point_masses) {
  for (const PointMass& point : point_masses) body = with_point_mass(body, point);
  return body;
}

}  // namespace

MassProperties section_mass_properties(const std::vector<Section>& sections) {
  if (sections.empty()) throw FieldError("sections", "must list at least one section");
  double mass = 0.0;
  double first_moment = 0.0;
  double x_start = 0.0;
  for (std::size_t i = 0; i < sections.size(); ++i) {
    const Section& s = sections[i];
    // Each section within the model's range on its own, so that a section
    // out of range is named, not the sums it would spoil.
    detail::require_positive(detail::Element{"sections", i, "length_m"}, s.length_m, "m");
    detail::require_in_range(detail::Element{"sections", i, "length_m"}, s.length_m, 0.0,
                             kMaxLength_m, "m");
    detail::require_in_range(detail::Element{"sections", i, "mass_kg"}, s.mass_kg, 0.0, kMaxMass_kg,
                             "kg");
    if (s.EI_N_m2) {
      detail::require_positive(detail::Element{"sections", i, "EI_N_m2"}, *s.EI_N_m2, "N m^2");
      detail::require_in_range(detail::Element{"sections", i, "EI_N_m2"}, *s.EI_N_m2, 0.0,
                               kMaxEI_N_m2, "N m^2");
    }
    mass += s.mass_kg;
    first_moment += kernel::section_first_moment(s.mass_kg, x_start, s.length_m);
    x_start += s.length_m;
  }
  if (!(mass > 0.0)) {
    throw FieldError("sections",
                     "total mass must be > 0 kg, got " + detail::format_number(mass) + " kg");
  }
  detail::require_in_range("sections total length", x_start, 0.0, kMaxLength_m, "m");
  detail::require_in_range("sections total mass", mass, 0.0, kMaxMass_kg, "kg");
  const double com = first_moment / mass;
  double I_cm = 0.0;
  x_start = 0.0;
  for (const Section& s : sections) {
    const double arm = x_start + 0.5 * s.length_m - com;
    I_cm += kernel::section_inertia(s.mass_kg, s.length_m, arm);
    x_start += s.length_m;
  }
  if (!(I_cm >= std::numeric_limits<double>::min())) {
    // Every section is too small for its inertia to be a normal number: name
    // the longest, the one that would have to grow.
    std::size_t longest = 0;
    for (std::size_t i = 1; i < sections.size(); ++i) {
      if (sections[i].length_m > sections[longest].length_m) longest = i;
    }
    throw FieldError(
        detail::indexed("sections", longest, "length_m"),
        "too short to model, got " + detail::format_number(sections[longest].length_m) +
            " m (the implement's moment of inertia underflows: " + detail::format_number(I_cm) +
            " kg m^2)");
  }
  return MassProperties{mass, com, I_cm};
}

Implement Implement::from_sections(std::vector<Section> sections,
                                   std::vector<PointMass> point_masses) {
  Implement implement;
  implement.frame_ = section_mass_properties(sections);
  for (const Section& s : sections) implement.length_m_ += s.length_m;
  detail::validate_point_masses(point_masses, implement.length_m_);
  implement.total_ = add_all(implement.frame_, point_masses);
  implement.sections_ = std::move(sections);
  implement.point_masses_ = std::move(point_masses);
  return implement;
}

std::vector<Section> profile_sections(const RoundProfile& profile,
                                      std::vector<RoundSlice>* slices) {
  const std::vector<ProfileStation>& s = profile.stations;
  if (s.size() < 2) {
    throw FieldError("profile", "needs at least two stations (the butt and the tip), got " +
                                    std::to_string(s.size()));
  }
  detail::require_positive("density_kg_m3", profile.density_kg_m3, "kg/m^3");
  detail::require_in_range("density_kg_m3", profile.density_kg_m3, 0.0, kMaxDensity_kg_m3,
                           "kg/m^3");
  detail::require_positive("youngs_modulus_Pa", profile.youngs_modulus_Pa, "Pa");
  detail::require_in_range("youngs_modulus_Pa", profile.youngs_modulus_Pa, 0.0, kMaxModulus_Pa,
                           "Pa");
  for (std::size_t k = 0; k < s.size(); ++k) {
    detail::require_positive(detail::Element{"profile", k, "diameter_m"}, s[k].diameter_m, "m");
    detail::require_in_range(detail::Element{"profile", k, "diameter_m"}, s[k].diameter_m, 0.0,
                             kMaxLength_m, "m");
    if (k == 0 && s[k].from_butt_m != 0.0) {
      throw FieldError(detail::indexed("profile", k, "from_butt_m"),
                       "the first station is the butt, 0, got " +
                           detail::format_number(s[k].from_butt_m) + " m");
    }
    if (k > 0 && !(s[k].from_butt_m > s[k - 1].from_butt_m)) {
      throw FieldError(detail::indexed("profile", k, "from_butt_m"),
                       "must be beyond the station before (" +
                           detail::format_number(s[k - 1].from_butt_m) + " m), got " +
                           detail::format_number(s[k].from_butt_m) + " m");
    }
  }
  detail::require_in_range(detail::Element{"profile", s.size() - 1, "from_butt_m"},
                           s.back().from_butt_m, 0.0, kMaxLength_m, "m");
  const double wall = profile.wall_m;
  detail::require_in_range("wall_m", wall, 0.0, kMaxLength_m, "m");
  const auto thinnest = std::min_element(
      s.begin(), s.end(), [](const auto& a, const auto& b) { return a.diameter_m < b.diameter_m; });
  if (!(wall <= 0.5 * thinnest->diameter_m)) {
    throw FieldError("wall_m", "must be at most half the profile's smallest diameter (" +
                                   detail::format_number(thinnest->diameter_m) + " m at station " +
                                   std::to_string(thinnest - s.begin()) + "), got " +
                                   detail::format_number(wall) + " m");
  }
  constexpr double kPi = 3.14159265358979323846;
  const double rho = profile.density_kg_m3, E = profile.youngs_modulus_Pa;
  const double slice_m = std::max(kProfileSlice_m, s.back().from_butt_m / 400.0);
  std::vector<Section> sections;
  for (std::size_t k = 0; k + 1 < s.size(); ++k) {
    const double length = s[k + 1].from_butt_m - s[k].from_butt_m;
    const auto n = static_cast<std::size_t>(std::ceil(length / slice_m * (1.0 - 1e-12)));
    const double h = length / static_cast<double>(n);
    const double d0 = s[k].diameter_m, d1 = s[k + 1].diameter_m;
    const auto diameter = [&](double t) { return d0 + (d1 - d0) * t; };
    // The frustum's a^2 + a b + b^2 and the disc's d^4, less the bore's (none when solid).
    const auto frustum = [](double a, double b) { return a * a + a * b + b * b; };
    const auto fourth = [](double d) { return d * d * d * d; };
    for (std::size_t i = 0; i < n; ++i) {
      const double a = diameter(static_cast<double>(i) / static_cast<double>(n));
      const double b = diameter(static_cast<double>(i + 1) / static_cast<double>(n));
      const double mid = diameter((static_cast<double>(i) + 0.5) / static_cast<double>(n));
      const double area_sum =
          wall == 0.0 ? frustum(a, b) : frustum(a, b) - frustum(a - 2.0 * wall, b - 2.0 * wall);
      const double disc = wall == 0.0 ? fourth(mid) : fourth(mid) - fourth(mid - 2.0 * wall);
      sections.push_back(Section{h, rho * kPi * h * area_sum / 12.0, E * kPi * disc / 64.0});
      if (slices) slices->push_back(RoundSlice{mid, wall});
    }
  }
  return sections;
}

double profile_diameter_m(const RoundProfile& profile, double from_butt_m) {
  const std::vector<ProfileStation>& s = profile.stations;
  if (s.empty() || !(from_butt_m >= s.front().from_butt_m && from_butt_m <= s.back().from_butt_m))
    return 0.0;
  const auto after = std::upper_bound(
      s.begin(), s.end(), from_butt_m,
      [](double x, const ProfileStation& station) { return x < station.from_butt_m; });
  if (after == s.end()) return s.back().diameter_m;
  const ProfileStation& a = *(after - 1);
  const ProfileStation& b = *after;
  const double t = (from_butt_m - a.from_butt_m) / (b.from_butt_m - a.from_butt_m);
  return a.diameter_m + (b.diameter_m - a.diameter_m) * t;
}

Implement Implement::from_profile(const RoundProfile& profile,
                                  std::vector<PointMass> point_masses) {
  std::vector<RoundSlice> slices;
  std::vector<Section> sections = profile_sections(profile, &slices);
  Implement implement = from_sections(std::move(sections), std::move(point_masses));
  implement.round_slices_ = std::move(slices);
  implement.profile_ = profile;
  return implement;
}

Implement Implement::paper_racquet(double length_m, double mass_kg,
                                   double head_to_handle_mass_ratio,
                                   std::vector<PointMass> point_masses) {
  detail::require_positive("length_m", length_m, "m");
  detail::require_positive("mass_kg", mass_kg, "kg");
  detail::require_in_range("length_m", length_m, 0.0, kMaxLength_m, "m");
  detail::require_in_range("mass_kg", mass_kg, kMinImplementMass_kg, kMaxMass_kg, "kg");
  detail::require_positive("head_to_handle_mass_ratio", head_to_handle_mass_ratio, "");
  // The inertia M L^2 / 12 must be a normal number: name the input that makes
  // it underflow rather than the halves built from it.
  if (!(0.5 * length_m * length_m >= std::numeric_limits<double>::min())) {
    throw FieldError("length_m", "too short to model, got " + detail::format_number(length_m) +
                                     " m (its moment of inertia underflows)");
  }
  if (!(mass_kg * length_m * length_m / 48.0 >= std::numeric_limits<double>::min())) {
    throw FieldError("mass_kg", "too light to model at this length, got " +
                                    detail::format_number(mass_kg) +
                                    " kg (its moment of inertia underflows)");
  }
  // M1 / M2 = ratio and M1 + M2 = M  =>  M2 = M / (1 + ratio).
  const kernel::Halves halves = kernel::paper_racquet_halves(mass_kg, head_to_handle_mass_ratio);
  Implement implement = from_sections(
      {Section{0.5 * length_m, halves.handle_kg, {}}, Section{0.5 * length_m, halves.head_kg, {}}},
      std::move(point_masses));
  // The halves' sums in closed form, the body the many-case kernels use
  // (kernels.hpp), so that a paper racquet has one set of bits on every path.
  const kernel::System body =
      kernel::paper_racquet_body(length_m, mass_kg, head_to_handle_mass_ratio);
  implement.frame_ = MassProperties{body.mass_kg, body.com_from_butt_m, body.I_cm_kg_m2};
  implement.total_ = add_all(implement.frame_, implement.point_masses_);
  return implement;
}

Implement Implement::from_specs(const IndustrySpecs& specs, std::vector<PointMass> point_masses) {
  const double L = specs.length_m;
  const double M = specs.mass_kg;
  const double B = specs.balance_from_butt_m;
  detail::require_positive("length_m", L, "m");
  detail::require_positive("mass_kg", M, "kg");
  detail::require_in_range("length_m", L, 0.0, kMaxLength_m, "m");
  // The lightest implement the model was verified for (design.hpp): a lighter
  // one's inertia would reach the underflow of the numbers it is built from.
  detail::require_in_range("mass_kg", M, kMinImplementMass_kg, kMaxMass_kg, "kg");
  if (!std::isfinite(B) || B <= 0.0 || B >= L) {
    throw FieldError("balance_from_butt_m",
                     "must lie inside the length (0, " + detail::format_number(L) + ") m, got " +
                         detail::format_number(B) + " m",
                     FieldError::Range{0.0, L, true, B, "inside the length", true});
  }
  detail::require_positive("swingweight_kg_m2", specs.swingweight_kg_m2, "kg m^2");
  // A body on [0, L] with its centre of mass at B has 0 < I_cm <= M B (L - B)
  // (the upper bound puts all the mass at the two ends).
  const double arm = B - kSwingweightAxisFromButt_m;
  const double sw_min = M * arm * arm;
  const double sw_max = sw_min + M * B * (L - B);
  // I_cm = SW - M (B - 0.1)^2 must also be a normal number, not an underflow.
  if (!(specs.swingweight_kg_m2 - sw_min >= std::numeric_limits<double>::min()) ||
      specs.swingweight_kg_m2 > sw_max) {
    // What the others would have to be for this swingweight, with the rest
    // as given: the range scales with the mass, and the balance moves it,
    // so a mass or balance in the wrong unit shows here.
    const double per_kg = specs.swingweight_kg_m2 / M;  // SW / M [m^2]
    const double a0 = kSwingweightAxisFromButt_m;
    const double mass_from_kg = specs.swingweight_kg_m2 / (arm * arm + B * (L - B));
    const double mass_to_kg = specs.swingweight_kg_m2 / (arm * arm);
    // (B - a0)^2 < SW / M <= (B - a0)^2 + B (L - B), the second
    // B (L - 2 a0) + a0^2 >= SW / M.
    const double balance_from_m =
        std::max({0.0, a0 - std::sqrt(per_kg), (per_kg - a0 * a0) / (L - 2.0 * a0)});
    const double balance_to_m = std::min(L, a0 + std::sqrt(per_kg));
    std::string after;
    if (std::isfinite(mass_from_kg) && mass_from_kg > 0.0 && mass_to_kg > mass_from_kg) {
      after =
          ": it would fit a mass of " + detail::format_significant(mass_from_kg, 2) +
          (std::isfinite(mass_to_kg) ? " to " + detail::format_significant(mass_to_kg, 2) + " kg"
                                     : " kg or more");
      if (L > 2.0 * a0 && balance_to_m > balance_from_m) {
        after += ", or a balance of " + detail::format_significant(100.0 * balance_from_m, 2) +
                 " to " + detail::format_significant(100.0 * balance_to_m, 2) + " cm from the butt";
      }
      after += ", the others as given";
    }
    throw FieldError("swingweight_kg_m2",
                     "must be in (" + detail::format_significant(sw_min) + ", " +
                         detail::format_significant(sw_max) +
                         "] kg m^2 for this mass, balance and length, got " +
                         detail::format_number(specs.swingweight_kg_m2) + " kg m^2",
                     FieldError::Range{sw_min, sw_max, true, specs.swingweight_kg_m2,
                                       "for this mass, balance and length"},
                     after);
  }
  Implement implement;
  implement.length_m_ = L;
  implement.frame_ = from_swingweight(M, B, specs.swingweight_kg_m2);
  detail::validate_point_masses(point_masses, L);
  implement.total_ = add_all(implement.frame_, point_masses);
  implement.point_masses_ = std::move(point_masses);
  return implement;
}

}  // namespace sweetspot
