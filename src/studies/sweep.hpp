#pragma once

// A study run as a what-if grid (`sweetspot sweep`): every output at every
// point of one or two variables, streamed as CSV.

#include <cstddef>
#include <functional>
#include <ostream>
#include <span>
#include <string_view>
#include <vector>

#include "io/format.hpp"
#include "io/plot.hpp"
#include "studies/study.hpp"

namespace sweetspot::studies {

struct SweepOptions {
  int threads = 1;  // >= 1; the output is in grid order whatever the number
  // Share a row's design when the first variable is the impact point and the
  // study is rigid: one design read per row, then ImpactSweep. Off, every
  // point is read and evaluated on its own (the reference the tests compare with).
  bool share_rows = true;
  // Set each point on the study's compiled design (design_binding.hpp). Off,
  // every point is written into the JSON document and read again: the
  // reference the tests compare the compiled path with, on good and bad points.
  bool compiled = true;
  // A rigid sweep whose outputs are all among rigid_outcome_outputs() computes
  // only those at each compiled point (evaluate_rigid_outcome()). Off, every
  // point is evaluated whole: the reference the tests compare it with.
  bool outcome_only = true;
  // The rows: CSV (a header line) or JSON Lines (one object a point, keyed
  // by the CSV's header, numbers as numbers, a missing value null).
  io::Format format = io::Format::kCsv;
};

// The outputs (outputs.hpp) that evaluate_rigid_outcome() answers.
std::span<const std::string_view> rigid_outcome_outputs();

// A sweep over the grid of the study's variables (one or two), streaming one
// row per point to `out` in grid order (the first variable fastest), in
// options.format (io/rows.hpp);
// `progress(done, total)` is called now and then. Returns one plot per output
// against the first variable, a line per value of the second; plot data is
// kept only for grids up to kMaxPlotPoints (memory stays bounded: points are
// evaluated kSweepChunkPoints at a time, split among the threads).
inline constexpr std::size_t kMaxPlotPoints = 100000;
inline constexpr std::size_t kSweepChunkPoints = 8192;
std::vector<io::Plot> run_sweep(const Study& study, std::ostream& out,
                                const std::function<void(std::size_t, std::size_t)>& progress,
                                const SweepOptions& options = {});

}  // namespace sweetspot::studies
