#pragma once

// The optimiser's bookkeeping, private to src/optimizer/: the Evaluator
// evaluates the Problem for every search (a one-point cache, difference
// gradients, the budget, threads) and its BestPoint keeps the best point seen,
// the histories, and whether a local search has stalled. The searches
// (nlopt_run.hpp, strategies.hpp) see the problem only through them.

#include <chrono>
#include <span>
#include <string>
#include <vector>

#include "optimizer/optimize.hpp"

namespace sweetspot::optimizer {

using Clock = std::chrono::steady_clock;

// Thrown when the budget is spent or a local search has stalled: inside
// NLopt's callbacks it becomes a forced stop, between NLopt's runs it ends the
// strategy (minimize() then gives the budget as the reason).
struct SearchStopped {};

// Why one stage of the search stopped (Summary::termination and its detail).
struct Ending {
  Termination termination = Termination::kFailure;
  std::string detail;
};

// The difference step of variable i: OptimizeOptions::difference_step_rel of its range.
double difference_step(const Problem& problem, const OptimizeOptions& options, std::size_t i);

// The best of the points recorded, feasible points ranking before infeasible
// ones (which rank by their violation), the best point's objective and
// violation after each record, and stall detection: a search that records
// `limit` points in a row without improving on the best by more than the
// objective tolerance has stalled.
class BestPoint {
 public:
  BestPoint(const Problem& problem, double f_tolerance_rel)
      : problem_(problem), f_tolerance_rel_(f_tolerance_rel) {}

  // The largest excess of a constraint over its limit, in multiples of its
  // tolerance, for values v = [objective, constraint 0, ...]: <= 1 feasible.
  double violation(const std::vector<double>& v) const;
  // Orders points: feasible before infeasible, then by objective or violation.
  bool better(const std::vector<double>& a, const std::vector<double>& b) const;

  // Takes values v at x into the ranking and the histories.
  void record(std::span<const double> x, const std::vector<double>& v);

  // The best point and its [objective, constraint 0, ...]; empty before the first record.
  const std::vector<double>& point() const { return x_; }
  const std::vector<double>& values() const { return values_; }
  bool feasible() const { return violation(values_) <= 1.0; }
  std::vector<double>& history() { return history_; }
  std::vector<double>& violation_history() { return violation_history_; }

  // Stalled once `limit` records from now on have not improved (0: never).
  void set_stall_limit(int limit) {
    stall_limit_ = limit;
    since_progress_ = 0;
  }
  bool stalled() const { return stall_limit_ > 0 && since_progress_ >= stall_limit_; }
  Ending stall_ending() const;

 private:
  // Better than b by more than the objective tolerance (or feasible where b is not).
  bool improves(const std::vector<double>& a, const std::vector<double>& b) const;

  const Problem& problem_;
  double f_tolerance_rel_;
  std::vector<double> x_, values_, history_, violation_history_;
  int stall_limit_ = 0, since_progress_ = 0;
};

// Evaluates the problem with a one-point cache (NLopt asks for the objective
// and the constraints at the same x in separate calls), difference gradients
// of all of them from one set of evaluations, and the evaluation and time
// budget; every evaluation goes to best(). Values that are not finite are
// replaced by a large penalty (never NaN to NLopt).
class Evaluator {
 public:
  Evaluator(const Problem& problem, const OptimizeOptions& options);

  // [objective, constraint 0, ...] at x. Throws SearchStopped when the budget
  // is spent or best() has stalled and x is not the cached point.
  const std::vector<double>& values(std::span<const double> x);

  // Rows [objective, constraint 0, ...], each of size n: central differences
  // (one-sided within a step of a bound). Throws SearchStopped as values() does.
  const std::vector<std::vector<double>>& jacobian(std::span<const double> x);

  // [objective, constraint 0, ...] at each point, in order, as values() would
  // give them one by one (the one-point cache aside); fewer when the budget
  // ends part way. On several threads when the problem forks and one
  // evaluation costs more than starting a thread: the points are computed
  // together, then booked in order, so the search is the same.
  // With `cache_last`, the last point booked becomes values()'s cached one.
  std::vector<std::vector<double>> values_of(const std::vector<std::vector<double>>& points,
                                             bool cache_last = false);

  int evaluations() const { return evaluations_; }
  double seconds() const { return std::chrono::duration<double>(Clock::now() - start_).count(); }
  BestPoint& best() { return best_; }
  const BestPoint& best() const { return best_; }

  // The budget never stops the first evaluation, so that every run has a
  // best point however small its budget.
  bool spent() const { return evaluations_ >= 1 && (out_of_evaluations() || out_of_time()); }
  // Why the budget stopped the run: kMaxEvaluations, else kMaxTime.
  Ending budget_ending() const;

 private:
  std::vector<std::vector<double>> values_of_points(const std::vector<std::vector<double>>& points);
  // Problem::evaluate and its forks at points[0, count) on `lanes` threads,
  // unbooked; rethrows the first exception a thread met.
  std::vector<std::vector<double>> compute_on_threads(
      const std::vector<std::vector<double>>& points, std::size_t count, std::size_t lanes);
  std::vector<double> evaluate(std::span<const double> x);
  std::vector<double> compute(const EvaluateFunction& f, std::span<const double> x) const;
  // Counts the evaluation at x and records it with best().
  std::vector<double> book(std::span<const double> x, std::vector<double> v);
  bool stopped() const { return spent() || best_.stalled(); }
  // How many threads values_of() uses for `count` points.
  std::size_t lanes_for(std::size_t count) const;
  bool out_of_evaluations() const { return evaluations_ >= options_.max_evaluations; }
  bool out_of_time() const { return seconds() >= options_.max_seconds; }

  const Problem& problem_;
  const OptimizeOptions& options_;
  std::size_t n_, m_;
  Clock::time_point start_;
  int evaluations_ = 0;
  double seconds_evaluating_ = 0.0;      // in Problem::evaluate (threads: summed)
  std::vector<EvaluateFunction> forks_;  // for threads 1, 2, ... of values_of()
  std::vector<double> cache_x_, cache_values_;
  std::vector<std::vector<double>> cache_jacobian_;
  BestPoint best_;
};

}  // namespace sweetspot::optimizer
