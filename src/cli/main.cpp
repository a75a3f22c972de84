// The sweetspot command line: reads designs, runs the physics core and writes
// reports. Exit status: 0 success, 1 a run-time failure (cannot write a file),
// 2 bad input or bad usage, with one line on stderr.

#include <CLI/CLI.hpp>
#include <fmt/format.h>

#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <iostream>
#include <string>

#include "sweetspot/evaluate.hpp"
#include "sweetspot/io/atomic_file.hpp"
#include "sweetspot/io/batch.hpp"
#include "sweetspot/io/bench.hpp"
#include "sweetspot/io/design_reader.hpp"
#include "sweetspot/io/format.hpp"
#include "sweetspot/io/input_error.hpp"
#include "sweetspot/io/paper_reports.hpp"
#include "sweetspot/io/modes_report.hpp"
#include "sweetspot/io/parallel.hpp"
#include "sweetspot/io/reports.hpp"
#include "sweetspot/io/response_report.hpp"
#include "sweetspot/io/study.hpp"

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

sweetspot::Fidelity fidelity_of(const std::string& name, const sweetspot::Design& design) {
  if (name == "rigid") return sweetspot::Fidelity::kRigid;
  if (name == "modal") return sweetspot::Fidelity::kModal;
  if (name == "response") return sweetspot::Fidelity::kResponse;
  return sweetspot::needed_fidelity(design);
}

// Renders a plot, or says on stderr why it could not.
int render_or_warn(const sweetspot::io::Plot& plot, const std::string& png) {
  std::string why;
  if (sweetspot::io::render_png(plot, png, &why)) return 0;
  std::cerr << "sweetspot: " << png << ": " << why << "\n";
  return kExitRuntimeError;
}

struct OptimizeCommand {
  CLI::App* command = nullptr;
  std::string study_path;
  std::string plot;
  OutputOptions out;

  void add_to(CLI::App& app) {
    command = app.add_subcommand(
        "optimize", "Search a study's variables for the best design under its constraints (NLopt)");
    command->add_option("study", study_path, "Study file (JSON)")->required();
    command->add_option("--plot", plot, "Also render the convergence plot to this PNG file");
    out.add_to(command);
  }

  int run() const {
    const auto study = sweetspot::io::load_study(study_path);
    const auto result = sweetspot::io::run_optimization(study);
    out.emit(sweetspot::io::optimization_report(study, result, out.parsed(), true));
    if (out.parsed() == Format::kMarkdown && !out.output.empty()) {
      std::cerr << result.summary.brief_report() << "\n";
    }
    const int plotted = plot.empty() ? 0 : render_or_warn(sweetspot::io::convergence_plot(study, result), plot);
    if (!result.summary.feasible) {
      // The report (the least infeasible design) is complete; the study is what is wrong.
      std::cerr << "sweetspot: " << study.source
                << ": /constraints: no design within the variables' bounds satisfies them all\n";
      return kExitBadInput;
    }
    return plotted;
  }
};

struct ModesCommand {
  CLI::App* command = nullptr;
  std::string design_path;
  int modes = 3;
  double tolerance = 1e-6;
  std::string method = "exact";
  std::string plot;
  OutputOptions out;

  void add_to(CLI::App& app) {
    command = app.add_subcommand(
        "modes", "Vibration modes free and hand-held: frequencies, damping, nodes, shapes (csv)");
    command->add_option("design", design_path, "Design file (JSON) with the frame's stiffness")->required();
    command->add_option("--modes,-n", modes, "How many flexible modes")->check(CLI::Range(1, sweetspot::kMaxExactModes))->capture_default_str();
    command->add_option("--tol", tolerance, "Relative error allowed in the finite-element frequencies")
        ->check(CLI::Range(sweetspot::kMinRelTol, sweetspot::kMaxRelTol))
        ->capture_default_str();
    command->add_option("--method", method, "Free modes: exact (transfer matrices) or fe")
        ->check(CLI::IsMember({"exact", "fe"}))
        ->capture_default_str();
    command->add_option("--plot", plot, "Also render the mode shapes to this PNG file");
    out.add_to(command);
  }

