// The table of named outputs: one name, one unit, one meaning, used by every
// writer, report and objective.
#include "io/outputs.hpp"

#include <catch2/catch.hpp>
#include <set>
#include <string>

namespace sweetspot::io {
namespace {

TEST_CASE("Output names are unique, found by name, and carry their SI unit in the name") {
  std::set<std::string_view> names;
  for (const OutputSpec& output : output_specs()) {
    CHECK(names.insert(output.name).second);
    CHECK(find_output(output.name) == &output);
    CHECK_FALSE(output.description.empty());
    REQUIRE(output.value != nullptr);
    // "_N" names are in N, "_m" in m, "_Hz" in Hz: the unit is the name's suffix.
    if (!output.unit.empty() && output.unit.find(' ') == std::string_view::npos &&
        output.unit.find('/') == std::string_view::npos) {
      const std::string suffix = "_" + std::string(output.unit);
      CHECK(std::string(output.name).ends_with(suffix));
    }
  }
  CHECK(find_output("no_such_output") == nullptr);
}

TEST_CASE("Outputs that need the modes are absent from a rigid evaluation, the rest present") {
  const Evaluation e = evaluate(Design{Implement::paper_racquet(0.70, 0.25, 0.8)});
  for (const OutputSpec& output : output_specs()) {
    if (output.needs_modes || output.needs_response) {
      CHECK_FALSE(output.value(e).has_value());
    } else if (output.when_absent.empty()) {
      CHECK(output.value(e).has_value());
    }
  }
  CHECK(find_output("peak_wrist_force_N")->value(e).value() ==
        Approx(568).margin(0.5));  // Table I, row 1
}

}  // namespace
}  // namespace sweetspot::io
