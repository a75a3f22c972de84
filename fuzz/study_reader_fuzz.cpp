// libFuzzer target: arbitrary bytes through the path a study file takes,
// parse_json -> read_study (which reads the design it names, checks every
// variable, objective and constraint, and evaluates the starting design).
//
// The contract under test (docs/studies.md, STYLE.md rule 5): bad input is
// refused with sweetspot::io::InputError naming the study (or the design it
// names) or std::invalid_argument from the physics core; anything else
// escaping, a crash, a sanitizer report, a hang or unbounded memory is a bug.
//
// A "design" given as a path is read relative to the shipped studies' folder
// (SWEETSPOT_FUZZ_STUDY_DIR), so that mutations of the shipped studies keep
// reaching their designs. Optimizations and sweeps are not run: their cost is
// the study's budget, not the reader's.
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

#include "input_layer.hpp"

#ifndef SWEETSPOT_FUZZ_STUDY_DIR
#define SWEETSPOT_FUZZ_STUDY_DIR "."
#endif

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string_view text(reinterpret_cast<const char*>(data), size);
  const std::string source = "fuzz-study.json";
  try {
    const sweetspot::io::Json document = sweetspot::io::parse_json(text, source);
    const sweetspot::studies::Study study =
        sweetspot::studies::read_study(document, source, SWEETSPOT_FUZZ_STUDY_DIR);
    // Every accepted study has a valid start: its objective is a number.
    std::vector<double> start;
    for (const sweetspot::studies::StudyVariable& v : study.variables) start.push_back(v.start);
    const sweetspot::io::DesignFile design = sweetspot::studies::design_at(study, start);
    (void)sweetspot::studies::objective_of(study, design);
  } catch (const sweetspot::io::InputError& refused) {
    // Refused with a source: the study, or the design file it names.
    if (std::string_view(refused.what()).empty()) std::abort();
  } catch (const std::invalid_argument&) {
    // A core refusal (a design the start makes invalid).
  }
  return 0;
}
