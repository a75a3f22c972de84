#pragma once

// `sweetspot bench`: speed against error, measured on this machine. A careful
// harness rather than a test: every figure is the median of repeated runs on
// one core, with the machine and compiler stated. Not part of the reports'
// reproducibility check (timings never reproduce).

#include <ostream>
#include <string>

namespace sweetspot::io {

struct BenchOptions {
  std::string designs_dir = "designs";
  std::string out_dir = "reports";
  int repeats = 5;  // runs per figure; the median is reported
};

// The machine, compiler and flags, for the head of every benchmark report.
std::string machine_description();

// Rigid evaluations per second through the library (evaluate_unchecked) and
// per study: every shipped optimisation with "auto" and with each NLopt
// algorithm that fits it (evaluations, median wall time, objective reached).
// Writes speed-vs-error.md and speed-vs-error.csv into out_dir; logs a summary.
void bench_optimize(const BenchOptions& options, std::ostream& log);

// Speed against error of every modal solver on the optimizer's study racquet
// (two sections, f1 = 150 Hz, 6 g of tape at 0.68 m; hand-held with the
// calibrated hand), as CSV: method, resolution, elements, median_us, f1_Hz,
// f1_rel_error, node_m, node_abs_error_m, order, reference. About
// `budget_ms` of timing per row.
std::string speed_vs_error_modes_csv(double budget_ms);

// Writes speed-vs-error-modes.md, .csv and .png into out_dir; logs a summary.
void bench_modes(const BenchOptions& options, std::ostream& log);

}  // namespace sweetspot::io
