// OptimizeOptions::algorithm "auto" (optimize.hpp says what it does).

#include <algorithm>
#include <cmath>
#include <nlopt.hpp>
#include <optional>
#include <random>
#include <string>
#include <vector>

#include "core/check.hpp"
#include "optimizer/nlopt_run.hpp"
#include "optimizer/strategies.hpp"

namespace sweetspot::optimizer {
namespace {

// Halton points in [0,1)^n, shifted by a seeded random vector (mod 1).
std::vector<std::vector<double>> halton(std::size_t count, std::size_t n, unsigned long seed) {
  static constexpr int kPrimes[] = {2, 3, 5, 7, 11, 13, 17, 19, 23, 29, 31, 37, 41, 43, 47, 53};
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> uniform(0.0, 1.0);
  std::vector<double> shift(n);
  for (double& s : shift) s = uniform(rng);
  std::vector<std::vector<double>> points(count, std::vector<double>(n));
  for (std::size_t k = 0; k < count; ++k) {
    for (std::size_t d = 0; d < n; ++d) {
      const int base = kPrimes[d % std::size(kPrimes)];
      double f = 1.0, r = 0.0;
      for (std::size_t i = k + 1; i > 0; i /= base) {
        f /= base;
        r += f * static_cast<double>(i % base);
      }
      points[k][d] = std::fmod(r + shift[d], 1.0);
    }
  }
  return points;
}

// auto's first step on a smooth problem with bounds only. A design
// objective often falls monotonically in each variable over the box (more
// mass, less shock), and is then bounded by the variables' bounds: its
// optimum is a vertex of the box (Papalambros and Wilde, "Principles of
// Optimal Design", the first monotonicity principle), which a
// quadratic-model search reaches only after tens of evaluations converging
// along each bound. The walk steps each variable by its difference step
// (inward from a bound) and goes to the vertex those steps point downhill
// to; from a vertex, again. A vertex whose every inward step rises is a
// first-order (KKT) point of the box, and the local search ends there; a
// vertex no better than the point before it, or a variable the objective is
// flat in, hands over to the local search from the best point. Each step
// costs n + 1 evaluations.
struct VertexWalk {
  bool first_order = false;  // the last vertex is the local search's answer
  std::string what;          // for Summary::algorithm
};
VertexWalk walk_downhill_vertices(const Problem& problem, const OptimizeOptions& options,
                                  Evaluator& evaluator) {
  const std::size_t n = problem.lower.size();
  std::vector<double> x = problem.start;
  double at_x = evaluator.values(x)[0];
  int vertices = 0;
  const auto walked = [&](const std::string& why) {
    return std::to_string(vertices) + (vertices == 1 ? " vertex" : " vertices") +
           " walked downhill (" + why + ")";
  };
  for (std::size_t step = 0; step <= n; ++step) {
    std::vector<std::vector<double>> probes(n, x);
    std::vector<bool> up(n);
    for (std::size_t i = 0; i < n; ++i) {
      const double h = difference_step(problem, options, i);
      up[i] = x[i] + h <= problem.upper[i];
      probes[i][i] = up[i] ? x[i] + h : x[i] - h;
    }
    const std::vector<std::vector<double>> at_probes = evaluator.values_of(probes);
    if (at_probes.size() < n) throw SearchStopped{};
    std::vector<double> next(n);
    for (std::size_t i = 0; i < n; ++i) {
      const double change = at_probes[i][0] - at_x;
      const bool at_bound = x[i] == problem.lower[i] || x[i] == problem.upper[i];
      if (change == 0.0 && !at_bound) return {false, walked("the objective is flat in a variable")};
      // Flat inward from a bound: the bound holds (a zero multiplier).
      const bool rises_upward = change == 0.0 ? x[i] == problem.lower[i] : up[i] == (change > 0.0);
      next[i] = rises_upward ? problem.lower[i] : problem.upper[i];
    }
    if (next == x) return {true, walked("no inward step from the last improves")};
    const double at_next = evaluator.values(next)[0];
    if (!(at_next < at_x)) return {false, walked("the next no better")};
    x = std::move(next);
    at_x = at_next;
    ++vertices;
  }
  return {false, walked("still moving")};
}

// The local stage: the vertex walk on a smooth problem with bounds only and
// n >= 2; unless it ends at a first-order vertex, a local search from the
// best point so far (the start, or a vertex or difference probe of the walk
// that beat it).
void search_locally(const Problem& problem, const OptimizeOptions& options, nlopt::algorithm local,
                    Evaluator& evaluator, Outcome& outcome) {
  std::optional<VertexWalk> vertex;
  if (problem.smooth && problem.constraints.empty() && problem.lower.size() >= 2)
    vertex = walk_downhill_vertices(problem, options, evaluator);
  if (vertex && vertex->first_order) {
    outcome.algorithm = "auto: " + vertex->what;
    outcome.ending = {Termination::kVertexFirstOrder,
                      " (sweetspot: no inward step of " +
                          detail::format_number(options.difference_step_rel) +
                          " of a range improves)"};
    return;
  }
  const bool from_start = evaluator.best().point() == problem.start;
  outcome.algorithm = std::string("auto: ") + (vertex ? vertex->what + ", then " : "") +
                      nlopt_name(local) +
                      (from_start ? " from the start" : " from the walk's best point");
  outcome.ending =
      run_nlopt(local, std::nullopt, problem, options, evaluator, evaluator.best().point());
}

// The global check: as many Halton samples of the box as the local stage
// cost (n + 1 to samples_per_variable n), the budget permitting. True when a
// sample beat the local optimum: it lies in another basin.
bool sample_the_box(const Problem& problem, const OptimizeOptions& options, Evaluator& evaluator,
                    Outcome& outcome) {
  const std::size_t n = problem.lower.size();
  const std::size_t most = std::max<std::size_t>(n + 1, options.samples_per_variable * n);
  const std::size_t count =
      std::clamp<std::size_t>(static_cast<std::size_t>(evaluator.evaluations()), n + 1, most);
  const std::vector<double> local_best = evaluator.best().point();
  std::vector<std::vector<double>> samples;
  for (const auto& unit : halton(count, n, options.seed)) {
    std::vector<double>& x = samples.emplace_back(n);
    for (std::size_t i = 0; i < n; ++i) {
      x[i] = problem.lower[i] + unit[i] * (problem.upper[i] - problem.lower[i]);
    }
  }
  const std::size_t sampled = evaluator.values_of(samples, true).size();
  if (sampled < count) outcome.ending = evaluator.budget_ending();
  const bool sample_better = evaluator.best().point() != local_best;
  outcome.algorithm += ", " + std::to_string(sampled) + " Halton samples" +
                       (sample_better ? "" : std::string(" (none better)"));
  return sample_better;
}

}  // namespace

void run_auto(const Problem& problem, const OptimizeOptions& options, Evaluator& evaluator,
              Outcome& outcome) {
  const nlopt::algorithm local = local_algorithm(problem, options);
  search_locally(problem, options, local, evaluator, outcome);
  const bool sample_better = sample_the_box(problem, options, evaluator, outcome);
  if (sample_better && options.local_starts >= 2 && !evaluator.spent()) {
    outcome.algorithm += ", again from the best sample";
    outcome.ending =
        run_nlopt(local, std::nullopt, problem, options, evaluator, evaluator.best().point());
  }
}

}  // namespace sweetspot::optimizer
