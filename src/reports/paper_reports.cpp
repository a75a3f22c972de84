#include "reports/paper_reports.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <functional>
#include <string>
#include <vector>

namespace sweetspot::reports {
namespace {

// The range of Fig. 11's axis s, as the paper draws it [cm].
constexpr double kFigure11Low_cm = -30.0;
constexpr double kFigure11High_cm = 40.0;

std::optional<double> head_to_handle_ratio(const Implement& implement) {
  const auto& s = implement.sections();
  if (s.size() != 2 || s[0].mass_kg == 0.0) return std::nullopt;
  return s[1].mass_kg / s[0].mass_kg;
}

std::string optional_csv(const std::optional<double>& value) {
  return value ? io::exact(*value) : std::string();
}

std::optional<double> diff(double ours, const std::optional<double>& paper) {
  if (!paper) return std::nullopt;
  return ours - *paper;
}

// The paper's printed values, quoted only beside the paper's own beam (its
// reference cites Cross 2004): another beam in their place must not be
// compared with them.
std::string paper_says(const io::DesignFile& beam, const std::string& printed) {
  const bool paper_beam = beam.reference.is_object() && beam.reference.contains("source") &&
                          beam.reference["source"].get<std::string>().rfind("Cross (2004)", 0) == 0;
  return paper_beam ? " (paper: " + printed + ")" : "";
}

// The value most rows share, then each other row's: "50 m/s (row 3: 30 m/s)".
// The caption says what the rows were computed for, not what the paper's were.
std::string by_row(const std::vector<studies::Table1Row>& rows,
                   const std::function<std::string(const studies::Table1Row&)>& value) {
  std::vector<std::string> values;
  for (const studies::Table1Row& r : rows) values.push_back(value(r));
  if (values.empty()) return "";
  std::string common = values.front();
  std::size_t most = 0;
  for (const std::string& v : values) {
    const auto n = static_cast<std::size_t>(std::count(values.begin(), values.end(), v));
    if (n > most) most = n, common = v;
  }
  std::string others;
  for (std::size_t k = 0; k < rows.size(); ++k) {
    if (values[k] == common) continue;
    others += fmt::format("{}row {}: {}", others.empty() ? " (" : "; ", rows[k].row, values[k]);
  }
  return common + (others.empty() ? "" : others + ")");
}

std::string table1_caption(const std::vector<studies::Table1Row>& rows) {
  const auto cm = [](double m) { return io::significant(m * 100.0, 4) + " cm"; };
  return fmt::format(
      "A {} racquet struck {} from the tip by a {} ball at {}; hand centre {} from the butt, "
      "wrist at the butt.",
      by_row(rows, [&](const auto& r) { return cm(r.design.design.implement.length_m()); }),
      by_row(rows,
             [&](const auto& r) {
               return cm(r.design.design.implement.length_m() - r.evaluation.impact_from_butt_m);
             }),
      by_row(rows,
             [](const auto& r) {
               return io::significant(r.design.design.ball.mass_kg * 1000.0, 4) + " g";
             }),
      by_row(rows,
             [](const auto& r) {
               const Evaluation& e = r.evaluation;
               const std::string v = io::significant(r.design.design.ball.speed_m_s, 4) + " m/s";
               if (e.swing_assumed) return v + " relative to the strings";
               return v + " onto the racquet swung at " + io::significant(e.racquet_speed_m_s, 4) +
                      " m/s there";
             }),
      by_row(rows, [&](const auto& r) { return cm(r.design.design.hand.center_from_butt_m); }));
}

}  // namespace

std::string table1_report(const std::vector<studies::Table1Row>& rows, io::Format format) {
  if (format == io::Format::kJson) {
    io::Json j = io::Json::array();
    for (const studies::Table1Row& r : rows) {
      j.push_back({{"row", r.row},
                   {"name", r.design.name},
                   {"peak_impact_force_N", r.evaluation.peak_impact_force_N},
                   {"peak_wrist_force_N", r.evaluation.peak_wrist_force_N},
                   {"paper_F0_N", r.paper_F0_N ? io::Json(*r.paper_F0_N) : io::Json(nullptr)},
                   {"paper_Fw_N", r.paper_Fw_N ? io::Json(*r.paper_Fw_N) : io::Json(nullptr)}});
    }
    return j.dump(2, ' ', false, io::Json::error_handler_t::replace) + "\n";
  }
  if (format == io::Format::kCsv) {
    std::string csv =
        "row,mass_kg,head_to_handle_mass_ratio,cor,impact_duration_s,hand_mass_kg,"
        "forearm_equivalent_mass_kg,effective_mass_kg,apparent_cor,peak_impact_force_N,"
        "peak_wrist_force_N,paper_F0_N,paper_Fw_N,diff_F0_N,diff_Fw_N\n";
    for (const studies::Table1Row& r : rows) {
      const Design& d = r.design.design;
      const Evaluation& e = r.evaluation;
      csv += fmt::format("{},{},{},{},{},{},{},{},{},{},{},{},{},{},{}\n", r.row,
                         io::exact(e.mass_kg), optional_csv(head_to_handle_ratio(d.implement)),
                         io::exact(e.cor), io::exact(e.impact_duration_s),
                         io::exact(d.hand.mass_kg), io::exact(d.forearm_equivalent_mass_kg),
                         io::exact(e.effective_mass_kg), io::exact(e.apparent_cor),
                         io::exact(e.peak_impact_force_N), io::exact(e.peak_wrist_force_N),
                         optional_csv(r.paper_F0_N), optional_csv(r.paper_Fw_N),
                         optional_csv(diff(e.peak_impact_force_N, r.paper_F0_N)),
                         optional_csv(diff(e.peak_wrist_force_N, r.paper_Fw_N)));
    }
    return csv;
  }
  std::string md =
      std::string("# Table I of Cross (2004), recomputed\n\n") + table1_caption(rows) +
      " Masses in kg, T in ms, forces in N. F0 is Eq. (15) with Eqs. (16)-(17); F_w is Eq. (11) "
      "times F0. The paper prints whole newtons.\n\n"
      "| row | M_b | M1/M2 | e | T | M_h | M_e | M_eff | e_A | F0 | paper F0 | ΔF0 | F_w | "
      "paper F_w | ΔF_w |\n"
      "|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|\n";
  double worst_F0 = 0.0, worst_Fw = 0.0;
  for (const studies::Table1Row& r : rows) {
    const Design& d = r.design.design;
    const Evaluation& e = r.evaluation;
    const auto dF0 = diff(e.peak_impact_force_N, r.paper_F0_N);
    const auto dFw = diff(e.peak_wrist_force_N, r.paper_Fw_N);
    if (dF0) worst_F0 = std::max(worst_F0, std::abs(*dF0));
    if (dFw) worst_Fw = std::max(worst_Fw, std::abs(*dFw));
    const auto ratio = head_to_handle_ratio(d.implement);
    const auto show = [](const std::optional<double>& v, const char* spec) {
      return v ? fmt::format(fmt::runtime(spec), *v) : std::string("—");
    };
    md += fmt::format(
        "| {} | {} | {} | {} | {} | {} | {} | {:.4f} | {:.4f} | {:.1f} | {} | {} | "
        "{:.1f} | {} | {} |\n",
        r.row, io::significant(e.mass_kg), show(ratio, "{:.2g}"), io::significant(e.cor),
        io::significant(e.impact_duration_s * 1000.0), io::significant(d.hand.mass_kg),
        io::significant(d.forearm_equivalent_mass_kg), e.effective_mass_kg, e.apparent_cor,
        e.peak_impact_force_N, show(r.paper_F0_N, "{:.0f}"), show(dF0, "{:+.2f}"),
        e.peak_wrist_force_N, show(r.paper_Fw_N, "{:.0f}"), show(dFw, "{:+.2f}"));
  }
  // The paper prints whole newtons (row 5's F0 truncated): within 1 N is its
  // rounding; more, and the rows are not the paper's.
  md += worst_F0 <= 1.0 && worst_Fw <= 1.0
            ? fmt::format(
                  "\nLargest difference from the printed values: {:.2f} N in F0 and {:.2f} N in "
                  "F_w, within the paper's rounding to whole newtons (row 5's F0 = 744.8 N is "
                  "printed 744, truncated rather than rounded).\n",
                  worst_F0, worst_Fw)
            : fmt::format(
                  "\nLargest difference from the printed values: {:.2f} N in F0 and {:.2f} N in "
                  "F_w, more than the paper's rounding to whole newtons: the rows that differ "
                  "are not the paper's set-up.\n",
                  worst_F0, worst_Fw);
  return md;
}

Figure figure5(const io::DesignFile& beam, const studies::Figure5Data& data) {
  const double L = data.length_m;
  Figure figure;
  figure.csv = "d_from_free_end_m,impact_from_butt_m,v2_over_v16\n";
  io::PlotSeries curve{"Eq. (6), free beam", {}, {}};
  for (std::size_t i = 0; i < data.d_m.size(); ++i) {
    const double d = data.d_m[i];
    const double x = L - d;
    const std::optional<double>& ratio = data.v2_over_v16[i];
    figure.csv += fmt::format("{},{},{}\n", io::exact(d), io::exact(x), optional_csv(ratio));
  }
  for (std::size_t i = 0; i < data.curve_d_m.size(); ++i) {
    curve.x.push_back(data.curve_d_m[i] * 100.0);
    curve.y.push_back(data.curve_ratio[i]);
  }
  const std::optional<double>&zero = data.zero_from_butt_m, &pole = data.pole_from_butt_m;
  figure.plot =
      io::Plot{"Fig. 5: velocity ratio v2/v16 of the free beam (Cross 2004, Eq. 6)",
               "impact distance d from the free end (cm)",
               "v2 / v16 (dimensionless)",
               std::pair{0.0, L * 100.0},
               std::pair{-4.0, 4.0},
               {curve},
               {io::PlotMarker{(L - data.com_from_butt_m) * 100.0, 1.0, "centre: v2/v16 = 1"}},
               {}};
  if (zero) figure.plot.vertical_lines.push_back({(L - *zero) * 100.0, "COP for the 2 cm disk"});
  if (pole) figure.plot.vertical_lines.push_back({(L - *pole) * 100.0, "COP for the 16 cm disk"});
  const auto at_d = [&](std::optional<double> from_butt_m) {
    return from_butt_m ? fmt::format("at d = {:.1f} cm", (L - *from_butt_m) * 100.0)
                       : std::string("nowhere");
  };
  figure.summary = fmt::format(
      "v2/v16 is 0 {}{}, has its pole {}{} and is 1 at the centre, d = {:.0f} cm{}.", at_d(zero),
      paper_says(beam, "COP 23.3 cm from the end"), at_d(pole), paper_says(beam, "14.4 cm"),
      (L - data.com_from_butt_m) * 100.0, paper_says(beam, "36 cm"));
  return figure;
}

Figure figure11(const io::DesignFile& beam, const studies::Figure11Data& data) {
  const double L = data.length_m;
  Figure figure;
  figure.csv = "d_from_free_end_m,s_free_m,s_hand_m\n";
  io::PlotSeries free{"free beam (Eq. 5)", {}, {}};
  io::PlotSeries hand{fmt::format("hand-held, M_h = {} kg, M_e = {} kg (Eq. 12)",
                                  io::significant(beam.design.hand.mass_kg),
                                  io::significant(beam.design.forearm_equivalent_mass_kg)),
                      {},
                      {}};
  for (std::size_t i = 0; i < data.d_m.size(); ++i) {
    const double d = data.d_m[i];
    const std::optional<double>&s_free = data.s_free_m[i], &s_hand = data.s_hand_m[i];
    figure.csv +=
        fmt::format("{},{},{}\n", io::exact(d), optional_csv(s_free), optional_csv(s_hand));
    free.x.push_back(d * 100.0);
    hand.x.push_back(d * 100.0);
    free.y.push_back(s_free ? std::optional(*s_free * 100.0) : std::nullopt);
    hand.y.push_back(s_hand ? std::optional(*s_hand * 100.0) : std::nullopt);
  }
  // Each curve is drawn up to its pole, where the axis runs off the plot; the
  // branch beyond it (the axis past the far end of the beam, coming back into
  // view near the handle) would be a stray segment without its context. The
  // CSV keeps every value.
  for (io::PlotSeries* series : {&free, &hand}) {
    bool shown = false, left = false;
    for (auto& y : series->y) {
      const bool in_view = y && *y >= kFigure11Low_cm && *y <= kFigure11High_cm;
      if (left)
        y.reset();
      else if (in_view)
        shown = true;
      else if (shown)
        left = true;
    }
  }
  figure.plot = io::Plot{"Fig. 11: rotation axis s against impact point d (Cross 2004)",
                         "impact distance d from the free end (cm)",
                         "rotation axis s from the handle end (cm)",
                         std::pair{0.0, L * 100.0},
                         std::pair{kFigure11Low_cm, kFigure11High_cm},
                         {free, hand},
                         {},
                         {}};
  const std::optional<studies::AxesCrossing>& crossing = data.crossing;
  if (crossing) {
    figure.plot.markers.push_back(io::PlotMarker{
        crossing->d_m * 100.0, crossing->s_m * 100.0,
        fmt::format("d = {:.1f} cm, s = {:.1f} cm", crossing->d_m * 100.0, crossing->s_m * 100.0),
        true});
    figure.summary = fmt::format(
        "The free and hand-held axes coincide at d = {:.1f} cm with the axis {:.1f} cm from the "
        "handle end{}.",
        crossing->d_m * 100.0, crossing->s_m * 100.0, paper_says(beam, "22.8 cm and 3.2 cm"));
  } else {
    figure.summary = "The free and hand-held axes do not coincide between d = 10 and 30 cm.";
  }
  return figure;
}

std::vector<ReportEntry> write_paper_reports(const studies::PaperResults& results,
                                             const ReportWriter& write) {
  const std::vector<studies::Table1Row>& rows = results.table1;
  const Figure fig5 = figure5(results.beam, results.figure5);
  const Figure fig11 = figure11(results.beam, results.figure11);
  const std::string table_md = table1_report(rows, io::Format::kMarkdown);
  write.text("table1.md", table_md);
  write.text("table1.csv", table1_report(rows, io::Format::kCsv));
  write.text("fig5.csv", fig5.csv);
  write.text("fig11.csv", fig11.csv);
  write.plot("fig5.png", fig5.plot);
  write.plot("fig11.png", fig11.plot);
  const std::string last_line = table_md.substr(table_md.rfind("\nLargest") + 1);
  return {
      {"[table1.md](table1.md), [table1.csv](table1.csv)",
       "Table I of the paper: peak force on the strings F0 and on the wrist F_w for eight "
       "racquet/player combinations, next to the printed values. " +
           last_line.substr(0, last_line.size() - 1)},
      {"[fig5.csv](fig5.csv), [fig5.png](fig5.png)",
       "Fig. 5: velocity ratio v2/v16 of the free 72 cm beam against the impact distance d from "
       "the "
       "free end (Eq. 6). " +
           fig5.summary},
      {"[fig11.csv](fig11.csv), [fig11.png](fig11.png)",
       "Fig. 11: rotation axis s (from the handle end) against d, for the free beam and the beam "
       "held "
       "in the hand. " +
           fig11.summary},
  };
}

}  // namespace sweetspot::reports
