#include "optimizer/optimize.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <exception>
#include <limits>
#include <nlopt.hpp>
#include <numeric>
#include <optional>
#include <random>
#include <sstream>
#include <stdexcept>
#include <thread>

#include "core/check.hpp"

namespace sweetspot::optimizer {
namespace {

using Clock = std::chrono::steady_clock;

// Thrown from inside NLopt callbacks when the budget is spent or a local
// search has stalled; NLopt turns it into a forced stop.
struct SearchStopped {};

// A local search that finds no better point in this many gradients' worth of
// evaluations (2n + 1 each) has stalled: SLSQP, given constraints no point of
// the box meets, can otherwise wander until the budget is spent.
constexpr int kStallGradients = 20;

// The difference step of variable i: OptimizeOptions::difference_step_rel of its range.
double difference_step(const Problem& problem, const OptimizeOptions& options, std::size_t i) {
  return options.difference_step_rel * (problem.upper[i] - problem.lower[i]);
}

// Independent points go to threads only when one evaluation costs more than
// this: starting a thread costs tens of microseconds, the rigid model a few.
constexpr double kParallelWorth_s = 100e-6;

std::optional<nlopt::algorithm> algorithm_from_name(const std::string& name) {
  for (int i = 0; i < NLOPT_NUM_ALGORITHMS; ++i) {
    const auto a = static_cast<nlopt_algorithm>(i);
    if (name == nlopt_algorithm_to_string(a)) return static_cast<nlopt::algorithm>(a);
  }
  return std::nullopt;
}

std::string result_name(nlopt::result r) {
  return nlopt_result_to_string(static_cast<nlopt_result>(r));
}

// Evaluates the problem with a one-point cache (NLopt asks for the objective
// and the constraints at the same x in separate calls), difference gradients
// of all of them from one set of evaluations, the evaluation budget, and the
// best point seen.
class Evaluator {
 public:
  Evaluator(const Problem& problem, const OptimizeOptions& options)
      : problem_(problem),
        options_(options),
        n_(problem.lower.size()),
        m_(problem.constraints.size()),
        start_(Clock::now()) {}

  // [objective, constraint 0, ...] at x.
  const std::vector<double>& values(std::span<const double> x) {
    if (!cache_x_.empty() && std::equal(x.begin(), x.end(), cache_x_.begin())) return cache_values_;
    cache_x_.assign(x.begin(), x.end());
    cache_values_ = evaluate(x);
    cache_jacobian_.clear();
    return cache_values_;
  }

  // Rows [objective, constraint 0, ...], each of size n: central differences.
  const std::vector<std::vector<double>>& jacobian(std::span<const double> x) {
    values(x);
    if (!cache_jacobian_.empty()) return cache_jacobian_;
    std::vector<std::vector<double>> probes;  // x + h e_i, x - h e_i, for each i
    for (std::size_t i = 0; i < n_; ++i) {
      const double h = difference_step(problem_, options_, i);
      probes.emplace_back(x.begin(), x.end());
      probes.back()[i] = std::min(problem_.upper[i], x[i] + h);
      probes.emplace_back(x.begin(), x.end());
      probes.back()[i] = std::max(problem_.lower[i], x[i] - h);
    }
    const std::vector<std::vector<double>> v = values_of(probes);
    if (v.size() < probes.size()) throw SearchStopped{};
    std::vector<std::vector<double>> rows(1 + m_, std::vector<double>(n_));
    for (std::size_t i = 0; i < n_; ++i) {
      const std::vector<double>&plus = v[2 * i], &minus = v[2 * i + 1];
      const double step = probes[2 * i][i] - probes[2 * i + 1][i];
      for (std::size_t k = 0; k <= m_; ++k) rows[k][i] = (plus[k] - minus[k]) / step;
    }
    cache_jacobian_ = std::move(rows);
    return cache_jacobian_;
  }

  // [objective, constraint 0, ...] at each point, in order, as values() would
  // give them one by one (the one-point cache aside); fewer when the budget
  // ends part way. On several threads when the problem forks and one
  // evaluation costs more than kParallelWorth_s: the points are computed
  // together, then booked in order, so the search is the same.
  // With `cache_last`, the last point booked becomes values()'s cached one.
  std::vector<std::vector<double>> values_of(const std::vector<std::vector<double>>& points,
                                             bool cache_last = false) {
    std::vector<std::vector<double>> out = values_of_points(points);
    if (cache_last && !out.empty()) {
      cache_x_ = points[out.size() - 1];
      cache_values_ = out.back();
      cache_jacobian_.clear();
    }
    return out;
  }

