#include "cli/output.hpp"

#include <CLI/CLI.hpp>
#include <filesystem>
#include <iostream>
#include <system_error>

#include "io/atomic_file.hpp"
#include "io/input_error.hpp"

namespace sweetspot::cli {

void OutputOptions::add_to(CLI::App* command, std::vector<std::string> formats) {
  command->add_option("--format", format, "Output format")
      ->check(CLI::IsMember(std::move(formats)))
      ->capture_default_str();
  command->add_option("--output,-o", output,
                      "Write to FILE instead of stdout (a regular file is replaced atomically; a "
                      "device or FIFO is written directly)");
}

io::Format OutputOptions::parsed() const { return *io::parse_format(format); }

void OutputOptions::emit(const std::string& text) const {
  if (output.empty()) {
    std::cout << text;
  } else {
    io::write_file_atomically(output, text);
  }
}

void OutputOptions::emit_stream(const std::function<void(std::ostream&)>& write) const {
  if (output.empty()) {
    write(std::cout);
  } else {
    io::write_stream_atomically(output, write);
  }
}

void require_distinct_outputs(const std::string& html, const std::string& output) {
  if (html.empty() || output.empty()) return;
  std::error_code error;
  const auto resolved = [&](const std::string& path) {
    return std::filesystem::weakly_canonical(std::filesystem::absolute(path, error), error);
  };
  if (html == output || resolved(html) == resolved(output)) {
    throw CLI::ValidationError("--html and --output: both name " + io::one_line(html) +
                               "; give the page and the text report two files");
  }
}

std::string plot_file(const std::string& png, const std::string& suffix) {
  const bool ends_png = png.size() >= 4 && png.compare(png.size() - 4, 4, ".png") == 0;
  return (ends_png ? png.substr(0, png.size() - 4) : png) + suffix + ".png";
}

int render_or_warn(const io::Plot& plot, const std::string& png) {
  std::string why;
  if (io::render_png(plot, png, &why)) return kExitOk;
  std::cerr << "sweetspot: cannot write " << io::one_line(png) << ": " << why << "\n";
  return kExitRuntimeError;
}

}  // namespace sweetspot::cli
