#pragma once

// Line plots rendered to PNG by gnuplot (Debian package gnuplot-nox). The
// plot is described as data; gnuplot_script() is pure and testable.

#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace sweetspot::io {

struct PlotSeries {
  std::string title;
  std::vector<double> x;
  std::vector<std::optional<double>> y;  // std::nullopt (and points off the y range) break the line
  std::string style = "lines lw 2";
  bool right_axis = false;  // drawn against the second y axis (Plot::y2_label)
};

struct PlotMarker {
  double x = 0.0;
  double y = 0.0;
  std::string label;
};

struct Plot {
  std::string title;
  std::string x_label;  // with the unit, e.g. "impact distance d from the free end (cm)"
  std::string y_label;
  std::optional<std::pair<double, double>> x_range;
  std::optional<std::pair<double, double>> y_range;
  std::vector<PlotSeries> series;
  std::vector<PlotMarker> markers;
  std::vector<std::pair<double, std::string>> vertical_lines;  // x and label
  std::string key_position = "top right";
  bool log_x = false;
  bool log_y = false;      // gnuplot's words: "bottom left", "outside right", ...
  std::string y2_label{};  // the second y axis, on the right, for series with right_axis
  bool log_y2 = false;
};

// The gnuplot script that draws `plot` into `png_path` ("": gnuplot's
// standard output).
std::string gnuplot_script(const Plot& plot, const std::string& png_path);

// Renders `plot` to `png_path` as an output file (io/atomic_file.hpp):
// gnuplot draws into a temporary file, which is checked to be a whole PNG
// before it replaces `png_path` (or is copied into a device or FIFO).
// gnuplot's own messages never reach standard output. Returns false, with
// why on one line (gnuplot missing or failing, with its messages; a PNG cut
// short by a full disk; a file that cannot be written), leaving `png_path`
// as it was.
bool render_png(const Plot& plot, const std::string& png_path, std::string* why);

// The same for any gnuplot script that sets a png terminal and no output
// (a heat map, say): rendered, checked and written like render_png().
bool render_script_png(const std::string& script, const std::string& png_path, std::string* why);

// `text` as a gnuplot string that prints literally (quotes and enhanced-text
// markup escaped), for scripts built outside this file.
std::string gnuplot_label(const std::string& text);

}  // namespace sweetspot::io
