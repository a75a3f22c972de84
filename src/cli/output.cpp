#include "cli/output.hpp"

#include <iostream>

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
