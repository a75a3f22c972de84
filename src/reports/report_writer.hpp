#pragma once

// What every report of the reports folder is written through, so that the
// paper's reports, the modes, the response and the studies share one writer.

#include <functional>
#include <string>

#include "io/plot.hpp"

namespace sweetspot::reports {

// One line of the reports' index: the files and what they show.
struct ReportEntry {
  std::string files;  // Markdown links
  std::string says;
};

// Writes into the reports folder: text atomically, plots through gnuplot
// (a missing gnuplot skips the plot and says so).
struct ReportWriter {
  std::function<void(const std::string& name, const std::string& content)> text;
  std::function<void(const std::string& name, const io::Plot& plot)> plot;
};

}  // namespace sweetspot::reports
