#pragma once

// What every subcommand shares: the exit statuses, where its text goes
// (standard output or a file written atomically) and how a plot is named and
// rendered.

#include <CLI/CLI.hpp>
#include <functional>
#include <ostream>
#include <string>

#include "io/format.hpp"
#include "io/plot.hpp"

namespace sweetspot::cli {

// Exit statuses (README "Exit status").
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
  std::string output;  // "" = standard output

  // Registers --format (with `formats` allowed) and --output/-o.
  void add_to(CLI::App* command, std::vector<std::string> formats = {"md", "json", "csv"});
  io::Format parsed() const;
  // Writes `text` where the options say.
  void emit(const std::string& text) const;
  // Streams through `write` where the options say.
  void emit_stream(const std::function<void(std::ostream&)>& write) const;
};

// Throws CLI::ValidationError when --html and --output name the same file
// (the page would replace the text report, or the report the page).
void require_distinct_outputs(const std::string& html, const std::string& output);

// "f.png" with suffix "-at-2cm" -> "f-at-2cm.png"; "f" -> "f-at-2cm.png".
std::string plot_file(const std::string& png, const std::string& suffix);

// Renders `plot` to `png`, or says on stderr why it could not: kExitOk or kExitRuntimeError.
int render_or_warn(const io::Plot& plot, const std::string& png);

}  // namespace sweetspot::cli
