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

// d ln(R / r0) / (2 pi): the string bed's compliance times the tension [m].
double compliance_tension_factor(const StringBed& bed) {
  return std::log(bed.head_radius_m / bed.contact_radius_m) / (2.0 * kPi) * bed.string_spacing_m;
}

}  // namespace

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
  return {};
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
