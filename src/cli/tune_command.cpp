// `sweetspot tune DESIGN --target ... --places ...`: the lead, and where, that
// brings a racquet to target specs; `sweetspot tune --match A B ...`: a set of
// racquets brought to common specs.

#include <filesystem>
#include <iostream>
#include <set>
#include <string>
#include <vector>

#include "cli/checks.hpp"
#include "cli/commands.hpp"
#include "io/atomic_file.hpp"
#include "io/design_reader.hpp"
#include "io/input_error.hpp"
#include "io/json_reader.hpp"
#include "reports/tune_report.hpp"
#include "studies/comparison.hpp"
#include "studies/design_settings.hpp"
#include "studies/tune.hpp"

namespace sweetspot::cli {
namespace {

// A design read once (standard input can be read only once).
struct ReadDesign {
  io::Json document;
  io::DesignFile file;
};

// With --set, the document is the variant's: the tuned file holds the settings too.
ReadDesign read(const std::string& path, const std::vector<studies::Setting>& settings) {
  io::Json document = io::read_json_file(path);
  io::DesignFile file = studies::read_design(document, io::input_name(path), settings);
  studies::apply_settings(document, settings);
  return {std::move(document), std::move(file)};
}

// A study's complaint about a command-line value as the option's error.
template <typename F>
auto as_option_error(const std::string& option, F f) {
  try {
    return f();
  } catch (const std::invalid_argument& error) {
    throw CLI::ValidationError(option, error.what());
  }
}

// The tuned racquet, evaluated beside the original (the file's own
// fidelity, as `compare` does).
reports::TunedRacquet evaluate_tuned(const ReadDesign& original, const studies::TuneResult& result,
                                     const io::Json& tuned, const std::string& written,
                                     double tolerance) {
  const std::string name =
      written.empty() ? original.file.source + " (tuned)" : io::input_name(written);
  studies::TuneEvaluations evaluations =
      studies::evaluate_tune(original.file, tuned, name, tolerance);
  return {result, std::move(evaluations.before), std::move(evaluations.after), written};
}

}  // namespace

void TuneCommand::add_to(CLI::App& app) {
  command = app.add_subcommand(
      "tune",
      "The lead tape, and where, that brings a racquet to target specs (mass, balance, "
      "swingweight, twistweight, or another racquet's), the least that reaches them, or the "
      "nearest specs lead can give and why; --match brings a set of racquets to common specs");
  command
      ->add_option("designs", design_paths,
                   "The design file to tune (JSON; - for standard input), or with --match two or "
                   "more")
      ->required()
      ->expected(1, 64);
  add_set_option(command, settings);
  command->add_option(
      "--target", target,
      "The specs to reach, NAME=VALUE separated by commas: mass_g (or mass_kg), "
      "balance_cm (or balance_from_butt_m, from the butt, or balance_pts_hl), swingweight_kg_cm2, "
      "twistweight_kg_cm2");
  command->add_option("--like", like,
                      "Reach the mass, balance and swingweight of this other racquet (a design "
                      "file); --target given as well wins for the specs it names");
  command
      ->add_option("--places", places,
                   "Where lead may go, separated by commas: clock hours on the hoop (12, 10.5; "
                   "a pair 3/9 takes half the lead at each), throat (6 o'clock), grip (under "
                   "the grip, 9 cm from the butt), butt or handle (under the butt cap, 2 cm "
                   "from the butt, as a design file's clock \"handle\")")
      ->required();
  command->add_flag("--match", match,
                    "Bring the designs to common specs: the mass, balance and swingweight every "
                    "one reaches with the least lead in all (the least common mass)");
  command
      ->add_option("--strip-g", strip_g,
                   "The strip of lead tape the lead is counted in [g] (default: 1 g, about 10 "
                   "cm of 1/4-inch tape)")
      ->check(finite_in(0.01, 100.0))
      ->capture_default_str();
  command->add_option("--tol", tolerance, "Relative error allowed in the hand-held frequency")
      ->check(finite_in(kMinRelTol, kMaxRelTol))
      ->capture_default_str();
  command->add_option("--format", format, "Format of the report on standard output")
      ->check(CLI::IsMember({"md", "json"}))
      ->capture_default_str();
  add_output_option(command, "--output,-o", output,
                    "Write the tuned racquet to FILE as a design file (the original with the "
                    "lead added as point masses), which evaluate reads; not written when the "
                    "targets cannot be reached");
  add_output_folder_option(command, "--output-dir", output_dir,
                           "With --match: write each tuned racquet into DIR as NAME-tuned.json "
                           "(NAME the design file's name without .json)");
  command->footer(
      "Examples:\n"
      "  sweetspot tune racquet.json --target mass_g=330,balance_cm=32,swingweight_kg_cm2=325 "
      "--places 12,3/9,grip -o tuned.json\n"
      "  sweetspot tune racquet.json --like other.json --places 12,3/9,throat,grip\n"
      "  sweetspot tune --match a.json b.json --places 12,3/9,grip --output-dir matched");
}

int TuneCommand::run() const {
  int stdin_uses = 0;
  for (const std::string& path : design_paths) stdin_uses += path == "-";
  if (stdin_uses > 1)
    throw CLI::ValidationError("designs: standard input (-) can be read only once");
  if (match) {
    if (design_paths.size() < 2)
      throw CLI::ValidationError("--match", "give two design files or more");
    if (!target.empty() || !like.empty())
      throw CLI::ValidationError(std::string(target.empty() ? "--like" : "--target") +
                                 ": not with --match (the common specs are found)");
    if (!output.empty())
      throw CLI::ValidationError("--output: not with --match (use --output-dir DIR)");
  } else {
    if (design_paths.size() != 1)
      throw CLI::ValidationError("designs", "one design file to tune (or --match A B ...)");
    if (target.empty() && like.empty())
      throw CLI::ValidationError("--target", "give the specs to reach (or --like OTHER.json)");
    if (!output_dir.empty())
      throw CLI::ValidationError("--output-dir: only with --match (use --output FILE)");
  }
  const std::vector<studies::LeadPlace> lead_places =
      as_option_error("--places", [&] { return studies::parse_lead_places(places); });
  studies::TuneTargets targets;
  if (!target.empty())
    targets = as_option_error("--target", [&] { return studies::parse_tune_targets(target); });

  OutputPlan plan;
  for (const std::string& path : design_paths) plan.read(path);
  plan.read(like);
  // `-o -`: the tuned design on standard output instead of the report.
  if (output != "-") plan.write(kReportOnStandardOutput, "-");
  if (!output.empty()) plan.write("--output", output);
  if (!output_dir.empty()) plan.write_folder("--output-dir", output_dir);

  std::vector<ReadDesign> designs;
  const std::vector<studies::Setting> settings_of = studies::parse_settings(settings);
  // A ball onto a rigid plate has no implement, so no specs to reach or take.
  const auto with_implement = [](const io::DesignFile& file) -> const io::DesignFile& {
    if (file.design.support.kind == Support::Kind::kRigidSurface)
      throw io::InputError(file.source, "/support",
                           "a rigid surface has no implement, so no specs to tune or match");
    return file;
  };
  for (const std::string& path : design_paths) {
    designs.push_back(read(path, settings_of));
    with_implement(designs.back().file);
  }
  const double strip_kg = strip_g * 1e-3;
  io::OutputSet outputs;
  std::vector<std::pair<std::string, std::string>> folder_files;  // --output-dir's, made with it
  std::vector<reports::TunedRacquet> tuned;
  bool all_exact = true;
  std::string rule;
  if (!match) {
    if (!like.empty()) {
      const studies::TuneTargets other = studies::targets_from(
          studies::specs_of(with_implement(io::load_design(like)).design), false);
      if (!targets.mass_kg) targets.mass_kg = other.mass_kg;
      if (!targets.has_balance()) targets.balance_from_butt_m = other.balance_from_butt_m;
      if (!targets.swingweight_kg_m2) targets.swingweight_kg_m2 = other.swingweight_kg_m2;
    }
    // (its complaints name their option)
    const studies::TuneResult result = studies::tune(designs[0].file, targets, lead_places);
    const io::Json document = studies::tuned_document(designs[0].document, result);
    all_exact = result.exact;
    const std::string written = result.exact && output != "-" ? output : "";
    tuned.push_back(evaluate_tuned(designs[0], result, document, written, tolerance));
    if (result.exact && !output.empty() && output != "-")
      outputs.write(output, document.dump(2) + "\n");
    if (result.exact && output == "-") {
      std::cout << document.dump(2) << "\n";
      return kExitOk;
    }
  } else {
    std::vector<io::DesignFile> files;
    for (const ReadDesign& d : designs) files.push_back(d.file);
    const studies::MatchResult result = studies::match(files, lead_places);
    rule =
        "Common specs: the mass, balance and swingweight that every racquet reaches with the "
        "least lead in all (lead only adds mass, so that is the least common mass).";
    std::set<std::string> names;
    for (std::size_t i = 0; i < designs.size(); ++i) {
      const studies::TuneResult& r = result.tuned[i];
      all_exact = all_exact && r.exact;
      const io::Json document = studies::tuned_document(designs[i].document, r);
      std::string written;
      if (!output_dir.empty()) {
        const std::string stem = design_paths[i] == "-"
                                     ? std::string("stdin")
                                     : std::filesystem::path(design_paths[i]).stem().string();
        if (!names.insert(stem).second) {
          throw CLI::ValidationError("--output-dir",
                                     "two designs named " + io::one_line(stem) +
                                         " would be written to one file (rename one)");
        }
        written = (std::filesystem::path(output_dir) / (stem + "-tuned.json")).string();
        plan.write("--output-dir", written, true);
      }
      tuned.push_back(evaluate_tuned(designs[i], r, document, r.exact ? written : "", tolerance));
      if (r.exact && !written.empty()) folder_files.emplace_back(written, document.dump(2) + "\n");
    }
  }
  // The files first: the report says what was written only once it is.
  if (all_exact) {
    outputs.commit();
    if (!folder_files.empty()) io::write_files_atomically(folder_files);
  }
  std::cout << reports::tune_report(tuned, strip_kg, *io::parse_format(format), rule);
  std::cout.flush();
  if (!all_exact) {
    std::cerr << "sweetspot: the targets cannot be reached with lead at these places; the "
                 "nearest specs are reported"
              << (output.empty() && output_dir.empty() ? "" : ", nothing written") << "\n";
    return kExitInfeasible;
  }
  return kExitOk;
}

}  // namespace sweetspot::cli
