// The sweetspot command line: one small unit per subcommand (commands.hpp),
// each calling the library; here only their registration and the one place
// where errors become a line on stderr and an exit status: 0 success, 1 a
// run-time failure (cannot write a file), 2 bad input or bad usage. An
// interrupted run (SIGINT, SIGTERM, SIGHUP, SIGPIPE) removes its temporary
// files and ends by the signal.

#include <CLI/CLI.hpp>
#include <iostream>
#include <stdexcept>
#include <string>

#include "cli/commands.hpp"
#include "io/atomic_file.hpp"
#include "io/input_error.hpp"

int main(int argc, char** argv) {
  using namespace sweetspot::cli;
  sweetspot::io::remove_temporaries_on_signals();
  CLI::App app{
      "sweetspot: where a ball should hit a racquet, bat or beam, and what the hand feels.\n"
      "Rigid-body model of R. Cross, Center of percussion of hand-held implements, "
      "Am. J. Phys. 72 (2004)."};
  app.set_version_flag("--version", std::string("sweetspot ") + SWEETSPOT_VERSION);
  app.require_subcommand(1);

  EvaluateCommand evaluate;
  Table1Command table1;
  FigureCommand figure;
  ReportCommand report;
  OptimizeCommand optimize;
  SweepCommand sweep;
  ModesCommand modes;
  ResponseCommand response;
  MapCommand map;
  BenchCommand bench;
  evaluate.add_to(app);
  table1.add_to(app);
  figure.add_to(app);
  report.add_to(app);
  optimize.add_to(app);
  sweep.add_to(app);
  modes.add_to(app);
  response.add_to(app);
  map.add_to(app);
  bench.add_to(app);

  try {
    app.parse(argc, argv);
  } catch (const CLI::CallForHelp& e) {
    return app.exit(e);
  } catch (const CLI::CallForAllHelp& e) {
    return app.exit(e);
  } catch (const CLI::CallForVersion& e) {
    return app.exit(e);
  } catch (const CLI::ParseError& e) {
    if (app.get_subcommands().empty()) {
      // No command was recognised: name the word taken for one (or the
      // option given before any), and list the commands.
      std::string commands;
      for (const CLI::App* command : app.get_subcommands([](const CLI::App*) { return true; })) {
        commands += (commands.empty() ? "" : ", ") + command->get_name();
      }
      if (argc > 1 && argv[1][0] == '-') {
        std::cerr << "sweetspot: unknown option '" << sweetspot::io::one_line(argv[1])
                  << "' before the subcommand (subcommands: " << commands << "; see --help)\n";
      } else if (argc > 1) {
        std::cerr << "sweetspot: unknown subcommand '" << sweetspot::io::one_line(argv[1])
                  << "' (subcommands: " << commands << "; see --help)\n";
      } else {
        std::cerr << "sweetspot: a subcommand is required (" << commands << "; see --help)\n";
      }
      return kExitBadInput;
    }
    std::cerr << "sweetspot: " << sweetspot::io::one_line(e.what()) << " (see --help)\n";
    return kExitBadInput;
  }

  int status = kExitOk;
  try {
    if (*evaluate.command)
      status = evaluate.run();
    else if (*table1.command)
      status = table1.run();
    else if (*figure.command)
      status = figure.run();
    else if (*report.command)
      status = report.run();
    else if (*optimize.command)
      status = optimize.run();
    else if (*sweep.command)
      status = sweep.run();
    else if (*modes.command)
      status = modes.run();
    else if (*response.command)
      status = response.run();
    else if (*map.command)
      status = map.run();
    else if (*bench.command)
      status = bench.run();
  } catch (const CLI::ParseError& e) {
    std::cerr << "sweetspot: " << sweetspot::io::one_line(e.what()) << "\n";
    return kExitBadInput;
  } catch (const sweetspot::io::InputError& e) {
    std::cerr << "sweetspot: " << sweetspot::io::one_line(e.what()) << "\n";
    return kExitBadInput;
  } catch (const std::invalid_argument& e) {
    std::cerr << "sweetspot: " << sweetspot::io::one_line(e.what()) << "\n";
    return kExitBadInput;
  } catch (const std::exception& e) {
    std::cerr << "sweetspot: " << sweetspot::io::one_line(e.what()) << "\n";
    return kExitRuntimeError;
  }
  std::cout.flush();
  if (!std::cout) {
    std::cerr << "sweetspot: cannot write to standard output\n";
    return kExitRuntimeError;
  }
  return status;
}
