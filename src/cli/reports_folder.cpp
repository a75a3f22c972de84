#include "cli/reports_folder.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <filesystem>
#include <optional>
#include <sstream>
#include <stdexcept>
#include <utility>

#include "io/atomic_file.hpp"
#include "io/input_error.hpp"
#include "reports/fidelity_report.hpp"
#include "reports/modes_report.hpp"
#include "reports/optimization_report.hpp"
#include "reports/paper_reports.hpp"
#include "reports/response_report.hpp"
#include "reports/string_report.hpp"
#include "reports/tension_report.hpp"
#include "studies/modes.hpp"
#include "studies/optimization.hpp"
#include "studies/paper.hpp"
#include "studies/response.hpp"
#include "studies/string_ticket.hpp"
#include "studies/study.hpp"
#include "studies/sweep.hpp"
#include "studies/tension_study.hpp"

namespace sweetspot::cli {
namespace {

namespace fs = std::filesystem;

// The first sentence after "**Answer.**" in a study report.
std::string answer_of(const std::string& md) {
  const auto at = md.find("**Answer.** ");
  if (at == std::string::npos) return "";
  const auto start = at + 12;
  return md.substr(start, md.find('\n', start) - start);
}

std::vector<fs::path> study_files(const std::string& designs_dir) {
  std::vector<fs::path> files;
  const fs::path folder = fs::path(designs_dir) / "studies";
  if (!fs::exists(folder)) return files;
  for (const auto& entry : fs::directory_iterator(folder)) {
    if (entry.path().extension() != ".json") continue;
    // Designs used by the studies live beside them; a study has variables.
    if (io::read_json_file(entry.path().string()).contains("variables"))
      files.push_back(entry.path());
  }
  std::sort(files.begin(), files.end());
  return files;
}

// The paper beam's modes, Euler-Bernoulli and Timoshenko.
void write_modes_reports(const std::string& designs_dir, const reports::ReportWriter& write,
                         std::vector<reports::ReportEntry>& entries) {
  const io::DesignFile beam = io::load_design(designs_dir + "/paper-beam.json");
  const studies::ModesData modes =
      studies::compute_modes(beam, 3, 1e-6, ModeOptions::Method::kExact);
  write.text("modes-paper-beam.md", reports::modes_report(modes, io::Format::kMarkdown));
  write.text("modes-paper-beam.csv", reports::modes_report(modes, io::Format::kCsv));
  write.plot("modes-paper-beam.png", reports::modes_plot(modes));
  entries.push_back(
      {"[modes-paper-beam.md](modes-paper-beam.md), [.csv](modes-paper-beam.csv), "
       "[.png](modes-paper-beam.png)",
       fmt::format(
           "Vibration modes of the paper's beam, free and hand-held (paper: 193 Hz free, 171 Hz "
           "held, nodes 15.8 cm from each end): {:.1f} Hz free with its node {:.1f} cm from the "
           "end; {:.1f} Hz held (damping ratio {:.3f}).",
           modes.free.modes[0].frequency_Hz,
           100 * (beam.design.implement.length_m() - modes.free.modes[0].nodes_from_butt_m.back()),
           modes.held_fundamental.value().frequency_Hz,
           modes.held_fundamental.value().damping_ratio)});

  const io::DesignFile thick = io::load_design(designs_dir + "/paper-beam-timoshenko.json");
  const studies::ModesData shear =
      studies::compute_modes(thick, 3, 1e-6, ModeOptions::Method::kFiniteElement);
  write.text("modes-paper-beam-timoshenko.md", reports::modes_report(shear, io::Format::kMarkdown));
  entries.push_back(
      {"[modes-paper-beam-timoshenko.md](modes-paper-beam-timoshenko.md)",
       fmt::format("The beam with shear and rotary inertia (Timoshenko, G = 1 GPa): modes 2 and 3 "
                   "at {:.1f} "
                   "and {:.1f} Hz, against {:.1f} and {:.1f} Hz without (Euler-Bernoulli) and the "
                   "measured 506 "
                   "and 962 Hz.",
                   shear.free.modes[1].frequency_Hz, shear.free.modes[2].frequency_Hz,
                   modes.free.modes[1].frequency_Hz, modes.free.modes[2].frequency_Hz)});
}

// Every shipped study: an optimisation's report and convergence plot, a
// sweep's CSV and plots.
void write_study_reports(const std::string& designs_dir, const reports::ReportWriter& write,
                         std::vector<reports::ReportEntry>& entries) {
  for (const fs::path& path : study_files(designs_dir)) {
    const studies::Study study = studies::load_study(path.string());
    const std::string stem = "studies/" + path.stem().string();
    if (!study.objective.empty()) {
      const studies::OptimizationResult result = studies::run_optimization(study);
      // A shipped study whose printed best design does not re-evaluate to
      // the search's numbers is a defect of sweetspot, never a report.
      if (!result.inconsistency.empty()) {
        throw std::runtime_error("internal error: " + study.source + ": " + result.inconsistency);
      }
      const std::string md =
          reports::optimization_report(study, result, io::Format::kMarkdown, false);
      write.text(stem + ".md", md);
      write.plot(stem + ".png", reports::convergence_plot(study, result));
      entries.push_back({fmt::format("[{0}.md]({0}.md), [.png]({0}.png)", stem),
                         study.name + ": " + answer_of(md)});
    } else {
      std::ostringstream csv;
      const std::vector<io::Plot> plots =
          studies::run_sweep(study, csv, [](std::size_t, std::size_t) {});
      write.text(stem + ".csv", csv.str());
      std::string links = fmt::format("[{0}.csv]({0}.csv)", stem);
      for (std::size_t k = 0; k < plots.size(); ++k) {
        const std::string png = fmt::format("{}-{}.png", stem, study.sweep_outputs[k]->name);
        write.plot(png, plots[k]);
        links += fmt::format(", [{}]({})", study.sweep_outputs[k]->name, png);
      }
      entries.push_back(
          {links, study.name + (study.question.empty() ? "" : ": " + study.question)});
    }
  }
}

// The string beds of every shipped design that has one, and for the
// stringer's tickets (designs/strings/) the tension on each that keeps every
// other's stiffness.
void write_string_reports(const std::string& designs_dir, const reports::ReportWriter& write,
                          std::vector<reports::ReportEntry>& entries) {
  std::vector<reports::ShippedBed> beds;
  std::vector<std::pair<std::string, io::DesignFile>> tickets;
  std::vector<fs::path> files;
  for (const char* folder : {"racquets", "strings"}) {
    const fs::path dir = fs::path(designs_dir) / folder;
    if (!fs::exists(dir)) continue;
    for (const auto& entry : fs::directory_iterator(dir))
      if (entry.path().extension() == ".json") files.push_back(entry.path());
  }
  std::sort(files.begin(), files.end());
  for (const fs::path& path : files) {
    io::DesignFile file = io::load_design(path.string());
    if (!file.design.strings) continue;
    const std::string relative = fs::relative(path, designs_dir).generic_string();
    beds.push_back({relative, file.name, studies::read_bed(file.design)});
    if (relative.starts_with("strings/")) tickets.emplace_back(relative, std::move(file));
  }
  if (beds.empty()) return;
  std::vector<reports::ShippedMatch> matches;
  for (const auto& [name, file] : tickets) {
    for (const auto& [like_name, like] : tickets) {
      if (name == like_name) continue;
      matches.push_back({name, like_name,
                         studies::tension_for(file.design, studies::BedQuantity::kStiffness,
                                              studies::read_bed(like.design).stiffness_N_m)});
    }
  }
  write.text("string-beds.md", reports::string_beds_report(beds, matches, io::Format::kMarkdown));
  write.text("string-beds.csv", reports::string_beds_report(beds, matches, io::Format::kCsv));
  std::string says =
      fmt::format("The string beds of the {} shipped designs that have one", beds.size());
  if (!matches.empty()) {
    const studies::TensionAnswer& t = matches.front().answer;
    says += fmt::format(": {} keeps the stiffness of {} at {} lb", matches.front().file,
                        matches.front().like_file, io::significant(t.rounded_pull_lb, 4));
  }
  entries.push_back({"[string-beds.md](string-beds.md), [.csv](string-beds.csv)", says + "."});
}

}  // namespace

void write_reports(const std::string& designs_dir, const std::string& out_dir, std::ostream& log,
                   const std::function<void(const std::string&)>& before_writing) {
  // Nothing is created before the inputs are known to be there.
  if (!fs::is_directory(designs_dir)) {
    throw io::InputError(designs_dir, "",
                         "not a folder of designs (expected table1/, paper-beam.json, studies/)");
  }
  // Every file is held until all are made, then written all or none: a study
  // that fails halfway leaves the folder as it was.
  std::vector<std::pair<std::string, std::string>> files;
  std::vector<std::string> skipped;
  const reports::ReportWriter write{
      [&](const std::string& name, const std::string& content) {
        files.emplace_back(out_dir + "/" + name, content);
      },
      [&](const std::string& name, const io::Plot& plot) {
        std::string why;
        if (std::optional<std::string> png = render_png_bytes(plot, &why)) {
          files.emplace_back(out_dir + "/" + name, std::move(*png));
        } else {
          skipped.push_back(out_dir + "/" + name + ": " + why);
        }
      }};

  std::vector<reports::ReportEntry> entries =
      reports::write_paper_reports(studies::paper_results(designs_dir), write);

  write_modes_reports(designs_dir, write, entries);

  for (reports::ReportEntry& entry :
       reports::write_response_reports(studies::response_reports(designs_dir), write))
    entries.push_back(std::move(entry));
  for (reports::ReportEntry& entry :
       reports::write_tension_report(studies::tension_study(designs_dir), write))
    entries.push_back(std::move(entry));

  write_study_reports(designs_dir, write, entries);
  write_string_reports(designs_dir, write, entries);
  for (reports::ReportEntry& entry :
       reports::write_fidelity_report(studies::fidelity_rows(designs_dir), write))
    entries.push_back(std::move(entry));

  std::string index =
      "# sweetspot reports\n\n"
      "Written by `scripts/run` (that is, `sweetspot report`); do not edit by hand. A test "
      "regenerates every `.md` and `.csv` here and fails when they differ from what is committed. "
      "PNG plots are rendered by gnuplot from the same data. Timings are not in these files (they "
      "would never reproduce); they are in the benchmark reports.\n\n"
      "| files | what they show |\n|---|---|\n";
  for (const reports::ReportEntry& e : entries)
    index += "| " + e.files + " | " + io::md_cell(e.says) + " |\n";
  write.text("README.md", index);
  if (before_writing) {
    for (const auto& file : files) before_writing(file.first);
  }
  io::write_files_atomically(files);
  for (const auto& file : files) log << "wrote " << io::terminal_text(file.first) << "\n";
  for (const std::string& file : skipped) log << "skipped " << io::terminal_text(file) << "\n";
  log << "\nSummary (index: " << io::terminal_text(out_dir + "/README.md") << "):\n";
  for (const reports::ReportEntry& e : entries) log << "- " << io::terminal_text(e.says) << "\n";
}

}  // namespace sweetspot::cli
