// The strict JSON layer: UTF-8 checks, and the key map that lets a core
// error quote the file's own key and value.
#include "io/json_reader.hpp"

#include <algorithm>
#include <string>
#include <vector>

#include <catch2/catch.hpp>

#include "io/input_error.hpp"

namespace sweetspot::io {
namespace {

TEST_CASE(
    "UTF-8 is checked byte by byte: overlong forms, surrogates and truncated sequences are not "
    "UTF-8") {
  CHECK(invalid_utf8_at("plain ascii") == std::string_view::npos);
  CHECK(invalid_utf8_at("caf\xC3\xA9 \xE2\x82\xAC \xF0\x9F\x8E\xBE") == std::string_view::npos);
  CHECK(invalid_utf8_at("a\xC0\xAF") == 1);         // overlong '/'
  CHECK(invalid_utf8_at("ab\xED\xA0\x80") == 2);    // a UTF-16 surrogate
  CHECK(invalid_utf8_at("\xF4\x90\x80\x80") == 0);  // beyond U+10FFFF
  CHECK(invalid_utf8_at("abc\xE2\x82") == 3);       // cut short
  CHECK(invalid_utf8_at("\xFF") == 0);
}

TEST_CASE("Text made valid UTF-8 replaces each stray byte and keeps the rest") {
  CHECK(valid_utf8("d\xFF.json") == "d\xEF\xBF\xBD.json");
  CHECK(valid_utf8("caf\xC3\xA9") == "caf\xC3\xA9");
  // What nlohmann refuses to write as a string, it now writes.
  CHECK_NOTHROW(Json(valid_utf8("bad\xC3(name")).dump());
}

TEST_CASE("The key map records the pointer and the value the file wrote") {
  const Json object = Json::parse(R"({"mass_g": 5e-324})");
  KeyMap keys;
  ObjectReader reader(object, "/hand", "hand", "d.json", &keys);
  CHECK(reader.quantity("mass", Dimension::kMass) == 0.0);  // 5e-327 kg underflows
  REQUIRE(keys.count("hand/mass_kg") == 1);
  CHECK(keys.at("hand/mass_kg").pointer == "/hand/mass_g");
  CHECK(keys.at("hand/mass_kg").given == "5e-324");
}

}  // namespace
}  // namespace sweetspot::io