  int run() const {
    const auto design = sweetspot::io::load_design(design_path);
    const auto data = sweetspot::io::compute_modes(
        design, modes, tolerance,
        method == "fe" ? sweetspot::ModeOptions::Method::kFiniteElement : sweetspot::ModeOptions::Method::kExact);
    out.emit(sweetspot::io::modes_report(data, out.parsed()));
    return plot.empty() ? 0 : render_or_warn(sweetspot::io::modes_plot(data), plot);
  }
};

struct ResponseCommand {
  CLI::App* command = nullptr;
  std::string design_path;
  std::vector<double> at{0.02, 0.16};
  std::vector<double> impacts;
  bool held = false;
  double until_ms = 20.0;
  std::string csv_path;
  std::string plot;

  void add_to(CLI::App& app) {
    command = app.add_subcommand(
        "response", "Velocity of points of the implement after the impact: rigid (dc) and vibration (ac) parts");
    command->add_option("design", design_path, "Design file (JSON) with the frame's stiffness")->required();
    // CLI11 reads "" as 0: an empty point is refused, not observed at the butt.
    const CLI::Validator a_number(
        [](const std::string& value) { return value.empty() ? std::string("an empty point (expected metres)") : ""; },
        "POINTS");
    command->add_option("--at", at, "Observation points, m from the butt")
        ->delimiter(',')
        ->check(a_number)
        ->capture_default_str();
    command->add_option("--impacts", impacts, "Impact points, m from the butt (default: the design's)")
        ->delimiter(',')
        ->check(a_number);
    command->add_flag("--held", held, "Held in the hand (default: free, as the paper's suspended beam)");
    command->add_option("--until-ms", until_ms, "Time window after the impact starts")
        ->check(CLI::Range(0.01, 1000.0))
        ->capture_default_str();
    command->add_option("--output,-o", csv_path, "Write the CSV to FILE instead of stdout");
    command->add_option("--plot", plot, "Also plot: FILE-at-<cm>cm.png per observation point");
  }

  int run() const {
    const auto design = sweetspot::io::load_design(design_path);
    sweetspot::io::ResponseRequest request;
    request.points_from_butt_m = at;
    request.impacts_from_butt_m = impacts;
    request.hand_held = held;
    request.until_s = until_ms / 1e3;
    const auto data = sweetspot::io::compute_response(design, request);
    const std::string csv = sweetspot::io::response_csv(data);
    if (csv_path.empty()) {
      std::cout << csv;
    } else {
      sweetspot::io::write_file_atomically(csv_path, csv);
    }
    if (plot.empty()) return 0;
    const auto plots = sweetspot::io::response_plots(data);
    const auto dot = plot.rfind(".png");
    const std::string stem = dot == std::string::npos ? plot : plot.substr(0, dot);
    int status = 0;
    for (std::size_t k = 0; k < plots.size(); ++k) {
      status = std::max(status, render_or_warn(plots[k], fmt::format("{}-at-{:g}cm.png", stem, at[k] * 100)));
    }
    return status;
  }
};

struct SweepCommand {
  CLI::App* command = nullptr;
  std::string study_path;
  std::string csv_path;
  std::string plot;
  bool quiet = false;
  int threads = sweetspot::io::all_cores();

  void add_to(CLI::App& app) {
    command = app.add_subcommand(
        "sweep", "What-if grid over one or two of a study's variables: every output at every point (CSV)");
    command->add_option("study", study_path, "Study file (JSON) with variables, grid and outputs")
        ->required();
    command->add_option("--output,-o", csv_path, "Write the CSV to FILE (atomically) instead of stdout");
    command->add_option("--plot", plot,
                        "Also render plots: FILE.png, or FILE-<output>.png for several outputs");
    command->add_flag("--quiet,-q", quiet, "No progress on the terminal");
    command->add_option("--threads", threads, "Threads to use (default: all cores); rows stay in grid order")
        ->check(CLI::Range(1, 1024));
  }

