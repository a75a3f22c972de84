// The string bed in two dimensions: `sweetspot map DESIGN.json`.

#include <iostream>
#include <stdexcept>
#include <string>

#include "cli/checks.hpp"
#include "cli/commands.hpp"
#include "cli/progress.hpp"
#include "io/design_reader.hpp"
#include "io/parallel.hpp"
#include "io/plot.hpp"
#include "reports/string_bed_map_report.hpp"
#include "studies/design_settings.hpp"
#include "studies/string_bed_map.hpp"

namespace sweetspot::cli {

void MapCommand::add_to(CLI::App& app) {
  command = app.add_subcommand(
      "map",
      "A grid over the string bed: power (apparent COR), shock (peak wrist force) and, with the "
      "frame's stiffness, feel (vibration energy), as CSV and heat maps");
  command
      ->add_option("design", design_path,
                   "Design file (JSON) with implement headsize_sq_in (or twistweight_kg_cm2)")
      ->required();
  add_set_option(command, settings);
  command
      ->add_option("--fidelity", fidelity,
                   "rigid: power and shock; modal or response: also feel (needs the frame's "
                   "stiffness); collision: the solved collision at every point (needs the "
                   "string tension and the stiffness, no COR); auto: as evaluate's auto "
                   "(collision, modal or rigid)")
      ->check(CLI::IsMember({"rigid", "modal", "response", "collision", "auto"}))
      ->capture_default_str();
  command->add_option("--columns", columns, "Grid points along the long axis")
      ->check(whole_in(2, 1000))
      ->capture_default_str();
  command->add_option("--rows", rows, "Grid points across the head")
      ->check(whole_in(2, 1000))
      ->capture_default_str();
  threads = io::all_cores();
  command
      ->add_option("--threads", threads,
                   "Threads to share the grid's columns (default: all cores); the map is the same")
      ->check(whole_in(1, 1024));
  command->add_flag("--quiet,-q", quiet, "No progress on standard error");
  add_output_option(command, "--plot", plot,
                    "Also render heat maps: FILE-power.png, FILE-shock.png (and FILE-feel.png)");
  out.add_to(command, {"csv"});
  command->footer(
      "Examples:\n"
      "  sweetspot map designs/racquets/tour-100.json -o tour-100-map.csv\n"
      "  sweetspot map designs/racquets/tour-100.json --plot maps/tour-100.png > map.csv");
}

int MapCommand::run() const {
  OutputPlan plan;
  plan.read(design_path);
  out.plan(plan);
  if (!plot.empty()) {
    require_plot_stem("--plot", plot);
    // Every heat map the map may have (feel only with the frame's stiffness).
    for (const reports::MapQuantity quantity :
         {reports::MapQuantity::kPower, reports::MapQuantity::kShock, reports::MapQuantity::kFeel})
      plan.write("--plot", plot_file(plot, "-" + reports::map_quantity_name(quantity)));
  }
  const io::DesignFile design =
      studies::load_design(design_path, studies::parse_settings(settings));
  studies::StringBedMapOptions options;
  options.columns = columns;
  options.rows = rows;
  options.threads = threads;
  Progress progress("grid points", !quiet);
  options.progress = [&](std::size_t done, std::size_t total) { progress.update(done, total); };
  studies::StringBedMap map;
  try {
    const std::string name = command->count("--fidelity") ? fidelity : design.fidelity;
    options.fidelity = resolve_fidelity(name == "response" ? "modal" : name, design.design);
    if (options.fidelity == Fidelity::kResponse) options.fidelity = Fidelity::kModal;
    map = studies::string_bed_map(design.design, options);
  } catch (const std::invalid_argument& e) {
    io::rethrow_in(design, e);
  }
  progress.finish();
  const double length_m = design.design.implement.length_m();
  io::OutputSet outputs;
  out.emit(reports::string_bed_map_csv(map, length_m), outputs);
  if (!plot.empty()) {
    for (const reports::MapQuantity quantity : reports::map_quantities(map)) {
      const std::string png = plot_file(plot, "-" + reports::map_quantity_name(quantity));
      if (const int failed = render_script_or_warn(
              reports::string_bed_heat_map_script(map, quantity, length_m, design.name), png,
              outputs);
          failed != kExitOk)
        return failed;
    }
  }
  outputs.commit();
  return kExitOk;
}

}  // namespace sweetspot::cli
