#pragma once

// `sweetspot response`: how the implement moves after the ball hits it, the
// rigid (dc) and vibration (ac) velocity of chosen points against time, as in
// Cross (2004) Figs. 3 and 4 (free) and 6 and 7 (hand-held); and the reports
// on the derived COR and the tension-derived impact duration.

#include <string>
#include <vector>

#include "io/design_reader.hpp"
#include "io/plot.hpp"
#include "reports/paper_reports.hpp"
#include "sweetspot/impact_response.hpp"

namespace sweetspot::reports {

struct ResponseRequest {
  std::vector<double> points_from_butt_m{0.02, 0.16};  // where the velocity is observed
  std::vector<double> impacts_from_butt_m;             // empty: the design's impact point
  bool hand_held = false;
  double until_s = 0.02;  // the time window after the impact starts
  int samples = 401;      // times in [0, until_s]
};

struct ResponseData {
  io::DesignFile design;
  ResponseRequest request;
  std::vector<double> time_s;
  std::vector<double> peak_force_N;       // per impact (Eq. 15 with the design's COR and T)
  std::vector<double> duration_s;         // per impact
  std::vector<ImpactResponse> responses;  // per impact
};

// Throws InputError at the design's JSON path when it cannot give modes.
ResponseData compute_response(const io::DesignFile& design, const ResponseRequest& request);

// Long CSV: impact_from_butt_m, t_s, point_from_butt_m, v_dc_m_s, v_ac_m_s, v_m_s.
std::string response_csv(const ResponseData& data);

// One plot per observation point: the velocity against time for each impact,
// traces shifted apart as in the paper's figures.
std::vector<io::Plot> response_plots(const ResponseData& data);

// Derived COR against the free fundamental for the Table I racquet, the
// frequencies that give the paper's 0.8 and 0.6, and the impact duration
// against string tension with the tensions that give Table I's 4 and 6 ms.
std::vector<ReportEntry> write_response_reports(const std::string& designs_dir,
                                                const ReportWriter& write);

}  // namespace sweetspot::reports
