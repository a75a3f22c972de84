// `sweetspot compare A.json B.json [C.json ...]`: designs side by side, and
// what changes from the first to each of the others in words.

#include <iostream>
#include <vector>

#include "cli/checks.hpp"
#include "cli/commands.hpp"
#include "io/atomic_file.hpp"
#include "io/design_reader.hpp"
#include "io/input_error.hpp"
#include "io/json_reader.hpp"
#include "reports/comparison.hpp"
#include "studies/comparison.hpp"
#include "studies/design_settings.hpp"

namespace sweetspot::cli {

void CompareCommand::add_to(CLI::App& app) {
  command = app.add_subcommand(
      "compare",
      "Designs side by side (before and after lead tape, two racquets): the sweet spots, the "
      "wrist force and the rebound of each, and what changes from the first to the others in "
      "words");
  command
      ->add_option("designs", design_paths,
                   "Two or more design files (JSON; - for standard input, once), or one with "
                   "--set: the design against itself with the settings")
      ->required()
      ->expected(1, 64);
  add_set_option(command, settings);
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
  if (design_paths.size() == 1 && settings.empty()) {
    throw CLI::ValidationError(
        "designs: give two or more design files, or one with --set FIELD=VALUE to compare it "
        "with its variant");
  }
  OutputPlan plan;
  for (const std::string& path : design_paths) plan.read(path);
  if (html.empty() || !out.output.empty()) out.plan(plan);
  if (!html.empty()) plan.write("--html", html);
  std::vector<reports::ComparedDesign> designs;
  const std::string level = command->count("--fidelity") ? fidelity : std::string();
  // One design with settings is compared with its variant; several all take the settings.
  const std::vector<studies::Setting> set = studies::parse_settings(settings);
  if (design_paths.size() == 1) {
    // Read once: standard input cannot be read twice.
    const io::Json document = io::read_json_file(design_paths[0]);
    const std::string file = io::input_name(design_paths[0]);
    for (const std::vector<studies::Setting>& settings_of :
         {std::vector<studies::Setting>(), set}) {
      designs.push_back(studies::compare_one(studies::read_design(document, file, settings_of),
                                             level, tolerance, !html.empty()));
    }
  }
  for (std::size_t k = 0; design_paths.size() > 1 && k < design_paths.size(); ++k) {
    designs.push_back(studies::compare_one(studies::load_design(design_paths[k], set), level,
                                           tolerance, !html.empty()));
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
