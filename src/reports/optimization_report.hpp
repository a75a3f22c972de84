#pragma once

// The report of an optimisation: a sentence first, then the evidence
// (constraints, convergence, the best design as a design file).

#include <string>

#include "io/format.hpp"
#include "io/plot.hpp"
#include "studies/optimization.hpp"

namespace sweetspot::io {

// The report: a sentence, then the numbers. `with_timing` adds the wall time
// (left out of committed reports so that they are reproducible).
std::string optimization_report(const Study& study, const OptimizationResult& result, Format format,
                                bool with_timing);
Plot convergence_plot(const Study& study, const OptimizationResult& result);

}  // namespace sweetspot::io
