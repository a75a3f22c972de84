#pragma once

// The named outputs of `evaluate`: one table that the JSON, CSV and Markdown
// writers, the reports and the optimizer's objectives all read, so a name
// means the same thing everywhere. Values are in the unit the name says.

#include <optional>
#include <span>
#include <string_view>

#include "sweetspot/evaluate.hpp"

namespace sweetspot::io {

struct OutputSpec {
  std::string_view name;         // e.g. "peak_wrist_force_N"
  std::string_view unit;         // e.g. "N" ("" when dimensionless)
  std::string_view description;  // one line, citing the paper's equation
  std::optional<double> (*value)(const Evaluation&);
  std::string_view when_absent;  // why the value can be null ("" if never)
  bool kinked = false;           // has a kink (an absolute value): not smooth everywhere
  bool needs_modes = false;      // only a modal evaluation (Fidelity::kModal) gives it
  bool needs_response = false;   // only the response model (Fidelity::kResponse) gives it
};

// Every output, in report order.
std::span<const OutputSpec> output_specs();

// The output called `name`, or nullptr.
const OutputSpec* find_output(std::string_view name);

}  // namespace sweetspot::io
