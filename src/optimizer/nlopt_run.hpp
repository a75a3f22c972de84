#pragma once

// One NLopt run, private to src/optimizer/: the problem mapped onto the unit
// box and scaled, the callbacks into the Evaluator, the stopping rules every
// run shares, and NLopt's result in sweetspot's words (Ending). Also the
// least-violation run, and the choice of a local algorithm by name or by the
// problem's shape.

#include <nlopt.hpp>
#include <optional>
#include <string>
#include <vector>

#include "optimizer/evaluator.hpp"
#include "optimizer/optimize.hpp"

namespace sweetspot::optimizer {

// The NLopt algorithm of that name ("LD_SLSQP"), if this build knows it.
std::optional<nlopt::algorithm> algorithm_from_name(const std::string& name);
// NLopt's name of the algorithm.
std::string nlopt_name(nlopt::algorithm algorithm);

// The local method for the problem's shape. A smooth problem with bounds
// only and two or more variables: BOBYQA's quadratic models, built from
// single evaluations, are cheaper than SLSQP's difference gradients (2n
// evaluations each). With constraints, or along one variable (where SLSQP's
// secant steps converge in a few), SLSQP; with kinks, COBYLA.
nlopt::algorithm default_local_algorithm(const Problem& problem);
// OptimizeOptions::local_algorithm, "auto" being default_local_algorithm().
nlopt::algorithm local_algorithm(const Problem& problem, const OptimizeOptions& options);

// One NLopt run of `algorithm` (with `local` as its subsidiary method, for
// MLSL and AUGLAG) from x0, within what is left of the budget. Constraints
// are added when the algorithm takes them; throws std::invalid_argument
// naming the algorithm when it does not. A local search (LD_, LN_) is
// stopped when it stalls. Throws SearchStopped when the budget is spent
// before x0 is evaluated.
Ending run_nlopt(nlopt::algorithm algorithm, std::optional<nlopt::algorithm> local,
                 const Problem& problem, const OptimizeOptions& options, Evaluator& evaluator,
                 std::vector<double> x0);

// The least-violation stage: when no feasible point has been found, the
// reported "least infeasible" design should be one. Minimises the
// violation, max_k excess_k / tolerance_k (kinked where two constraints
// cross, hence derivative-free COBYLA, bounds only), from the best point so
// far; the evaluator keeps whichever point violates least.
Ending reduce_violation(const Problem& problem, const OptimizeOptions& options,
                        Evaluator& evaluator);

}  // namespace sweetspot::optimizer
