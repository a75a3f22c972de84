#include "io/input_error.hpp"

#include <exception>
#include <utility>

#include "sweetspot/invariants.hpp"

namespace sweetspot::io {
namespace {
std::string compose(const std::string& source, const std::string& pointer,
                    const std::string& detail) {
  std::string text = one_line(source);
  if (!pointer.empty()) text += ": " + one_line(pointer);
  return text + ": " + one_line(detail);
}
}  // namespace

std::string one_line(std::string_view text) {
  std::string out;
  out.reserve(text.size());
  for (const char c : text) {
    const auto byte = static_cast<unsigned char>(c);
    if (byte >= 0x20 && byte != 0x7f) {
      out += c;
    } else if (c == '\n') {
      out += "\\n";
    } else if (c == '\r') {
      out += "\\r";
    } else if (c == '\t') {
      out += "\\t";
    } else {
      constexpr char kHex[] = "0123456789abcdef";
      out += "\\x";
      out += kHex[byte >> 4];
      out += kHex[byte & 0xf];
    }
  }
  return out;
}

InputError::InputError(std::string source, std::string pointer, std::string detail)
    : std::runtime_error(compose(source, pointer, detail)),
      source_(std::move(source)),
      pointer_(std::move(pointer)),
      detail_(std::move(detail)) {}

bool InputError::shape_fault() const {
  return detail_.starts_with("unknown key") || detail_.starts_with(kAnotherFormsKey) ||
         detail_.starts_with("expected a JSON object") || detail_.starts_with("expected an array");
}

bool InputError::model_refused() const {
  if (!nested_ptr()) return false;
  try {
    std::rethrow_exception(nested_ptr());
  } catch (const ModelRefusal&) {
    return true;
  } catch (const InputError& inner) {
    return inner.model_refused();
  } catch (...) {
    return false;
  }
}

ReadError::ReadError(const std::string& source, const std::string& detail)
    : std::runtime_error(compose(source, "", detail)) {}

}  // namespace sweetspot::io
