#pragma once

// The one error type of the input layer: which file, where in it (a JSON
// pointer, "" for the document or a position), what was wrong.

#include <stdexcept>
#include <string>

namespace sweetspot::io {

class InputError : public std::runtime_error {
 public:
  // what() is "SOURCE: POINTER: DETAIL" (POINTER omitted when empty).
  InputError(std::string source, std::string pointer, std::string detail);

  const std::string& source() const { return source_; }
  const std::string& pointer() const { return pointer_; }
  const std::string& detail() const { return detail_; }

 private:
  std::string source_;
  std::string pointer_;
  std::string detail_;
};

}  // namespace sweetspot::io
