#pragma once

// The subcommands of `sweetspot`, one small unit each: `add_to` registers its
// options, `run` calls the library and returns the exit status. Errors are
// thrown (InputError, std::invalid_argument) and turned into one line and an
// exit status by main().

#include <CLI/CLI.hpp>
#include <string>
#include <vector>

#include "bench/bench.hpp"
#include "cli/output.hpp"

namespace sweetspot::cli {

struct EvaluateCommand {
  CLI::App* command = nullptr;
  std::string design_path;
  std::vector<std::string> settings;  // --set FIELD=VALUE, repeatable
  std::string batch_path;
  std::string batch_base;
  std::string batch_map;   // --map: a JSON file, or COLUMN=field,... inline
  std::string batch_sort;  // --sort OUTPUT
  bool batch_descending = false;
  std::size_t batch_top = 0;
  std::string fidelity = "auto";
  double tolerance = 1e-6;
  int threads = 1;
  bool quiet = false;        // --batch: no progress on stderr
  std::string units = "si";  // "people": CSV and JSON also in cm, g, kg·cm², ms
  OutputOptions out;

  void add_to(CLI::App& app);
  int run() const;
};

struct CompareCommand {
  CLI::App* command = nullptr;
  std::vector<std::string> design_paths;
  std::vector<std::string> settings;  // --set FIELD=VALUE, repeatable
  std::string fidelity = "auto";
  double tolerance = 1e-6;
  OutputOptions out;
  std::string html;  // --html FILE: the comparison as one web page

  void add_to(CLI::App& app);
  int run() const;
};

struct TuneCommand {
  CLI::App* command = nullptr;
  std::vector<std::string> design_paths;
  std::vector<std::string> settings;  // --set FIELD=VALUE, repeatable
  std::string target;                 // --target mass_g=330,balance_cm=32,...
  std::string like;                   // --like OTHER.json: its specs are the targets
  std::string places;                 // --places 12,3/9,handle
  bool match = false;                 // --match A B ...: common specs
  double strip_g = 1.0;
  double tolerance = 1e-6;
  std::string format = "md";
  std::string output;      // -o FILE: the tuned design
  std::string output_dir;  // --output-dir DIR: with --match, each tuned design

  void add_to(CLI::App& app);
  int run() const;
};

struct StringCommand {
  CLI::App* command = nullptr;
  std::string design_path;
  std::vector<std::string> settings;  // --set FIELD=VALUE, repeatable
  std::string like;                   // --like OTHER.json: its bed is the target
  std::string keep = "stiffness";     // what the customer keeps
  std::string target;                 // --target stiffness_lb_in=180
  std::string format = "md";

  void add_to(CLI::App& app);
  int run() const;
};

struct Table1Command {
  CLI::App* command = nullptr;
  std::string dir = "designs/table1";
  OutputOptions out;

  void add_to(CLI::App& app);
  int run() const;
};

struct FigureCommand {
  CLI::App* command = nullptr;
  int number = 0;
  std::string design = "designs/paper-beam.json";
  std::string csv_path;
  std::string png;

  void add_to(CLI::App& app);
  int run() const;
};

struct ReportCommand {
  CLI::App* command = nullptr;
  std::string designs = "designs";
  std::string out_dir = "reports";
  std::string design;                 // `report DESIGN.json --html FILE`: one design's page
  std::vector<std::string> settings;  // --set FIELD=VALUE, repeatable
  std::string html;

  void add_to(CLI::App& app);
  int run() const;
};

struct OptimizeCommand {
  CLI::App* command = nullptr;
  std::string study_path;
  std::string plot;
  OutputOptions out;
  std::string html;  // --html FILE: the study's report as one web page
  int threads = 1;   // for independent evaluations (default: all cores)

  void add_to(CLI::App& app);
  int run() const;
};

struct SweepCommand {
  CLI::App* command = nullptr;
  std::string study_path;
  std::string csv_path;
  std::string plot;
  std::string format = "csv";  // or "json": JSON Lines, one object per grid point
  bool quiet = false;
  int threads = 1;

  void add_to(CLI::App& app);
  int run() const;
};

struct ModesCommand {
  CLI::App* command = nullptr;
  std::string design_path;
  std::vector<std::string> settings;  // --set FIELD=VALUE, repeatable
  int modes = 3;
  double tolerance = 1e-6;
  std::string method = "exact";
  std::string plot;
  OutputOptions out;

  void add_to(CLI::App& app);
  int run() const;
};

struct MapCommand {
  CLI::App* command = nullptr;
  std::string design_path;
  std::vector<std::string> settings;  // --set FIELD=VALUE, repeatable
  std::string fidelity = "auto";
  int columns = 50;
  int rows = 50;
  int threads = 1;  // default: all cores
  bool quiet = false;
  std::string plot;
  OutputOptions out{"csv", ""};

  void add_to(CLI::App& app);
  int run() const;
};

struct ResponseCommand {
  CLI::App* command = nullptr;
  std::string design_path;
  std::vector<std::string> settings;  // --set FIELD=VALUE, repeatable
  std::vector<double> at{0.02, 0.16};
  std::vector<double> impacts;
  bool held = false;
  double until_ms = 20.0;
  std::string csv_path;
  std::string plot;

  void add_to(CLI::App& app);
  int run() const;
};

struct BenchCommand {
  CLI::App* command = nullptr;
  std::string what = "all";
  bench::BenchOptions options;

  void add_to(CLI::App& app);
  int run() const;
};

}  // namespace sweetspot::cli
