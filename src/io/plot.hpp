#pragma once

// Line plots rendered to PNG by gnuplot (Debian package gnuplot-nox). The
// plot is described as data; gnuplot_script() is pure and testable.

#include <optional>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "io/outputs.hpp"

namespace sweetspot::io {

struct PlotSeries {
  std::string title;
  std::vector<double> x;
  std::vector<std::optional<double>> y;  // std::nullopt (and points off the y range) break the line
  std::string style = "lines lw 2";
  bool right_axis = false;  // drawn against the second y axis (Plot::y2_label)
  std::string color{};      // "#rrggbb"; "": plot_color() of the series' place in the plot
};

// A second x axis along the top, in another unit of the same quantity
// (tension in lb above tension in N): top = bottom * factor.
struct SecondXAxis {
  std::string label;
  double factor = 1.0;
  double tic_step = 0.0;  // > 0: tics at its multiples (gnuplot would put them under x's tics)
};

struct PlotMarker {
  double x = 0.0;
  double y = 0.0;
  std::string label;
  bool label_above = false;  // the label above and right of the point (else below and right)
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
  std::string key_position = "top right";  // or "off": no key (one series the labels name)
  bool log_x = false;
  bool log_y = false;      // gnuplot's words: "bottom left", "outside right", ...
  std::string y2_label{};  // the second y axis, on the right, for series with right_axis
  bool log_y2 = false;
  std::string key_title{};      // a heading over the key's entries
  bool integer_x_tics = false;  // a count on x (threads): tics only at whole numbers
  std::optional<SecondXAxis> x2{};
};

// The colour of the i-th series: twelve colours that stay distinct from one
// another (Okabe and Ito's eight for colour-blind readers, then four more),
// repeating only after twelve series.
std::string plot_color(std::size_t i);

// What an axis shows in a reader's words and unit, and the factor from the
// SI value to that unit (metres are shown in cm).
struct AxisQuantity {
  std::string label;  // e.g. "peak wrist force (N)", "lead mass 1 (g)"
  double factor = 1.0;
  std::string name{};  // the label without its unit: "peak wrist force"
  std::string unit{};  // "N" ("" when dimensionless)
};

// The axis of a named output: its name in words (the unit suffix dropped,
// COP and COR in capitals) with its unit once, metres as cm.
AxisQuantity output_axis(const OutputSpec& output);

// The axis of a design input named by a JSON pointer as a study wrote it
// ("/implement/point_masses/0/mass_g" -> "lead mass 1 (g)"), the unit taken
// from the key's suffix; the value is in the file's unit, metres shown as cm.
AxisQuantity pointer_axis(std::string_view pointer);

// The gnuplot script that draws `plot` into `png_path` ("": gnuplot's
// standard output).
std::string gnuplot_script(const Plot& plot, const std::string& png_path);

// The gnuplot script that draws `plot` as SVG on gnuplot's standard output,
// laid out at `width` x `height` pixels and scaling with the page (gnuplot's
// svg terminal, "dynamic"): a smaller layout makes larger text on a phone.
std::string gnuplot_svg_script(const Plot& plot, int width = 960, int height = 640);

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

// `plot` rendered as PNG bytes, held in memory (for files written all or
// none, io/atomic_file.hpp). std::nullopt, with why, when gnuplot is missing
// or fails.
std::optional<std::string> render_png_bytes(const Plot& plot, std::string* why);
// The same for a script that sets a png terminal and no output (a heat map).
std::optional<std::string> render_script_png_bytes(const std::string& script, std::string* why);

// `text` as a gnuplot string that prints literally (quotes and enhanced-text
// markup escaped), for scripts built outside this file.
std::string gnuplot_label(const std::string& text);

// `plot` as an inline <svg> element for an HTML page: gnuplot's SVG without
// its XML prologue, every id (and reference to one) prefixed with `id_prefix`
// so that several plots can share a page. std::nullopt, with why, when
// gnuplot is missing or fails.
std::optional<std::string> render_svg(const Plot& plot, const std::string& id_prefix,
                                      std::string* why, int width = 960, int height = 640);

// The same for any gnuplot script that sets an svg terminal and no output (a
// heat map, say).
std::optional<std::string> render_script_svg(const std::string& script,
                                             const std::string& id_prefix, std::string* why);

// One plot of several that render_svgs() draws: a script that sets an svg
// terminal and no output (gnuplot_svg_script(), a heat map's) and the prefix
// of its ids on the page.
struct SvgPlot {
  std::string script;
  std::string id_prefix;
};

// A plot render_svgs() drew (`svg`, as render_script_svg() returns it), or
// why not.
struct RenderedSvg {
  std::optional<std::string> svg;
  std::string why;
};

// The plots of a page, each as render_script_svg() draws it, drawn by one
// gnuplot (its start costs more than most plots): the scripts run one after
// another, every setting back to gnuplot's defaults between them, and each
// SVG is cut from gnuplot's standard output at a tag printed after it. When
// that gnuplot fails, each plot is drawn by a gnuplot of its own, so that a
// plot gnuplot cannot draw loses only itself and says why.
// The SVG is byte for byte the one a gnuplot of its own draws for the plots
// of the pages (tests/io/plot_test.cpp). One thing carries over in gnuplot
// 5.4's svg terminal: the stroke colour of the empty group that opens a plot
// is the last colour of the plot before, where that plot ends on a coloured
// stroke rather than its labels (a colour box with no label, say); nothing
// in that group is drawn.
std::vector<RenderedSvg> render_svgs(const std::vector<SvgPlot>& plots);

}  // namespace sweetspot::io
