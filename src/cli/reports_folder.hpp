#pragma once

// `sweetspot report`: everything `scripts/run` writes into reports/, each
// report's numbers computed by its analysis in studies/ and written by its
// renderer in reports/.

#include <functional>
#include <ostream>
#include <string>

namespace sweetspot::cli {

// Writes the paper's Table I and figures, the paper beam's vibration modes,
// and every shipped study in `designs_dir`/studies (optimisations: a report
// and a convergence plot; sweeps: CSV and plots) into `out_dir`, with a
// README.md index; logs each file. Reports hold no wall times, so that
// regenerating them reproduces the committed files exactly. Nothing is
// written until every file is made; `before_writing` is then called with
// each file's path (a check that may throw: then nothing is written), and
// the files are written all or none (io/atomic_file.hpp).
void write_reports(const std::string& designs_dir, const std::string& out_dir, std::ostream& log,
                   const std::function<void(const std::string&)>& before_writing = {});

}  // namespace sweetspot::cli
