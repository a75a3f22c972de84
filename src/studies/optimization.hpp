#pragma once

// A study run as an optimisation: the problem handed to sweetspot::minimize
// and the outcome with each constraint judged at the best design.

#include <string>
#include <vector>

#include "studies/study.hpp"
#include "sweetspot/optimize.hpp"

namespace sweetspot::io {

// The study as an optimisation problem for sweetspot::minimize.
Problem make_problem(const Study& study);

struct ConstraintReport {
  std::string name;  // "swingweight_kg_cm2 <= 330"
  double value = 0.0;
  bool satisfied = false;
  bool active = false;  // on its limit: removing it would change the optimum
};

struct OptimizationResult {
  Summary summary;
  std::vector<double> start_x;
  DesignFile start;
  DesignFile best;
  double start_objective = 0.0;
  std::vector<ConstraintReport> constraints;
};

OptimizationResult run_optimization(const Study& study);

}  // namespace sweetspot::io
