#include "optimizer/nlopt_run.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace sweetspot::optimizer {
namespace {

// A local search that finds no better point in this many gradients' worth of
// evaluations (2n + 1 each) has stalled: SLSQP, given constraints no point of
// the box meets, can otherwise wander until the budget is spent.
constexpr int kStallGradients = 20;

// NLopt works on the unit box u in [0, 1]^n (x = lower + u (upper - lower))
// with the objective divided by its size at the run's start and each
// constraint by its own: gradient methods (SLSQP in particular) then behave
// the same whatever the units of the design variables and outputs.
struct Scaling {
  std::vector<double> lower, range;
  double objective = 1.0;
  std::vector<double> constraint;

  std::vector<double> to_x(const double* u) const {
    std::vector<double> x(lower.size());
    for (std::size_t i = 0; i < x.size(); ++i) x[i] = lower[i] + u[i] * range[i];
    return x;
  }
  std::vector<double> to_u(std::span<const double> x) const {
    std::vector<double> u(lower.size());
    for (std::size_t i = 0; i < u.size(); ++i)
      u[i] = std::clamp((x[i] - lower[i]) / range[i], 0.0, 1.0);
    return u;
  }
};

// The problem's box mapped onto the unit cube (objective and constraint
// scales are left at 1).
Scaling box_scaling(const Problem& problem) {
  Scaling scaling;
  scaling.lower = problem.lower;
  for (std::size_t i = 0; i < problem.lower.size(); ++i)
    scaling.range.push_back(problem.upper[i] - problem.lower[i]);
  return scaling;
}

// The unit cube, with the objective and each constraint scaled by its size
// at x0 (a constraint never below a thousand of its tolerances).
Scaling scaling_at(const Problem& problem, Evaluator& evaluator, std::span<const double> x0) {
  Scaling scaling = box_scaling(problem);
  const std::vector<double>& at_start = evaluator.values(x0);
  scaling.objective = std::abs(at_start[0]) > 0 ? std::abs(at_start[0]) : 1.0;
  for (std::size_t k = 0; k < problem.constraints.size(); ++k) {
    // Never scale a constraint's tolerance below a thousandth.
    scaling.constraint.push_back(
        std::max(std::abs(at_start[1 + k]), 1e3 * problem.constraints[k].tolerance));
  }
  return scaling;
}

struct Callback {
  Evaluator* evaluator;
  const Scaling* scaling;
  std::vector<std::size_t> indices;  // constraint indices for an mconstraint
};

double objective_callback(unsigned n, const double* u, double* grad, void* data) {
  auto* cb = static_cast<Callback*>(data);
  const Scaling& s = *cb->scaling;
  const std::vector<double> x = s.to_x(u);
  try {
    const double f = cb->evaluator->values(x)[0] / s.objective;
    if (grad) {
      const auto& row = cb->evaluator->jacobian(x)[0];
      for (unsigned i = 0; i < n; ++i) grad[i] = row[i] * s.range[i] / s.objective;
    }
    return f;
  } catch (const SearchStopped&) {
    throw nlopt::forced_stop();
  }
}

void constraints_callback(unsigned m, double* result, unsigned n, const double* u, double* grad,
                          void* data) {
  auto* cb = static_cast<Callback*>(data);
  const Scaling& s = *cb->scaling;
  const std::vector<double> x = s.to_x(u);
  try {
    const auto& v = cb->evaluator->values(x);
    for (unsigned k = 0; k < m; ++k) {
      const std::size_t c = cb->indices[k];
      result[k] = v[1 + c] / s.constraint[c];
    }
    if (grad) {
      const auto& rows = cb->evaluator->jacobian(x);
      for (unsigned k = 0; k < m; ++k) {
        const std::size_t c = cb->indices[k];
        for (unsigned i = 0; i < n; ++i)
          grad[k * n + i] = rows[1 + c][i] * s.range[i] / s.constraint[c];
      }
    }
  } catch (const SearchStopped&) {
    throw nlopt::forced_stop();
  }
}

// The constraints, each kind one NLopt mconstraint.
struct ConstraintCallbacks {
  Callback inequalities, equalities;
};

ConstraintCallbacks constraint_callbacks(const Problem& problem, Evaluator& evaluator,
                                         const Scaling& scaling) {
  ConstraintCallbacks callbacks{{&evaluator, &scaling, {}}, {&evaluator, &scaling, {}}};
  for (std::size_t k = 0; k < problem.constraints.size(); ++k) {
    (problem.constraints[k].kind == ConstraintKind::kZero ? callbacks.equalities
                                                          : callbacks.inequalities)
        .indices.push_back(k);
  }
  return callbacks;
}

// Adds the nonempty kinds of constraint to `opt`, with their tolerances
// scaled; throws std::invalid_argument when the algorithm takes none.
void add_constraints(nlopt::opt& opt, nlopt::algorithm algorithm, const Problem& problem,
                     const Scaling& scaling, ConstraintCallbacks& callbacks) {
  const auto tolerances = [&](const Callback& cb) {
    std::vector<double> tol;
    for (const std::size_t k : cb.indices)
      tol.push_back(problem.constraints[k].tolerance / scaling.constraint[k]);
    return tol;
  };
  Callback& inequalities = callbacks.inequalities;
  Callback& equalities = callbacks.equalities;
  try {
    if (!inequalities.indices.empty()) {
      opt.add_inequality_mconstraint(constraints_callback, &inequalities, tolerances(inequalities));
    }
    if (!equalities.indices.empty()) {
      opt.add_equality_mconstraint(constraints_callback, &equalities, tolerances(equalities));
    }
  } catch (const std::invalid_argument&) {
    throw std::invalid_argument(
        "algorithm: " + nlopt_name(algorithm) +
        " does not take nonlinear constraints; use auto, LD_SLSQP, LN_COBYLA, GN_ISRES or AUGLAG");
  }
}

// The unit-cube bounds and the stopping rules every run shares: the
// tolerances and what is left of the evaluation and time budgets.
void set_box_and_stopping(nlopt::opt& opt, const OptimizeOptions& options,
                          const Evaluator& evaluator) {
  const unsigned n = opt.get_dimension();
  opt.set_lower_bounds(std::vector<double>(n, 0.0));
  opt.set_upper_bounds(std::vector<double>(n, 1.0));
  opt.set_xtol_abs(std::vector<double>(n, options.x_tolerance_rel));
  opt.set_ftol_rel(options.f_tolerance_rel);
  opt.set_maxeval(std::max(1, options.max_evaluations - evaluator.evaluations()));
  opt.set_maxtime(std::max(1e-3, options.max_seconds - evaluator.seconds()));
  opt.set_initial_step(std::vector<double>(n, 0.1));
}

// The subsidiary method of MLSL and AUGLAG, with the run's tolerances.
void set_local_optimizer(nlopt::opt& opt, nlopt::algorithm local, const OptimizeOptions& options) {
  const unsigned n = opt.get_dimension();
  nlopt::opt local_opt(local, n);
  local_opt.set_xtol_abs(std::vector<double>(n, options.x_tolerance_rel));
  local_opt.set_ftol_rel(options.f_tolerance_rel);
  opt.set_local_optimizer(local_opt);
}

// NLopt's successful results (opt::optimize throws the others).
Ending ending_of(nlopt::result result) {
  switch (result) {
    case nlopt::SUCCESS:
      return {Termination::kSuccess, ""};
    case nlopt::STOPVAL_REACHED:
      return {Termination::kStopValueReached, ""};
    case nlopt::FTOL_REACHED:
      return {Termination::kFtolReached, ""};
    case nlopt::XTOL_REACHED:
      return {Termination::kXtolReached, ""};
    case nlopt::MAXEVAL_REACHED:
      return {Termination::kMaxEvaluations, ""};
    case nlopt::MAXTIME_REACHED:
      return {Termination::kMaxTime, ""};
    default:
      return {Termination::kFailure,
              std::string(": ") + nlopt_result_to_string(static_cast<nlopt_result>(result))};
  }
}

// Runs `opt` from u and says how it ended (NLopt's exceptions as words).
Ending run_once(nlopt::opt& opt, std::vector<double> u, const Evaluator& evaluator) {
  double f = 0.0;
  try {
    return ending_of(opt.optimize(u, f));
  } catch (const nlopt::forced_stop&) {
    return evaluator.spent()            ? evaluator.budget_ending()
           : evaluator.best().stalled() ? evaluator.best().stall_ending()
                                        : Ending{Termination::kForcedStop, ""};
  } catch (const nlopt::roundoff_limited&) {
    return {Termination::kRoundoffLimited, ""};
  } catch (const std::invalid_argument& e) {
    return {Termination::kInvalidArguments, std::string(": ") + e.what()};
  } catch (const std::runtime_error& e) {
    return {Termination::kFailure, std::string(": ") + e.what()};
  }
}

// run_once, a local search stopped when it stalls (global ones explore).
Ending run_to_end(nlopt::opt& opt, std::vector<double> u, Evaluator& evaluator, bool local) {
  if (local)
    evaluator.best().set_stall_limit(kStallGradients * (2 * static_cast<int>(u.size()) + 1));
  Ending ended = run_once(opt, std::move(u), evaluator);
  evaluator.best().set_stall_limit(0);
  return ended;
}

struct ViolationCallback {
  Evaluator* evaluator;
  const Scaling* scaling;
};

double violation_callback(unsigned, const double* u, double*, void* data) {
  auto* cb = static_cast<ViolationCallback*>(data);
  try {
    return cb->evaluator->best().violation(cb->evaluator->values(cb->scaling->to_x(u)));
  } catch (const SearchStopped&) {
    throw nlopt::forced_stop();
  }
}

}  // namespace

