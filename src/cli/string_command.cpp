// `sweetspot string DESIGN`: the string bed as a stringer reads it; with
// --like OTHER (or --target), the tension on this frame that gives the
// other's stiffness, ring or dwell.

#include <cmath>
#include <iostream>
#include <string>
#include <tuple>

#include "cli/checks.hpp"
#include "cli/commands.hpp"
#include "io/design_reader.hpp"
#include "io/input_error.hpp"
#include "io/json_reader.hpp"
#include "reports/string_report.hpp"
#include "studies/design_settings.hpp"
#include "studies/string_ticket.hpp"
#include "sweetspot/frame_modes.hpp"

namespace sweetspot::cli {
namespace {

// --target NAME=VALUE: the quantity and its value in SI.
std::pair<studies::BedQuantity, double> parse_target(const std::string& text) {
  // The tension that reaches one measurement: two would over-determine it.
  if (text.find(',') != std::string::npos) {
    throw CLI::ValidationError("--target",
                               "one target: the tension is solved to reach one of the bed's "
                               "stiffness, ring or dwell, got " +
                                   io::one_line(text));
  }
  const auto eq = text.find('=');
  const std::string name = text.substr(0, eq);
  double value = 0.0;
  std::size_t used = 0;
  bool number = false;
  if (eq != std::string::npos) {
    try {
      value = std::stod(text.substr(eq + 1), &used);
      number = used == text.size() - eq - 1 && std::isfinite(value) && value > 0.0;
    } catch (const std::exception&) {
      number = false;
    }
  }
  struct Spelling {
    const char* name;
    studies::BedQuantity quantity;
    double to_si;
  };
  static const Spelling kSpellings[] = {
      {"stiffness_N_m", studies::BedQuantity::kStiffness, 1.0},
      {"stiffness_lb_in", studies::BedQuantity::kStiffness, io::kPoundForce_N / io::kInch_m},
      {"ring_Hz", studies::BedQuantity::kRing, 1.0},
      {"dwell_ms", studies::BedQuantity::kDwell, 1e-3},
      {"dwell_s", studies::BedQuantity::kDwell, 1.0}};
  for (const Spelling& s : kSpellings) {
    if (name != s.name) continue;
    if (!number) {
      throw CLI::ValidationError(
          "--target", "expected " + name + "=VALUE with VALUE > 0, got " + io::one_line(text));
    }
    return {s.quantity, value * s.to_si};
  }
  throw CLI::ValidationError("--target",
                             "expected one of stiffness_N_m, stiffness_lb_in, ring_Hz, dwell_ms, "
                             "dwell_s =VALUE, got " +
                                 io::one_line(text));
}

}  // namespace

void StringCommand::add_to(CLI::App& app) {
  command = app.add_subcommand(
      "string",
      "The string bed as a stringer reads it (the tension on the machine and in the bed, the "
      "bed's stiffness, its ring, the dwell, what a pound changes); with --like, the tension "
      "on this frame that gives another's bed");
  command->add_option("design", design_path, "The design file (JSON; - for standard input)")
      ->required();
  add_set_option(command, settings);
  command->add_option("--like", like,
                      "The design whose bed to match (its stiffness, or what --keep names), at "
                      "its own tension");
  command->add_option("--keep", keep, "What the customer keeps: stiffness, ring or dwell")
      ->check(CLI::IsMember({"stiffness", "ring", "dwell"}))
      ->capture_default_str();
  command->add_option("--target", target,
                      "A bed to reach instead of another design's: stiffness_N_m, "
                      "stiffness_lb_in, ring_Hz, dwell_ms or dwell_s =VALUE");
  command->add_option("--format", format, "Format of the report on standard output")
      ->check(CLI::IsMember({"md", "json"}))
      ->capture_default_str();
  command->footer(
      "Examples:\n"
      "  sweetspot string ticket.json\n"
      "  sweetspot string new-frame.json --like old-frame.json\n"
      "  sweetspot string ticket.json --set strings.material=polyester --like ticket.json\n"
      "  sweetspot string ticket.json --target stiffness_lb_in=180 --format json");
}

int StringCommand::run() const {
  if (!like.empty() && !target.empty())
    throw CLI::ValidationError("--target", "not with --like: match one bed");
  if (command->count("--keep") > 0 && like.empty())
    throw CLI::ValidationError("--keep",
                               "only with --like OTHER (what of its bed to keep; --target names "
                               "its own)");
  if (design_path == "-" && like == "-")
    throw CLI::ValidationError("--like: standard input (-) can be read only once");
  const std::vector<studies::Setting> settings_of = studies::parse_settings(settings);
  const io::DesignFile file = studies::read_design(io::read_json_file(design_path),
                                                   io::input_name(design_path), settings_of);
  if (!file.design.strings) {
    throw io::InputError(file.source, "/strings",
                         is_round(file.design)
                             ? "no string bed: an implement given by its profile is round (a "
                               "bat, a rod) and has none; `string` answers a racquet's strings"
                             : "no string bed: give strings.tension_lb (or a stringer's ticket: "
                               "pattern, mains, crosses)");
  }
  reports::StringAnswer answer{file.name, studies::read_bed(file.design), std::nullopt, ""};
  // The contact time `evaluate` gives, beside the two springs' estimate, when
  // the frame's stiffness lets the collision be solved; none when it refuses.
  if (has_stiffness(file.design) && !is_rig(file.design.support)) {
    try {
      answer.solved_contact_time_s =
          io::evaluate_design_file(file, "collision", 1e-6).impact_duration_s;  // evaluate's --tol
    } catch (const io::InputError&) {  // a refusal: the estimate alone
    }
  }
  if (!like.empty() || !target.empty()) {
    studies::BedQuantity quantity = *studies::parse_bed_quantity(keep);
    double value = 0.0;
    if (!like.empty()) {
      const io::DesignFile other = io::load_design(like);
      if (!other.design.strings) {
        throw io::InputError(other.source, "/strings",
                             "no string bed to match: give strings.tension_lb");
      }
      const studies::BedReading theirs = studies::read_bed(other.design);
      value = theirs.value(quantity);
      const std::string mains = io::significant(theirs.pull_tension_N / io::kPoundForce_N, 4);
      const std::string crosses =
          io::significant(theirs.cross_pull_tension_N / io::kPoundForce_N, 4);
      answer.target_from =
          other.name + " at " + (mains == crosses ? mains : mains + "/" + crosses) + " lb";
    } else {
      std::tie(quantity, value) = parse_target(target);
      answer.target_from = "the target";
    }
    answer.tension = studies::tension_for(file.design, quantity, value);
  }
  std::cout << reports::string_report(answer, *io::parse_format(format));
  std::cout.flush();
  if (answer.tension && !answer.tension->reachable) {
    std::cerr << "sweetspot: no tension in the model's range gives that bed; the nearest is "
                 "reported\n";
    return kExitInfeasible;
  }
  return kExitOk;
}

}  // namespace sweetspot::cli
