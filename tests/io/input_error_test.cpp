// An input error is one line whatever the file is called or holds.
#include "io/input_error.hpp"

#include <algorithm>
#include <catch2/catch.hpp>
#include <string>

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