 private:
  std::vector<std::vector<double>> values_of_points(
      const std::vector<std::vector<double>>& points) {
    std::vector<std::vector<double>> out;
    const std::size_t lanes = lanes_for(points.size());
    if (lanes <= 1) {
      try {
        for (const std::vector<double>& x : points) out.push_back(evaluate(x));
      } catch (const SearchStopped&) {
      }
      return out;
    }
    if (spent() || stalled()) return out;
    const auto left = static_cast<std::size_t>(options_.max_evaluations - evaluations_);
    const std::size_t count = std::min(points.size(), left);
    std::vector<std::vector<double>> raw(count);
    while (forks_.size() + 1 < lanes) forks_.push_back(problem_.fork());
    std::vector<std::exception_ptr> errors(lanes);
    const auto lane = [&](std::size_t t) {
      try {
        const EvaluateFunction& f = t == 0 ? problem_.evaluate : forks_[t - 1];
        for (std::size_t k = count * t / lanes; k < count * (t + 1) / lanes; ++k)
          raw[k] = compute(f, points[k]);
      } catch (...) {
        errors[t] = std::current_exception();
      }
    };
    const Clock::time_point began = Clock::now();
    std::vector<std::thread> pool;
    for (std::size_t t = 1; t < lanes; ++t) pool.emplace_back(lane, t);
    lane(0);
    for (std::thread& thread : pool) thread.join();
    for (const std::exception_ptr& error : errors) {
      if (error) std::rethrow_exception(error);
    }
    seconds_evaluating_ +=
        std::chrono::duration<double>(Clock::now() - began).count() * static_cast<double>(lanes);
    for (std::size_t k = 0; k < count && !spent() && !stalled(); ++k)
      out.push_back(book(points[k], std::move(raw[k])));
    return out;
  }

 public:
  double violation(const std::vector<double>& v) const {
    double worst = 0.0;
    for (std::size_t k = 0; k < m_; ++k) {
      const ConstraintInfo& c = problem_.constraints[k];
      const double excess = c.kind == ConstraintKind::kZero ? std::abs(v[1 + k]) : v[1 + k];
      worst = std::max(worst, excess / c.tolerance);
    }
    return worst;  // <= 1: feasible
  }

  // Orders points: feasible before infeasible, then by objective or violation.
  bool better(const std::vector<double>& a, const std::vector<double>& b) const {
    const double va = violation(a), vb = violation(b);
    const bool fa = va <= 1.0, fb = vb <= 1.0;
    if (fa != fb) return fa;
    return fa ? a[0] < b[0] : va < vb;
  }

  int evaluations() const { return evaluations_; }
  const std::vector<double>& best_x() const { return best_x_; }
  const std::vector<double>& best_values() const { return best_values_; }
  std::vector<double>& history() { return history_; }
  std::vector<double>& violation_history() { return violation_history_; }
  double seconds() const { return std::chrono::duration<double>(Clock::now() - start_).count(); }
  // Stops the search after `limit` evaluations without a better point (from
  // now; 0: never).
  void set_stall_limit(int limit) {
    stall_limit_ = limit;
    last_progress_ = evaluations_;
  }
  bool stalled() const { return stall_limit_ > 0 && evaluations_ - last_progress_ >= stall_limit_; }
  std::string stall_reason() const {
    return "STALLED (sweetspot: no better point in " + std::to_string(stall_limit_) +
           " evaluations)";
  }
  // The budget never stops the first evaluation, so that every run has a
  // best point however small its budget.
  bool spent() const { return evaluations_ >= 1 && (out_of_evaluations() || out_of_time()); }
  // Why the budget stopped the run, in NLopt's words.
  std::string spent_reason() const {
    return out_of_evaluations() ? "MAXEVAL_REACHED (sweetspot's budget, including differences)"
                                : "MAXTIME_REACHED (sweetspot's budget)";
  }

