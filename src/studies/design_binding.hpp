#pragma once

// Study variables, sweep axes and batch columns compiled once: each JSON
// pointer becomes a typed binding (the key's unit factor and a setter on the
// design's description), so that a point is evaluated from a typed copy of
// the design instead of writing the number into a copy of the JSON document
// and reading it all again. The JSON path stays the reference: a pointer that
// cannot be bound is not compiled, and a point the binding cannot vouch for
// (any value the reader or the core would refuse) is left to the JSON path,
// which says what is wrong with the same message as ever.

#include <cstddef>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "io/design_description.hpp"
#include "io/json_reader.hpp"

namespace sweetspot::studies {

struct FieldBinding {
  std::string pointer;  // as the study or the header wrote it, e.g. "/hand/mass_g"
  io::UnitScale scale;  // the key's unit to SI (mass_g: 10^-3), as the reader converts
  // Writes the SI value into the description (`index`: the section, or the
  // entry of the file's list of point masses).
  void (*set)(io::DesignDescription&, std::size_t index, double si) = nullptr;
  std::size_t index = 0;
  bool implement = false;  // the implement is rebuilt when the value changes
  // The field of the design's field table the pointer sets (object, stem).
  std::string_view object, stem;
};

// The binding of `pointer` in a design read as `description`, or std::nullopt
// when the pointer names no number of that design that a binding can set (a
// published value, a name, a key of another form of the implement).
std::optional<FieldBinding> bind_field(const io::DesignDescription& description,
                                       std::string_view pointer);

// The fields of the design's field table (object, stem) that a binding can
// set, one row per setter (a field with two setters appears twice).
std::vector<std::pair<std::string_view, std::string_view>> bindable_fields();

// A design read once, with some of its numbers bound to JSON pointers.
class CompiledDesign {
 public:
  // std::nullopt when any pointer cannot be bound.
  static std::optional<CompiledDesign> compile(io::DesignDescription description,
                                               std::span<const std::string> pointers);

  const io::DesignDescription& description() const { return description_; }
  const std::vector<FieldBinding>& bindings() const { return bindings_; }
  bool rebuilds_implement() const { return rebuilds_implement_; }

 private:
  explicit CompiledDesign(io::DesignDescription description)
      : description_(std::move(description)) {}
  io::DesignDescription description_;
  std::vector<FieldBinding> bindings_;
  bool rebuilds_implement_ = false;
};

// One thread's working copy of a compiled design. Not thread-safe; cheap to
// make (one copy of the design).
class BoundDesign {
 public:
  explicit BoundDesign(const CompiledDesign& compiled);

  // The design with values[i] (in the unit of binding i's key) at binding i,
  // bit for bit the design read_design() reads from the file with those
  // values written at the pointers; the implement is rebuilt only when one of
  // its numbers changed since the last point. nullptr when the reader or the
  // core would refuse the point: read the file for the message. The design
  // stays valid until the next call.
  const Design* at(std::span<const double> values);

 private:
  const CompiledDesign* compiled_;
  io::DesignDescription live_;
  std::vector<double> last_si_;  // the implement bindings' values at the last build
  bool implement_built_ = false;
};

}  // namespace sweetspot::studies
