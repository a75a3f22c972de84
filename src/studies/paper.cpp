#include "studies/paper.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>

#include "sweetspot/rigid_impact.hpp"
#include "sweetspot/roots.hpp"

namespace sweetspot::studies {
namespace {

// The accelerometers of Section II: 2 and 16 cm from the handle end.
constexpr double kDisk2_m = 0.02;
constexpr double kDisk16_m = 0.16;
// Resolution of the figures' curves along the beam.
constexpr double kFigureStep_m = 0.005;
// Where to look for the crossing of Fig. 11 and how precisely.
constexpr double kCrossingSearchLo_m = 0.10;
constexpr double kCrossingSearchHi_m = 0.30;
constexpr double kCrossingTolerance_m = 1e-9;

std::optional<double> reference(const io::DesignFile& file, const char* name) {
  if (!file.reference.is_object() || !file.reference.contains(name)) return std::nullopt;
  return file.reference[name].get<double>();
}

std::optional<double> free_axis(const io::DesignFile& beam, double d) {
  const Implement& implement = beam.design.implement;
  return free_conjugate_from_butt(implement.mass_properties(), implement.length_m() - d);
}

std::optional<double> hand_axis(const io::DesignFile& beam, double d) {
  const Implement& implement = beam.design.implement;
  return hand_held_rotation_axis_from_butt(hand_held_system(beam.design),
                                           beam.design.forearm_equivalent_mass_kg,
                                           implement.length_m() - d);
}

}  // namespace

std::vector<Table1Row> compute_table1(const std::string& dir) {
  std::vector<Table1Row> rows;
  for (int row = 1; row <= kTableIRows; ++row) {
    io::DesignFile file = io::load_design(fmt::format("{}/row{}.json", dir, row));
    // As `sweetspot evaluate` answers the row's file (its own fidelity).
    const Evaluation evaluation = io::evaluate_design_file(file, "", 1e-6);
    const auto F0 = reference(file, "peak_impact_force_N");
    const auto Fw = reference(file, "peak_wrist_force_N");
    rows.push_back(Table1Row{row, std::move(file), evaluation, F0, Fw});
  }
  return rows;
}

std::vector<double> figure_impact_distances(double length_m) {
  std::vector<double> d;
  const int steps = static_cast<int>(std::lround(length_m / kFigureStep_m));
  for (int i = 0; i <= steps; ++i) d.push_back(std::min(length_m, i * kFigureStep_m));
  return d;
}

Figure5Data figure5_data(const io::DesignFile& beam) {
  const MassProperties& body = beam.design.implement.mass_properties();
  Figure5Data data;
  data.length_m = beam.design.implement.length_m();
  data.com_from_butt_m = body.com_from_butt_m;
  data.d_m = figure_impact_distances(data.length_m);
  for (const double d : data.d_m)
    data.v2_over_v16.push_back(velocity_ratio(body, data.length_m - d, kDisk2_m, kDisk16_m));
  data.zero_from_butt_m = free_conjugate_from_butt(body, kDisk2_m);
  data.pole_from_butt_m = free_conjugate_from_butt(body, kDisk16_m);
  std::vector<std::pair<double, std::optional<double>>> curve;
  for (std::size_t i = 0; i < data.d_m.size(); ++i)
    curve.emplace_back(data.d_m[i], data.v2_over_v16[i]);
  if (data.pole_from_butt_m) {
    const double pole_d = data.length_m - *data.pole_from_butt_m;
    for (const double side : {-1.0, 1.0}) {
      // Halving the distance to the pole: the ratio grows as 1 / distance.
      for (double gap = kFigureStep_m; gap > 1e-9; gap /= 2) {
        const double d = pole_d + side * gap;
        if (d < 0 || d > data.length_m) continue;
        const auto ratio = velocity_ratio(body, data.length_m - d, kDisk2_m, kDisk16_m);
        curve.emplace_back(d, ratio);
        if (ratio && std::abs(*ratio) > kFigure5Reach) break;
      }
    }
    curve.emplace_back(pole_d, std::nullopt);
  }
  std::sort(curve.begin(), curve.end(),
            [](const auto& a, const auto& b) { return a.first < b.first; });
  for (const auto& [d, ratio] : curve) {
    data.curve_d_m.push_back(d);
    data.curve_ratio.push_back(ratio);
  }
  return data;
}

std::optional<AxesCrossing> figure11_crossing(const io::DesignFile& beam) {
  const auto gap = [&](double d) {
    const auto free = free_axis(beam, d);
    const auto hand = hand_axis(beam, d);
    return free && hand ? *free - *hand : NAN;
  };
  const auto d = find_root(gap, kCrossingSearchLo_m, kCrossingSearchHi_m, kCrossingTolerance_m);
  if (!d) return std::nullopt;
  return AxesCrossing{*d, *hand_axis(beam, *d)};
}

Figure11Data figure11_data(const io::DesignFile& beam) {
  Figure11Data data;
  data.length_m = beam.design.implement.length_m();
  data.d_m = figure_impact_distances(data.length_m);
  for (const double d : data.d_m) {
    data.s_free_m.push_back(free_axis(beam, d));
    data.s_hand_m.push_back(hand_axis(beam, d));
  }
  data.crossing = figure11_crossing(beam);
  return data;
}

PaperResults paper_results(const std::string& designs_dir) {
  std::vector<Table1Row> table1 = compute_table1(designs_dir + "/table1");
  io::DesignFile beam = io::load_design(designs_dir + "/paper-beam.json");
  Figure5Data figure5 = figure5_data(beam);
  Figure11Data figure11 = figure11_data(beam);
  return PaperResults{std::move(table1), std::move(beam), std::move(figure5), std::move(figure11)};
}

}  // namespace sweetspot::studies
