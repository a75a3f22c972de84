#pragma once

// The searches minimize() runs, private to src/optimizer/: "auto"
// (auto_strategy.cpp) and an NLopt algorithm named in the options
// (named_strategy.cpp). Each writes what ran and why its last stage stopped
// into an Outcome as it goes, so that when the budget ends it between two
// NLopt runs (SearchStopped) the Outcome says how far it came.

#include <string>

#include "optimizer/evaluator.hpp"
#include "optimizer/optimize.hpp"

namespace sweetspot::optimizer {

struct Outcome {
  std::string algorithm;  // Summary::algorithm
  Ending ending;          // Summary::termination and its detail
};

// OptimizeOptions::algorithm "auto": a local stage (the vertex walk where it
// applies, then a local search), a global check with Halton samples of the
// box costing no more than it did, and a second local search from a sample
// better than the local optimum (at most local_starts searches in all).
// May throw SearchStopped.
void run_auto(const Problem& problem, const OptimizeOptions& options, Evaluator& evaluator,
              Outcome& outcome);

// OptimizeOptions::algorithm an NLopt name: that algorithm from the start
// (MLSL and AUGLAG with the local algorithm), a global one (GN_) then
// polished by the default local method. May throw SearchStopped.
void run_named_algorithm(const Problem& problem, const OptimizeOptions& options,
                         Evaluator& evaluator, Outcome& outcome);

}  // namespace sweetspot::optimizer
