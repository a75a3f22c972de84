#include "io/plot.hpp"

#include <sys/wait.h>

#include <cstdio>

#include <fmt/format.h>

#include "io/atomic_file.hpp"

namespace sweetspot::io {
namespace {

// A double-quoted gnuplot string (a file name: taken as it is).
std::string quoted(const std::string& text) {
  std::string out = "\"";
  for (const char c : text) {
    if (c == '"' || c == '\\') out += '\\';
    out += c;
  }
  return out + "\"";
}

// A double-quoted label that the enhanced text mode prints as it is: an
// underscore is a literal (output names are snake_case), not a subscript.
std::string label(const std::string& text) {
  std::string escaped;
  for (const char c : text) {
    if (c == '_' || c == '^') escaped += '\\';
    escaped += c;
  }
  return quoted(escaped);
}

bool on_plot(const Plot& plot, double y) {
  return !plot.y_range || (y >= plot.y_range->first && y <= plot.y_range->second);
}

}  // namespace

std::string gnuplot_script(const Plot& plot, const std::string& png_path) {
  std::string s;
  s += "set terminal pngcairo size 960,640 enhanced font 'DejaVu Sans,11'\n";
  s += "set output " + quoted(png_path) + "\n";
  s += "set title " + label(plot.title) + "\n";
  s += "set xlabel " + label(plot.x_label) + "\n";
  s += "set ylabel " + label(plot.y_label) + "\n";
  s += "set grid\nset key " + plot.key_position + " box opaque\n";
  if (plot.log_x) s += "set logscale x\nset format x '10^{%L}'\n";
  if (plot.log_y) s += "set logscale y\nset format y '10^{%L}'\n";
  if (plot.x_range) s += fmt::format("set xrange [{}:{}]\n", plot.x_range->first, plot.x_range->second);
  if (plot.y_range) s += fmt::format("set yrange [{}:{}]\n", plot.y_range->first, plot.y_range->second);
  if (!plot.y2_label.empty()) {
    s += "set y2label " + label(plot.y2_label) + "\nset ytics nomirror\nset y2tics\n";
    if (plot.log_y2) s += "set logscale y2\nset format y2 '10^{%L}'\n";
  }
  int tag = 1;
  for (const auto& [x, text] : plot.vertical_lines) {
    s += fmt::format("set arrow {} from {},graph 0 to {},graph 1 nohead dt 2 lc rgb 'gray40'\n", tag,
                     x, x);
    // Stagger the labels so that neighbouring lines do not overwrite each other.
    s += fmt::format("set label {} {} at {},graph {} left offset 0.5,0 tc rgb 'gray30'\n", tag,
                     label(text), x, 0.96 - 0.06 * (tag - 1));
    ++tag;
  }
  for (const PlotMarker& m : plot.markers) {
    s += fmt::format("set label {} {} at {},{} left offset 1,-1 point pt 7 ps 1.2\n", tag++,
                     label(m.label), m.x, m.y);
  }
  for (std::size_t i = 0; i < plot.series.size(); ++i) {
    const PlotSeries& series = plot.series[i];
    s += fmt::format("$series{} << EOD\n", i);
    bool broken = true;
    for (std::size_t k = 0; k < series.x.size(); ++k) {
      const auto& y = series.y[k];
      const bool log_y = series.right_axis ? plot.log_y2 : plot.log_y;
      const bool off_log = (log_y && y && *y <= 0) || (plot.log_x && series.x[k] <= 0);
      if (!y || (!series.right_axis && !on_plot(plot, *y)) || off_log) {
        if (!broken) s += "\n";
        broken = true;
        continue;
      }
      s += fmt::format("{} {}\n", series.x[k], *y);
      broken = false;
    }
    s += "EOD\n";
  }
  s += "plot ";
  for (std::size_t i = 0; i < plot.series.size(); ++i) {
    if (i) s += ", \\\n     ";
    s += fmt::format("$series{} using 1:2{} with {} title {}", i,
                     plot.series[i].right_axis ? " axes x1y2" : "", plot.series[i].style,
                     label(plot.series[i].title));
  }
  return s + "\n";
}

bool render_png(const Plot& plot, const std::string& png_path, std::string* why) {
  const std::string temporary = temporary_path_for(png_path);
  FILE* pipe = popen("gnuplot 2>&1 >/dev/null", "w");
  if (!pipe) {
    discard_file(temporary);
    if (why) *why = "cannot start gnuplot";
    return false;
  }
  const std::string script = gnuplot_script(plot, temporary);
  std::fwrite(script.data(), 1, script.size(), pipe);
  const int status = pclose(pipe);
  if (status != 0) {
    discard_file(temporary);
    if (why) {
      *why = WIFEXITED(status) && WEXITSTATUS(status) == 127
                 ? "gnuplot is not installed (apt-get install gnuplot-nox)"
                 : "gnuplot failed";
    }
    return false;
  }
  commit_file(temporary, png_path);
  return true;
}

}  // namespace sweetspot::io
