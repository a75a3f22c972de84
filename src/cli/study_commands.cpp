// Studies: `sweetspot optimize STUDY.json` and `sweetspot sweep STUDY.json`.

#include <fmt/format.h>
#include <unistd.h>

#include <algorithm>
#include <cstdlib>
#include <iostream>
#include <string>
#include <vector>

#include "cli/checks.hpp"
#include "cli/commands.hpp"
#include "cli/progress.hpp"
#include "io/atomic_file.hpp"
#include "io/input_error.hpp"
#include "io/parallel.hpp"
#include "optimizer/optimize.hpp"
#include "reports/optimization_report.hpp"
#include "studies/optimization.hpp"
#include "studies/study.hpp"
#include "studies/sweep.hpp"

namespace sweetspot::cli {

void OptimizeCommand::add_to(CLI::App& app) {
  command = app.add_subcommand(
      "optimize", "Search a study's variables for the best design under its constraints (NLopt)");
  command->add_option("study", study_path, "Study file (JSON)")->required();
  add_output_option(command, "--plot", plot, "Also render the convergence plot to this PNG file");
  out.add_to(command);
  add_output_option(command, "--html", html,
                    "Also write the report as one self-contained web page (a phone or a desktop "
                    "browser opens it; no network needed), when the study has an optimum; "
                    "standard output then says only what was written, the text report going to "
                    "--output when given");
  threads = io::all_cores();
  command
      ->add_option("--threads", threads,
                   "Threads for independent evaluations (differences, samples of the box) when "
                   "one costs over 0.1 ms, as the modal and collision models do (default: all "
                   "cores); the search and its answer are the same whatever the threads")
      ->check(whole_in(1, optimizer::kMaxThreads));
  command->footer(
      "Examples:\n"
      "  sweetspot optimize designs/studies/1-lowest-wrist-force-table1-ranges.json\n"
      "  sweetspot optimize study.json --html study.html\n"
      "  sweetspot optimize study.json --format json -o result.json --plot convergence.png");
}

int OptimizeCommand::run() const {
  studies::Study study = studies::load_study(study_path);
  OutputPlan plan;
  plan.read(study_path);
  plan.read(study.design_source);
  if (html.empty() || !out.output.empty()) out.plan(plan);
  if (!html.empty()) plan.write("--html", html);
  if (!plot.empty()) plan.write("--plot", plot);
  study.options.threads = threads;
  const studies::OptimizationResult result = studies::run_optimization(study);
  // The report is complete whatever the outcome: an infeasible study's names
  // the least violating design and each violated constraint. It is not the
  // answer asked for, so it never replaces an --output file: it goes to
  // standard output, and the file is left as it was.
  // A best design whose printed form does not give the search's numbers is
  // a defect of sweetspot, never an answer: the report (with the printed
  // design's values) goes to standard output and the run ends with exit 1.
  const bool consistent = result.inconsistency.empty();
  const bool optimum = result.outcome == studies::Outcome::kOptimum && consistent;
  const std::string report = reports::optimization_report(study, result, out.parsed(), true);
  io::OutputSet outputs;
  if (optimum && !html.empty()) {
    if (!out.output.empty()) out.emit(report, outputs);
    outputs.write(html, reports::optimization_html(study, result));
  } else if (optimum) {
    out.emit(report, outputs);
  } else {
    std::cout << report;
  }
  if (out.parsed() == io::Format::kMarkdown && !out.output.empty() && optimum) {
    std::cerr << result.summary.brief_report() << "\n";
  }
  const int plotted = plot.empty()
                          ? kExitOk
                          : render_or_warn(reports::convergence_plot(study, result), plot, outputs);
  if (plotted != kExitOk) return plotted;  // a file that could not be written comes first
  outputs.commit();
  if (optimum && !html.empty()) say_written(html);
  const std::string where = out.output.empty() && html.empty()
                                ? std::string("the report gives")
                                : "the report on standard output gives";
  std::string kept_files;
  for (const std::string& file : {out.output, html})
    if (!file.empty()) kept_files += (kept_files.empty() ? "" : " and ") + io::one_line(file);
  const std::string kept = kept_files.empty() ? "" : " (" + kept_files + " left as it was)";
  if (!consistent) {
    std::cerr << "sweetspot: internal error: " << io::one_line(study.source) << ": "
              << io::one_line(result.inconsistency) << kept << "\n";
    return kExitRuntimeError;
  }
  switch (result.outcome) {
    case studies::Outcome::kOptimum:
      return kExitOk;
    case studies::Outcome::kInfeasible:
      std::cerr << "sweetspot: " << io::one_line(study.source)
                << ": no design meets the constraints; " << where << " the least violating one"
                << kept << "\n";
      return kExitInfeasible;
    case studies::Outcome::kNoValue:
      std::cerr << "sweetspot: " << io::one_line(study.source)
                << ": no valid design was found: " << result.no_value << kept << "\n";
      return kExitInfeasible;
  }
  return kExitOk;
}

namespace {

// The plot of the sweep's k-th output: FILE, or FILE-<output>.png for several.
std::string sweep_png(const studies::Study& study, const std::string& plot, std::size_t k) {
  return study.sweep_outputs.size() > 1
             ? plot_file(plot, "-" + std::string(study.sweep_outputs[k]->name))
             : plot;
}

}  // namespace

void SweepCommand::add_to(CLI::App& app) {
  command = app.add_subcommand(
      "sweep",
      "What-if grid over one or two of a study's variables: every output at every point (CSV)");
  threads = io::all_cores();
  command->add_option("study", study_path, "Study file (JSON) with variables, grid and outputs")
      ->required();
  add_output_option(command, "--output,-o", csv_path,
                    "Write the CSV to FILE (atomically) instead of stdout (- for stdout)");
  add_output_option(command, "--plot", plot,
                    "Also render plots: FILE.png, or FILE-<output>.png for several outputs");
  command
      ->add_option("--format", format,
                   "csv (streamed in grid order), or json: JSON Lines, one object per grid point "
                   "with the same keys as the CSV header (numbers as numbers, a missing value "
                   "null), in grid order")
      ->check(CLI::IsMember({"csv", "json"}))
      ->capture_default_str();
  command->add_flag("--quiet,-q", quiet, "No progress on standard error");
  command
      ->add_option("--threads", threads,
                   "Threads to use (default: all cores); rows stay in grid order")
      ->check(whole_in(1, 1024));
}

int SweepCommand::run() const {
  const studies::Study study = studies::load_study(study_path);
  OutputPlan plan;
  plan.read(study_path);
  plan.read(study.design_source);
  OutputOptions{"csv", csv_path}.plan(plan);
  if (!plot.empty()) {
    if (study.sweep_outputs.size() > 1) require_plot_stem("--plot", plot);
    for (std::size_t k = 0; k < study.sweep_outputs.size(); ++k)
      plan.write("--plot", sweep_png(study, plot, k));
  }
  studies::SweepOptions options{threads};
  options.format = format == "json" ? io::Format::kJson : io::Format::kCsv;
  Progress shown("designs", !quiet);
  const auto progress = [&](std::size_t done, std::size_t total) {
    shown.update(done, total);
    if (done == total) shown.finish();
  };
  std::vector<io::Plot> plots;
  io::OutputSet outputs;
  OutputOptions{"csv", csv_path}.emit_stream(
      [&](std::ostream& out) { plots = studies::run_sweep(study, out, progress, options); },
      outputs);
  if (!plot.empty() && plots.empty()) {
    std::cerr << "sweetspot: no plot: the grid has more than " << studies::kMaxPlotPoints
              << " points\n";
  }
  if (!plot.empty()) {
    for (std::size_t k = 0; k < plots.size(); ++k) {
      // The first plot that cannot be made ends the run: one message, exit 1, nothing written.
      if (const int failed = render_or_warn(plots[k], sweep_png(study, plot, k), outputs);
          failed != kExitOk)
        return failed;
    }
  }
  outputs.commit();
  return kExitOk;
}

}  // namespace sweetspot::cli
