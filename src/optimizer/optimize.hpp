#pragma once

// Bound- and constraint-limited minimisation of a function of a few design
// variables. The problem knows nothing of the optimiser and the optimiser
// nothing of racquets: a Problem evaluates the objective and every constraint
// at a point; minimize() searches (with NLopt, hidden in src/) and returns a
// Summary. Nothing here prints.

#include <array>
#include <functional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

namespace sweetspot::optimizer {

enum class ConstraintKind {
  kAtMostZero,  // feasible when value <= tolerance
  kZero,        // feasible when |value| <= tolerance
};

struct ConstraintInfo {
  std::string name;
  ConstraintKind kind = ConstraintKind::kAtMostZero;
  double tolerance = 1e-8;  // in the constraint's own unit, > 0
};

// Writes the objective and each constraint's value at x.
using EvaluateFunction = std::function<void(std::span<const double> x, double& objective,
                                            std::span<double> constraints)>;

struct Problem {
  std::vector<double> lower;  // bounds, lower[i] < upper[i], finite
  std::vector<double> upper;
  std::vector<double> start;  // inside the bounds
  std::vector<ConstraintInfo> constraints;
  // Must be finite; a point where the model has no answer should return a
  // large penalty. Called from one thread at a time.
  EvaluateFunction evaluate;
  // Optional: a new evaluate function that may run at the same time as
  // `evaluate` and every other one made (each keeps its own working state).
  // Given, independent points (the differences of a gradient, the steps of
  // auto's vertex walk, its samples of the box) are evaluated on
  // OptimizeOptions::threads threads; results are booked in the order of the
  // points, so the search and its Summary are the same whatever the threads.
  std::function<EvaluateFunction()> fork;
  // False when the objective has kinks (a max over impacts, an absolute
  // value): "auto" then uses a derivative-free local method.
  bool smooth = true;
};

inline constexpr int kMaxThreads = 256;

struct OptimizeOptions {
  // An NLopt algorithm name (LD_SLSQP, LD_MMA, LN_COBYLA, LN_BOBYQA,
  // GN_DIRECT_L, GN_ISRES, G_MLSL_LDS, ...) or "auto": with bounds only, a
  // smooth objective and n >= 2, first a walk over the box's vertices
  // downhill (forward differences point to a vertex, taken when better; one
  // where no inward step improves is first-order and ends the local stage);
  // else a local search from the best point so far
  // (smooth: LN_BOBYQA with bounds only and n >= 2, else LD_SLSQP with
  // central-difference gradients; not smooth: LN_COBYLA), then as many
  // low-discrepancy samples of the box as it cost
  // (n + 1 to samples_per_variable n), then a second local search from the
  // best sample if one beats the first optimum. auto thus costs at most about
  // twice its local search.
  std::string algorithm = "auto";
  // The local algorithm for G_MLSL / G_MLSL_LDS / AUGLAG, or for "auto"'s
  // local stage ("auto": chosen as above).
  std::string local_algorithm = "auto";
  double x_tolerance_rel = 1e-7;   // stop when steps are this small, relative to each range
  double f_tolerance_rel = 1e-10;  // stop when the objective changes this little
  int max_evaluations = 5000;      // evaluations of Problem::evaluate, including differences
  double max_seconds = 60.0;
  unsigned long seed = 1;  // for stochastic algorithms and "auto"'s samples
  // Central differences step, relative to each variable's range.
  double difference_step_rel = 1e-6;
  // "auto": the most samples per variable in the global check, and the most
  // local searches (1: from the start only; 2: also from a better sample).
  int samples_per_variable = 8;
  int local_starts = 2;
  // Threads for independent points (needs Problem::fork), in [1, kMaxThreads]. Used
  // only when one evaluation costs more than starting a thread does.
  int threads = 1;

