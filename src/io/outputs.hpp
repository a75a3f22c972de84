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
  std::optional<double> (*compute)(const Evaluation&);
  std::string_view when_absent;  // why the value can be null ("" if never)
  bool kinked = false;           // has a kink (an absolute value): not smooth everywhere
  bool needs_modes = false;      // only a modal evaluation (Fidelity::kModal) gives it
  bool needs_response = false;   // only the response model (Fidelity::kResponse) gives it

  // The value for `e`, absent where the evaluation has none: compute()'s,
  // and on a rig (Evaluation::support) absent unless a rig gives it
  // (given_on_rig()), the effective mass of an impact point held still
  // (infinite) included.
  std::optional<double> value(const Evaluation& e) const;
  // Why value(e) is absent: on a rig kAbsentOnRig (or, for an impact point
  // held still, kHeldStill), else when_absent.
  std::string_view absent_because(const Evaluation& e) const;
};

// Whether `output` is the string bed's (its tension, stiffness, ring, the
// strings' deflection).
bool of_the_string_bed(const OutputSpec& output);

// Whether a design can have a string bed at all: not a round implement given
// by its profile (a bat) without head or strings, whose tables for people
// leave the string bed's outputs out rather than ask for strings.
bool can_be_strung(const Design& design);

// Whether an evaluation on a rig of `kind` gives the output `name`: the
// ball's impact on the rig and the implement's own numbers (none of them on
// a rigid surface), nothing of the player (hand, forearm, swing, centres of
// percussion, twist).
bool given_on_rig(std::string_view name, Support::Kind kind);
// The names given_on_rig() refuses on every rig (the player's), and the only
// ones it gives on a rigid surface (the ball's).
std::span<const std::string_view> player_outputs();
std::span<const std::string_view> ball_outputs();

// Why an output is absent on a rig (for the documentation and the reports).
inline constexpr std::string_view kAbsentOnRig =
    "absent on a rig (support head_clamped, handle_clamped, pivot or rigid_surface): no player, "
    "and on a rigid surface no implement";
inline constexpr std::string_view kHeldStill = "infinite: the rig holds the impact point still";

// Every output, in report order.
std::span<const OutputSpec> output_specs();

// The output called `name`, or nullptr.
const OutputSpec* find_output(std::string_view name);

}  // namespace sweetspot::io
