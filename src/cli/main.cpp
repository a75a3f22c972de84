// The sweetspot command line: reads designs, runs the physics core and writes
// reports. Exit status: 0 success, 1 a run-time failure (cannot write a file),
// 2 bad input or bad usage, with one line on stderr.

#include <CLI/CLI.hpp>
#include <fmt/format.h>

#include <iostream>
#include <string>

#include "sweetspot/evaluate.hpp"
#include "sweetspot/io/atomic_file.hpp"
#include "sweetspot/io/design_reader.hpp"
#include "sweetspot/io/format.hpp"
#include "sweetspot/io/input_error.hpp"
#include "sweetspot/io/paper_reports.hpp"

namespace {

using sweetspot::io::Format;

constexpr int kExitRuntimeError = 1;
constexpr int kExitBadInput = 2;

struct OutputOptions {
  std::string format = "md";
  std::string output;  // "" = stdout

  void add_to(CLI::App* command) {
    command->add_option("--format", format, "Output format")
        ->check(CLI::IsMember({"md", "json", "csv"}))
        ->capture_default_str();
    command->add_option("--output,-o", output,
                        "Write to FILE (atomically: temporary file and rename) instead of stdout");
  }
  Format parsed() const { return *sweetspot::io::parse_format(format); }
  void emit(const std::string& text) const {
    if (output.empty()) {
      std::cout << text;
    } else {
      sweetspot::io::write_file_atomically(output, text);
    }
  }
};

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{
      "sweetspot: where a ball should hit a racquet, bat or beam, and what the hand feels.\n"
      "Rigid-body model of R. Cross, Center of percussion of hand-held implements, "
      "Am. J. Phys. 72 (2004)."};
  app.set_version_flag("--version", std::string("sweetspot ") + SWEETSPOT_VERSION);
  app.require_subcommand(1);

  OutputOptions evaluate_out;
  std::string design_path;
  CLI::App* evaluate = app.add_subcommand("evaluate", "Every quantity of the paper for one design");
  evaluate->add_option("design", design_path, "Design file (JSON)")->required();
  evaluate_out.add_to(evaluate);

  OutputOptions table_out;
  std::string table_dir = "designs/table1";
  CLI::App* table1 =
      app.add_subcommand("table1", "Table I of the paper from row1.json ... row8.json");
  table1->add_option("--dir", table_dir, "Folder with the eight row designs")->capture_default_str();
  table_out.add_to(table1);

  int figure_number = 0;
  std::string figure_design = "designs/paper-beam.json";
  std::string figure_csv;
  std::string figure_png;
  CLI::App* figure = app.add_subcommand("figure", "Data (CSV) and plot (PNG) of Fig. 5 or Fig. 11");
  figure->add_option("number", figure_number, "5 or 11")->required()->check(CLI::IsMember({5, 11}));
  figure->add_option("--design", figure_design, "The beam")->capture_default_str();
  figure->add_option("--output,-o", figure_csv, "Write the CSV to FILE instead of stdout");
  figure->add_option("--plot", figure_png, "Also render the plot to this PNG file");

  std::string report_designs = "designs";
  std::string report_dir = "reports";
  CLI::App* report =
      app.add_subcommand("report", "Reproduce Table I and Figs. 5 and 11 into a folder");
  report->add_option("--designs", report_designs, "Folder holding table1/ and paper-beam.json")
      ->capture_default_str();
  report->add_option("--out", report_dir, "Folder to write")->capture_default_str();

  try {
    app.parse(argc, argv);
  } catch (const CLI::CallForHelp& e) {
    return app.exit(e);
  } catch (const CLI::CallForAllHelp& e) {
    return app.exit(e);
  } catch (const CLI::CallForVersion& e) {
    return app.exit(e);
  } catch (const CLI::ParseError& e) {
    app.exit(e);
    return kExitBadInput;
  }

  try {
    if (*evaluate) {
      const auto design = sweetspot::io::load_design(design_path);
      const auto result = sweetspot::evaluate(design.design);
      evaluate_out.emit(sweetspot::io::evaluation_report(design, result, evaluate_out.parsed()));
    } else if (*table1) {
      const auto rows = sweetspot::io::compute_table1(table_dir);
      table_out.emit(sweetspot::io::table1_report(rows, table_out.parsed()));
    } else if (*figure) {
      const auto beam = sweetspot::io::load_design(figure_design);
      const auto data =
          figure_number == 5 ? sweetspot::io::figure5(beam) : sweetspot::io::figure11(beam);
      if (figure_csv.empty()) {
        std::cout << data.csv;
      } else {
        sweetspot::io::write_file_atomically(figure_csv, data.csv);
      }
      std::cerr << data.summary << "\n";
      if (!figure_png.empty()) {
        std::string why;
        if (!sweetspot::io::render_png(data.plot, figure_png, &why)) {
          std::cerr << "sweetspot: " << figure_png << ": " << why << "\n";
          return kExitRuntimeError;
        }
      }
    } else if (*report) {
      sweetspot::io::write_paper_reports(report_designs, report_dir, std::cout);
    }
  } catch (const sweetspot::io::InputError& e) {
    std::cerr << "sweetspot: " << e.what() << "\n";
    return kExitBadInput;
  } catch (const std::invalid_argument& e) {
    std::cerr << "sweetspot: " << e.what() << "\n";
    return kExitBadInput;
  } catch (const std::exception& e) {
    std::cerr << "sweetspot: " << e.what() << "\n";
    return kExitRuntimeError;
  }
  return 0;
}