  // Empty when valid, else what is wrong ("max_evaluations: must be >= 1, got 0").
  std::string validate() const;
};

// Why the last stage of a run stopped. NLopt's own reasons keep NLopt's
// names; sweetspot's budget, its stall detection and auto's vertex walk add
// theirs.
enum class Termination {
  kSuccess,           // NLopt: SUCCESS (a method's own convergence test)
  kStopValueReached,  // NLopt: STOPVAL_REACHED
  kFtolReached,       // NLopt: FTOL_REACHED, the objective changed by under f_tolerance_rel
  kXtolReached,       // NLopt: XTOL_REACHED, steps under x_tolerance_rel of each range
  // The evaluation budget: sweetspot's (max_evaluations, differences
  // included) or NLopt's count of its own calls, set to what is left of it.
  kMaxEvaluations,
  kMaxTime,           // the time budget (max_seconds), by sweetspot's clock or NLopt's
  kStalled,           // a local search found no better point in many evaluations
  kVertexFirstOrder,  // auto: a vertex of the box where no inward step improves
  kRoundoffLimited,   // NLopt: ROUNDOFF_LIMITED (the point is still typically good)
  kForcedStop,        // NLopt stopped by an exception the budget does not explain
  kInvalidArguments,  // NLopt refused the problem (INVALID_ARGS)
  kFailure,           // NLopt failed (FAILURE), or no run filled the Summary
};

// Every Termination, in declaration order.
inline constexpr std::array kTerminations = {
    Termination::kSuccess,     Termination::kStopValueReached, Termination::kFtolReached,
    Termination::kXtolReached, Termination::kMaxEvaluations,   Termination::kMaxTime,
    Termination::kStalled,     Termination::kVertexFirstOrder, Termination::kRoundoffLimited,
    Termination::kForcedStop,  Termination::kInvalidArguments, Termination::kFailure,
};

// The reason's name as reports print it, e.g. "XTOL_REACHED",
// "VERTEX_FIRST_ORDER"; Summary::termination_detail may follow it.
std::string_view message(Termination termination);

// True for the reasons that mean the run failed rather than stopped:
// kForcedStop, kInvalidArguments, kFailure. A spent budget, a stall or
// NLopt's round-off limit still leave the best point seen as an answer.
bool is_failure(Termination termination);

struct Summary {
  std::vector<double> x;  // best point found
  double objective = 0.0;
  std::vector<double> constraints;  // values at x
  bool feasible = false;            // every constraint within its tolerance at x
  int evaluations = 0;
  double seconds = 0.0;
  std::string algorithm;  // what ran, e.g. "auto: LD_SLSQP from the start, 16 Halton samples"
  // Why the last stage stopped, and what message() cannot know of it: whose
  // budget (" (sweetspot's budget)"), the stall's length, auto's difference
  // step, NLopt's error text (": ..."); "" for most reasons.
  Termination termination = Termination::kFailure;
  std::string termination_detail;
  // Objective of the best point after each evaluation, feasible points ranking
  // before infeasible ones (which rank by their constraint violation).
  std::vector<double> history;
  // The best point's constraint violation after each evaluation: the largest
  // excess over a limit in multiples of that constraint's tolerance (0 within
  // every limit, <= 1 feasible).
  std::vector<double> violation_history;

  // message(termination) + termination_detail, e.g. "MAXEVAL_REACHED
  // (sweetspot's budget, including differences)": the words reports print.
  std::string termination_text() const;
  // Whether x is an answer: feasible, and the run stopped rather than failed
  // (!is_failure(termination)). A run its budget stopped is usable: x is the
  // best point it saw.
  bool usable() const;
  std::string brief_report() const;
};

// True when `name` is an NLopt algorithm this build knows, or "auto".
bool is_known_algorithm(const std::string& name);

// Minimises problem.evaluate's objective within the bounds subject to the
// constraints. Throws std::invalid_argument for an invalid problem or options
// (sizes, bounds, start outside the bounds, unknown algorithm). Failing to
// converge is not an exception: it is in Summary::termination. The start is
// evaluated whatever the budget, so the Summary always holds a point; a spent
// budget ends the run with Termination::kMaxEvaluations or kMaxTime.
Summary minimize(const Problem& problem, const OptimizeOptions& options);

// Central-difference gradient of f at x with step h_i = step_rel (upper_i -
// lower_i), one-sided where x is within h_i of a bound. Writes grad (size n).
void difference_gradient(const std::function<double(std::span<const double>)>& f,
                         std::span<const double> x, std::span<const double> lower,
                         std::span<const double> upper, double step_rel, std::span<double> grad);

}  // namespace sweetspot::optimizer
