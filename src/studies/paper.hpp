#pragma once

// The paper's Table I and the curves of Figs. 5 and 11, computed from the
// design files; reports/paper_reports.hpp writes them as Markdown, CSV and PNG.

#include <optional>
#include <string>
#include <vector>

#include "io/design_reader.hpp"
#include "sweetspot/evaluate.hpp"

namespace sweetspot::studies {

inline constexpr int kTableIRows = 8;

struct Table1Row {
  int row = 0;
  io::DesignFile design;
  Evaluation evaluation;
  std::optional<double> paper_F0_N;  // from the design's "reference"
  std::optional<double> paper_Fw_N;
};

// Evaluates DIR/row1.json ... DIR/row8.json.
std::vector<Table1Row> compute_table1(const std::string& dir);

// The impact distances d from the free end of the figures' curves: every
// 5 mm from 0 to the length.
std::vector<double> figure_impact_distances(double length_m);

// Fig. 5: v2/v16 against the impact distance d from the free end for the free
// beam, Eq. (6), with observation points 2 and 16 cm from the handle end.
struct Figure5Data {
  double length_m = 0.0;
  double com_from_butt_m = 0.0;  // where v2/v16 = 1
  std::vector<double> d_m;       // figure_impact_distances()
  std::vector<std::optional<double>> v2_over_v16;
  // The impacts that leave the 2 cm point at rest (its COP) and the 16 cm one
  // (the ratio's pole), from the butt.
  std::optional<double> zero_from_butt_m, pole_from_butt_m;
  // The curve to draw: the grid and, on each side of the pole, points nearing
  // it until |v2/v16| passes kFigure5Reach, with a gap at the pole itself, so
  // that both branches run off the plot's range instead of stopping short.
  std::vector<double> curve_d_m;
  std::vector<std::optional<double>> curve_ratio;
};
inline constexpr double kFigure5Reach = 8.0;
Figure5Data figure5_data(const io::DesignFile& beam);

// Where the free and hand-held rotation axes of Fig. 11 coincide.
struct AxesCrossing {
  double d_m = 0.0;  // impact distance from the free end
  double s_m = 0.0;  // rotation axis from the handle end
};
// Searched for between d = 10 and 30 cm.
std::optional<AxesCrossing> figure11_crossing(const io::DesignFile& beam);

// Fig. 11: rotation axis s = h - A against d, free (Eq. 5) and hand-held (Eq. 12).
struct Figure11Data {
  double length_m = 0.0;
  std::vector<double> d_m;  // figure_impact_distances()
  std::vector<std::optional<double>> s_free_m, s_hand_m;
  std::optional<AxesCrossing> crossing;
};
Figure11Data figure11_data(const io::DesignFile& beam);

// Table I (`designs_dir`/table1) and Figs. 5 and 11 of `designs_dir`/paper-beam.json.
struct PaperResults {
  std::vector<Table1Row> table1;
  io::DesignFile beam;
  Figure5Data figure5;
  Figure11Data figure11;
};
PaperResults paper_results(const std::string& designs_dir);

}  // namespace sweetspot::studies
