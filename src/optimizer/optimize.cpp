// minimize() and the public pieces of optimize.hpp. The parts it is made of:
// evaluator.hpp (the cache, differences, budget, threads and the best point),
// nlopt_run.hpp (one NLopt run), strategies.hpp ("auto" and a named
// algorithm).

#include "optimizer/optimize.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>
#include <stdexcept>

#include "core/check.hpp"
#include "optimizer/evaluator.hpp"
#include "optimizer/nlopt_run.hpp"
#include "optimizer/strategies.hpp"

namespace sweetspot::optimizer {
namespace {

void validate_problem(const Problem& p) {
  const std::size_t n = p.lower.size();
  if (n == 0) throw std::invalid_argument("variables: need at least one");
  if (p.upper.size() != n || p.start.size() != n) {
    throw std::invalid_argument("variables: lower, upper and start must have the same size");
  }
  if (!p.evaluate) throw std::invalid_argument("evaluate: no function given");
  for (std::size_t i = 0; i < n; ++i) {
    const std::string at = "variables/" + std::to_string(i);
    detail::require_finite(at + "/min", p.lower[i]);
    detail::require_finite(at + "/max", p.upper[i]);
    if (!(p.lower[i] < p.upper[i])) {
      throw std::invalid_argument(at + ": min must be < max, got min " +
                                  detail::format_number(p.lower[i]) + " and max " +
                                  detail::format_number(p.upper[i]));
    }
    detail::require_in_range(at + "/start", p.start[i], p.lower[i], p.upper[i], "");
  }
  for (std::size_t k = 0; k < p.constraints.size(); ++k) {
    detail::require_positive("constraints/" + std::to_string(k) + "/tolerance",
                             p.constraints[k].tolerance, "");
  }
}

// The strategy options.algorithm names; the budget, spent between two NLopt
// runs, ends it with the Outcome it has written so far.
Outcome search(const Problem& problem, const OptimizeOptions& options, Evaluator& evaluator) {
  Outcome outcome;
  try {
    if (options.algorithm == "auto") {
      run_auto(problem, options, evaluator, outcome);
    } else {
      run_named_algorithm(problem, options, evaluator, outcome);
    }
  } catch (const SearchStopped&) {
    outcome.ending = evaluator.budget_ending();
  }
  if (outcome.algorithm.empty()) outcome.algorithm = options.algorithm;
  return outcome;
}

// With constraints no point met, the least violating point is the answer:
// the budget permitting, a last run minimises the violation.
void reduce_violation_if_infeasible(const Problem& problem, const OptimizeOptions& options,
                                    Evaluator& evaluator, Outcome& outcome) {
  if (problem.constraints.empty() || evaluator.best().feasible() || evaluator.spent()) return;
  outcome.ending = reduce_violation(problem, options, evaluator);
  outcome.algorithm += " + LN_COBYLA on the violation (no feasible point found)";
}

Summary summarize(Evaluator& evaluator, Outcome outcome) {
  BestPoint& best = evaluator.best();
  Summary summary;
  summary.x = best.point();
  summary.objective = best.values()[0];
  summary.constraints.assign(best.values().begin() + 1, best.values().end());
  summary.feasible = best.feasible();
  summary.evaluations = evaluator.evaluations();
  summary.seconds = evaluator.seconds();
  summary.algorithm = std::move(outcome.algorithm);
  summary.termination = outcome.ending.termination;
  summary.termination_detail = std::move(outcome.ending.detail);
  summary.history = std::move(best.history());
  summary.violation_history = std::move(best.violation_history());
  return summary;
}

}  // namespace

std::string_view message(Termination termination) {
  switch (termination) {
    case Termination::kSuccess:
      return "SUCCESS";
    case Termination::kStopValueReached:
      return "STOPVAL_REACHED";
    case Termination::kFtolReached:
      return "FTOL_REACHED";
    case Termination::kXtolReached:
      return "XTOL_REACHED";
    case Termination::kMaxEvaluations:
      return "MAXEVAL_REACHED";
    case Termination::kMaxTime:
      return "MAXTIME_REACHED";
    case Termination::kStalled:
      return "STALLED";
    case Termination::kVertexFirstOrder:
      return "VERTEX_FIRST_ORDER";
    case Termination::kRoundoffLimited:
      return "ROUNDOFF_LIMITED";
    case Termination::kForcedStop:
      return "FORCESTOP";
    case Termination::kInvalidArguments:
      return "INVALID_ARGS";
    case Termination::kFailure:
      return "FAILURE";
  }
  return "FAILURE";  // not a Termination
}

bool is_failure(Termination termination) {
  return termination == Termination::kForcedStop || termination == Termination::kInvalidArguments ||
         termination == Termination::kFailure;
}

std::string OptimizeOptions::validate() const {
  if (!is_known_algorithm(algorithm))
    return "algorithm: unknown NLopt algorithm \"" + algorithm + "\"";
  if (!is_known_algorithm(local_algorithm)) {
    return "local_algorithm: unknown NLopt algorithm \"" + local_algorithm + "\"";
  }
  const auto positive = [](const char* name, double value) -> std::string {
    return std::isfinite(value) && value > 0
               ? ""
               : std::string(name) + ": must be > 0, got " + detail::format_number(value);
  };
  for (const auto& why :
       {positive("x_tolerance_rel", x_tolerance_rel), positive("f_tolerance_rel", f_tolerance_rel),
        positive("max_seconds", max_seconds),
        positive("difference_step_rel", difference_step_rel)}) {
    if (!why.empty()) return why;
  }
  if (max_evaluations < 1)
    return "max_evaluations: must be >= 1, got " + std::to_string(max_evaluations);
  if (samples_per_variable < 1) {
    return "samples_per_variable: must be >= 1, got " + std::to_string(samples_per_variable);
  }
  if (local_starts < 1) return "local_starts: must be >= 1, got " + std::to_string(local_starts);
  if (threads < 1 || threads > kMaxThreads) {
    return "threads: must be in [1, " + std::to_string(kMaxThreads) + "], got " +
           std::to_string(threads);
  }
  return "";
}

bool is_known_algorithm(const std::string& name) {
  return name == "auto" || algorithm_from_name(name).has_value();
}

std::string Summary::termination_text() const {
  return std::string(message(termination)) + termination_detail;
}

bool Summary::usable() const { return feasible && !is_failure(termination); }

std::string Summary::brief_report() const {
  std::ostringstream out;
  out << "objective " << objective << (feasible ? " (feasible)" : " (INFEASIBLE)") << " after "
      << evaluations << " evaluations in " << seconds * 1e3 << " ms; " << algorithm << ": "
      << termination_text();
  return out.str();
}

void difference_gradient(const std::function<double(std::span<const double>)>& f,
                         std::span<const double> x, std::span<const double> lower,
                         std::span<const double> upper, double step_rel, std::span<double> grad) {
  Problem problem;
  problem.lower.assign(lower.begin(), lower.end());
  problem.upper.assign(upper.begin(), upper.end());
  problem.evaluate = [&](std::span<const double> at, double& value, std::span<double>) {
    value = f(at);
  };
  OptimizeOptions options;
  options.difference_step_rel = step_rel;
  Evaluator evaluator(problem, options);
  const auto& row = evaluator.jacobian(x)[0];
  std::copy(row.begin(), row.end(), grad.begin());
}

Summary minimize(const Problem& problem, const OptimizeOptions& options) {
  validate_problem(problem);
  if (const std::string why = options.validate(); !why.empty()) throw std::invalid_argument(why);
  Evaluator evaluator(problem, options);
  // The start first: whatever the budget, the run then has a best point.
  evaluator.values(problem.start);
  Outcome outcome = search(problem, options, evaluator);
  reduce_violation_if_infeasible(problem, options, evaluator, outcome);
  return summarize(evaluator, std::move(outcome));
}

}  // namespace sweetspot::optimizer
