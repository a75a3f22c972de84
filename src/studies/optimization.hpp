#pragma once

// A study run as an optimisation: the problem handed to sweetspot::minimize
// and the outcome with each constraint judged at the best design.

#include <memory>
#include <mutex>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include "studies/study.hpp"
#include "sweetspot/optimize.hpp"

namespace sweetspot::io {

// The evaluations of the start and of the point with the lowest objective
// seen, which a study's evaluate functions (and their forks) keep, so that
// the report does not evaluate them again (the modal model in the loop costs
// hundreds of microseconds an evaluation).
class EvaluationMemo {
 public:
  void keep(std::span<const double> x, double objective, const Evaluation& e);
  // The evaluation kept at exactly x, if any.
  std::optional<Evaluation> at(std::span<const double> x) const;

 private:
  mutable std::mutex mutex_;
  std::vector<double> start_, best_;
  std::optional<Evaluation> at_start_, at_best_;
  double best_objective_ = 0.0;
};

// The study as an optimisation problem for sweetspot::minimize; with `memo`,
// its evaluate functions keep the start's and the best point's evaluations
// there.
Problem make_problem(const Study& study, std::shared_ptr<EvaluationMemo> memo = nullptr);

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
  Summary summary;
  std::vector<double> start_x;
  DesignFile start;
  DesignFile best;
  std::optional<double> start_objective{};  // std::nullopt: the objective has no value at the start
  // Every output at the start and at the best design (std::nullopt: the model refuses the design).
  std::optional<Evaluation> start_outputs{}, best_outputs{};
  std::vector<ConstraintReport> constraints{};
  Outcome outcome = Outcome::kOptimum;
  std::string no_value{};  // kNoValue: why the best design gives the objective no value
};

// Runs the study's optimisation. Throws InputError for a study that cannot be
// optimised (no objective, a variable without a range).
OptimizationResult run_optimization(const Study& study);

}  // namespace sweetspot::io
