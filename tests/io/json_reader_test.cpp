// The strict JSON layer: UTF-8 checks, the alternative spellings of a
// quantity that an override replaces, the key map that lets a core error
// quote the file's own key and value, and reading files within their limits.
#include "io/json_reader.hpp"

#include <unistd.h>

#include <algorithm>
#include <catch2/catch.hpp>
#include <chrono>
#include <cstdint>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <limits>
#include <random>
#include <stdexcept>
#include <string>
#include <vector>

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

TEST_CASE("A number is quoted as the shortest text that reads back to it") {
  CHECK(brief(-52.0) == "-52");
  CHECK(brief(0.1) == "0.1");
  CHECK(brief(0.17000000000000004) == "0.17000000000000004");  // every digit it has
  CHECK(brief(1e300) == "1e+300");
  CHECK(brief(std::numeric_limits<double>::infinity()) == "null");  // as JSON has it
  // A value of the file the same way: 1e9 not as JSON's 1000000000.0.
  CHECK(brief(Json::parse("1e9")) == "1000000000");
  CHECK(brief(Json::parse("2.5e-7")) == "2.5e-07");
  CHECK(brief(Json::parse("5.0")) == "5");
  CHECK(brief(Json::parse("5")) == "5");
  CHECK(brief(std::string("16x19")) == "\"16x19\"");
}

TEST_CASE("A known key that nothing read is not called unknown") {
  const Json object = Json::parse(R"({"mass_kg": 0.3, "spacing_m": 0.02})");
  ObjectReader r(object, "/strings", "strings", "d.json", nullptr);
  CHECK(r.number("mass_kg") == 0.3);
  try {
    r.finish({"mass_kg", "spacing_m"});
    FAIL("finish() passed a key nothing read");
  } catch (const InputError& e) {
    const std::string message = e.what();
    CHECK(message.find("/strings/spacing_m: is not read beside what else /strings gives") !=
          std::string::npos);
    CHECK(message.find("unknown") == std::string::npos);
  }
  // A key it does not know stays unknown.
  const Json typo = Json::parse(R"({"mass_kg": 0.3, "spacnig_m": 0.02})");
  ObjectReader t(typo, "/strings", "strings", "d.json", nullptr);
  t.number("mass_kg");
  CHECK_THROWS_WITH(t.finish({"mass_kg", "spacing_m"}), Catch::Contains("unknown key"));
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

TEST_CASE(
    "An override of a quantity the field table spells in keys of its own removes the others") {
  // The head's size in square inches or square centimetres; a swing's speed
  // in rad/s, rpm or as the racquet's speed at the impact point.
  Json design = Json::parse(R"({"implement": {"headsize_sq_in": 98},
                                "swing": {"angular_speed_rpm": 150, "pivot_beyond_butt_cm": 60}})");
  override_field(design, "/implement/headsize_cm2", 640);
  override_field(design, "/swing/angular_speed_rad_s", 15);
  CHECK(design == Json::parse(R"({"implement": {"headsize_cm2": 640},
                                  "swing": {"angular_speed_rad_s": 15, "pivot_beyond_butt_cm": 60}})"));
  override_field(design, "/swing/speed_at_impact_mph", 40);
  CHECK(design["swing"] ==
        Json::parse(R"({"speed_at_impact_mph": 40, "pivot_beyond_butt_cm": 60})"));
  override_field(design, "/swing/angular_speed_rpm", 100);
  CHECK(design["swing"] ==
        Json::parse(R"({"angular_speed_rpm": 100, "pivot_beyond_butt_cm": 60})"));
}

TEST_CASE(
    "An override of a lead's place replaces its other forms: from the butt, the tip, or the "
    "clock") {
  Json design = Json::parse(R"({"implement": {"point_masses": [
      {"mass_g": 2, "from_tip_cm": 10, "off_axis_cm": 3}, {"mass_g": 2, "clock": 12}]}})");
  // A clock places the piece on the hoop: its offset goes with its old place.
  override_field(design, "/implement/point_masses/0/clock", 3);
  CHECK(design["implement"]["point_masses"][0] == Json::parse(R"({"mass_g": 2, "clock": 3})"));
  override_field(design, "/implement/point_masses/1/from_butt_cm", 50);
  CHECK(design["implement"]["point_masses"][1] ==
        Json::parse(R"({"mass_g": 2, "from_butt_cm": 50})"));
  // An offset given keeps the place it is the offset of.
  override_field(design, "/implement/point_masses/1/off_axis_cm", 2);
  CHECK(design["implement"]["point_masses"][1] ==
        Json::parse(R"({"mass_g": 2, "from_butt_cm": 50, "off_axis_cm": 2})"));
}