  int run() const {
    const auto study = sweetspot::io::load_study(study_path);
    const sweetspot::io::SweepOptions options{threads};
    const bool show_progress = !quiet && isatty(fileno(stderr));
    const auto progress = [&](std::size_t done, std::size_t total) {
      if (show_progress) std::cerr << fmt::format("\r{}/{} designs", done, total) << std::flush;
      if (show_progress && done == total) std::cerr << "\n";
    };
    std::vector<sweetspot::io::Plot> plots;
    if (csv_path.empty()) {
      plots = sweetspot::io::run_sweep(study, std::cout, progress, options);
    } else {
      sweetspot::io::write_stream_atomically(
          csv_path, [&](std::ostream& file) { plots = sweetspot::io::run_sweep(study, file, progress, options); });
    }
    if (plot.empty()) return 0;
    if (plots.empty()) {
      std::cerr << "sweetspot: no plot: the grid has more than " << sweetspot::io::kMaxPlotPoints
                << " points\n";
      return 0;
    }
    int status = 0;
    for (std::size_t k = 0; k < plots.size(); ++k) {
      std::string png = plot;
      if (plots.size() > 1) {
        const auto dot = png.rfind(".png");
        png = (dot == std::string::npos ? png : png.substr(0, dot)) + "-" +
              std::string(study.sweep_outputs[k]->name) + ".png";
      }
      status = std::max(status, render_or_warn(plots[k], png));
    }
    return status;
  }
};

