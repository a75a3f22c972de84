#pragma once

// reports/tension-and-stiffness.md, drawn from studies/tension_study.hpp: the
// solved collision of the typical racquet over string tension and frame stiffness: rebound speed,
// contact time, frame vibration and the shock to the wrist; the published
// numbers beside the model's; the sensitivity to the string bed's mass and loss.

#include <string>
#include <vector>

#include "reports/report_writer.hpp"
#include "studies/tension_study.hpp"

namespace sweetspot::reports {

// Writes the study (studies::tension_study()) as Markdown, CSV and plots.
std::vector<ReportEntry> write_tension_report(const studies::TensionStudy& study,
                                              const ReportWriter& write);

}  // namespace sweetspot::reports
