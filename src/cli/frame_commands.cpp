// The flexible frame: `sweetspot modes DESIGN.json` and `sweetspot response DESIGN.json`.

#include <fmt/format.h>

#include <algorithm>
#include <iostream>
#include <string>
#include <utility>
#include <vector>

#include "cli/checks.hpp"
#include "cli/commands.hpp"
#include "io/design_reader.hpp"
#include "reports/modes_report.hpp"
#include "reports/response_report.hpp"
#include "studies/design_settings.hpp"
#include "studies/modes.hpp"
#include "studies/response.hpp"

namespace sweetspot::cli {
namespace {

// The numbers of every occurrence of a list option ("--at 0.1,0.2 --at 0.3").
std::vector<double> points(const std::string& option, const std::vector<std::string>& lists) {
  std::vector<double> all;
  for (const std::string& list : lists) {
    const std::vector<double> some = number_list(option, list);
    all.insert(all.end(), some.begin(), some.end());
  }
  return all;
}

// The plot of the observation point `x_m` m from the butt: FILE-at-<cm>cm.png.
std::string plot_png(const std::string& plot, double x_m) {
  return plot_file(plot, fmt::format("-at-{:g}cm", x_m * 100));
}

}  // namespace

void ModesCommand::add_to(CLI::App& app) {
  command = app.add_subcommand(
      "modes", "Vibration modes free and hand-held: frequencies, damping, nodes, shapes (csv)");
  command->add_option("design", design_path, "Design file (JSON) with the frame's stiffness")
      ->required();
  add_set_option(command, settings);
  command->add_option("--modes,-n", modes, "How many flexible modes")
      ->check(whole_in(1, kMaxExactModes))
      ->capture_default_str();
  command
      ->add_option("--tol", tolerance, "Relative error allowed in the finite-element frequencies")
      ->check(finite_in(kMinRelTol, kMaxRelTol))
      ->capture_default_str();
  command->add_option("--method", method, "Free modes: exact (transfer matrices) or fe")
      ->check(CLI::IsMember({"exact", "fe"}))
      ->capture_default_str();
  add_output_option(command, "--plot", plot, "Also render the mode shapes to this PNG file");
  out.add_to(command);
}

int ModesCommand::run() const {
  OutputPlan plan;
  plan.read(design_path);
  out.plan(plan);
  if (!plot.empty()) plan.write("--plot", plot);
  const io::DesignFile design =
      studies::load_design(design_path, studies::parse_settings(settings));
  const auto data = studies::compute_modes(
      design, modes, tolerance,
      method == "fe" ? ModeOptions::Method::kFiniteElement : ModeOptions::Method::kExact);
  io::OutputSet outputs;
  out.emit(reports::modes_report(data, out.parsed()), outputs);
  if (!plot.empty()) {
    if (const int failed = render_or_warn(reports::modes_plot(data), plot, outputs);
        failed != kExitOk)
      return failed;
  }
  outputs.commit();
  return kExitOk;
}

void ResponseCommand::add_to(CLI::App& app) {
  command = app.add_subcommand(
      "response",
      "Velocity of points of the implement after the impact: rigid (dc) and vibration (ac) parts");
  command->add_option("design", design_path, "Design file (JSON) with the frame's stiffness")
      ->required();
  add_set_option(command, settings);
  // Lists are split here rather than by CLI11, which would drop an empty
  // item ("0.1,,0.2") or read "" as 0, the butt: both are refused.
  command
      ->add_option_function<std::vector<std::string>>(
          "--at", [this](const std::vector<std::string>& lists) { at = points("--at", lists); },
          "Observation points, m from the butt (comma-separated)")
      ->expected(1)
      ->multi_option_policy(CLI::MultiOptionPolicy::TakeAll)
      ->default_str("0.02,0.16");
  command
      ->add_option_function<std::vector<std::string>>(
          "--impacts",
          [this](const std::vector<std::string>& lists) { impacts = points("--impacts", lists); },
          "Impact points, m from the butt, comma-separated (default: the design's)")
      ->expected(1)
      ->multi_option_policy(CLI::MultiOptionPolicy::TakeAll);
  command->add_flag("--held", held,
                    "Held in the hand (default: free, as the paper's suspended beam)");
  command->add_option("--until-ms", until_ms, "Time window after the impact starts")
      ->check(finite_in(0.01, 1000.0))
      ->capture_default_str();
  add_output_option(command, "--output,-o", csv_path,
                    "Write the CSV to FILE instead of stdout (- for stdout)");
  add_output_option(command, "--plot", plot, "Also plot: FILE-at-<cm>cm.png per observation point");
}

int ResponseCommand::run() const {
  const io::DesignFile design =
      studies::load_design(design_path, studies::parse_settings(settings));
  // Points are the command line's, checked and named as such.
  const double length_m = design.design.implement.length_m();
  for (const auto& [option, list] : {std::pair{"--at", &at}, std::pair{"--impacts", &impacts}}) {
    for (const double x : *list) {
      if (!(x >= 0.0 && x <= length_m)) {
        throw CLI::ValidationError(fmt::format("{} {}", option, x),
                                   fmt::format("outside the implement (length {} m)", length_m));
      }
    }
  }
  OutputPlan plan;
  plan.read(design_path);
  OutputOptions{"csv", csv_path}.plan(plan);
  if (!plot.empty()) {
    require_plot_stem("--plot", plot);
    for (const double x : at) plan.write("--plot", plot_png(plot, x));
  }
  studies::ResponseRequest request;
  request.points_from_butt_m = at;
  request.impacts_from_butt_m = impacts;
  request.hand_held = held;
  request.until_s = until_ms / 1e3;
  const auto data = studies::compute_response(design, request);
  io::OutputSet outputs;
  OutputOptions{"csv", csv_path}.emit(reports::response_csv(data), outputs);
  if (!plot.empty()) {
    const auto plots = reports::response_plots(data);
    for (std::size_t k = 0; k < plots.size(); ++k) {
      // The first plot that cannot be made ends the run: one message, exit 1, nothing written.
      if (const int failed = render_or_warn(plots[k], plot_png(plot, at[k]), outputs);
          failed != kExitOk)
        return failed;
    }
  }
  outputs.commit();
  return kExitOk;
}

}  // namespace sweetspot::cli
