#include "reports/string_bed_map_report.hpp"

#include <fmt/format.h>

#include <cmath>
#include <numbers>

#include "io/format.hpp"
#include "io/plot.hpp"

namespace sweetspot::reports {

std::string string_bed_map_csv(const studies::StringBedMap& map, double length_m) {
  const bool feel = map.fidelity != Fidelity::kRigid;
  std::string out =
      "from_butt_m,from_tip_m,off_axis_m,effective_mass_kg,apparent_cor,peak_wrist_force_N,"
      "peak_twist_torque_N_m";
  out += feel ? ",vibration_energy_J\n" : "\n";
  for (const studies::StringBedMapPoint& p : map.points) {
    if (!p.on_bed) continue;
    bool first = true;
    for (const double value :
         {p.from_butt_m, length_m - p.from_butt_m, p.off_axis_m, p.effective_mass_kg,
          p.apparent_cor, p.peak_wrist_force_N, p.peak_twist_torque_N_m}) {
      if (!first) out += ',';
      first = false;
      io::append_exact(out, value);
    }
    if (feel) {
      out += ',';
      if (p.vibration_energy_J) io::append_exact(out, *p.vibration_energy_J);
    }
    out += '\n';
  }
  return out;
}

std::vector<MapQuantity> map_quantities(const studies::StringBedMap& map) {
  std::vector<MapQuantity> all{MapQuantity::kPower, MapQuantity::kShock};
  if (map.fidelity != Fidelity::kRigid) all.push_back(MapQuantity::kFeel);
  return all;
}

std::string map_quantity_name(MapQuantity quantity) {
  switch (quantity) {
    case MapQuantity::kPower:
      return "power";
    case MapQuantity::kShock:
      return "shock";
    case MapQuantity::kFeel:
      return "feel";
  }
  return "power";
}

namespace {

double value_of(const studies::StringBedMapPoint& p, MapQuantity quantity) {
  switch (quantity) {
    case MapQuantity::kPower:
      return p.apparent_cor;
    case MapQuantity::kShock:
      return p.peak_wrist_force_N;
    case MapQuantity::kFeel:
      return p.vibration_energy_J.value_or(std::nan(""));
  }
  return 0.0;
}

}  // namespace

namespace {

// Everything of a heat map but the terminal.
std::string heat_map_commands(const studies::StringBedMap& map, MapQuantity quantity,
                              double length_m, const std::string& design_name) {
  const HeadEllipse& bed = map.bed;
  const double cm = 100.0;
  // Seen from the front, tip up: x across (cm off the axis), y along (cm from the tip, down).
  const double half_w = bed.semi_width_m * cm,
               tip_top = (length_m - bed.center_from_butt_m - bed.semi_length_m) * cm;
  const double tip_bottom = (length_m - bed.center_from_butt_m + bed.semi_length_m) * cm;
  std::string title, colour_label, palette;
  switch (quantity) {
    case MapQuantity::kPower:
      title = map.fidelity == Fidelity::kCollision
                  ? "power, the solved collision's e_A (rebound / incident speed)"
                  : "power, the apparent COR e_A at the frame's COR (Eq. 16)";
      colour_label = "apparent COR";
      palette = "set palette defined (0 '#2c7bb6', 0.5 '#ffffbf', 1 '#d7191c')\n";
      break;
    case MapQuantity::kShock:
      title = "shock, the peak force on the wrist |F_w / F| F0";
      colour_label = "peak wrist force (N)";
      palette = "set palette defined (0 '#1a9850', 0.5 '#ffffbf', 1 '#d73027')\n";
      break;
    case MapQuantity::kFeel:
      title = "feel, the vibration energy left in the free frame";
      colour_label = "vibration energy (J)";
      palette = "set palette defined (0 '#1a9850', 0.5 '#ffffbf', 1 '#d73027')\n";
      break;
  }
  std::string s;
  s += "set title " + io::gnuplot_label(design_name.empty() ? title : design_name + ": " + title) +
       "\n";
  s += "set xlabel " + io::gnuplot_label("off the long axis (cm; 3 o'clock to the right)") + "\n";
  s += "set ylabel " + io::gnuplot_label("from the tip (cm)") + "\n";
  s += "set cblabel " + io::gnuplot_label(colour_label) + "\n";
  s += palette;
  s += "set size ratio -1\nset key below box opaque\n";
  s += "unset grid\nset tics out\n";
  const double pad = 1.5;
  // The tip up: the range runs from the throat (bottom) to the tip (top).
  s += fmt::format("set xrange [{}:{}]\nset yrange [{}:{}]\n", -half_w - pad, half_w + pad,
                   tip_bottom + pad, tip_top - pad);
  // The grid as a matrix of cell centres: rows are y (across), columns x (along).
  s += "$grid << EOD\n";
  for (int i = map.columns - 1; i >= 0; --i) {
    for (int j = 0; j < map.rows; ++j) {
      const studies::StringBedMapPoint& p =
          map.points[static_cast<std::size_t>(j) * map.columns + i];
      const double from_tip = (length_m - p.from_butt_m) * cm;
      if (p.on_bed && std::isfinite(value_of(p, quantity))) {
        s += fmt::format("{} {} {}\n", p.off_axis_m * cm, from_tip, value_of(p, quantity));
      } else {
        s += fmt::format("{} {} NaN\n", p.off_axis_m * cm, from_tip);
      }
    }
    s += "\n";
  }
  s += "EOD\n";
  // The string bed's outline.
  s += "$outline << EOD\n";
  for (int k = 0; k <= 180; ++k) {
    const double t = 2.0 * std::numbers::pi * k / 180.0;
    s += fmt::format("{} {}\n", bed.semi_width_m * cm * std::sin(t),
                     (length_m - bed.center_from_butt_m - bed.semi_length_m * std::cos(t)) * cm);
  }
  s += "EOD\n";
  std::string lines;
  const auto across = [&](const std::optional<double>& x, const std::string& name,
                          const std::string& style) {
    if (!x) return;
    const double u = (*x - bed.center_from_butt_m) / bed.semi_length_m;
    if (!(std::abs(u) < 1.0)) return;  // off the string bed: nothing to draw across it
    const double half = bed.semi_width_m * cm * std::sqrt(1.0 - u * u);
    const double from_tip = (length_m - *x) * cm;
    s += fmt::format("${} << EOD\n{} {}\n{} {}\nEOD\n", name, -half, from_tip, half, from_tip);
    lines += fmt::format(
        ", ${} using 1:2 with lines {} title {}", name, style,
        io::gnuplot_label(fmt::format(
            "{} ({:.1f} cm from the tip)",
            name == "cop" ? "hand-held COP" : "node of the free fundamental", from_tip)));
  };
  across(map.cop_hand_from_butt_m, "cop", "lw 3 dt 1 lc rgb 'black'");
  across(map.node_free_from_butt_m, "node", "lw 3 dt 2 lc rgb '#4d4d4d'");
  s += "plot $grid using 1:2:3 with image notitle, $outline using 1:2 with lines lw 2 lc rgb "
       "'gray20' title " +
       io::gnuplot_label("string bed") + lines + "\n";
  return s;
}

}  // namespace

std::string string_bed_heat_map_script(const studies::StringBedMap& map, MapQuantity quantity,
                                       double length_m, const std::string& design_name) {
  return "set terminal pngcairo size 720,900 enhanced font 'DejaVu Sans,11'\n" +
         heat_map_commands(map, quantity, length_m, design_name);
}

std::string string_bed_heat_map_svg_script(const studies::StringBedMap& map, MapQuantity quantity,
                                           double length_m, const std::string& design_name,
                                           int width, int height) {
  return fmt::format(
             "set terminal svg size {},{} dynamic enhanced font 'DejaVu Sans,12' background "
             "'#ffffff'\n"
             // The svg terminal's text is measured smaller than drawn: room
             // below for the axis label and the key under it, and on the right
             // for the colour bar's tics and its label, which ran off the edge.
             "set bmargin 8\nset rmargin 14\n",
             width, height) +
         heat_map_commands(map, quantity, length_m, design_name);
}

}  // namespace sweetspot::reports
