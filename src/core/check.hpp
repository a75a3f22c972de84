#pragma once

// Argument checks shared by the physics core. Each throws std::invalid_argument
// with a message that names the argument, what was expected and the value.

#include <cmath>
#include <string>
#include <string_view>
#include <vector>

namespace sweetspot {
struct PointMass;
}

namespace sweetspot::detail {

// Shortest round-trip text of a double ("0.25", "1e-09", "inf").
std::string format_number(double value);
// `digits` significant digits, for computed bounds in messages: %g, except
// that an everyday size below a million is written whole rather than with
// an exponent ("1510", not "1.5e+03", for 1510 to 3 digits); 0 is "0".
std::string format_significant(double value, int digits = 6);

// The name of a field of a list element as a relative JSON pointer,
// "point_masses/1/mass_kg", so the JSON layer can point at the file's key.
std::string indexed(std::string_view list, std::size_t index, std::string_view field);

// Point masses must lie on [0, length_m] and weigh >= 0 kg.
void validate_point_masses(const std::vector<PointMass>& point_masses, double length_m);

// The messages, out of line; the checks below are inline so that a passing
// check costs a comparison (they sit in the rigid model's hot path).
[[noreturn]] void fail_finite(std::string_view name, double value);
[[noreturn]] void fail_positive(std::string_view name, double value, std::string_view unit);
[[noreturn]] void fail_at_least(std::string_view name, double value, double min,
                                std::string_view unit);
[[noreturn]] void fail_in_range(std::string_view name, double value, double min, double max,
                                std::string_view unit);

inline void require_finite(std::string_view name, double value) {
  if (!std::isfinite(value)) [[unlikely]]
    fail_finite(name, value);
}
inline void require_positive(std::string_view name, double value, std::string_view unit) {
  if (!std::isfinite(value) || value <= 0.0) [[unlikely]]
    fail_positive(name, value, unit);
}
inline void require_at_least(std::string_view name, double value, double min,
                             std::string_view unit) {
  if (!std::isfinite(value) || value < min) [[unlikely]]
    fail_at_least(name, value, min, unit);
}
inline void require_in_range(std::string_view name, double value, double min, double max,
                             std::string_view unit) {
  if (!std::isfinite(value) || value < min || value > max) [[unlikely]]
    fail_in_range(name, value, min, max, unit);
}

// A list element's field, named only when a check on it fails (building the
// name on the happy path would cost more than the check).
struct Element {
  std::string_view list;
  std::size_t index;
  std::string_view field;
};
inline void require_finite(const Element& e, double value) {
  if (!std::isfinite(value)) [[unlikely]]
    fail_finite(indexed(e.list, e.index, e.field), value);
}
inline void require_positive(const Element& e, double value, std::string_view unit) {
  if (!std::isfinite(value) || value <= 0.0) [[unlikely]]
    fail_positive(indexed(e.list, e.index, e.field), value, unit);
}
inline void require_at_least(const Element& e, double value, double min, std::string_view unit) {
  if (!std::isfinite(value) || value < min) [[unlikely]]
    fail_at_least(indexed(e.list, e.index, e.field), value, min, unit);
}
inline void require_in_range(const Element& e, double value, double min, double max,
                             std::string_view unit) {
  if (!std::isfinite(value) || value < min || value > max) [[unlikely]]
    fail_in_range(indexed(e.list, e.index, e.field), value, min, max, unit);
}

}  // namespace sweetspot::detail
