// `sweetspot evaluate DESIGN.json` and `sweetspot evaluate --batch FILE`.

#include <unistd.h>

#include <cerrno>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <string>

#include "cli/checks.hpp"
#include "cli/commands.hpp"
#include "cli/progress.hpp"
#include "io/design_reader.hpp"
#include "io/input_error.hpp"
#include "io/json_reader.hpp"
#include "io/outputs.hpp"
#include "io/parallel.hpp"
#include "reports/summary.hpp"
#include "studies/batch.hpp"
#include "studies/design_settings.hpp"
#include "studies/sweet_spots.hpp"

namespace sweetspot::cli {
namespace {

// evaluate --batch: exit 0 when every row evaluated, 1 when some failed.
int run_batch(const EvaluateCommand& c) {
  studies::BatchOptions options;
  options.input = studies::catalogue_format(c.batch_path);
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
  if (!c.batch_map.empty()) {
    // COLUMN=field,... inline; anything else is a JSON file holding the map.
    if (c.batch_map.find('=') != std::string::npos) {
      options.map = studies::parse_column_map(c.batch_map, "--map");
    } else {
      options.map_source = io::input_name(c.batch_map);
      options.map =
          studies::column_map_from_json(io::read_json_file(c.batch_map), options.map_source);
    }
  }
  options.sort_output = c.batch_sort;
  options.descending = c.batch_descending;
  options.top = c.batch_top;
  options.format = c.out.parsed() == io::Format::kJson ? io::Format::kJson : io::Format::kCsv;
  options.threads = c.threads;
  options.fidelity = c.command->count("--fidelity") ? c.fidelity : std::string();
  options.modal_tolerance = c.tolerance;
  // How far the catalogue is read: by bytes when its size is known.
  std::uint64_t size = 0;
  if (c.batch_path != "-") {
    std::error_code error;
    if (std::filesystem::is_regular_file(c.batch_path, error))
      size = std::filesystem::file_size(c.batch_path, error);
    if (error) size = 0;
  }
  // Rows streaming onto the terminal show that the work goes on; a bar among them would not.
  const bool rows_on_terminal =
      (c.out.output.empty() || c.out.output == "-") && isatty(fileno(stdout)) == 1;
  Progress progress("rows", !c.quiet && !rows_on_terminal);
  options.progress = [&](std::size_t rows, std::uint64_t bytes) {
    progress.update(rows, 0,
                    size > 0 ? static_cast<double>(bytes) / static_cast<double>(size) : -1.0);
  };
  studies::BatchSummary summary;
  io::OutputSet outputs;
  if (c.batch_path == "-") {
    // Through a file buffer, which reports a read error as one (std::cin's
    // buffer, shared with C stdio, would report the end of the input).
    std::ifstream in("/dev/stdin", std::ios::binary);
    std::istream& input = in ? in : std::cin;
    c.out.emit_stream(
        [&](std::ostream& out) {
          summary = studies::run_batch(input, "(standard input)", options, out);
        },
        outputs);
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
        [&](std::ostream& out) { summary = studies::run_batch(in, c.batch_path, options, out); },
        outputs);
  }
  progress.finish();
  outputs.commit();
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
  add_set_option(command, settings);
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
  command->add_option("--map", batch_map,
                      "With --batch: the catalogue's own column names mapped onto design fields, "
                      "as a JSON file ({\"weight\": \"implement.mass_g\"}) or inline "
                      "(weight=implement.mass_g,flex=frame.RA); the field's suffix is the unit of "
                      "the column's values. Columns neither mapped nor design fields are passed "
                      "through to the output");
  command
      ->add_option("--sort", batch_sort,
                   "With --batch: order the rows by this output, ascending (failed rows last)")
      ->check(CLI::Validator(
          [](std::string& name) -> std::string {
            if (io::find_output(name)) return "";
            return "expected an output of evaluate, such as peak_wrist_force_N, got " +
                   io::one_line(name) +
                   (name.starts_with("-") ? " (for descending order add --desc)" : "");
          },
          "OUTPUT"));
  command->add_flag("--desc", batch_descending, "With --sort: descending order");
  command->add_flag("--quiet,-q", quiet, "With --batch: no progress on standard error");
  command->add_option("--top", batch_top, "With --sort: only the first N rows")
      ->check(whole_in(1, 1000000000));
  command
      ->add_option(
          "--fidelity", fidelity,
          "rigid: the paper's rigid body; modal: also the vibration modes (needs the "
          "frame's stiffness); response: also the frame's response to the ball (vibration "
          "energy, a COR derived from cor_rigid); collision: the ball, strings and frame solved "
          "together (needs a tension and the frame's stiffness); auto: the cheapest that answers "
          "the design")
      ->check(fidelity_name())
      ->capture_default_str();
  command->add_option("--tol", tolerance, "Relative error allowed in the hand-held frequency")
      ->check(finite_in(kMinRelTol, kMaxRelTol))
      ->capture_default_str();
  command
      ->add_option(
          "--units", units,
          "si: CSV and JSON in SI only (stable keys for programs); people: also a "
          "column (CSV) or an outputs_people key (JSON) in cm, g, kg·cm², ms for each "
          "output in m, kg, kg m^2, s, and lb for a string tension in N. Markdown is always in "
          "people's units. Not with --batch")
      ->check(CLI::IsMember({"si", "people"}))
      ->capture_default_str();
  out.add_to(command);
}

int EvaluateCommand::run() const {
  for (const char* option : {"--base", "--threads", "--map", "--sort", "--desc", "--top"}) {
    if (batch_path.empty() && command->count(option)) {
      throw CLI::ValidationError(std::string(option) + ": only with --batch FILE");
    }
  }
  if (batch_sort.empty() && (command->count("--desc") || command->count("--top"))) {
    throw CLI::ValidationError(std::string(command->count("--top") ? "--top" : "--desc") +
                               ": only with --sort OUTPUT (the order to take the rows in)");
  }
  if (!batch_path.empty()) {
    if (!design_path.empty()) throw CLI::ValidationError("give a design file or --batch, not both");
    if (!settings.empty()) {
      throw CLI::ValidationError(
          "--set: not with --batch (a catalogue sets a field with a column, or every row's "
          "with --base FILE)");
    }
    // Said, not ignored: a catalogue is written in SI only.
    if (command->count("--format") && out.parsed() == io::Format::kMarkdown) {
      throw CLI::ValidationError(
          "--format md: not with --batch (a catalogue is written as csv or json)");
    }
    if (units == "people") {
      throw CLI::ValidationError(
          "--units people: not with --batch (a catalogue's rows are in SI units, one column "
          "per output as `evaluate --format csv` names it)");
    }
    OutputPlan plan;
    plan.read(batch_path);
    plan.read(batch_base);
    if (batch_map.find('=') == std::string::npos) plan.read(batch_map);
    out.plan(plan);
    return run_batch(*this);
  }
  if (design_path.empty())
    throw CLI::ValidationError("design: a design file (or --batch FILE) is required");
  OutputPlan plan;
  plan.read(design_path);
  out.plan(plan);
  // A design without an impact has the default of its kind (the reader's).
  const io::DesignFile design =
      studies::load_design(design_path, studies::parse_settings(settings));
  // The command line's --fidelity wins over the file's "fidelity".
  Evaluation result = io::evaluate_design_file(
      design, command->count("--fidelity") ? fidelity : std::string(), tolerance);
  std::string answer;
  if (is_rig(result.support)) {
    // No sweet spots and no power point on a rig: they are the player's.
    if (out.parsed() == io::Format::kMarkdown) answer = reports::rig_paragraph(design, result);
  } else if (out.parsed() == io::Format::kMarkdown) {
    const studies::SweetSpots spots = studies::find_sweet_spots(design, result, tolerance);
    answer = reports::sweet_spot_paragraph(design, spots);
    if (spots.power_point) {
      result.power_point_from_butt_m = result.length_m - spots.power_point->from_tip_m;
      result.power_point_shot_speed_m_s = spots.power_point->evaluation.shot_speed_m_s;
    }
  } else {
    result = studies::with_power_point(design, std::move(result), tolerance);
  }
  io::OutputSet outputs;
  out.emit(io::evaluation_report(design, result, out.parsed(), answer, units == "people"), outputs);
  outputs.commit();
  return kExitOk;
}

}  // namespace sweetspot::cli
