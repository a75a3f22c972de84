// libFuzzer target: arbitrary bytes through the whole input path a user's file
// takes, parse_json -> read_design -> evaluate.
//
// The contract under test (docs/design-files.md, STYLE.md rule 5): bad input
// is refused with sweetspot::io::InputError (the JSON layer) or
// std::invalid_argument (the physics core); anything else escaping, a crash,
// a sanitizer report or a hang is a bug. Only those two exceptions are caught
// here, so any other one reaches std::terminate and libFuzzer reports it.
//
// With SWEETSPOT_FUZZ_REQUIRE_FINITE=1 in the environment an accepted design
// must also evaluate to finite numbers (docs/command-line.md promises "never NaN"); a
// non-finite output aborts with the offending field on stderr. Off by default
// while the overflow defects of evaluate() are open.
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <optional>
#include <stdexcept>
#include <string>
#include <string_view>

#include "input_layer.hpp"

namespace {

bool g_require_finite = false;

void require_finite(const char* name, double value) {
  if (std::isfinite(value)) return;
  std::fprintf(stderr, "design_reader_fuzz: accepted design evaluates %s = %g\n", name, value);
  std::abort();
}

void require_finite(const char* name, const std::optional<double>& value) {
  if (value) require_finite(name, *value);
}

void check_finite(const sweetspot::Evaluation& e) {
#define SWEETSPOT_FUZZ_FINITE(field) require_finite(#field, e.field)
  SWEETSPOT_FUZZ_FINITE(length_m);
  SWEETSPOT_FUZZ_FINITE(mass_kg);
  SWEETSPOT_FUZZ_FINITE(balance_from_butt_m);
  SWEETSPOT_FUZZ_FINITE(I_cm_kg_m2);
  SWEETSPOT_FUZZ_FINITE(swingweight_kg_m2);
  SWEETSPOT_FUZZ_FINITE(impact_from_butt_m);
  SWEETSPOT_FUZZ_FINITE(impact_from_com_m);
  SWEETSPOT_FUZZ_FINITE(cop_free_from_butt_m);
  SWEETSPOT_FUZZ_FINITE(rotation_axis_free_from_butt_m);
  SWEETSPOT_FUZZ_FINITE(effective_mass_kg);
  SWEETSPOT_FUZZ_FINITE(apparent_cor);
  SWEETSPOT_FUZZ_FINITE(rebound_speed_m_s);
  SWEETSPOT_FUZZ_FINITE(impulse_N_s);
  SWEETSPOT_FUZZ_FINITE(peak_impact_force_N);
  SWEETSPOT_FUZZ_FINITE(system_mass_kg);
  SWEETSPOT_FUZZ_FINITE(system_com_from_butt_m);
  SWEETSPOT_FUZZ_FINITE(system_I_cm_kg_m2);
  SWEETSPOT_FUZZ_FINITE(cop_hand_from_butt_m);
  SWEETSPOT_FUZZ_FINITE(rotation_axis_hand_from_butt_m);
  SWEETSPOT_FUZZ_FINITE(wrist_force_ratio);
  SWEETSPOT_FUZZ_FINITE(peak_wrist_force_N);
#undef SWEETSPOT_FUZZ_FINITE
}

}  // namespace

extern "C" int LLVMFuzzerInitialize(int*, char***) {
  const char* flag = std::getenv("SWEETSPOT_FUZZ_REQUIRE_FINITE");
  g_require_finite = flag != nullptr && std::strcmp(flag, "1") == 0;
  return 0;
}

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string_view text(reinterpret_cast<const char*>(data), size);
  const std::string source = "fuzz.json";
  try {
    const sweetspot::io::Json document = sweetspot::io::parse_json(text, source);
    const sweetspot::io::DesignFile file = sweetspot::io::read_design(document, source);
    const sweetspot::Evaluation evaluation = sweetspot::evaluate(file.design);
    if (g_require_finite) check_finite(evaluation);
  } catch (const sweetspot::io::InputError& refused) {
    // Refused with its source and JSON pointer: what() must say where.
    if (std::string_view(refused.what()).substr(0, source.size()) != source) std::abort();
  } catch (const std::invalid_argument&) {
    // A core refusal that evaluate() raised for a design read_design() accepted.
  }
  return 0;
}