 private:
  std::vector<double> evaluate(std::span<const double> x) {
    if (spent() || stalled()) throw SearchStopped{};
    const Clock::time_point began = Clock::now();
    std::vector<double> v = compute(problem_.evaluate, x);
    seconds_evaluating_ += std::chrono::duration<double>(Clock::now() - began).count();
    return book(x, std::move(v));
  }
  std::vector<double> compute(const EvaluateFunction& f, std::span<const double> x) const {
    std::vector<double> v(1 + m_);
    f(x, v[0], std::span<double>(v).subspan(1));
    for (double& value : v) {
      if (!std::isfinite(value))
        value = std::numeric_limits<double>::max() / 4;  // never NaN to NLopt
    }
    return v;
  }
  // Counts the evaluation at x and keeps the best point and the history.
  std::vector<double> book(std::span<const double> x, std::vector<double> v) {
    ++evaluations_;
    if (best_x_.empty() || better(v, best_values_)) {
      if (best_x_.empty() || improves(v, best_values_)) last_progress_ = evaluations_;
      best_x_.assign(x.begin(), x.end());
      best_values_ = v;
    }
    history_.push_back(best_values_[0]);
    violation_history_.push_back(violation(best_values_));
    return v;
  }
  // Better than b by more than the objective tolerance (or feasible where b is not).
  bool improves(const std::vector<double>& a, const std::vector<double>& b) const {
    const double va = violation(a), vb = violation(b);
    const bool fa = va <= 1.0, fb = vb <= 1.0;
    if (fa != fb) return fa;
    return fa ? b[0] - a[0] > options_.f_tolerance_rel * std::abs(b[0])
              : vb - va > options_.f_tolerance_rel * vb;
  }
  // How many threads values_of() uses for `count` points.
  std::size_t lanes_for(std::size_t count) const {
    if (options_.threads <= 1 || !problem_.fork || count < 2 || evaluations_ == 0) return 1;
    if (seconds_evaluating_ / evaluations_ < kParallelWorth_s) return 1;
    return std::min(static_cast<std::size_t>(options_.threads), count);
  }
  bool out_of_evaluations() const { return evaluations_ >= options_.max_evaluations; }
  bool out_of_time() const { return seconds() >= options_.max_seconds; }

