#include "sweetspot/string_bed.hpp"

#include <cmath>
#include <numbers>
#include <stdexcept>

#include "core/check.hpp"

namespace sweetspot {
namespace {

constexpr double kPi = std::numbers::pi;

std::string bad(const char* field, const std::string& expected, double value) {
  return std::string(field) + ": must be " + expected + ", got " + detail::format_number(value);
}

void require_valid(const StringBed& bed) {
  const std::string why = bed.validate();
  if (!why.empty()) throw std::invalid_argument("bed." + why);
}

// d ln(R / r0) / (2 pi sqrt(T_c / T_m)): the string bed's compliance times the
// mains' tension [m]; sqrt(N_m N_c) = T_m sqrt(T_c / T_m) / d.
double compliance_tension_factor(const StringBed& bed) {
  return std::log(bed.head_radius_m / bed.contact_radius_m) /
         (2.0 * kPi * std::sqrt(bed.cross_tension_ratio)) * bed.string_spacing_m;
}

// (N_m + N_c) / (sigma A) / T_m: the squared ring frequency over the mains'
// tension, times 4 [1 / (kg m)].
double ring_per_tension(const StringBed& bed) {
  const double d_m = bed.main_spacing_m(), d_c = bed.cross_spacing_m();
  const double per_tension = 1.0 / d_m + bed.cross_tension_ratio / d_c;  // (N_m + N_c) / T_m
  const double sigma = bed.main_linear_density_kg_m / d_m + bed.cross_linear_density_kg_m / d_c;
  const double area = kPi * bed.head_radius_m * bed.head_radius_m;
  return per_tension / (sigma * area);
}

}  // namespace

double string_material_density_kg_m3(StringMaterial material) {
  switch (material) {
    case StringMaterial::kNaturalGut:
      return 1300.0;
    case StringMaterial::kNylon:
    case StringMaterial::kMultifilament:
      return 1140.0;
    case StringMaterial::kPolyester:
      return 1380.0;
    case StringMaterial::kKevlar:
      return 1440.0;
  }
  return 1140.0;
}

double string_linear_density(StringMaterial material, double diameter_m) {
  detail::require_positive("diameter_m", diameter_m, "m");
  return string_material_density_kg_m3(material) * kPi * diameter_m * diameter_m / 4.0;
}

double reduced_mass(double ball_mass_kg, double effective_mass_kg) {
  detail::require_positive("ball_mass_kg", ball_mass_kg, "kg");
  detail::require_positive("effective_mass_kg", effective_mass_kg, "kg");
  return ball_mass_kg * effective_mass_kg / (ball_mass_kg + effective_mass_kg);
}

std::string StringBed::validate() const {
  if (!(std::isfinite(tension_N) && tension_N > 0.0)) return bad("tension_N", "> 0 N", tension_N);
  if (!(std::isfinite(string_spacing_m) && string_spacing_m > 0.0)) {
    return bad("string_spacing_m", "> 0 m", string_spacing_m);
  }
  if (!(std::isfinite(contact_radius_m) && contact_radius_m > 0.0)) {
    return bad("contact_radius_m", "> 0 m", contact_radius_m);
  }
  if (!(std::isfinite(head_radius_m) && head_radius_m > contact_radius_m)) {
    return bad("head_radius_m",
               "> contact_radius_m (" + detail::format_number(contact_radius_m) + " m)",
               head_radius_m);
  }
  if (!(tension_loss >= 0.0 && tension_loss <= kMaxTensionLoss)) {
    return bad("tension_loss", "in [0, " + detail::format_number(kMaxTensionLoss) + "]",
               tension_loss);
  }
  if (!(std::isfinite(cross_tension_ratio) && cross_tension_ratio > 0.0)) {
    return bad("cross_tension_ratio", "> 0", cross_tension_ratio);
  }
  if (!(std::isfinite(cross_spacing_ratio) && cross_spacing_ratio > 0.0)) {
    return bad("cross_spacing_ratio", "> 0", cross_spacing_ratio);
  }
  if (!(std::isfinite(main_linear_density_kg_m) && main_linear_density_kg_m > 0.0)) {
    return bad("main_linear_density_kg_m", "> 0 kg/m", main_linear_density_kg_m);
  }
  if (!(std::isfinite(cross_linear_density_kg_m) && cross_linear_density_kg_m > 0.0)) {
    return bad("cross_linear_density_kg_m", "> 0 kg/m", cross_linear_density_kg_m);
  }
  return {};
}

double StringBed::main_spacing_m() const {
  return string_spacing_m / std::sqrt(cross_spacing_ratio);
}
double StringBed::cross_spacing_m() const {
  return string_spacing_m * std::sqrt(cross_spacing_ratio);
}

double string_bed_ring_frequency(const StringBed& bed) {
  require_valid(bed);
  return 0.5 * std::sqrt(bed.tension_N * ring_per_tension(bed));
}

double string_bed_strings_mass(const StringBed& bed) {
  require_valid(bed);
  const double sigma = bed.main_linear_density_kg_m / bed.main_spacing_m() +
                       bed.cross_linear_density_kg_m / bed.cross_spacing_m();
  return sigma * kPi * bed.head_radius_m * bed.head_radius_m;
}

double tension_for_stiffness(const StringBed& bed, double stiffness_N_m) {
  require_valid(bed);
  detail::require_positive("stiffness_N_m", stiffness_N_m, "N/m");
  return stiffness_N_m * compliance_tension_factor(bed);
}

double tension_for_ring(const StringBed& bed, double frequency_Hz) {
  require_valid(bed);
  detail::require_positive("frequency_Hz", frequency_Hz, "Hz");
  return 4.0 * frequency_Hz * frequency_Hz / ring_per_tension(bed);
}

double string_bed_stiffness(const StringBed& bed) {
  require_valid(bed);
  return bed.tension_N / compliance_tension_factor(bed);  // 2 pi T_s / (d ln(R/r0))
}

double series_stiffness(double ball_stiffness_N_m, double string_bed_stiffness_N_m) {
  detail::require_positive("ball_stiffness_N_m", ball_stiffness_N_m, "N/m");
  detail::require_positive("string_bed_stiffness_N_m", string_bed_stiffness_N_m, "N/m");
  return 1.0 / (1.0 / ball_stiffness_N_m + 1.0 / string_bed_stiffness_N_m);
}

double spring_contact_duration(double ball_mass_kg, double effective_mass_kg,
                               double stiffness_N_m) {
  detail::require_positive("stiffness_N_m", stiffness_N_m, "N/m");
  return kPi * std::sqrt(reduced_mass(ball_mass_kg, effective_mass_kg) / stiffness_N_m);
}

TensionDuration tension_impact_duration(const StringBed& bed, double ball_mass_kg,
                                        double effective_mass_kg, double ball_stiffness_N_m) {
  TensionDuration out;
  out.string_bed_stiffness_N_m = string_bed_stiffness(bed);
  out.stiffness_N_m = series_stiffness(ball_stiffness_N_m, out.string_bed_stiffness_N_m);
  out.reduced_mass_kg = reduced_mass(ball_mass_kg, effective_mass_kg);
  out.duration_s = spring_contact_duration(ball_mass_kg, effective_mass_kg, out.stiffness_N_m);
  return out;
}

std::optional<double> tension_for_duration(const StringBed& bed, double duration_s,
                                           double ball_mass_kg, double effective_mass_kg,
                                           double ball_stiffness_N_m) {
  require_valid(bed);
  detail::require_positive("duration_s", duration_s, "s");
  detail::require_positive("ball_stiffness_N_m", ball_stiffness_N_m, "N/m");
  const double mu = reduced_mass(ball_mass_kg, effective_mass_kg);
  const double compliance = duration_s * duration_s / (kPi * kPi * mu);  // 1/k
  const double strings_compliance = compliance - 1.0 / ball_stiffness_N_m;
  if (!(strings_compliance > 0.0)) return std::nullopt;
  return compliance_tension_factor(bed) / strings_compliance;
}

}  // namespace sweetspot