std::optional<nlopt::algorithm> algorithm_from_name(const std::string& name) {
  for (int i = 0; i < NLOPT_NUM_ALGORITHMS; ++i) {
    const auto a = static_cast<nlopt_algorithm>(i);
    if (name == nlopt_algorithm_to_string(a)) return static_cast<nlopt::algorithm>(a);
  }
  return std::nullopt;
}

std::string nlopt_name(nlopt::algorithm algorithm) {
  return nlopt_algorithm_to_string(static_cast<nlopt_algorithm>(algorithm));
}

nlopt::algorithm default_local_algorithm(const Problem& problem) {
  if (!problem.smooth) return nlopt::LN_COBYLA;
  return problem.constraints.empty() && problem.lower.size() >= 2 ? nlopt::LN_BOBYQA
                                                                  : nlopt::LD_SLSQP;
}

nlopt::algorithm local_algorithm(const Problem& problem, const OptimizeOptions& options) {
  return options.local_algorithm == "auto" ? default_local_algorithm(problem)
                                           : *algorithm_from_name(options.local_algorithm);
}

Ending run_nlopt(nlopt::algorithm algorithm, std::optional<nlopt::algorithm> local,
                 const Problem& problem, const OptimizeOptions& options, Evaluator& evaluator,
                 std::vector<double> x0) {
  const Scaling scaling = scaling_at(problem, evaluator, x0);
  nlopt::opt opt(algorithm, static_cast<unsigned>(problem.lower.size()));
  set_box_and_stopping(opt, options, evaluator);
  Callback objective{&evaluator, &scaling, {}};
  ConstraintCallbacks constraints = constraint_callbacks(problem, evaluator, scaling);
  opt.set_min_objective(objective_callback, &objective);
  add_constraints(opt, algorithm, problem, scaling, constraints);
  if (local) set_local_optimizer(opt, *local, options);
  const std::string name = nlopt_name(algorithm);
  const bool local_search = name.starts_with("LD_") || name.starts_with("LN_");
  return run_to_end(opt, scaling.to_u(x0), evaluator, local_search);
}

Ending reduce_violation(const Problem& problem, const OptimizeOptions& options,
                        Evaluator& evaluator) {
  const Scaling scaling = box_scaling(problem);
  ViolationCallback callback{&evaluator, &scaling};
  nlopt::opt opt(nlopt::LN_COBYLA, static_cast<unsigned>(problem.lower.size()));
  set_box_and_stopping(opt, options, evaluator);
  opt.set_min_objective(violation_callback, &callback);
  return run_to_end(opt, scaling.to_u(evaluator.best().point()), evaluator, true);
}

}  // namespace sweetspot::optimizer
