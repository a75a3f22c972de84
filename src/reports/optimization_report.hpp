#pragma once

// The report of an optimisation: a sentence first, then the evidence
// (constraints, convergence, the best design as a design file).

#include <string>

#include "io/format.hpp"
#include "io/plot.hpp"
#include "studies/optimization.hpp"

namespace sweetspot::reports {

// The report: a sentence, then the numbers. `with_timing` adds the wall time
// (left out of committed reports so that they are reproducible).
std::string optimization_report(const studies::Study& study,
                                const studies::OptimizationResult& result, io::Format format,
                                bool with_timing);
io::Plot convergence_plot(const studies::Study& study, const studies::OptimizationResult& result);

// The report as one self-contained web page (reports/html_page.hpp): the
// study's question and the answer in sentences, the variables (bounds, start,
// best), the constraints, the convergence plot with the numbers behind it,
// the starting and the best design drawn to one scale, every output at both,
// and the best design as a file. Every string from the study is escaped.
std::string optimization_html(const studies::Study& study,
                              const studies::OptimizationResult& result);

}  // namespace sweetspot::reports
