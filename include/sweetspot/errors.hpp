#pragma once

// The core's refusal of an input, as a type: which field of the design it
// names (a path relative to the design, as the design file's SI keys spell
// it: "frame/EI_N_m2", "point_masses/1/mass_kg", "hand/grip_length_m") and
// what is wrong with it ("must be > 0 N m^2, got -3 N m^2"). what() is
// "field: detail". The layer that read the design maps the field to the
// file's own key (its unit, its JSON pointer) by lookup, never by reading
// the message.

#include <optional>
#include <stdexcept>
#include <string>

namespace sweetspot {

class FieldError : public std::invalid_argument {
 public:
  // The range a value broke, in the SI unit of its field, so the layer that
  // read it can state the range again in the file's own unit.
  struct Range {
    double min = 0.0;       // -inf when there is no lower bound
    double max = 0.0;       // +inf when there is no upper bound
    bool min_open = false;  // "> min" rather than ">= min"
    double value = 0.0;     // the value refused, in SI
    const char* why = "";   // what sets the range, said after it ("for this mass, ...")
    bool max_open = false;  // "< max" rather than "<= max"
  };

  // `after` ends the detail and is said again after a range restated in
  // another unit (": it would fit a mass of 0.19 to 0.63 kg ...").
  FieldError(std::string field, std::string detail, std::optional<Range> range = std::nullopt,
             std::string after = {})
      : std::invalid_argument(field + ": " + detail + after),
        field_(std::move(field)),
        detail_(detail + after),
        range_(range),
        after_(std::move(after)) {}

  const std::string& field() const { return field_; }
  const std::string& detail() const { return detail_; }
  const std::optional<Range>& range() const { return range_; }
  const std::string& after() const { return after_; }

 private:
  std::string field_;
  std::string detail_;
  std::optional<Range> range_;
  std::string after_;
};

// `error` with its field placed under `part` ("frame/" + "cor": "frame/cor"):
// a FieldError keeps its type, any other message is prefixed as text.
[[noreturn]] inline void rethrow_under(const std::string& part,
                                       const std::invalid_argument& error) {
  if (const auto* field = dynamic_cast<const FieldError*>(&error))
    throw FieldError(part + field->field(),
                     field->detail().substr(0, field->detail().size() - field->after().size()),
                     field->range(), field->after());
  throw std::invalid_argument(part + error.what());
}

}  // namespace sweetspot