TEST_CASE("An override sets an entry of a list or adds the next one, and no further") {
  // nlohmann::json fills a gap with nulls, which the reader would then blame.
  Json design = Json::parse(R"({"implement": {"point_masses": [{"mass_g": 4, "clock": 12}]}})");
  override_field(design, "/implement/point_masses/0/mass_g", 5);
  override_field(design, "/implement/point_masses/1/mass_g", 3);
  CHECK(design["implement"]["point_masses"] ==
        Json::parse(R"([{"mass_g": 5, "clock": 12}, {"mass_g": 3}])"));
  const Json before = design;
  try {
    override_field(design, "/implement/point_masses/3/mass_g", 3);
    FAIL("an entry two past the end was set");
  } catch (const PathError& e) {
    CHECK(e.pointer() == "/implement/point_masses/3");
    CHECK(e.detail() == "the list has 2 entries (0 to 1): set one of them, or add the next, 2");
  }
  CHECK(design == before);  // nothing half-set
  CHECK_THROWS_MATCHES(
      override_field(design, "/implement/point_masses/0x1/mass_g", 3), PathError,
      Catch::Matchers::Message("/implement/point_masses/0x1: a list's entry is named by its index, "
                               "a whole number from 0, got \"0x1\""));
  // A list the design does not have is empty: its entry 0 makes it, entry 1 is refused,
  // whether its object is there or not.
  for (const char* base : {R"({"implement": {"mass_kg": 0.3}})", R"({})"}) {
    Json bare = Json::parse(base);
    CHECK_THROWS_MATCHES(override_field(bare, "/implement/sections/1/length_m", 0.2), PathError,
                         Catch::Matchers::Message(
                             "/implement/sections/1: the list is empty: add its first entry, 0"));
    override_field(bare, "/implement/sections/0/length_m", 0.2);
    CHECK(bare["implement"]["sections"] == Json::parse(R"([{"length_m": 0.2}])"));
  }
}

TEST_CASE("The key map records the pointer and the value the file wrote") {
  const Json object = Json::parse(R"({"mass_g": 5e-324})");
  KeyMap keys;
  ObjectReader reader(object, "/hand", "hand", "d.json", &keys);
  CHECK(reader.quantity("mass", Dimension::kMass) == 0.0);  // 5e-327 kg underflows
  REQUIRE(keys.count("hand/mass_kg") == 1);
  CHECK(keys.at("hand/mass_kg").pointer == "/hand/mass_g");
  CHECK(given_text(keys.at("hand/mass_kg")) == "5e-324");
}

namespace fs = std::filesystem;

class Folder {
 public:
  Folder() : dir_(fs::temp_directory_path() / ("sweetspot-json-" + std::to_string(::getpid()))) {
    fs::create_directories(dir_);
  }
  ~Folder() { fs::remove_all(dir_); }
  std::string path(const std::string& name) const { return (dir_ / name).string(); }

 private:
  fs::path dir_;
};

constexpr std::size_t kSmallLimit = 1000;

TEST_CASE(
    "A file up to the limit is read whole, one byte more is refused naming the file and the "
    "limit") {
  const Folder folder;
  const std::string at_limit = folder.path("at-limit.json");
  std::ofstream(at_limit) << "{}" << std::string(kSmallLimit - 2, ' ');
  CHECK(read_input_file(at_limit, kSmallLimit).size() == kSmallLimit);
  const std::string over = folder.path("over.json");
  std::ofstream(over) << "{}" << std::string(kSmallLimit - 1, ' ');
  CHECK_THROWS_WITH(
      read_input_file(over, kSmallLimit),
      over + ": the file is larger than the limit of 1000 bytes for a design or study file");
  CHECK(read_input_file(over, std::size_t{1} << 20).size() == kSmallLimit + 1);
}

