#pragma once

// `sweetspot response`: how the implement moves after the ball hits it, the
// rigid (dc) and vibration (ac) velocity of chosen points against time, as in
// Cross (2004) Figs. 3 and 4 (free) and 6 and 7 (hand-held); and the reports
// on the derived COR and the tension-derived impact duration. The numbers
// are studies/response.hpp's; this draws them.

#include <string>
#include <vector>

#include "io/design_reader.hpp"
#include "io/plot.hpp"
#include "reports/paper_reports.hpp"
#include "studies/response.hpp"

namespace sweetspot::reports {

// Long CSV: impact_from_butt_m, t_s, point_from_butt_m, v_dc_m_s, v_ac_m_s, v_m_s.
std::string response_csv(const studies::ResponseData& data);

// One plot per observation point: the velocity against time for each impact,
// traces shifted apart as in the paper's figures.
std::vector<io::Plot> response_plots(const studies::ResponseData& data);

// The paper beam's motion (Figs. 3, 4, 6 and 7), the derived COR against the
// free fundamental for the Table I racquet with the frequencies that give
// the paper's 0.8 and 0.6, and the impact duration against string tension
// with the tensions that give Table I's 4 and 6 ms, from
// studies::response_reports().
std::vector<ReportEntry> write_response_reports(const studies::ResponseReports& computed,
                                                const ReportWriter& write);

}  // namespace sweetspot::reports
