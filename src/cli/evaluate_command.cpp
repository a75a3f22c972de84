// `sweetspot evaluate DESIGN.json` and `sweetspot evaluate --batch FILE`.

#include <cerrno>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <string>

#include "cli/checks.hpp"
#include "cli/commands.hpp"
#include "io/design_reader.hpp"
#include "io/input_error.hpp"
#include "io/json_reader.hpp"
#include "io/parallel.hpp"
#include "reports/summary.hpp"
#include "studies/batch.hpp"

namespace sweetspot::cli {
namespace {

// evaluate --batch: exit 0 when every row evaluated, 1 when some failed.
int run_batch(const EvaluateCommand& c) {
  io::BatchOptions options;
  options.input = io::catalogue_format(c.batch_path);
  if (!c.batch_base.empty()) {
    options.base = io::read_json_file(c.batch_base);
    // A base that is not a valid design on its own is the caller's error, not every row's.
    if (!options.base->contains("implement")) {
      throw io::InputError(c.batch_base, "/implement",
                           "missing: the base design needs an implement");
    }
    // ... and a value it gets wrong is wrong for every row: said once, at the base's own path.
    io::evaluate_design_file(io::read_design(*options.base, c.batch_base), "", c.tolerance);
  }
  options.format = c.out.parsed() == io::Format::kJson ? io::Format::kJson : io::Format::kCsv;
  options.threads = c.threads;
  options.fidelity = c.command->count("--fidelity") ? c.fidelity : std::string();
  options.modal_tolerance = c.tolerance;
  io::BatchSummary summary;
  if (c.batch_path == "-") {
    // Through a file buffer, which reports a read error as one (std::cin's
    // buffer, shared with C stdio, would report the end of the input).
    std::ifstream in("/dev/stdin", std::ios::binary);
    std::istream& input = in ? in : std::cin;
    c.out.emit_stream([&](std::ostream& out) {
      summary = io::run_batch(input, "(standard input)", options, out);
    });
  } else {
    std::error_code error;
    if (std::filesystem::is_directory(c.batch_path, error)) {
      throw io::InputError(c.batch_path, "",
                           "is a directory, expected a catalogue file (CSV or JSON Lines)");
    }
    errno = 0;
    std::ifstream in(c.batch_path, std::ios::binary);
    if (!in) {
      throw io::InputError(c.batch_path, "",
                           std::string("cannot open the file for reading") +
                               (errno ? std::string(": ") + std::strerror(errno) : ""));
    }
    c.out.emit_stream(
        [&](std::ostream& out) { summary = io::run_batch(in, c.batch_path, options, out); });
  }
  if (summary.failed > 0) {
    std::cerr << "sweetspot: " << summary.failed << " of " << summary.rows
              << " rows failed (see their error column)\n";
    return kExitRuntimeError;
  }
  return kExitOk;
}

}  // namespace

void EvaluateCommand::add_to(CLI::App& app) {
  command = app.add_subcommand("evaluate", "Every quantity of the paper for one design");
  threads = io::all_cores();
  command->add_option("design", design_path, "Design file (JSON)");
  command->add_option(
      "--batch", batch_path,
      "Evaluate a catalogue instead (- for standard input): JSON Lines (.jsonl, one design "
      "per line) or CSV (.csv) whose header names design fields "
      "(implement.mass_g,impact.from_butt_m,...); another name is JSON Lines if its first "
      "line starts with '{', else CSV. Output CSV (or JSON Lines with --format json), one "
      "row per input in order");
  command->add_option("--base", batch_base,
                      "With --batch: a design file giving every row's defaults");
  command->add_option("--threads", threads, "With --batch: threads to use (default: all cores)")
      ->check(whole_in(1, 1024));
  command
      ->add_option(
          "--fidelity", fidelity,
          "rigid: the paper's rigid body; modal: also the vibration modes (needs the "
          "frame's stiffness); response: also the frame's response to the ball (vibration "
          "energy, a COR derived from cor_rigid); auto: the cheapest that answers the design")
      ->check(CLI::IsMember({"rigid", "modal", "response", "auto"}))
      ->capture_default_str();
  command->add_option("--tol", tolerance, "Relative error allowed in the hand-held frequency")
      ->check(finite_in(kMinRelTol, kMaxRelTol))
      ->capture_default_str();
  out.add_to(command);
}

int EvaluateCommand::run() const {
  if (!batch_path.empty()) {
    if (!design_path.empty()) throw CLI::ValidationError("give a design file or --batch, not both");
    return run_batch(*this);
  }
  if (design_path.empty())
    throw CLI::ValidationError("design: a design file (or --batch FILE) is required");
  // A racquet without an impact is evaluated at the centre of its strings.
  const io::DesignFile design = reports::with_default_impact(io::load_design(design_path));
  // The command line's --fidelity wins over the file's "fidelity".
  const Evaluation result = io::evaluate_design_file(
      design, command->count("--fidelity") ? fidelity : std::string(), tolerance);
  std::string answer;
  if (out.parsed() == io::Format::kMarkdown) {
    answer =
        reports::sweet_spot_paragraph(design, reports::find_sweet_spots(design, result, tolerance));
  }
  out.emit(io::evaluation_report(design, result, out.parsed(), answer));
  return kExitOk;
}

}  // namespace sweetspot::cli
