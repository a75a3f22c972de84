#include "io/design_fields.hpp"

#include <algorithm>
#include <functional>
#include <map>
#include <stdexcept>
#include <utility>

#include "sweetspot/ball_contact.hpp"
#include "sweetspot/design.hpp"
#include "sweetspot/head_geometry.hpp"
#include "sweetspot/string_bed.hpp"

namespace sweetspot::io {

const std::vector<DesignField>& design_fields() {
  using D = Dimension;
  static const std::vector<DesignField> kFields{
      // The document.
      {"", "$schema", {}, {}, "$schema", "", "", ""},
      {"", "name", {}, {}, "name", "the file name", "", ""},
      {"", "description", {}, {}, "description", "", "", ""},
      {"", "fidelity", {}, {}, "fidelity", "auto", "rigid, modal, response, collision, auto", ""},
      {"", "implement", {}, {}, "implement", "required (none on support rigid_surface)", "", ""},
      {"", "frame", {}, {}, "frame", "", "", ""},
      {"", "strings", {}, {}, "strings", "", "", ""},
      {"", "hand", {}, {}, "hand", "", "", ""},
      {"", "forearm", {}, {}, "forearm", "", "", ""},
      {"", "ball", {}, {}, "ball", "", "", ""},
      {"", "impact", {}, {}, "impact", "", "", ""},
      {"", "reference", {}, {}, "reference", "", "", ""},
      {"", "swing", {}, {}, "swing", "none: the shot of an assumed groundstroke", "", ""},
      {"",
       "support",
       {},
       {},
       "support",
       "free",
       "free, hand, head_clamped, handle_clamped, rigid_surface, or a pivot {pivot_from_butt}",
       ""},
      // The implement: the paper's racquet, sections or a spec sheet.
      {"implement", "length", D::kLength, {}, "length_m", "", "(0, kMaxLength_m]", ""},
      {"implement", "mass", D::kMass, {}, "mass_kg", "", "(0, kMaxMass_kg]", ""},
      {"implement",
       "head_to_handle_mass_ratio",
       {},
       {},
       "head_to_handle_mass_ratio",
       "",
       "> 0",
       "length, mass"},
      {"implement", "sections", {}, {}, "sections", "", "", ""},
      {"implement", "profile", {}, {}, "profile", "", "", "density_kg_m3, youngs_modulus"},
      {"implement",
       "density_kg_m3",
       {},
       {},
       "density_kg_m3",
       "",
       "(0, kMaxDensity_kg_m3]",
       "profile"},
      {"implement",
       "youngs_modulus",
       {},
       {{"youngs_modulus_Pa"}, {"youngs_modulus_GPa", {1e9, 9}}},
       "youngs_modulus_Pa",
       "",
       "(0, kMaxModulus_Pa]",
       "profile"},
      {"implement",
       "wall",
       D::kLength,
       {},
       "wall_m",
       "0 (solid)",
       "[0, half the profile's smallest diameter]",
       "profile"},
      {"implement", "point_masses", {}, {}, "point_masses", "none", "", ""},
      {"implement",
       "balance",
       {},
       {{"balance_from_butt_m"}, {"balance_cm", {0.01, -2}}, {"balance_pts_hl"}},
       "balance_from_butt_m",
       "",
       "inside the length",
       "length, mass, swingweight"},
      {"implement", "swingweight", D::kInertia, {}, "swingweight_kg_m2", "", "", "balance"},
      {"implement",
       "headsize",
       {},
       {{"headsize_sq_in", {kSquareInch_m2, 0}}, {"headsize_cm2", {1e-4, -4}}},
       "headsize_cm2",
       "none",
       "> 0, fits the length",
       ""},
      {"implement",
       "head_aspect_ratio",
       {},
       {},
       "head_aspect_ratio",
       "1.35",
       "[1, 10]",
       "headsize",
       kDefaultHeadAspectRatio},
      {"implement",
       "hoop_width",
       D::kLength,
       {},
       "hoop_width_m",
       "1.5 cm",
       "[0, 1] m",
       "headsize",
       kDefaultHoopWidth_m},
      {"implement",
       "twistweight",
       D::kInertia,
       {},
       "twistweight_kg_m2",
       "estimated from the head",
       "> 0",
       ""},
      {"implement/sections/N", "length", D::kLength, {}, "length_m", "", "(0, kMaxLength_m]", ""},
      {"implement/sections/N", "mass", D::kMass, {}, "mass_kg", "", "[0, kMaxMass_kg]", ""},
      {"implement/sections/N",
       "EI",
       D::kStiffness,
       {},
       "EI_N_m2",
       "the frame's",
       "(0, kMaxEI_N_m2]",
       ""},
      {"implement/profile/N",
       "from_butt",
       D::kLength,
       {},
       "from_butt_m",
       "",
       "0 first, then increasing, up to kMaxLength_m",
       ""},
      {"implement/profile/N",
       "diameter",
       D::kLength,
       {},
       "diameter_m",
       "",
       "(0, kMaxLength_m]",
       ""},
      {"implement/point_masses/N", "mass", D::kMass, {}, "mass_kg", "", "[0, kMaxMass_kg]", ""},
      {"implement/point_masses/N",
       "from_butt",
       D::kLength,
       {},
       "from_butt_m",
       "",
       "[0, length]",
       "length"},
      {"implement/point_masses/N",
       "from_tip",
       D::kLength,
       {},
       "from_tip_m",
       "",
       "[0, length]",
       "length"},
      {"implement/point_masses/N",
       "off_axis",
       D::kLength,
       {},
       "off_axis_m",
       "0",
       "[-length, length]",
       "length",
       0.0},
      {"implement/point_masses/N",
       "clock",
       {},
       {},
       "clock",
       "",
       "[0, 12], \"throat\", \"handle\"",
       "headsize, length"},
      // The frame.
      {"frame", "cor", {}, {}, "cor", "0.8", "[0, 1]", "", 0.8},
      {"frame", "cor_rigid", {}, {}, "cor_rigid", "", "[0, 1]", "stiffness"},
      {"frame", "EI", D::kStiffness, {}, "EI_N_m2", "none: rigid only", "(0, kMaxEI_N_m2]", ""},
      {"frame", "fundamental_free", D::kFrequency, {}, "fundamental_free_Hz", "", "> 0", ""},
      {"frame", "RA", {}, {}, "RA", "", "[kMinRA, kMaxRA]", "mass"},
      {"frame", "cross_section", {}, {}, "cross_section", "Euler-Bernoulli", "", "stiffness"},
      {"frame/cross_section",
       "shear_modulus_Pa",
       {},
       {},
       "shear_modulus_Pa",
       "",
       "(0, kMaxShearModulus_Pa]",
       ""},
      {"frame/cross_section", "width", D::kLength, {}, "width_m", "", "> 0", ""},
      {"frame/cross_section", "thickness", D::kLength, {}, "thickness_m", "", "> 0", ""},
      {"frame/cross_section",
       "shape",
       {},
       {},
       "shape",
       "rectangle",
       "rectangle, circle, hollow_circle, ellipse, box or profile",
       ""},
      {"frame/cross_section", "diameter", D::kLength, {}, "diameter_m", "", "> 0", ""},
      {"frame/cross_section",
       "wall",
       D::kLength,
       {},
       "wall_m",
       "",
       "(0, diameter / 2] (tube), (0, min(width, thickness) / 2) (box)",
       ""},
      {"frame/cross_section",
       "poisson_ratio",
       {},
       {},
       "poisson_ratio",
       "0",
       "[0, kMaxPoissonRatio]",
       "",
       0.0},
      // The strings.
      {"strings",
       "impact_duration",
       D::kTime,
       {},
       "impact_duration_s",
       "4 ms",
       "[kMinDuration_s, kMaxDuration_s]",
       "",
       0.004},
      {"strings", "tension", D::kForce, {}, "tension_N", "", "> 0", ""},
      {"strings",
       "string_spacing",
       D::kLength,
       {},
       "string_spacing_m",
       "16.5 mm",
       "> 0",
       "tension",
       StringBed{}.string_spacing_m},
      {"strings",
       "head_size",
       {},
       {{"head_size_in2", {kSquareInch_m2, 0}}, {"head_size_cm2", {1e-4, -4}}},
       "head_size_cm2",
       "implement.headsize, else 100 in^2",
       "> 0",
       "tension"},
      {"strings",
       "contact_radius",
       D::kLength,
       {},
       "contact_radius_m",
       "3 cm",
       "> 0, < head radius",
       "tension",
       StringBed{}.contact_radius_m},
      {"strings", "bed_mass", D::kMass, {}, "bed_mass_kg", "4 g", "> 0", "", kStringBedMass_kg},
      {"strings",
       "bed_damping_ratio",
       {},
       {},
       "bed_damping_ratio",
       "0.008",
       "[0, 1)",
       "",
       kStringBedDampingRatio},
      // A stringer's ticket: the pattern, each family's string and tension, the
      // share the bed loses, a measurement of the bed to calibrate it to.
      {"strings", "pattern", {}, {}, "pattern", "from string_spacing", "\"MxC\", 4-40 each", ""},
      {"strings",
       "tension_loss",
       {},
       {},
       "tension_loss",
       "0 (the bed holds the pull)",
       "[0, kMaxTensionLoss]",
       ""},
      {"strings", "material", {}, {}, "material", "nylon", "kStringMaterials", ""},
      {"strings",
       "gauge",
       {},
       {{"gauge_m", {1.0, 0}}, {"gauge_mm", {1e-3, -3}}, {"gauge", {}}},
       "gauge_m",
       "1.30 mm (16)",
       "[kMinGauge_m, kMaxGauge_m]; gauge: 15, 15L, 16, 16L, 17, 18, 19",
       ""},
      {"strings",
       "linear_density",
       D::kLinearDensity,
       {},
       "linear_density_kg_m",
       "material x gauge",
       "[kMinStringLinearDensity_kg_m, kMaxStringLinearDensity_kg_m]",
       ""},
      {"strings", "mains", {}, {}, "mains", "", "", ""},
      {"strings", "crosses", {}, {}, "crosses", "", "", ""},
      {"strings", "measured_ring", D::kFrequency, {}, "measured_ring_Hz", "", "> 0", ""},
      {"strings",
       "measured_stiffness",
       D::kSpringRate,
       {},
       "measured_stiffness_N_m",
       "",
       "> 0",
       ""},
      {"strings/mains", "tension", D::kForce, {}, "tension_N", "strings.tension", "> 0", ""},
      {"strings/mains", "spacing", D::kLength, {}, "spacing_m", "from the pattern", "> 0", ""},
      {"strings/mains", "material", {}, {}, "material", "strings.material", "kStringMaterials", ""},
      {"strings/mains",
       "gauge",
       {},
       {{"gauge_m", {1.0, 0}}, {"gauge_mm", {1e-3, -3}}, {"gauge", {}}},
       "gauge_m",
       "strings.gauge",
       "[kMinGauge_m, kMaxGauge_m]",
       ""},
      {"strings/mains",
       "linear_density",
       D::kLinearDensity,
       {},
       "linear_density_kg_m",
       "material x gauge",
       "[kMinStringLinearDensity_kg_m, kMaxStringLinearDensity_kg_m]",
       ""},
      {"strings/crosses", "tension", D::kForce, {}, "tension_N", "strings.tension", "> 0", ""},
      {"strings/crosses", "spacing", D::kLength, {}, "spacing_m", "from the pattern", "> 0", ""},
      {"strings/crosses",
       "material",
       {},
       {},
       "material",
       "strings.material",
       "kStringMaterials",
       ""},
      {"strings/crosses",
       "gauge",
       {},
       {{"gauge_m", {1.0, 0}}, {"gauge_mm", {1e-3, -3}}, {"gauge", {}}},
       "gauge_m",
       "strings.gauge",
       "[kMinGauge_m, kMaxGauge_m]",
       ""},
      {"strings/crosses",
       "linear_density",
       D::kLinearDensity,
       {},
       "linear_density_kg_m",
       "material x gauge",
       "[kMinStringLinearDensity_kg_m, kMaxStringLinearDensity_kg_m]",
       ""},
      // The hand, the forearm, the ball, the impact.
      {"hand", "mass", D::kMass, {}, "mass_kg", "0.5 kg", "[0, kMaxMass_kg]", "", Hand{}.mass_kg},
      {"hand",
       "center_from_butt",
       D::kLength,
       {},
       "center_from_butt_m",
       "0.07 m",
       "[0, length]",
       "length",
       Hand{}.center_from_butt_m},
      {"hand",
       "grip_length",
       D::kLength,
       {},
       "grip_length_m",
       "0.10 m",
       "> 0",
       "",
       Hand{}.grip_length_m},
      {"hand",
       "grip_stiffness",
       D::kStiffness,
       {},
       "grip_stiffness_N_m2",
       "2e5",
       "[0, kMaxGripStiffness_N_m2]",
       "",
       Hand{}.grip_stiffness_N_m2},
      {"hand",
       "grip_damping",
       D::kDamping,
       {},
       "grip_damping_N_s_m2",
       "1300",
       "[0, kMaxGripDamping_N_s_m2]",
       "",
       Hand{}.grip_damping_N_s_m2},
      {"hand",
       "grip",
       {},
       {},
       "grip",
       "paper",
       "paper, light, medium, tight (its grip_stiffness and grip_damping unless given)",
       ""},
      {"forearm",
       "equivalent_mass",
       D::kMass,
       {},
       "equivalent_mass_kg",
       "0.5 kg",
       "[0, kMaxForearmMass_kg]",
       "",
       0.5},
      {"forearm", "mass", D::kMass, {}, "mass_kg", "", "[0, 3 kMaxForearmMass_kg]", ""},
      {"ball", "mass", D::kMass, {}, "mass_kg", "0.057 kg", "(0, kMaxMass_kg]", "", Ball{}.mass_kg},
      {"ball",
       "speed",
       D::kSpeed,
       {},
       "speed_m_s",
       "50 m/s",
       "(0, kMaxSpeed_m_s]",
       "",
       Ball{}.speed_m_s},
      {"ball",
       "cor_on_rigid_surface",
       {},
       {},
       "cor_on_rigid_surface",
       "none: the contact law as given",
       "[0, 1): the law's loss solved to match at the drop test's 7.06 m/s; 0 a dead ball",
       ""},
      {"ball", "contact", {}, {}, "contact", "the calibrated tennis ball", "", ""},
      {"ball/contact",
       "law",
       {},
       {},
       "law",
       "power",
       "power (k x^n + b x^p x'), hysteretic (the buckling, hysteretic ball), two_mass (the "
       "hysteretic ball of two masses, whose far side moves on)",
       ""},
      {"ball/contact",
       "stiffness",
       {},
       {},
       "stiffness",
       "the tennis ball's",
       "(0, 1e15]",
       "",
       kTennisBallLaw.stiffness},
      {"ball/contact",
       "exponent",
       {},
       {},
       "exponent",
       "the tennis ball's",
       "[1, 3]",
       "",
       kTennisBallLaw.exponent},
      {"ball/contact",
       "damping",
       {},
       {},
       "damping",
       "the tennis ball's",
       "[0, 1e12]",
       "",
       kTennisBallLaw.damping},
      {"ball/contact",
       "damping_exponent",
       {},
       {},
       "damping_exponent",
       "the tennis ball's",
       "[0, 3]",
       "",
       kTennisBallLaw.damping_exponent},
      {"impact",
       "from_tip",
       D::kLength,
       {},
       "from_tip_m",
       "a racquet with a head: the centre of the strings; else 5 cm from the tip",
       "[0, length]",
       "length, head"},
      {"impact", "from_butt", D::kLength, {}, "from_butt_m", "", "[0, length]", "length"},
      {"impact",
       "off_axis",
       D::kLength,
       {},
       "off_axis_m",
       "0",
       "on the string bed",
       "twistweight or headsize",
       0.0},
      // The racquet swung at the ball (swing.hpp): one speed, one pivot.
      {"swing",
       "angular_speed",
       {},
       {{"angular_speed_rad_s"}, {"angular_speed_rpm", {2.0 * 3.141592653589793 / 60.0, 0}}},
       "angular_speed_rad_s",
       "",
       "(0, kMaxAngularSpeed_rad_s]",
       "pivot_beyond_butt"},
      {"swing",
       "speed_at_impact",
       D::kSpeed,
       {},
       "speed_at_impact_m_s",
       "",
       "(0, kMaxSpeed_m_s], instead of angular_speed",
       "pivot_beyond_butt"},
      {"swing",
       "pivot_beyond_butt",
       D::kLength,
       {},
       "pivot_beyond_butt_m",
       "required",
       "[0, kMaxPivotBeyondButt_m]",
       ""},
      {"swing",
       "reference_swingweight",
       D::kInertia,
       {},
       "reference_swingweight_kg_m2",
       "none: the swing as given",
       "> 0",
       "angular_speed or speed_at_impact"},
      // What holds the implement when it is not a name (design.hpp, Support).
      {"support", "pivot_from_butt", D::kLength, {}, "pivot_from_butt_m", "required", "[0, L]", ""},
  };
  return kFields;
}

std::vector<std::string> spellings_of(const DesignField& field) {
  if (field.dimension) return spellings(field.stem, *field.dimension);
  if (!field.keys.empty()) {
    std::vector<std::string> keys;
    for (const KeySpelling& k : field.keys) keys.emplace_back(k.key);
    return keys;
  }
  return {std::string(field.stem)};
}

std::optional<FieldSpelling> find_spelling(std::string_view object, std::string_view key) {
  for (const DesignField& field : design_fields()) {
    if (field.object != object) continue;
    if (field.dimension) {
      if (const auto scale = unit_scale(key, field.stem, *field.dimension))
        return FieldSpelling{&field, *scale};
    } else if (!field.keys.empty()) {
      for (const KeySpelling& k : field.keys) {
        if (k.key == key) return FieldSpelling{&field, k.scale};
      }
    } else if (field.stem == key) {
      return FieldSpelling{&field, UnitScale{}};
    }
  }
  return std::nullopt;
}

const std::string& si_key(std::string_view object, std::string_view stem) {
  static const std::map<std::pair<std::string, std::string>, std::string, std::less<>> kKeys = [] {
    std::map<std::pair<std::string, std::string>, std::string, std::less<>> keys;
    for (const DesignField& field : design_fields())
      keys[{std::string(field.object), std::string(field.stem)}] = field.si_key;
    return keys;
  }();
  const auto it = kKeys.find(std::pair{std::string(object), std::string(stem)});
  if (it == kKeys.end()) {
    throw std::logic_error("the design's field table has no field " + std::string(stem) + " in " +
                           (object.empty() ? std::string("the document") : std::string(object)));
  }
  return it->second;
}

const std::vector<std::string>& design_keys(std::string_view object) {
  static const std::map<std::string, std::vector<std::string>, std::less<>> kKeys = [] {
    std::map<std::string, std::vector<std::string>, std::less<>> keys;
    for (const DesignField& field : design_fields()) {
      std::vector<std::string>& list = keys[std::string(field.object)];
      for (std::string& key : spellings_of(field)) list.push_back(std::move(key));
    }
    return keys;
  }();
  static const std::vector<std::string> kNone;
  const auto it = kKeys.find(object);
  return it == kKeys.end() ? kNone : it->second;
}

std::string design_object_of(std::string_view canonical) {
  std::string out;
  std::size_t start = 0;
  while (start <= canonical.size()) {
    const std::size_t slash = std::min(canonical.find('/', start), canonical.size());
    const std::string_view token = canonical.substr(start, slash - start);
    if (!out.empty()) out += '/';
    const bool index =
        !token.empty() && token.find_first_not_of("0123456789") == std::string_view::npos;
    out += index ? std::string_view("N") : token;
    start = slash + 1;
  }
  return out;
}

std::string design_path_problem(std::string_view pointer) {
  if (!pointer.starts_with('/')) return "";
  std::string object;
  std::size_t start = 1;
  while (start <= pointer.size()) {
    const std::size_t slash = std::min(pointer.find('/', start), pointer.size());
    const std::string_view token = pointer.substr(start, slash - start);
    const bool index =
        !token.empty() && token.find_first_not_of("0123456789") == std::string_view::npos;
    const std::vector<std::string>& known = design_keys(object);
    if (!index && !known.empty() && std::find(known.begin(), known.end(), token) == known.end()) {
      return unknown_key_detail(token, known);
    }
    if (!object.empty() || start > 1) object += '/';
    object += index ? std::string_view("N") : token;
    start = slash + 1;
  }
  return "";
}

}  // namespace sweetspot::io