// evaluate --batch: exit 0 when every row evaluated, 1 when some failed.
int run_batch_command(const std::string& path, const std::string& base, int threads,
                      const std::string& fidelity, double tolerance, const OutputOptions& out) {
  sweetspot::io::BatchOptions options;
  options.csv_input = path.size() >= 4 && path.compare(path.size() - 4, 4, ".csv") == 0;
  if (!base.empty()) {
    options.base = sweetspot::io::read_json_file(base);
    // A base that is not a valid design on its own is the caller's error, not every row's.
    if (!options.base->contains("implement")) {
      throw sweetspot::io::InputError(base, "/implement", "missing: the base design needs an implement");
    }
  }
  options.format = out.parsed() == Format::kJson ? Format::kJson : Format::kCsv;
  options.threads = threads;
  options.fidelity = fidelity;
  options.modal_tolerance = tolerance;
  std::ifstream in(path, std::ios::binary);
  if (!in) throw sweetspot::io::InputError(path, "", "cannot open the file for reading");
  sweetspot::io::BatchSummary summary;
  if (out.output.empty()) {
    summary = sweetspot::io::run_batch(in, path, options, std::cout);
  } else {
    sweetspot::io::write_stream_atomically(
        out.output, [&](std::ostream& file) { summary = sweetspot::io::run_batch(in, path, options, file); });
  }
  if (summary.failed > 0) {
    std::cerr << "sweetspot: " << summary.failed << " of " << summary.rows << " rows failed (see their error column)\n";
    return kExitRuntimeError;
  }
  return 0;
}

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
  std::string fidelity = "auto";
  double tolerance = 1e-6;
  CLI::App* evaluate = app.add_subcommand("evaluate", "Every quantity of the paper for one design");
  std::string batch_path;
  std::string batch_base;
  int threads = sweetspot::io::all_cores();
  evaluate->add_option("design", design_path, "Design file (JSON)");
  evaluate->add_option("--batch", batch_path,
                       "Evaluate a catalogue instead: JSON Lines (.jsonl, one design per line) or CSV "
                       "whose header names design fields (implement.mass_g,impact.from_butt_m,...); "
                       "output CSV (or JSON Lines with --format json), one row per input in order");
  evaluate->add_option("--base", batch_base, "With --batch: a design file giving every row's defaults");
  evaluate->add_option("--threads", threads, "With --batch: threads to use (default: all cores)")
      ->check(CLI::Range(1, 1024));
  evaluate->add_option("--fidelity", fidelity,
                       "rigid: the paper's rigid body; modal: also the vibration modes (needs the "
                       "frame's stiffness); response: also the frame's response to the ball (vibration "
                       "energy, a COR derived from cor_rigid); auto: the cheapest that answers the design")
      ->check(CLI::IsMember({"rigid", "modal", "response", "auto"}))
      ->capture_default_str();
  evaluate->add_option("--tol", tolerance, "Relative error allowed in the hand-held frequency")
      ->check(CLI::Range(sweetspot::kMinRelTol, sweetspot::kMaxRelTol))
      ->capture_default_str();
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
      app.add_subcommand("report", "Reproduce Table I and Figs. 5 and 11, the beam's modes and the shipped studies into a folder");
  report->add_option("--designs", report_designs, "Folder holding table1/ and paper-beam.json")
      ->capture_default_str();
  report->add_option("--out", report_dir, "Folder to write")->capture_default_str();

  OptimizeCommand optimize_cmd;
  optimize_cmd.add_to(app);
  SweepCommand sweep_cmd;
  sweep_cmd.add_to(app);
  ModesCommand modes_cmd;
  modes_cmd.add_to(app);
  ResponseCommand response_cmd;
  response_cmd.add_to(app);

  sweetspot::io::BenchOptions bench_options;
  std::string bench_what = "all";
  CLI::App* bench = app.add_subcommand(
      "bench", "Speed against error on this machine (median of repeated runs) into reports/");
  bench->add_option("what", bench_what,
                    "speed (the rigid model, the command line end to end, the optimizer, each fidelity), "
                    "modes, or all")
      ->check(CLI::IsMember({"speed", "modes", "all"}))
      ->capture_default_str();
  bench->add_option("--designs", bench_options.designs_dir, "Folder holding studies/")->capture_default_str();
  bench->add_option("--out", bench_options.out_dir, "Folder to write")->capture_default_str();
  bench->add_option("--repeats", bench_options.repeats, "Runs per figure (the median is reported)")
      ->check(CLI::Range(1, 1000))
      ->capture_default_str();

  try {
    app.parse(argc, argv);
  } catch (const CLI::CallForHelp& e) {
    return app.exit(e);
  } catch (const CLI::CallForAllHelp& e) {
    return app.exit(e);
  } catch (const CLI::CallForVersion& e) {
    return app.exit(e);
  } catch (const CLI::ParseError& e) {
    std::cerr << "sweetspot: " << e.what() << " (see --help)\n";
    return kExitBadInput;
  }

  int status = 0;
  try {
    status = [&]() -> int {
    if (*evaluate && !batch_path.empty()) {
      if (!design_path.empty()) throw CLI::ValidationError("give a design file or --batch, not both");
      return run_batch_command(batch_path, batch_base, threads,
                               evaluate->count("--fidelity") ? fidelity : std::string(), tolerance, evaluate_out);
    } else if (*evaluate) {
      if (design_path.empty()) throw CLI::ValidationError("design: a design file (or --batch FILE) is required");
      const auto design = sweetspot::io::load_design(design_path);
      sweetspot::Evaluation result;
      try {
        // The command line's --fidelity wins over the file's "fidelity".
        const std::string chosen = evaluate->count("--fidelity") ? fidelity : design.fidelity;
        result = sweetspot::evaluate(design.design, fidelity_of(chosen, design.design), tolerance);
      } catch (const std::invalid_argument& e) {
        sweetspot::io::rethrow_in(design, e);
      }
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
      sweetspot::io::write_reports(report_designs, report_dir, std::cout);
    } else if (*optimize_cmd.command) {
      return optimize_cmd.run();
    } else if (*sweep_cmd.command) {
      return sweep_cmd.run();
    } else if (*modes_cmd.command) {
      return modes_cmd.run();
    } else if (*response_cmd.command) {
      return response_cmd.run();
    } else if (*bench) {
      std::error_code no_exe;  // the command-line figures run this very program
      bench_options.executable = std::filesystem::read_symlink("/proc/self/exe", no_exe).string();
      if (bench_what != "modes") sweetspot::io::bench_speed(bench_options, std::cout);
      if (bench_what != "speed") sweetspot::io::bench_modes(bench_options, std::cout);
    }
    return 0;
    }();
  } catch (const CLI::ParseError& e) {
    std::cerr << "sweetspot: " << e.what() << "\n";
    return kExitBadInput;
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
  std::cout.flush();
  if (!std::cout) {
    std::cerr << "sweetspot: cannot write to standard output\n";
    return kExitRuntimeError;
  }
  return status;
}
