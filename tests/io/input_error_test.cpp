// An input error is one line whatever the file is called or holds.
#include "io/input_error.hpp"

#include <algorithm>
#include <catch2/catch.hpp>
#include <stdexcept>
#include <string>

#include "sweetspot/invariants.hpp"

namespace sweetspot::io {
namespace {

TEST_CASE(
    "Control characters in a file name, pointer or detail are escaped, so a message is one line") {
  const InputError error("a\nb\r\x01.json", "/x\ty", "bad\n value");
  const std::string what = error.what();
  CHECK(what == "a\\nb\\r\\x01.json: /x\\ty: bad\\n value");
  CHECK(std::count(what.begin(), what.end(), '\n') == 0);
  // The parts stay as given, for code that reads them.
  CHECK(error.source() == "a\nb\r\x01.json");
}

TEST_CASE("Text that is printable, UTF-8 included, is left as it is") {
  CHECK(one_line("caf\xC3\xA9 racquet.json") == "caf\xC3\xA9 racquet.json");
  CHECK(one_line("\x7f") == "\\x7f");
  CHECK(InputError("d.json", "", "missing").what() == std::string("d.json: missing"));
}

TEST_CASE("A read error is one line naming the file") {
  const ReadError error("line\nbreak.csv", "cannot read line 3: Input/output error");
  CHECK(std::string(error.what()) == "line\\nbreak.csv: cannot read line 3: Input/output error");
}

}  // namespace
}  // namespace sweetspot::io

namespace sweetspot::io {
namespace {

// The command line's exit status 3 (a model that cannot answer) against 2 (bad
// input) survives the JSON layer's rethrow at the file's key.
TEST_CASE("An input error made while handling a model's refusal says so, any other does not") {
  const auto rethrown = [](auto&& core_error) {
    try {
      try {
        throw core_error;
      } catch (const std::invalid_argument&) {
        throw InputError("d.json", "/ball/speed_m_s", "the model cannot answer");
      }
    } catch (const InputError& e) {
      return e.model_refused();
    }
    return false;
  };
  CHECK(rethrown(ModelRefusal("ball/speed_m_s", 1e-9, "the model cannot answer")));
  CHECK_FALSE(rethrown(std::invalid_argument("ball/speed_m_s: must be > 0 m/s, got 0")));
  CHECK_FALSE(InputError("d.json", "/ball", "missing").model_refused());
}

}  // namespace
}  // namespace sweetspot::io
