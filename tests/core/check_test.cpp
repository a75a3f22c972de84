// The core's argument checks: a passing value costs nothing, a failing one
// throws a message naming the argument, the expectation and the value as given.
#include "core/check.hpp"

#include <catch2/catch.hpp>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>

namespace sweetspot::detail {
namespace {

TEST_CASE("Numbers in messages are the shortest text that reads back to the same double") {
  CHECK(format_number(0.25) == "0.25");
  CHECK(format_number(0.1 + 0.2) == "0.30000000000000004");
  CHECK(format_number(5e-324) == "5e-324");  // never rounded to 0
  CHECK(format_number(-0.0) == "-0");
  CHECK(format_number(std::numeric_limits<double>::infinity()) == "inf");
  CHECK(format_number(std::nan("")) == "nan");
  CHECK(format_significant(1.0 / 3.0) == "0.333333");
}

TEST_CASE("A computed bound keeps its significant digits and writes an everyday size whole") {
  // Read back, the text is the value to half a unit of its last digit.
  for (const int digits : {2, 4, 6}) {
    for (const double value : {0.1906, 9.04, 11.3, 1510.4, 5.339e5, 1.234567e7, 3.2e-9, -0.6321}) {
      const std::string text = format_significant(value, digits);
      INFO(value << " to " << digits << ": " << text);
      const double back = std::stod(text);
      CHECK(std::fabs(back - value) <=
            0.5 * std::pow(10.0, std::floor(std::log10(std::fabs(value))) + 1 - digits) *
                (1 + 1e-12));
      // No exponent below a million.
      CHECK((text.find('e') == std::string::npos) ==
            (std::fabs(value) >= 1e-4 && std::fabs(back) < 1e6));
    }
  }
  CHECK(format_significant(-0.0, 2) == "0");
  CHECK(format_significant(1510.4, 3) == "1510");
}

TEST_CASE("Each check throws naming the argument, the range and the value") {
  CHECK_NOTHROW(require_positive("mass", 1e-300, "kg"));
  CHECK_THROWS_WITH(require_positive("mass", 0.0, "kg"), "mass: must be > 0 kg, got 0 kg");
  CHECK_THROWS_WITH(require_at_least("hand/mass_kg", -0.5, 0.0, "kg"),
                    "hand/mass_kg: must be >= 0 kg, got -0.5 kg");
  CHECK_THROWS_WITH(require_in_range("frame/cor", 1.5, 0.0, 1.0, ""),
                    "frame/cor: must be in [0, 1], got 1.5");
  CHECK_THROWS_WITH(require_finite("x", std::nan("")), "x: must be a finite number, got nan");
  // Non-finite values never pass a range check, and their unit is not appended.
  CHECK_THROWS_WITH(require_in_range("t", std::numeric_limits<double>::infinity(), 0.0, 1.0, "s"),
                    "t: must be in [0, 1] s, got inf");
  CHECK_THROWS_AS(require_at_least("x", std::nan(""), 0.0, ""), std::invalid_argument);
}

TEST_CASE("A list element's field is named as a relative JSON pointer") {
  CHECK(indexed("point_masses", 1, "mass_kg") == "point_masses/1/mass_kg");
}

}  // namespace
}  // namespace sweetspot::detail
