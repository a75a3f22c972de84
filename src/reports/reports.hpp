#pragma once

// `sweetspot report`: everything `scripts/run` writes into reports/.

#include <ostream>
#include <string>

namespace sweetspot::io {

// Writes the paper's Table I and figures, the paper beam's vibration modes,
// and every shipped study in `designs_dir`/studies (optimisations: a report
// and a convergence plot; sweeps: CSV and plots) into `out_dir`, with a
// README.md index; logs each file. Reports hold no wall times, so that
// regenerating them reproduces the committed files exactly.
void write_reports(const std::string& designs_dir, const std::string& out_dir, std::ostream& log);

}  // namespace sweetspot::io
