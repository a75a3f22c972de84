#pragma once

// `sweetspot bench`: speed against error, measured on this machine. A careful
// harness rather than a test: every figure is the median of repeated runs on
// one core, with the machine and compiler stated. Not part of the reports'
// reproducibility check (timings never reproduce).

#include <optional>
#include <ostream>
#include <string>
#include <vector>

#include "io/plot.hpp"

namespace sweetspot::bench {

struct BenchOptions {
  std::string designs_dir = "designs";
  std::string out_dir = "reports";
  int repeats = 5;  // runs per figure; the median is reported
  // The sweetspot program, run end to end for the command-line figures
  // (empty: those are skipped).
  std::string executable;
  // The peers: the same work in NumPy/SciPy, run with `python` (skipped, with
  // the reason, when it cannot import numpy and scipy).
  std::string peers_dir = "bench/peers";
  std::string python = "/usr/bin/python3";
};

// The median of repeated timings (the mean of the middle two for an even count).
double median(std::vector<double> values);

// The machine, compiler and flags, for the head of every benchmark report.
std::string machine_description();

// Everything in speed-vs-error.md (+ .csv, speed-vs-error-threads.png in
// out_dir): rigid evaluations per second through the library (rigid_outcomes
// on distinct designs, ImpactSweep, evaluate_unchecked); the command line end
// to end (bench_throughput); every shipped optimisation with "auto" and with
// each NLopt algorithm that fits it (evaluations, median wall time, objective
// reached); the cost of each fidelity against its error. Logs a summary.
void bench_speed(const BenchOptions& options, std::ostream& log);
// Throws InputError when bench_speed()'s inputs are missing (DESIGNS/studies):
// checked first, before the output folder and any timing.
void require_bench_speed_inputs(const BenchOptions& options);

// The string-bed map (`sweetspot map`): a 50 x 50 grid over a 100 in^2 head at
// the rigid level (with a given duration and with one derived from the string
// tension at every point) and at the modal level (the vibration energy too,
// modes solved once): median wall time of the library call. Returns the
// Markdown section that bench_speed() puts in speed-vs-error.md.
std::string bench_maps(const BenchOptions& options, std::ostream& log);

// The command line end to end: a one-million-point sweep along the impact, a
// million-point sweep that reads every point, and a 100 000-row CSV catalogue through
// `evaluate --batch`, each on 1, 2, 4, ... and all cores: median wall time,
// points per second, speed-up, peak resident memory.
struct ThroughputReport {
  std::string markdown;                // a section of speed-vs-error.md
  std::string csv;                     // its table
  std::optional<io::Plot> plot;        // points per second against threads
  double million_point_sweep_s = 0.0;  // on all cores
  double million_point_sweep_MB = 0.0;
  double every_point_sweep_s = 0.0;  // a million points, every one evaluated, on all cores
  double every_point_sweep_1_thread_s = 0.0;
  double batch_1_thread_s = 0.0;  // 100 000 CSV rows on one core
};
ThroughputReport bench_throughput(const BenchOptions& options, std::ostream& log);

// The same work done the obvious way in NumPy/SciPy (bench/peers/*.py): the
// every-point sweep and the batch as whole processes (median wall time of
// options.repeats runs), study 1 with scipy.optimize SLSQP and the rigid model
// on a million designs in-process (as the scripts time them).
struct PeerFigures {
  std::string skipped;               // why they were not measured; empty when they were
  double every_point_sweep_s = 0.0;  // 1000 x 1000 points, CSV out, whole process
  double batch_s = 0.0;              // 100 000 racquets by specs, CSV in and out, whole process
  double study1_ms = 0.0;            // one SLSQP optimisation
  int study1_evaluations = 0;
  double study1_objective = 0.0;
  double rigid_ns = 0.0;  // per design
  // The free beam's fundamental by finite elements (kFreeFeElements), one
  // assembly and scipy.linalg.eigh, and the f1 it gives.
  double free_fe_us = 0.0;
  double free_fe_f1_Hz = 0.0;
};
// The mesh of the free finite-element comparison with SciPy's eigh.
inline constexpr int kFreeFeElements = 30;
PeerFigures bench_peers(const BenchOptions& options, std::ostream& log);

// One solved collision of the typical racquet (collision.hpp): time and error
// against the step, against a tenth of the step and a fine reference, into
// speed-vs-error-collision.md (+ .csv) in out_dir.
void bench_collision(const BenchOptions& options, std::ostream& log);

// Speed against error of every modal solver on the optimizer's study racquet
// (two sections, f1 = 150 Hz, 6 g of tape at 0.68 m; hand-held with the
// calibrated hand), as CSV: method, resolution, elements, median_us, f1_Hz,
// f1_rel_error, node_m, node_abs_error_m, order, reference. About
// `budget_ms` of timing per row.
std::string speed_vs_error_modes_csv(double budget_ms);

// Writes speed-vs-error-modes.md, .csv and .png into out_dir; logs a summary.
void bench_modes(const BenchOptions& options, std::ostream& log);

}  // namespace sweetspot::bench
