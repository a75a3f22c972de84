#pragma once

// The errors of the input layer: which file, where in it (a JSON pointer, ""
// for the document or a position), what was wrong. Their messages are one
// line whatever the file name or the input hold: control characters are
// written as escapes (a newline in a file name prints as "\n").

#include <exception>
#include <stdexcept>
#include <string>
#include <string_view>

namespace sweetspot::io {

// Bad input (exit status 2): a file that is not what it should be. Made while
// handling a core error (the JSON layer rethrowing it at the file's key), it
// keeps that error as its nested exception (std::nested_exception), so that a
// ModelRefusal (exit status 3) is still one where its key is named.
class InputError : public std::runtime_error, public std::nested_exception {
 public:
  // what() is "SOURCE: POINTER: DETAIL" (POINTER omitted when empty), with
  // control characters escaped.
  InputError(std::string source, std::string pointer, std::string detail);

  // Whether the error it rethrows is the core's refusal to answer
  // (sweetspot::ModelRefusal): the input is in range, the model cannot answer.
  bool model_refused() const;

  const std::string& source() const { return source_; }
  const std::string& pointer() const { return pointer_; }
  const std::string& detail() const { return detail_; }
  // Whether the design cannot hold the value at its pointer at all (a key the
  // object does not know, or knows only in another form of it; a number where
  // it has an object or a list): a catalogue column's fault, not its row's.
  bool shape_fault() const;

 private:
  std::string source_;
  std::string pointer_;
  std::string detail_;
};

// How the detail of a key of another form of its object begins ("balance_cm"
// beside an implement's sections): InputError::shape_fault() knows it.
inline constexpr std::string_view kAnotherFormsKey = "belongs to another way of giving";

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