TEST_CASE("A device that never ends is read only up to the limit") {
  // /dev/zero reports size 0 and never ends: st_size cannot be trusted. Its
  // first chunk holds a NUL byte, so reading stops there and the parser says binary.
  const auto start = std::chrono::steady_clock::now();
  CHECK_THROWS_WITH(read_json_file("/dev/zero"),
                    Catch::Contains("/dev/zero") && Catch::Contains("binary"));
  CHECK_THROWS_WITH(read_json_file("/dev/urandom"), Catch::Contains("/dev/urandom"));
  CHECK(std::chrono::steady_clock::now() - start < std::chrono::seconds(2));
}

TEST_CASE("A directory is said to be one, not an empty file") {
  const Folder folder;
  CHECK_THROWS_AS(read_json_file(folder.path("")), InputError);
  CHECK_THROWS_WITH(read_json_file(folder.path("")), Catch::Contains("is a directory"));
}

TEST_CASE("A read error is a run-time error naming the file, never the end of the input") {
  // Reading /proc/self/mem at offset 0 (unmapped) fails with EIO.
  try {
    read_input_file("/proc/self/mem", kMaxInputFileBytes);
    FAIL("no error");
  } catch (const InputError& e) {
    FAIL("an input error: " << e.what());
  } catch (const std::runtime_error& e) {
    CHECK(std::string(e.what()) == "cannot read /proc/self/mem: Input/output error");
  }
}

TEST_CASE("A missing file is bad input with the system's reason") {
  const Folder folder;
  CHECK_THROWS_WITH(read_json_file(folder.path("nowhere.json")),
                    Catch::Contains("cannot open the file for reading: No such file or directory"));
}

TEST_CASE("The documented limit of a design or study file is 16 MiB") {
  CHECK(kMaxInputFileBytes == 16u * 1024 * 1024);
  CHECK(input_name("-") == "standard input");
  CHECK(input_name("d.json") == "d.json");
}

}  // namespace
}  // namespace sweetspot::io

namespace sweetspot::io {

TEST_CASE(
    "Every unit spelling that is a power of ten gives the correctly rounded SI value of the "
    "decimal the user wrote") {
  // The oracle: the decimal text with its exponent moved, read by the
  // correctly rounding std::strtod.
  const std::uint32_t seed = 20261201;
  INFO("seed " << seed);
  std::mt19937 random(seed);
  struct Spelling {
    const char* base;
    Dimension dimension;
  };
  const Spelling bases[] = {{"length", Dimension::kLength},
                            {"mass", Dimension::kMass},
                            {"impact_duration", Dimension::kTime},
                            {"swingweight", Dimension::kInertia}};
  std::size_t checked = 0;
  for (const Spelling& s : bases) {
    for (const std::string& key : spellings(s.base, s.dimension)) {
      const UnitScale scale = *unit_scale(key, s.base, s.dimension);
      if (scale.power_of_ten == 0) continue;  // 1 or not a power of ten: multiplied
      for (int i = 0; i < 2000; ++i) {
        // d.ddd...e<exp>, 1 to 15 significant digits.
        const int digits = 1 + static_cast<int>(random() % 15);
        std::string mantissa(1, static_cast<char>('1' + random() % 9));
        if (digits > 1) mantissa += '.';
        for (int k = 1; k < digits; ++k) mantissa += static_cast<char>('0' + random() % 10);
        const int exponent = static_cast<int>(random() % 13) - 6;
        const std::string text = mantissa + "e" + std::to_string(exponent);
        const std::string shifted = mantissa + "e" + std::to_string(exponent + scale.power_of_ten);
        const Json object = Json::parse("{\"" + key + "\": " + text + "}");
        ObjectReader r(object, "/x", "x", "test.json", nullptr);
        INFO(key << " = " << text);
        const double si = *r.quantity(s.base, s.dimension);
        CHECK(si == std::strtod(shifted.c_str(), nullptr));
        ++checked;
      }
    }
  }
  CHECK(checked == 5 * 2000);  // _cm, _mm, _g, _ms, _kg_cm2
  // The README's example, exactly.
  CHECK(UnitScale{0.001, -3}.to_si(282) == 0.282);
  CHECK(UnitScale{0.001, -3}.to_si(282) != 282 * 0.001);
}

}  // namespace sweetspot::io
