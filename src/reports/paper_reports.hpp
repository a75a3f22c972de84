#pragma once

// The paper's Table I and Figs. 5 and 11 (computed in studies/paper.hpp)
// written as Markdown, CSV and PNG into reports/.

#include <optional>
#include <ostream>
#include <string>
#include <vector>

#include "io/design_reader.hpp"
#include "io/format.hpp"
#include "io/plot.hpp"
#include "reports/report_writer.hpp"
#include "studies/paper.hpp"

namespace sweetspot::reports {

// Table I (studies::compute_table1()) in `format`: Markdown beside the
// printed values, CSV, JSON.
std::string table1_report(const std::vector<studies::Table1Row>& rows, io::Format format);

// A figure's data as CSV, its plot and a sentence comparing it with the paper.
struct Figure {
  std::string csv;
  io::Plot plot;
  std::string summary;
};

// Fig. 5 of `beam` (studies::figure5_data(beam)): v2/v16 against the impact
// distance d from the free end for the free beam, Eq. (6), with observation
// points 2 and 16 cm from the handle end; the paper's printed values beside
// the paper's own beam (its reference cites Cross 2004).
Figure figure5(const io::DesignFile& beam, const studies::Figure5Data& data);

// Fig. 11 of `beam` (studies::figure11_data(beam)): rotation axis s = h - A
// against d, free (Eq. 5) and hand-held (Eq. 12), and where they cross.
Figure figure11(const io::DesignFile& beam, const studies::Figure11Data& data);

// Table I and Figs. 5 and 11 (studies::paper_results()): table1.md,
// table1.csv, fig5.csv, fig5.png, fig11.csv, fig11.png. Returns their index entries.
std::vector<ReportEntry> write_paper_reports(const studies::PaperResults& results,
                                             const ReportWriter& write);

}  // namespace sweetspot::reports
