#pragma once

// `sweetspot map`: the string-bed map as CSV and as heat maps (gnuplot PNG),
// with the hand-held COP and the fundamental's node drawn across the head.

#include <string>
#include <vector>

#include "studies/string_bed_map.hpp"

namespace sweetspot::reports {

// One row per grid point on the string bed, x fastest:
// from_butt_m,from_tip_m,off_axis_m,effective_mass_kg,apparent_cor,peak_wrist_force_N,
// peak_twist_torque_N_m and, at the modal level, vibration_energy_J (empty where
// the response model's energy limit is passed). Numbers
// shortest round-trip.
std::string string_bed_map_csv(const studies::StringBedMap& map, double length_m);

// What a heat map shows.
enum class MapQuantity { kPower, kShock, kFeel };

// The quantities the map holds: power and shock, and feel at the modal level.
std::vector<MapQuantity> map_quantities(const studies::StringBedMap& map);

// "power", "shock", "feel": the suffix of the PNG file.
std::string map_quantity_name(MapQuantity quantity);

// The gnuplot script of one heat map (a png terminal, no output set): the head
// seen from the front with the tip up, cm from the tip against cm off the axis,
// the string bed's outline, and lines across it at the hand-held COP and the
// free fundamental's node.
std::string string_bed_heat_map_script(const studies::StringBedMap& map, MapQuantity quantity,
                                       double length_m, const std::string& design_name);

// The same heat map for gnuplot's svg terminal ("dynamic": it scales with the
// page), laid out at `width` x `height` pixels, for io::render_script_svg();
// an empty `design_name` leaves the title to the quantity alone.
std::string string_bed_heat_map_svg_script(const studies::StringBedMap& map, MapQuantity quantity,
                                           double length_m, const std::string& design_name,
                                           int width = 600, int height = 680);

}  // namespace sweetspot::reports
