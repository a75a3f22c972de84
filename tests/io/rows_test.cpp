// One writer of rows, CSV or JSON Lines: what it writes reads back as the
// cells it was given (JSON by nlohmann's parser, CSV by RFC 4180's rules).
#include "io/rows.hpp"

#include <bit>
#include <catch2/catch.hpp>
#include <cmath>
#include <cstdint>
#include <limits>
#include <nlohmann/json.hpp>
#include <random>
#include <string>

#include "io/json_reader.hpp"

namespace sweetspot::io {

TEST_CASE("JSON Lines rows read back as the numbers and texts written, keys in header order") {
  const auto rows = row_writer(Format::kJson);
  std::string out;
  rows->header({"/impact/from_tip_m", "peak \"force\"", "error"}, out);
  CHECK(out.empty());
  std::mt19937_64 random(20261202);
  std::uniform_int_distribution<std::uint64_t> bits;
  for (int i = 0; i < 2000; ++i) {
    double x = std::bit_cast<double>(bits(random));
    if (!std::isfinite(x)) x = std::numeric_limits<double>::denorm_min();
    std::string line;
    rows->number(0, x, line);
    rows->number(1, std::nullopt, line);
    rows->text(2, i % 2 ? std::optional<std::string_view>("a, \"quoted\"\nline") : std::nullopt,
               line);
    rows->end_row(line);
    REQUIRE(line.back() == '\n');
    const nlohmann::ordered_json j = nlohmann::ordered_json::parse(line);
    auto key = j.items().begin();
    CHECK(key.key() == "/impact/from_tip_m");
    CHECK((++key).key() == "peak \"force\"");
    CHECK((++key).key() == "error");
    CHECK(std::bit_cast<std::uint64_t>(j["/impact/from_tip_m"].get<double>()) ==
          std::bit_cast<std::uint64_t>(x));
    CHECK(j["peak \"force\""].is_null());
    if (i % 2) {
      CHECK(j["error"] == "a, \"quoted\"\nline");
    } else {
      CHECK(j["error"].is_null());
    }
  }
}

TEST_CASE("CSV rows quote as RFC 4180 says and their numbers read back exactly") {
  const auto rows = row_writer(Format::kCsv);
  std::string out;
  rows->header({"x", "y", "error"}, out);
  CHECK(out == "x,y,error\n");
  out.clear();
  rows->number(0, 0.1, out);
  rows->number(1, std::nullopt, out);
  rows->text(2, "a,b \"c\"", out);
  rows->end_row(out);
  CHECK(out == "0.1,,\"a,b \"\"c\"\"\"\n");
  std::mt19937_64 random(7);
  std::uniform_real_distribution<double> uniform(-1e6, 1e6);
  for (int i = 0; i < 1000; ++i) {
    const double x = uniform(random);
    std::string cell;
    rows->number(0, x, cell);
    CHECK(std::strtod(cell.c_str(), nullptr) == x);
  }
}

}  // namespace sweetspot::io
