// `sweetspot bench`: speed against error on this machine.

#include <filesystem>
#include <iostream>

#include "cli/checks.hpp"
#include "cli/commands.hpp"

namespace sweetspot::cli {

void BenchCommand::add_to(CLI::App& app) {
  command = app.add_subcommand(
      "bench", "Speed against error on this machine (median of repeated runs) into reports/");
  command
      ->add_option(
          "what", what,
          "speed (the rigid model, the command line end to end, the optimizer, each fidelity), "
          "modes, collision (one solved collision), map (the string-bed map alone, printed), or "
          "all")
      ->check(CLI::IsMember({"speed", "modes", "collision", "map", "all"}))
      ->capture_default_str();
  command->add_option("--designs", options.designs_dir, "Folder holding studies/")
      ->capture_default_str();
  add_output_folder_option(command, "--out", options.out_dir,
                           "Folder to write (not with map, which prints its table)")
      ->capture_default_str();
  command->add_option("--peers", options.peers_dir, "Folder of the NumPy/SciPy peer scripts")
      ->capture_default_str();
  command->add_option("--repeats", options.repeats, "Runs per figure (the median is reported)")
      ->check(whole_in(1, 1000))
      ->capture_default_str();
}

int BenchCommand::run() const {
  bench::BenchOptions with_exe = options;
  std::error_code no_exe;  // the command-line figures run this very program
  with_exe.executable = std::filesystem::read_symlink("/proc/self/exe", no_exe).string();
  if (what == "map" && command->count("--out")) {
    throw CLI::ValidationError("--out: not with bench map (its table goes to standard output)");
  }
  // The inputs first, then the outputs, before the benchmark runs.
  if (what == "speed" || what == "all") bench::require_bench_speed_inputs(options);
  if (what != "map") {
    // The folder is checked before the benchmark runs, not after.
    OutputPlan plan;
    plan.read_folder(options.designs_dir);
    plan.read_folder(options.peers_dir);
    plan.write_folder("--out", options.out_dir);
  }
  if (what == "map") {
    std::cout << bench::bench_maps(with_exe, std::cout);
    return kExitOk;
  }
  if (what == "speed" || what == "all") bench::bench_speed(with_exe, std::cout);
  if (what == "modes" || what == "all") bench::bench_modes(with_exe, std::cout);
  if (what == "collision" || what == "all") bench::bench_collision(with_exe, std::cout);
  return kExitOk;
}

}  // namespace sweetspot::cli
