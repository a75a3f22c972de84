// The paper's results: `sweetspot table1`, `sweetspot figure 5|11` and
// `sweetspot report` (everything into a folder).

#include <filesystem>
#include <iostream>
#include <string>
#include <system_error>

#include "cli/checks.hpp"
#include "cli/commands.hpp"
#include "cli/reports_folder.hpp"
#include "io/atomic_file.hpp"
#include "io/design_reader.hpp"
#include "io/input_error.hpp"
#include "reports/html_report.hpp"
#include "reports/paper_reports.hpp"
#include "reports/summary.hpp"
#include "studies/design_page.hpp"
#include "studies/design_settings.hpp"
#include "studies/paper.hpp"

namespace sweetspot::cli {

void Table1Command::add_to(CLI::App& app) {
  command = app.add_subcommand("table1", "Table I of the paper from row1.json ... row8.json");
  command->add_option("--dir", dir, "Folder with the eight row designs")->capture_default_str();
  out.add_to(command);
}

namespace {

// The default folder of the shipped designs: the repository's when run from it,
// else the installed copy; a folder found in neither says which option points at it.
std::string shipped(const std::string& path, const std::string& option, bool given) {
  std::error_code error;
  if (given || std::filesystem::exists(path, error)) return path;
  const std::string installed = std::string(SWEETSPOT_DATA_DIR) + "/" + path;
  if (std::filesystem::exists(installed, error)) return installed;
  throw io::InputError(path, "",
                       "not found here (run from the sweetspot repository) nor installed at " +
                           installed + ": give " + option + " with the shipped designs' path");
}

}  // namespace

int Table1Command::run() const {
  const std::string folder = shipped(dir, "--dir", command->count("--dir") > 0);
  OutputPlan plan;
  plan.read_folder(folder);
  out.plan(plan);
  io::OutputSet outputs;
  out.emit(reports::table1_report(studies::compute_table1(folder), out.parsed()), outputs);
  outputs.commit();
  return kExitOk;
}

void FigureCommand::add_to(CLI::App& app) {
  command = app.add_subcommand("figure", "Data (CSV) and plot (PNG) of Fig. 5 or Fig. 11");
  command->add_option("number", number, "5 or 11")->required()->check(CLI::IsMember({5, 11}));
  command->add_option("--design", design, "The beam")->capture_default_str();
  add_output_option(command, "--output,-o", csv_path,
                    "Write the CSV to FILE instead of stdout (- for stdout)");
  add_output_option(command, "--plot", png, "Also render the plot to this PNG file");
}

int FigureCommand::run() const {
  const std::string beam_path = shipped(design, "--design", command->count("--design") > 0);
  OutputPlan plan;
  plan.read(beam_path);
  OutputOptions{"csv", csv_path}.plan(plan);
  if (!png.empty()) plan.write("--plot", png);
  const io::DesignFile beam = io::load_design(beam_path);
  if (beam.design.support.kind == Support::Kind::kRigidSurface) {
    throw io::InputError(beam.source, "/support",
                         "a rigid surface has no implement, so no beam to draw the figure of");
  }
  const reports::Figure data = number == 5 ? reports::figure5(beam, studies::figure5_data(beam))
                                           : reports::figure11(beam, studies::figure11_data(beam));
  io::OutputSet outputs;
  OutputOptions{"csv", csv_path}.emit(data.csv, outputs);
  if (!png.empty()) {
    if (const int failed = render_or_warn(data.plot, png, outputs); failed != kExitOk)
      return failed;
  }
  outputs.commit();
  std::cerr << data.summary << "\n";
  return kExitOk;
}

void ReportCommand::add_to(CLI::App& app) {
  command = app.add_subcommand("report",
                               "Reproduce Table I and Figs. 5 and 11, the beam's modes and the "
                               "shipped studies into a folder");
  command->add_option("--designs", designs, "Folder holding table1/ and paper-beam.json")
      ->capture_default_str();
  add_output_folder_option(command, "--out", out_dir, "Folder to write")->capture_default_str();
  command->add_option("design", design,
                      "A design file: write its report as one HTML page (with --html) instead");
  add_set_option(command, settings);
  add_output_option(command, "--html", html,
                    "With a design: the self-contained HTML page to write (a phone or a "
                    "desktop browser opens it; no network needed)");
}

int ReportCommand::run() const {
  if (design.empty() && html.empty()) {
    OutputPlan plan;
    plan.read_folder(designs);
    plan.write_folder("--out", out_dir);
    // Each file is checked again once its name is known, before any is written.
    write_reports(designs, out_dir, std::cout,
                  [&plan](const std::string& file) { plan.write("--out", file, true); });
    return kExitOk;
  }
  for (const char* option : {"--designs", "--out"}) {
    if (command->count(option)) {
      throw CLI::ValidationError(std::string(option) +
                                 ": only for the reports folder (sweetspot report), not with a "
                                 "design's page (DESIGN.json --html FILE)");
    }
  }
  if (design.empty()) {
    std::cerr << "sweetspot: report --html: needs a design file (sweetspot report DESIGN.json "
                 "--html FILE)\n";
    return kExitBadInput;
  }
  if (html.empty()) {
    std::cerr << "sweetspot: report " << io::one_line(design)
              << ": a design's report is a web page: give --html FILE\n";
    return kExitBadInput;
  }
  OutputPlan plan;
  plan.read(design);
  plan.write("--html", html);
  const std::vector<studies::Setting> set = studies::parse_settings(settings);
  const io::DesignFile file = studies::load_design(design, set);
  io::Json document = io::read_json_file(design);
  studies::apply_settings(document, set);
  io::write_file_atomically(
      html, reports::design_html_report(file, document, studies::design_page(file)));
  say_written(html);
  return kExitOk;
}

}  // namespace sweetspot::cli
