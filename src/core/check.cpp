#include "core/check.hpp"

#include <charconv>
#include <cmath>
#include <cstdio>
#include <limits>
#include <stdexcept>

#include "sweetspot/errors.hpp"
#include "sweetspot/implement.hpp"

namespace sweetspot::detail {

std::string format_number(double value) {
  if (std::isnan(value)) return "nan";
  if (std::isinf(value)) return value > 0 ? "inf" : "-inf";
  char buffer[32];
  const auto result = std::to_chars(buffer, buffer + sizeof buffer, value);
  return std::string(buffer, result.ptr);
}

std::string indexed(std::string_view list, std::size_t index, std::string_view field) {
  return std::string(list) + "/" + std::to_string(index) + "/" + std::string(field);
}

void validate_point_masses(const std::vector<PointMass>& point_masses, double length_m) {
  for (std::size_t i = 0; i < point_masses.size(); ++i) {
    require_in_range(Element{"point_masses", i, "from_butt_m"}, point_masses[i].from_butt_m, 0.0,
                     length_m, "m");
    require_in_range(Element{"point_masses", i, "mass_kg"}, point_masses[i].mass_kg, 0.0,
                     kMaxMass_kg, "kg");
    // How far off the axis it may sit depends on the implement's outline
    // there, which the design knows (validate() in design.cpp).
    require_finite(Element{"point_masses", i, "off_axis_m"}, point_masses[i].off_axis_m);
  }
}

std::string format_significant(double value, int digits) {
  if (value == 0.0) return "0";  // no "-0"
  char buffer[48];
  const double scale = std::pow(10.0, std::floor(std::log10(std::fabs(value))) + 1 - digits);
  const double rounded = std::round(value / scale) * scale;
  if (std::fabs(rounded) >= std::pow(10.0, digits) && std::fabs(rounded) < 1e6)
    std::snprintf(buffer, sizeof buffer, "%.0f", rounded);
  else
    std::snprintf(buffer, sizeof buffer, "%.*g", digits, value);
  return buffer;
}

namespace {
[[noreturn]] void fail(std::string_view name, const std::string& expected, double value,
                       std::string_view unit, std::optional<FieldError::Range> range = {}) {
  std::string detail = "must be " + expected + ", got " + format_number(value);
  if (!unit.empty() && std::isfinite(value)) detail += " " + std::string(unit);
  if (range) range->value = value;
  throw FieldError(std::string(name), std::move(detail), range);
}
constexpr double kInf = std::numeric_limits<double>::infinity();
}  // namespace

void fail_finite(std::string_view name, double value) { fail(name, "a finite number", value, ""); }

void fail_positive(std::string_view name, double value, std::string_view unit) {
  fail(name, "> 0" + (unit.empty() ? "" : " " + std::string(unit)), value, unit,
       FieldError::Range{0.0, kInf, true});
}

void fail_at_least(std::string_view name, double value, double min, std::string_view unit) {
  fail(name, ">= " + format_number(min) + (unit.empty() ? "" : " " + std::string(unit)), value,
       unit, FieldError::Range{min, kInf});
}

void fail_in_range(std::string_view name, double value, double min, double max,
                   std::string_view unit) {
  fail(name,
       "in [" + format_number(min) + ", " + format_number(max) + "]" +
           (unit.empty() ? "" : " " + std::string(unit)),
       value, unit, FieldError::Range{min, max});
}

}  // namespace sweetspot::detail
