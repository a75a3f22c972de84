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
#include "studies/comparison.hpp"

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
  add_output_option(command, "--html", html,
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
  int stdin_uses = 0;
  for (const std::string& path : design_paths) stdin_uses += path == "-";
  if (stdin_uses > 1)
    throw CLI::ValidationError("designs: standard input (-) can be read only once");
  if (!html.empty() && out.output.empty() && command->count("--format")) {
    throw CLI::ValidationError(
        "--format: with --html, only with --output FILE (standard output then says only what "
        "was written)");
  }
  OutputPlan plan;
  for (const std::string& path : design_paths) plan.read(path);
  if (html.empty() || !out.output.empty()) out.plan(plan);
  if (!html.empty()) plan.write("--html", html);
  std::vector<reports::ComparedDesign> designs;
  const std::string level = command->count("--fidelity") ? fidelity : std::string();
  for (const std::string& path : design_paths) {
    designs.push_back(studies::compare_one(io::load_design(path), level, tolerance, !html.empty()));
  }
  io::OutputSet outputs;
  if (html.empty() || !out.output.empty())
    out.emit(reports::comparison_report(designs, out.parsed()), outputs);
  if (!html.empty()) outputs.write(html, reports::comparison_html(designs));
  outputs.commit();
  if (!html.empty()) say_written(html);
  return kExitOk;
}

}  // namespace sweetspot::cli
