#pragma once

// The paper's Table I and Figs. 5 and 11, computed from design files and
// written as Markdown, CSV and PNG into reports/.

#include <optional>
#include <ostream>
#include <string>
#include <vector>

#include "io/design_reader.hpp"
#include "io/format.hpp"
#include "io/plot.hpp"
#include "reports/report_writer.hpp"
#include "sweetspot/evaluate.hpp"

namespace sweetspot::reports {

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
std::string table1_report(const std::vector<Table1Row>& rows, io::Format format);

// A figure's data as CSV, its plot and a sentence comparing it with the paper.
struct Figure {
  std::string csv;
  io::Plot plot;
  std::string summary;
};

// Fig. 5: v2/v16 against the impact distance d from the free end for the free
// beam, Eq. (6), with observation points 2 and 16 cm from the handle end.
Figure figure5(const io::DesignFile& beam);

// Where the free and hand-held rotation axes of Fig. 11 coincide.
struct AxesCrossing {
  double d_m = 0.0;  // impact distance from the free end
  double s_m = 0.0;  // rotation axis from the handle end
};
std::optional<AxesCrossing> figure11_crossing(const io::DesignFile& beam);

// Fig. 11: rotation axis s = h - A against d, free (Eq. 5) and hand-held (Eq. 12).
Figure figure11(const io::DesignFile& beam);

// Table I and Figs. 5 and 11 from the designs in `designs_dir`: table1.md,
// table1.csv, fig5.csv, fig5.png, fig11.csv, fig11.png. Returns their index entries.
std::vector<ReportEntry> write_paper_reports(const std::string& designs_dir,
                                             const std::string& out_dir, const ReportWriter& write);

}  // namespace sweetspot::reports
