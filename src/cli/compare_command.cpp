// `sweetspot compare A.json B.json [C.json ...]`: designs side by side, and
// what changes from the first to each of the others in words.

#include <iostream>
#include <vector>

#include "cli/checks.hpp"
#include "cli/commands.hpp"
#include "io/atomic_file.hpp"
#include "io/design_reader.hpp"
#include "io/input_error.hpp"
#include "reports/comparison.hpp"

namespace sweetspot::cli {

void CompareCommand::add_to(CLI::App& app) {
  command = app.add_subcommand(
      "compare",
      "Designs side by side (before and after lead tape, two racquets): the sweet spots, the "
      "wrist force and the rebound of each, and what changes from the first to the others in "
      "words");
  command
      ->add_option("designs", design_paths,
                   "Two or more design files (JSON; - for standard input, once)")
      ->required()
      ->expected(2, 64);
  command
      ->add_option("--fidelity", fidelity,
                   "rigid, modal, response, collision or auto (each file's own, else the "
                   "cheapest that answers it)")
      ->check(fidelity_name())
      ->capture_default_str();
  command->add_option("--tol", tolerance, "Relative error allowed in the hand-held frequency")
      ->check(finite_in(kMinRelTol, kMaxRelTol))
      ->capture_default_str();
  out.add_to(command);
  command->add_option("--html", html,
                      "Also write the comparison as one self-contained web page (a phone or a "
                      "desktop browser opens it; no network needed); standard output then says "
                      "only what was written, the text report going to --output when given");
  command->footer(
      "Examples:\n"
      "  sweetspot compare racquet.json racquet-with-lead.json\n"
      "  sweetspot compare racquet.json racquet-with-lead.json --html compared.html\n"
      "  sweetspot compare a.json b.json c.json --format csv -o compared.csv");
}

int CompareCommand::run() const {
  require_distinct_outputs(html, out.output);
  int stdin_uses = 0;
  for (const std::string& path : design_paths) stdin_uses += path == "-";
  if (stdin_uses > 1)
    throw CLI::ValidationError("designs: standard input (-) can be read only once");
  std::vector<reports::ComparedDesign> designs;
  const std::string level = command->count("--fidelity") ? fidelity : std::string();
  for (const std::string& path : design_paths) {
    designs.push_back(reports::compare_one(io::load_design(path), level, tolerance));
  }
  if (html.empty()) {
    out.emit(reports::comparison_report(designs, out.parsed()));
    return kExitOk;
  }
  if (!out.output.empty()) out.emit(reports::comparison_report(designs, out.parsed()));
  io::write_file_atomically(html, reports::comparison_html(designs));
  std::cout << "wrote " << io::one_line(html) << "\n";
  return kExitOk;
}

}  // namespace sweetspot::cli
