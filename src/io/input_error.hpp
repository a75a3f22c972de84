#pragma once

// The errors of the input layer: which file, where in it (a JSON pointer, ""
// for the document or a position), what was wrong. Their messages are one
// line whatever the file name or the input hold: control characters are
// written as escapes (a newline in a file name prints as "\n").

#include <stdexcept>
#include <string>
#include <string_view>

namespace sweetspot::io {

// Bad input (exit status 2): a file that is not what it should be.
class InputError : public std::runtime_error {
 public:
  // what() is "SOURCE: POINTER: DETAIL" (POINTER omitted when empty), with
  // control characters escaped.
  InputError(std::string source, std::string pointer, std::string detail);

  const std::string& source() const { return source_; }
  const std::string& pointer() const { return pointer_; }
  const std::string& detail() const { return detail_; }

 private:
  std::string source_;
  std::string pointer_;
  std::string detail_;
};

// A file that could not be read to its end (exit status 1: not the input's
// fault). what() is "SOURCE: DETAIL", one line as for InputError.
class ReadError : public std::runtime_error {
 public:
  ReadError(const std::string& source, const std::string& detail);
};

// `text` on one line: \n, \r and \t as those escapes, every other control
// character (below U+0020, and DEL) as \xHH; everything else as it is.
std::string one_line(std::string_view text);

}  // namespace sweetspot::io
