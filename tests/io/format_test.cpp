// Number formatting of the CSV and JSON writers.
#include "io/format.hpp"

#include <cmath>
#include <cstdlib>
#include <limits>
#include <cstdint>
#include <cstring>
#include <random>
#include <string>

#include <catch2/catch.hpp>

namespace sweetspot::io {
namespace {

TEST_CASE("Appending a number writes exactly the text exact() gives, shortest and round-trip") {
  const unsigned seed = 20040622;
  INFO("seed " << seed);
  std::mt19937_64 random(seed);
  std::vector<double> values{0.0, -0.0, 1.0, -1.0, 0.1, 0.3, 1e-300, 5e-324, -2.2250738585072014e-308,
                             std::numeric_limits<double>::max(), 1e21, 123456789012345680.0, 250.06908906015684,
                             std::numeric_limits<double>::infinity(), -std::numeric_limits<double>::infinity()};
  for (int i = 0; i < 10000; ++i) {
    double value = 0.0;
    const std::uint64_t bits = random();
    std::memcpy(&value, &bits, sizeof value);
    if (!std::isnan(value)) values.push_back(value);
  }
  for (const double value : values) {
    std::string text = "x";
    append_exact(text, value);
    CHECK(text == "x" + exact(value));
    if (std::isfinite(value)) CHECK(std::strtod(exact(value).c_str(), nullptr) == value);
  }
  std::string zero;
  append_exact(zero, -0.0);
  CHECK(zero == "0");
}

}  // namespace
}  // namespace sweetspot::io
