// The sweetspot command line: one small unit per subcommand (commands.hpp),
// each calling the library; here only their registration and the one place
// where errors become a line on stderr and an exit status: 0 success, 1 a
// run-time failure (cannot write a file), 2 bad input or bad usage (an input
// outside its stated range), 3 a model that cannot answer the design
// (sweetspot::ModelRefusal) or a study with no feasible design. An
// interrupted run (any catchable signal that ends a process:
// io::remove_temporaries_on_signals()) removes its temporary files and ends
// by the signal.

#include <CLI/CLI.hpp>
#include <iostream>
#include <stdexcept>
#include <string>
#include <utility>

#include "cli/commands.hpp"
#include "io/atomic_file.hpp"
#include "io/input_error.hpp"
#include "sweetspot/invariants.hpp"

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
  CompareCommand compare;
  TuneCommand tune;
  StringCommand string;
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
  compare.add_to(app);
  tune.add_to(app);
  string.add_to(app);
  table1.add_to(app);
  figure.add_to(app);
  report.add_to(app);
  optimize.add_to(app);
  sweep.add_to(app);
  modes.add_to(app);
  response.add_to(app);
  map.add_to(app);
  bench.add_to(app);
  // Every --help ends with examples that run as written from the repository.
  const std::pair<const char*, const char*> kExamples[] = {
      {"evaluate",
       "Examples:\n  sweetspot evaluate designs/racquets/tour-100.json\n"
       "  cat racquet.json | sweetspot evaluate - --format json --units people"},
      {"table1",
       "Examples:\n  sweetspot table1\n  sweetspot table1 --dir "
       "/usr/local/share/sweetspot/designs/table1 "
       "--format csv"},
      {"figure",
       "Examples:\n  sweetspot figure 11 --plot fig11.png > fig11.csv\n"
       "  sweetspot figure 5 --design designs/paper-beam.json -o fig5.csv"},
      {"report", "Example:\n  sweetspot report --designs designs --out reports"},
      {"optimize",
       "Examples:\n  sweetspot optimize designs/studies/1-lowest-wrist-force-table1-ranges.json\n"
       "  sweetspot optimize STUDY.json --format json -o best.json --plot convergence.png"},
      {"sweep",
       "Examples:\n  sweetspot sweep designs/studies/5a-sweep-wrist-force-hand-mass.json -o "
       "sweep.csv\n"
       "  sweetspot sweep STUDY.json --plot sweep.png --threads 2"},
      {"modes",
       "Examples:\n  sweetspot modes designs/paper-beam.json\n"
       "  sweetspot modes designs/racquets/tour-100.json -n 2 --plot modes.png"},
      {"response",
       "Examples:\n  sweetspot response designs/paper-beam.json --at 0.02,0.16 --plot "
       "response.png\n"
       "  sweetspot response designs/paper-beam.json --held --impacts 0.05,0.16"},
      {"bench", "Example:\n  sweetspot bench speed --repeats 3"},
  };
  for (const auto& [name, examples] : kExamples) {
    if (CLI::App* command = app.get_subcommand(name)) {
      if (command->get_footer().empty()) command->footer(examples);
    }
  }
  app.footer(
      "Examples:\n  sweetspot evaluate designs/racquets/tour-100.json\n"
      "  sweetspot compare designs/racquets/tour-100.json "
      "designs/racquets/tour-100-lead-at-tip.json");

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

  // An option given an empty value ("-o ''", "--map ''") is refused, never
  // taken as not given.
  for (const CLI::App* command : app.get_subcommands()) {
    for (const CLI::Option* option : command->get_options()) {
      if (option->get_type_size() == 0 || option->count() == 0) continue;
      for (const std::string& value : option->results()) {
        if (value.empty()) {
          std::cerr << "sweetspot: " << option->get_name() << ": an empty value (see --help)\n";
          return kExitBadInput;
        }
      }
    }
  }

  int status = kExitOk;
  try {
    if (*evaluate.command)
      status = evaluate.run();
    else if (*compare.command)
      status = compare.run();
    else if (*tune.command)
      status = tune.run();
    else if (*string.command)
      status = string.run();
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
    return e.model_refused() ? kExitModelRefused : kExitBadInput;
  } catch (const sweetspot::ModelRefusal& e) {
    std::cerr << "sweetspot: " << sweetspot::io::one_line(e.what()) << "\n";
    return kExitModelRefused;
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