  const Problem& problem_;
  const OptimizeOptions& options_;
  std::size_t n_, m_;
  Clock::time_point start_;
  int evaluations_ = 0;
  int stall_limit_ = 0, last_progress_ = 0;
  double seconds_evaluating_ = 0.0;      // in Problem::evaluate (threads: summed)
  std::vector<EvaluateFunction> forks_;  // for threads 1, 2, ... of values_of()
  std::vector<double> cache_x_, cache_values_;
  std::vector<std::vector<double>> cache_jacobian_;
  std::vector<double> best_x_, best_values_, history_, violation_history_;
};

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

struct RunResult {
  std::string termination;
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

// Runs `opt` from u and says how it ended (NLopt's exceptions as words).
std::string run_once(nlopt::opt& opt, std::vector<double> u, const Evaluator& evaluator) {
  double f = 0.0;
  try {
    return result_name(opt.optimize(u, f));
  } catch (const nlopt::forced_stop&) {
    return evaluator.spent()     ? evaluator.spent_reason()
           : evaluator.stalled() ? evaluator.stall_reason()
                                 : "FORCESTOP";
  } catch (const nlopt::roundoff_limited&) {
    return "ROUNDOFF_LIMITED";
  } catch (const std::invalid_argument& e) {
    return std::string("INVALID_ARGS: ") + e.what();
  } catch (const std::runtime_error& e) {
    return std::string("FAILURE: ") + e.what();
  }
}

// run_once, a local search stopped when it stalls (global ones explore).
std::string run_to_end(nlopt::opt& opt, std::vector<double> u, Evaluator& evaluator, bool local) {
  if (local) evaluator.set_stall_limit(kStallGradients * (2 * static_cast<int>(u.size()) + 1));
  const std::string ended = run_once(opt, std::move(u), evaluator);
  evaluator.set_stall_limit(0);
  return ended;
}

// One NLopt run from x0. Constraints are added when the algorithm takes them.
RunResult run_nlopt(nlopt::algorithm algorithm, std::optional<nlopt::algorithm> local,
                    const Problem& problem, const OptimizeOptions& options, Evaluator& evaluator,
                    std::vector<double> x0) {
  const unsigned n = static_cast<unsigned>(problem.lower.size());
  Scaling scaling = box_scaling(problem);
  const std::vector<double>& at_start = evaluator.values(x0);
  scaling.objective = std::abs(at_start[0]) > 0 ? std::abs(at_start[0]) : 1.0;
  for (std::size_t k = 0; k < problem.constraints.size(); ++k) {
    // Never scale a constraint's tolerance below a thousandth.
    scaling.constraint.push_back(
        std::max(std::abs(at_start[1 + k]), 1e3 * problem.constraints[k].tolerance));
  }

  nlopt::opt opt(algorithm, n);
  set_box_and_stopping(opt, options, evaluator);
  Callback objective{&evaluator, &scaling, {}};
  Callback inequalities{&evaluator, &scaling, {}};
  Callback equalities{&evaluator, &scaling, {}};
  for (std::size_t k = 0; k < problem.constraints.size(); ++k) {
    (problem.constraints[k].kind == ConstraintKind::kZero ? equalities : inequalities)
        .indices.push_back(k);
  }
  opt.set_min_objective(objective_callback, &objective);
  const auto tolerances = [&](const Callback& cb) {
    std::vector<double> tol;
    for (const std::size_t k : cb.indices)
      tol.push_back(problem.constraints[k].tolerance / scaling.constraint[k]);
    return tol;
  };
  try {
    if (!inequalities.indices.empty()) {
      opt.add_inequality_mconstraint(constraints_callback, &inequalities, tolerances(inequalities));
    }
    if (!equalities.indices.empty()) {
      opt.add_equality_mconstraint(constraints_callback, &equalities, tolerances(equalities));
    }
  } catch (const std::invalid_argument&) {
    throw std::invalid_argument(
        std::string("algorithm: ") +
        nlopt_algorithm_to_string(static_cast<nlopt_algorithm>(algorithm)) +
        " does not take nonlinear constraints; use auto, LD_SLSQP, LN_COBYLA, GN_ISRES or AUGLAG");
  }
  if (local) {
    nlopt::opt local_opt(*local, n);
    local_opt.set_xtol_abs(std::vector<double>(n, options.x_tolerance_rel));
    local_opt.set_ftol_rel(options.f_tolerance_rel);
    opt.set_local_optimizer(local_opt);
  }
  const std::string name = nlopt_algorithm_to_string(static_cast<nlopt_algorithm>(algorithm));
  const bool local_search = name.starts_with("LD_") || name.starts_with("LN_");
  return {run_to_end(opt, scaling.to_u(x0), evaluator, local_search)};
}

// The least-violation stage: when no feasible point has been found, the
// reported "least infeasible" design should be one. Minimises the evaluator's
// violation, max_k excess_k / tolerance_k (kinked where two constraints
// cross, hence derivative-free COBYLA, bounds only), from the best point so
// far; the evaluator keeps whichever point violates least.
struct ViolationCallback {
  Evaluator* evaluator;
  const Scaling* scaling;
};

double violation_callback(unsigned, const double* u, double*, void* data) {
  auto* cb = static_cast<ViolationCallback*>(data);
  try {
    return cb->evaluator->violation(cb->evaluator->values(cb->scaling->to_x(u)));
  } catch (const SearchStopped&) {
    throw nlopt::forced_stop();
  }
}

std::string reduce_violation(const Problem& problem, const OptimizeOptions& options,
                             Evaluator& evaluator) {
  const Scaling scaling = box_scaling(problem);
  ViolationCallback callback{&evaluator, &scaling};
  nlopt::opt opt(nlopt::LN_COBYLA, static_cast<unsigned>(problem.lower.size()));
  set_box_and_stopping(opt, options, evaluator);
  opt.set_min_objective(violation_callback, &callback);
  return run_to_end(opt, scaling.to_u(evaluator.best_x()), evaluator, true);
}

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

}  // namespace

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
  for (const auto& message :
       {positive("x_tolerance_rel", x_tolerance_rel), positive("f_tolerance_rel", f_tolerance_rel),
        positive("max_seconds", max_seconds),
        positive("difference_step_rel", difference_step_rel)}) {
    if (!message.empty()) return message;
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

std::string Summary::brief_report() const {
  std::ostringstream out;
  out << "objective " << objective << (feasible ? " (feasible)" : " (INFEASIBLE)") << " after "
      << evaluations << " evaluations in " << seconds * 1e3 << " ms; " << algorithm << ": "
      << termination;
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
  const std::size_t n = problem.lower.size();
  std::string algorithm_used;
  std::string termination;

  // A smooth problem with bounds only and two or more variables: BOBYQA's
  // quadratic models, built from single evaluations, are cheaper than SLSQP's
  // difference gradients (2n evaluations each). With constraints, or along
  // one variable (where SLSQP's secant steps converge in a few), SLSQP; with
  // kinks, COBYLA.
  const auto default_local = [&] {
    if (!problem.smooth) return nlopt::LN_COBYLA;
    return problem.constraints.empty() && n >= 2 ? nlopt::LN_BOBYQA : nlopt::LD_SLSQP;
  };
  const auto local_choice = [&]() -> nlopt::algorithm {
    return options.local_algorithm == "auto" ? default_local()
                                             : *algorithm_from_name(options.local_algorithm);
  };

  // The start first: whatever the budget, the run then has a best point.
  evaluator.values(problem.start);
  try {
    if (options.algorithm == "auto") {
      // A local search from the start, then a global check costing no more
      // than it did: low-discrepancy samples of the box. A sample better
      // than the local optimum lies in another basin; the search goes on
      // from it (at most local_starts searches in all).
      const nlopt::algorithm local = local_choice();
      std::optional<VertexWalk> vertex;
      if (problem.smooth && problem.constraints.empty() && n >= 2) {
        vertex = walk_downhill_vertices(problem, options, evaluator);
      }
      if (vertex && vertex->first_order) {
        algorithm_used = "auto: " + vertex->what;
        termination = "VERTEX_FIRST_ORDER (sweetspot: no inward step of " +
                      detail::format_number(options.difference_step_rel) + " of a range improves)";
      } else {
        // From the best point so far: the start, or a vertex or difference
        // probe of the walk that beat it.
        const bool from_start = evaluator.best_x() == problem.start;
        algorithm_used = std::string("auto: ") + (vertex ? vertex->what + ", then " : "") +
                         nlopt_algorithm_to_string(static_cast<nlopt_algorithm>(local)) +
                         (from_start ? " from the start" : " from the walk's best point");
        termination =
            run_nlopt(local, std::nullopt, problem, options, evaluator, evaluator.best_x())
                .termination;
      }
      const std::size_t most = std::max<std::size_t>(n + 1, options.samples_per_variable * n);
      const std::size_t count =
          std::clamp<std::size_t>(static_cast<std::size_t>(evaluator.evaluations()), n + 1, most);
      const std::vector<double> local_best = evaluator.best_x();
      std::vector<std::vector<double>> samples;
      for (const auto& unit : halton(count, n, options.seed)) {
        std::vector<double>& x = samples.emplace_back(n);
        for (std::size_t i = 0; i < n; ++i) {
          x[i] = problem.lower[i] + unit[i] * (problem.upper[i] - problem.lower[i]);
        }
      }
      const std::size_t sampled = evaluator.values_of(samples, true).size();
      if (sampled < count) termination = evaluator.spent_reason();
      const bool sample_better = evaluator.best_x() != local_best;
      algorithm_used += ", " + std::to_string(sampled) + " Halton samples" +
                        (sample_better ? "" : std::string(" (none better)"));
      if (sample_better && options.local_starts >= 2 && !evaluator.spent()) {
        algorithm_used += ", again from the best sample";
        termination =
            run_nlopt(local, std::nullopt, problem, options, evaluator, evaluator.best_x())
                .termination;
      }
    } else {
      const nlopt::algorithm chosen = *algorithm_from_name(options.algorithm);
      const std::string name = options.algorithm;
      const bool needs_local = name.starts_with("G_MLSL") || name.starts_with("AUGLAG");
      std::optional<nlopt::algorithm> local;
      if (needs_local) local = local_choice();
      nlopt::srand(options.seed);
      algorithm_used = name;
      if (local) {
        algorithm_used +=
            std::string(" with ") + nlopt_algorithm_to_string(static_cast<nlopt_algorithm>(*local));
      }
      termination =
          run_nlopt(chosen, local, problem, options, evaluator, problem.start).termination;
      // Global algorithms stop on the budget, not on a tolerance: polish locally.
      if (name.starts_with("GN_") && !evaluator.spent()) {
        const nlopt::algorithm polish = default_local();
        algorithm_used += std::string(" + ") +
                          nlopt_algorithm_to_string(static_cast<nlopt_algorithm>(polish)) +
                          " polish";
        termination =
            run_nlopt(polish, std::nullopt, problem, options, evaluator, evaluator.best_x())
                .termination;
      }
    }
  } catch (const SearchStopped&) {
    termination = evaluator.spent_reason();
  }
  if (algorithm_used.empty()) algorithm_used = options.algorithm;
  if (!problem.constraints.empty() && evaluator.violation(evaluator.best_values()) > 1.0 &&
      !evaluator.spent()) {
    termination = reduce_violation(problem, options, evaluator);
    algorithm_used += " + LN_COBYLA on the violation (no feasible point found)";
  }

  Summary summary;
  summary.x = evaluator.best_x();
  summary.objective = evaluator.best_values()[0];
  summary.constraints.assign(evaluator.best_values().begin() + 1, evaluator.best_values().end());
  summary.feasible = evaluator.violation(evaluator.best_values()) <= 1.0;
  summary.evaluations = evaluator.evaluations();
  summary.seconds = evaluator.seconds();
  summary.algorithm = algorithm_used;
  summary.termination = termination;
  summary.history = std::move(evaluator.history());
  summary.violation_history = std::move(evaluator.violation_history());
  return summary;
}

}  // namespace sweetspot::optimizer
