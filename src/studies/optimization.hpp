#pragma once

// A study run as an optimisation: the problem handed to sweetspot::minimize
// and the outcome with each constraint judged at the best design.

#include <optional>
#include <span>
#include <string>
#include <vector>

#include "optimizer/optimize.hpp"
#include "studies/study.hpp"

namespace sweetspot::studies {

// The study as an optimisation problem for sweetspot::minimize.
optimizer::Problem make_problem(const Study& study);

struct ConstraintReport {
  std::string name;             // "swingweight_kg_cm2 <= 330"
  std::string unit;             // the output's, "" when dimensionless
  std::optional<double> value;  // the output at the best design; std::nullopt: no finite value
  double limit = 0.0;
  double tolerance =
      0.0;  // how far outside the limit still counts as on it (study's, or the default)
  double violation =
      0.0;  // how far outside the limit the value is (0 within it; a missing value: +inf)
  bool satisfied = false;  // violation <= tolerance
  bool active = false;     // on its limit: removing it would change the optimum
};

// How a study's optimisation ended.
enum class Outcome {
  kOptimum,     // the best design found meets every constraint
  kInfeasible,  // no design found meets them all: the least violating one is reported
  kNoValue,     // no design found gives the objective a value (only the optimizer's penalty)
};

struct OptimizationResult {
  optimizer::Summary summary;
  std::vector<double> start_x;
  io::DesignFile start;
  io::DesignFile best;
  std::optional<double> start_objective{};  // std::nullopt: the objective has no value at the start
  // Every output at the start and at the best design (std::nullopt: the model refuses the design).
  std::optional<Evaluation> start_outputs{}, best_outputs{};
  std::vector<ConstraintReport> constraints{};
  Outcome outcome = Outcome::kOptimum;
  std::string no_value{};  // kNoValue: why the best design gives the objective no value
  // The best design exactly as the report prints it (printed_design); `best`,
  // `best_outputs`, the objective and the constraints are this document read
  // again and evaluated as `sweetspot evaluate` does.
  io::Json best_document{};
  // Empty, or why the search's own evaluation of its best design differs,
  // bit for bit, from the printed design's: a defect of sweetspot (the report
  // gives the printed design's values; `optimize` exits 1 with this line).
  std::string inconsistency{};
};

// The study's design with the variables at x, as a design file `sweetspot
// evaluate` reads as the design the study evaluated at x (`at_x`, read from
// document_at): the study's document with the numbers set, the impact written
// out when the file left it to the default, the study's fidelity when the
// file's own would differ, and without the notes that describe the starting
// design ("description", "reference", "$schema").
io::Json printed_design(const Study& study, std::span<const double> x, const io::DesignFile& at_x);

// Runs the study's optimisation. Throws InputError for a study that cannot be
// optimised (no objective, a variable without a range).
//
// Postcondition: the best design is printed (printed_design), read back by the
// reader `evaluate` uses and evaluated as `evaluate` evaluates it; its
// objective and constraint values are compared bit for bit with the search's
// own evaluation at the same point. The result reports the re-read design's
// values; a difference is named in `inconsistency`.
OptimizationResult run_optimization(const Study& study);

// What run_optimization() refuses before any search, as io::InputError: no
// objective, a variable without a range, a bound the design cannot take by
// itself (its other inputs as given).
void check_can_optimize(const Study& study);

}  // namespace sweetspot::studies
