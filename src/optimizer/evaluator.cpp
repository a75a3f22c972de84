#include "optimizer/evaluator.hpp"

#include <algorithm>
#include <cmath>
#include <exception>
#include <limits>
#include <thread>

namespace sweetspot::optimizer {
namespace {

// Independent points go to threads only when one evaluation costs more than
// this: starting a thread costs tens of microseconds, the rigid model a few.
constexpr double kParallelWorth_s = 100e-6;

}  // namespace

double difference_step(const Problem& problem, const OptimizeOptions& options, std::size_t i) {
  return options.difference_step_rel * (problem.upper[i] - problem.lower[i]);
}

// ---------------------------------------------------------------- BestPoint

double BestPoint::violation(const std::vector<double>& v) const {
  double worst = 0.0;
  for (std::size_t k = 0; k < problem_.constraints.size(); ++k) {
    const ConstraintInfo& c = problem_.constraints[k];
    const double excess = c.kind == ConstraintKind::kZero ? std::abs(v[1 + k]) : v[1 + k];
    worst = std::max(worst, excess / c.tolerance);
  }
  return worst;  // <= 1: feasible
}

bool BestPoint::better(const std::vector<double>& a, const std::vector<double>& b) const {
  const double va = violation(a), vb = violation(b);
  const bool fa = va <= 1.0, fb = vb <= 1.0;
  if (fa != fb) return fa;
  return fa ? a[0] < b[0] : va < vb;
}

bool BestPoint::improves(const std::vector<double>& a, const std::vector<double>& b) const {
  const double va = violation(a), vb = violation(b);
  const bool fa = va <= 1.0, fb = vb <= 1.0;
  if (fa != fb) return fa;
  return fa ? b[0] - a[0] > f_tolerance_rel_ * std::abs(b[0]) : vb - va > f_tolerance_rel_ * vb;
}

void BestPoint::record(std::span<const double> x, const std::vector<double>& v) {
  bool progress = false;
  if (x_.empty() || better(v, values_)) {
    progress = x_.empty() || improves(v, values_);
    x_.assign(x.begin(), x.end());
    values_ = v;
  }
  since_progress_ = progress ? 0 : since_progress_ + 1;
  history_.push_back(values_[0]);
  violation_history_.push_back(violation(values_));
}

Ending BestPoint::stall_ending() const {
  return {Termination::kStalled,
          " (sweetspot: no better point in " + std::to_string(stall_limit_) + " evaluations)"};
}

// ---------------------------------------------------------------- Evaluator

Evaluator::Evaluator(const Problem& problem, const OptimizeOptions& options)
    : problem_(problem),
      options_(options),
      n_(problem.lower.size()),
      m_(problem.constraints.size()),
      start_(Clock::now()),
      best_(problem, options.f_tolerance_rel) {}

const std::vector<double>& Evaluator::values(std::span<const double> x) {
  if (!cache_x_.empty() && std::equal(x.begin(), x.end(), cache_x_.begin())) return cache_values_;
  cache_x_.assign(x.begin(), x.end());
  cache_values_ = evaluate(x);
  cache_jacobian_.clear();
  return cache_values_;
}

const std::vector<std::vector<double>>& Evaluator::jacobian(std::span<const double> x) {
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

std::vector<std::vector<double>> Evaluator::values_of(
    const std::vector<std::vector<double>>& points, bool cache_last) {
  std::vector<std::vector<double>> out = values_of_points(points);
  if (cache_last && !out.empty()) {
    cache_x_ = points[out.size() - 1];
    cache_values_ = out.back();
    cache_jacobian_.clear();
  }
  return out;
}

Ending Evaluator::budget_ending() const {
  return out_of_evaluations()
             ? Ending{Termination::kMaxEvaluations, " (sweetspot's budget, including differences)"}
             : Ending{Termination::kMaxTime, " (sweetspot's budget)"};
}

std::vector<std::vector<double>> Evaluator::values_of_points(
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
  if (stopped()) return out;
  const auto left = static_cast<std::size_t>(options_.max_evaluations - evaluations_);
  const std::size_t count = std::min(points.size(), left);
  std::vector<std::vector<double>> raw = compute_on_threads(points, count, lanes);
  for (std::size_t k = 0; k < count && !stopped(); ++k)
    out.push_back(book(points[k], std::move(raw[k])));
  return out;
}

std::vector<std::vector<double>> Evaluator::compute_on_threads(
    const std::vector<std::vector<double>>& points, std::size_t count, std::size_t lanes) {
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
  return raw;
}

std::vector<double> Evaluator::evaluate(std::span<const double> x) {
  if (stopped()) throw SearchStopped{};
  const Clock::time_point began = Clock::now();
  std::vector<double> v = compute(problem_.evaluate, x);
  seconds_evaluating_ += std::chrono::duration<double>(Clock::now() - began).count();
  return book(x, std::move(v));
}

std::vector<double> Evaluator::compute(const EvaluateFunction& f, std::span<const double> x) const {
  std::vector<double> v(1 + m_);
  f(x, v[0], std::span<double>(v).subspan(1));
  for (double& value : v) {
    if (!std::isfinite(value))
      value = std::numeric_limits<double>::max() / 4;  // never NaN to NLopt
  }
  return v;
}

std::vector<double> Evaluator::book(std::span<const double> x, std::vector<double> v) {
  ++evaluations_;
  best_.record(x, v);
  return v;
}

std::size_t Evaluator::lanes_for(std::size_t count) const {
  if (options_.threads <= 1 || !problem_.fork || count < 2 || evaluations_ == 0) return 1;
  if (seconds_evaluating_ / evaluations_ < kParallelWorth_s) return 1;
  return std::min(static_cast<std::size_t>(options_.threads), count);
}

}  // namespace sweetspot::optimizer
