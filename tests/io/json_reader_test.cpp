// The strict JSON layer: UTF-8 checks, the alternative spellings of a
// quantity that an override replaces, and the key map that lets a core error
// quote the file's own key and value.
#include "io/json_reader.hpp"

#include <algorithm>
#include <string>
#include <vector>

#include <catch2/catch.hpp>

#include "io/input_error.hpp"

namespace sweetspot::io {
namespace {

bool lists(const std::vector<std::string>& keys, const std::string& key) {
  return std::find(keys.begin(), keys.end(), key) != keys.end();
}

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

TEST_CASE("A quantity's alternative spellings cover its units and its other forms") {
  CHECK(lists(alternative_spellings("mass_g"), "mass_kg"));
  CHECK(lists(alternative_spellings("tension_lb"), "tension_N"));
  CHECK(lists(alternative_spellings("tension_lb"), "impact_duration_s"));
  CHECK(lists(alternative_spellings("impact_duration_ms"), "tension_kg"));
  CHECK(lists(alternative_spellings("cor_rigid"), "cor"));
  CHECK(lists(alternative_spellings("cor"), "cor_rigid"));
  CHECK_FALSE(lists(alternative_spellings("mass_g"), "mass_g"));
}

TEST_CASE("An override of one form of a quantity removes the others beside it") {
  Json design = Json::parse(R"({"frame": {"cor": 0.8}, "strings": {"impact_duration_ms": 4}})");
  override_field(design, "/frame/cor_rigid", 0.85);
  override_field(design, "/strings/tension_N", 250.0);
  CHECK(design ==
        Json::parse(R"({"frame": {"cor_rigid": 0.85}, "strings": {"tension_N": 250.0}})"));
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
