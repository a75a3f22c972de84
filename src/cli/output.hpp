#pragma once

// What every subcommand shares: the exit statuses, where its text goes
// (standard output or a file written atomically) and how a plot is named and
// rendered.

#include <CLI/CLI.hpp>
#include <functional>
#include <ostream>
#include <string>

#include "cli/output_plan.hpp"
#include "io/atomic_file.hpp"
#include "io/format.hpp"
#include "io/plot.hpp"

namespace sweetspot::cli {

// Exit statuses (README.md and docs/command-line.md, "Exit status").
inline constexpr int kExitOk = 0;
inline constexpr int kExitRuntimeError =
    1;  // not the input's fault: a write or read error (ENOSPC, EIO)
inline constexpr int kExitBadInput = 2;  // bad input or usage, one line on stderr
inline constexpr int kExitInfeasible =
    3;  // a study with no feasible design (its report is written)
// The model cannot answer the design (sweetspot::ModelRefusal): its inputs are
// in range, an evaluation broke an invariant of its fidelity. One line on stderr.
inline constexpr int kExitModelRefused = 3;

// --format and --output of a subcommand: standard output, or FILE written
// as io/atomic_file.hpp says (a regular file replaced atomically, a device
// or FIFO written directly).
struct OutputOptions {
  std::string format = "md";
  std::string output;  // "" or "-" = standard output

  // Registers --format (with `formats` allowed) and --output/-o.
  void add_to(CLI::App* command, std::vector<std::string> formats = {"md", "json", "csv"});
  io::Format parsed() const;
  // Adds the output to `plan`: --output FILE, else standard output.
  void plan(OutputPlan& plan) const;
  // Writes `text` where the options say: standard output at once, a file
  // into `outputs` (replaced when the command commits them all).
  void emit(const std::string& text, io::OutputSet& outputs) const;
  // Streams through `write` where the options say.
  void emit_stream(const std::function<void(std::ostream&)>& write, io::OutputSet& outputs) const;
};

// The label of the standard output a command writes its text to when it
// has no --output: named in the output plan's messages.
inline constexpr const char* kReportOnStandardOutput = "the report on standard output";

// Registers an output option as the output plan knows it: its group in
// --help is "Output files" (kOutputGroup), which the test that walks every
// output option reads, so that a new output is tested the day it is added;
// its value is shown as FILE (a folder's, add_output_folder_option, as DIR).
inline constexpr const char* kOutputGroup = "Output files";
CLI::Option* add_output_option(CLI::App* command, const std::string& name, std::string& file,
                               const std::string& description);
CLI::Option* add_output_folder_option(CLI::App* command, const std::string& name,
                                      std::string& folder, const std::string& description);

// "f.png" with suffix "-at-2cm" -> "f-at-2cm.png"; "f" -> "f-at-2cm.png".
std::string plot_file(const std::string& png, const std::string& suffix);

// Renders `plot` into `outputs` as `png`, or says on stderr why it could
// not: kExitOk or kExitRuntimeError (then nothing of the command is written).
int render_or_warn(const io::Plot& plot, const std::string& png, io::OutputSet& outputs);
// The same for a gnuplot script that sets a png terminal (a heat map).
int render_script_or_warn(const std::string& script, const std::string& png,
                          io::OutputSet& outputs);

}  // namespace sweetspot::cli
