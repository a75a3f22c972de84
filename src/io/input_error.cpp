#include "io/input_error.hpp"

#include <utility>

namespace sweetspot::io {
namespace {
std::string compose(const std::string& source, const std::string& pointer,
                    const std::string& detail) {
  std::string text = source;
  if (!pointer.empty()) text += ": " + pointer;
  return text + ": " + detail;
}
}  // namespace

InputError::InputError(std::string source, std::string pointer, std::string detail)
    : std::runtime_error(compose(source, pointer, detail)),
      source_(std::move(source)),
      pointer_(std::move(pointer)),
      detail_(std::move(detail)) {}

}  // namespace sweetspot::io
