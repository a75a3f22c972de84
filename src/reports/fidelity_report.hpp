#pragma once

// reports/fidelity.md and .csv, drawn from studies/fidelity.hpp: each
// published number a shipped design sets up, the model's value beside it and
// the error, with the source.

#include <vector>

#include "reports/report_writer.hpp"
#include "studies/fidelity.hpp"

namespace sweetspot::reports {

std::vector<ReportEntry> write_fidelity_report(const std::vector<studies::FidelityRow>& rows,
                                               const ReportWriter& write);

}  // namespace sweetspot::reports
