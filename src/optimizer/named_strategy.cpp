#include <nlopt.hpp>
#include <optional>
#include <string>

#include "optimizer/nlopt_run.hpp"
#include "optimizer/strategies.hpp"

namespace sweetspot::optimizer {

void run_named_algorithm(const Problem& problem, const OptimizeOptions& options,
                         Evaluator& evaluator, Outcome& outcome) {
  const std::string& name = options.algorithm;
  const nlopt::algorithm chosen = *algorithm_from_name(name);
  std::optional<nlopt::algorithm> local;
  if (name.starts_with("G_MLSL") || name.starts_with("AUGLAG"))
    local = local_algorithm(problem, options);
  nlopt::srand(options.seed);
  outcome.algorithm = name;
  if (local) outcome.algorithm += " with " + nlopt_name(*local);
  outcome.ending = run_nlopt(chosen, local, problem, options, evaluator, problem.start);
  // Global algorithms stop on the budget, not on a tolerance: polish locally.
  if (name.starts_with("GN_") && !evaluator.spent()) {
    const nlopt::algorithm polish = default_local_algorithm(problem);
    outcome.algorithm += " + " + nlopt_name(polish) + " polish";
    outcome.ending =
        run_nlopt(polish, std::nullopt, problem, options, evaluator, evaluator.best().point());
  }
}

}  // namespace sweetspot::optimizer
