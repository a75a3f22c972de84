#include "studies/optimization.hpp"

#include <algorithm>
#include <cmath>
#include <memory>

#include <fmt/format.h>

#include "io/format.hpp"
#include "io/input_error.hpp"
#include "studies/design_binding.hpp"
#include "sweetspot/evaluate.hpp"

namespace sweetspot::io {
namespace {

// A constraint within this fraction of its limit counts as active.
constexpr double kActiveFraction = 1e-4;

struct ProblemConstraint {
  const StudyConstraint* source;
  enum { kMin, kMax, kEquals } which;
};

std::vector<ProblemConstraint> expand_constraints(const Study& study) {
  std::vector<ProblemConstraint> list;
  for (const StudyConstraint& c : study.constraints) {
    if (c.equals) list.push_back({&c, ProblemConstraint::kEquals});
    if (c.min) list.push_back({&c, ProblemConstraint::kMin});
    if (c.max) list.push_back({&c, ProblemConstraint::kMax});
  }
  return list;
}

double limit_of(const ProblemConstraint& pc) {
  return pc.which == ProblemConstraint::kEquals ? *pc.source->equals
         : pc.which == ProblemConstraint::kMin  ? *pc.source->min
                                                : *pc.source->max;
}

std::string constraint_name(const ProblemConstraint& pc) {
  const char* op = pc.which == ProblemConstraint::kEquals ? "=" : pc.which == ProblemConstraint::kMin ? ">=" : "<=";
  return fmt::format("{} {} {}", pc.source->output->name, op, significant(limit_of(pc)));
}

// Signed constraint value: <= 0 (or = 0) when satisfied.
double constraint_value(const ProblemConstraint& pc, const Evaluation& e) {
  const auto value = pc.source->output->value(e);
  if (!value) return kPenalty;
  switch (pc.which) {
    case ProblemConstraint::kEquals: return *value - *pc.source->equals;
    case ProblemConstraint::kMin: return *pc.source->min - *value;
    case ProblemConstraint::kMax: return *value - *pc.source->max;
  }
  return kPenalty;
}

// "min" or "max" when x sits on that bound (to a millionth of the range), else "".

}  // namespace

namespace {

// Minimising a non-negative output with a kink where its signed form changes
// sign (|F_w|) is minimising its square, which is smooth there: gradient
// methods then apply. The reported objective is the output itself.
bool minimizes_square(const Study& study) {
  return study.objective.size() == 1 && study.objective[0].goal == Goal::kMinimize &&
         study.objective[0].output->kinked && !study.over_impacts;
}

}  // namespace

Problem make_problem(const Study& study) {
  Problem problem;
  for (const StudyVariable& v : study.variables) {
    problem.lower.push_back(v.min);
    problem.upper.push_back(v.max);
    problem.start.push_back(v.start);
  }
  const std::vector<ProblemConstraint> constraints = expand_constraints(study);
  for (const ProblemConstraint& pc : constraints) {
    problem.constraints.push_back(ConstraintInfo{
        constraint_name(pc), pc.which == ProblemConstraint::kEquals ? ConstraintKind::kZero : ConstraintKind::kAtMostZero,
        pc.source->tolerance});
  }
  const bool square = minimizes_square(study);
  problem.smooth = !(study.over_impacts && study.over_impacts->reduce == ImpactSpread::Reduce::kMax);
  for (const ObjectiveTerm& term : study.objective) {
    problem.smooth = problem.smooth && (square || !term.output->kinked);
  }
  // Each point is set on the study's compiled design (one working copy for
  // the run); a point it cannot vouch for is read from JSON (design_at).
  const auto bound =
      compiled_for_variables(study) ? std::make_shared<BoundDesign>(*study.compiled) : std::shared_ptr<BoundDesign>();
  problem.evaluate = [&study, constraints, square, bound](std::span<const double> x, double& f,
                                                          std::span<double> c) {
    const auto at = [&](const Design& design) {
      const Evaluation e = evaluate_in(study, design);
      f = study.over_impacts ? objective_of(study, design) : terms_value(study, e);
      if (square) f *= f;
      for (std::size_t k = 0; k < constraints.size(); ++k) c[k] = constraint_value(constraints[k], e);
    };
    try {
      if (const Design* design = bound ? bound->at(x) : nullptr) return at(*design);
    } catch (const std::exception&) {  // the JSON path below decides
    }
    try {
      at(design_at(study, x).design);
    } catch (const std::exception&) {  // InputError or std::invalid_argument: no valid design here
      f = kPenalty;
      std::fill(c.begin(), c.end(), kPenalty);
    }
  };
  return problem;
}

OptimizationResult run_optimization(const Study& study) {
  if (study.objective.empty()) throw InputError(study.source, "/objective", "missing: optimize needs an objective");
  const Problem problem = make_problem(study);
  Summary summary = minimize(problem, study.options);
  if (minimizes_square(study)) {
    summary.objective = std::sqrt(summary.objective);
    for (double& value : summary.history) value = std::sqrt(value);
  }
  DesignFile start = design_at(study, problem.start);
  DesignFile best = design_at(study, summary.x);
  const double start_objective = objective_of(study, start);
  std::vector<ConstraintReport> reports;
  const Evaluation e = evaluate_in(study, best);
  const std::vector<ProblemConstraint> constraints = expand_constraints(study);
  for (const ProblemConstraint& pc : constraints) {
    const double value = constraint_value(pc, e);
    const double limit = limit_of(pc);
    const bool equality = pc.which == ProblemConstraint::kEquals;
    reports.push_back(ConstraintReport{
        constraint_name(pc), pc.source->output->value(e).value_or(std::nan("")),
        equality ? std::abs(value) <= pc.source->tolerance : value <= pc.source->tolerance,
        equality || std::abs(value) <= std::max(pc.source->tolerance, kActiveFraction * std::max(1.0, std::abs(limit)))});
  }
  return OptimizationResult{std::move(summary), problem.start, std::move(start), std::move(best),
                            start_objective, std::move(reports)};
}

}  // namespace sweetspot::io
