#pragma once

// reports/tension-and-stiffness.md: the solved collision (collision.hpp) of
// the typical racquet over string tension and frame stiffness: rebound speed,
// contact time, frame vibration and the shock to the wrist; the published
// numbers beside the model's; the sensitivity to the string bed's mass and loss.

#include <string>
#include <vector>

#include "reports/report_writer.hpp"

namespace sweetspot::reports {

// Reads `designs_dir`/racquets/tour-100.json and table1/row1.json.
std::vector<ReportEntry> write_tension_report(const std::string& designs_dir,
                                              const ReportWriter& write);

}  // namespace sweetspot::reports
