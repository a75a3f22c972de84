#include "cli/output.hpp"

#include <CLI/CLI.hpp>
#include <iostream>
#include <optional>

#include "io/atomic_file.hpp"
#include "io/input_error.hpp"

namespace sweetspot::cli {

void OutputOptions::add_to(CLI::App* command, std::vector<std::string> formats) {
  command->add_option("--format", format, "Output format")
      ->check(CLI::IsMember(std::move(formats)))
      ->capture_default_str();
  add_output_option(command, "--output,-o", output,
                    "Write to FILE instead of stdout (- for stdout; a regular file is replaced "
                    "atomically; a device or FIFO is written directly)");
}

void OutputOptions::plan(OutputPlan& plan) const {
  if (output.empty()) {
    plan.write(kReportOnStandardOutput, "-");
  } else {
    plan.write("--output", output);
  }
}

CLI::Option* add_output_option(CLI::App* command, const std::string& name, std::string& file,
                               const std::string& description) {
  return command->add_option(name, file, description)->group(kOutputGroup)->type_name("FILE");
}

CLI::Option* add_output_folder_option(CLI::App* command, const std::string& name,
                                      std::string& folder, const std::string& description) {
  return command->add_option(name, folder, description)->group(kOutputGroup)->type_name("DIR");
}

io::Format OutputOptions::parsed() const { return *io::parse_format(format); }

void OutputOptions::emit(const std::string& text, io::OutputSet& outputs) const {
  if (output.empty() || output == "-") {
    std::cout << text;
  } else {
    std::cout.flush();  // a device written directly gets it after what came before
    outputs.write(output, text);
  }
}

void OutputOptions::emit_stream(const std::function<void(std::ostream&)>& write,
                                io::OutputSet& outputs) const {
  if (output.empty() || output == "-") {
    // A write that fails (a full disk, `ulimit -f`) ends a long stream at once.
    const std::ios::iostate old = std::cout.exceptions();
    std::cout.exceptions(std::ios::badbit);
    try {
      write(std::cout);
      std::cout.flush();
    } catch (const std::ios::failure&) {
      std::cout.exceptions(old);
      if (!std::cout.bad()) throw;
      throw io::WriteError("standard output", "the write failed");
    }
    std::cout.exceptions(old);
  } else {
    std::cout.flush();
    outputs.write_stream(output, write);
  }
}

std::string plot_file(const std::string& png, const std::string& suffix) {
  const bool ends_png = png.size() >= 4 && png.compare(png.size() - 4, 4, ".png") == 0;
  return (ends_png ? png.substr(0, png.size() - 4) : png) + suffix + ".png";
}

namespace {

int png_or_warn(const std::optional<std::string>& png, const std::string& path,
                const std::string& why, io::OutputSet& outputs) {
  if (!png) {
    std::cerr << "sweetspot: cannot write " << io::one_line(path) << ": " << why << "\n";
    return kExitRuntimeError;
  }
  std::cout.flush();  // a plot on standard output comes after the text before it
  outputs.write(path, *png);
  return kExitOk;
}

}  // namespace

int render_or_warn(const io::Plot& plot, const std::string& png, io::OutputSet& outputs) {
  std::string why;
  const std::optional<std::string> bytes = io::render_png_bytes(plot, &why);
  return png_or_warn(bytes, png, why, outputs);
}

int render_script_or_warn(const std::string& script, const std::string& png,
                          io::OutputSet& outputs) {
  std::string why;
  const std::optional<std::string> bytes = io::render_script_png_bytes(script, &why);
  return png_or_warn(bytes, png, why, outputs);
}

}  // namespace sweetspot::cli
