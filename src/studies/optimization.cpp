#include "studies/optimization.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstdint>
#include <limits>
#include <memory>

#include "io/format.hpp"
#include "io/input_error.hpp"
#include "studies/design_binding.hpp"
#include "sweetspot/evaluate.hpp"

namespace sweetspot::studies {
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
  const char* op = pc.which == ProblemConstraint::kEquals ? "="
                   : pc.which == ProblemConstraint::kMin  ? ">="
                                                          : "<=";
  return fmt::format("{} {} {}", pc.source->output->name, op, io::significant(limit_of(pc)));
}

// Signed constraint value: <= 0 (or = 0) when satisfied.
double constraint_value(const ProblemConstraint& pc, const Evaluation& e) {
  const auto value = pc.source->output->value(e);
  if (!value) return kPenalty;
  switch (pc.which) {
    case ProblemConstraint::kEquals:
      return *value - *pc.source->equals;
    case ProblemConstraint::kMin:
      return *pc.source->min - *value;
    case ProblemConstraint::kMax:
      return *value - *pc.source->max;
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

optimizer::Problem make_problem(const Study& study) {
  optimizer::Problem problem;
  for (const StudyVariable& v : study.variables) {
    problem.lower.push_back(v.min);
    problem.upper.push_back(v.max);
    problem.start.push_back(v.start);
  }
  const std::vector<ProblemConstraint> constraints = expand_constraints(study);
  for (const ProblemConstraint& pc : constraints) {
    problem.constraints.push_back(optimizer::ConstraintInfo{
        constraint_name(pc),
        pc.which == ProblemConstraint::kEquals ? optimizer::ConstraintKind::kZero
                                               : optimizer::ConstraintKind::kAtMostZero,
        tolerance_at(*pc.source, limit_of(pc))});
  }
  const bool square = minimizes_square(study);
  problem.smooth =
      !(study.over_impacts && study.over_impacts->reduce == ImpactSpread::Reduce::kMax);
  for (const ObjectiveTerm& term : study.objective) {
    problem.smooth = problem.smooth && (square || !term.output->kinked);
  }
  // Each point is set on the study's compiled design (one working copy per
  // evaluate function, so a fork runs beside it); a point it cannot vouch
  // for is read from JSON (design_at).
  const auto make_evaluate = [&study, constraints, square]() -> optimizer::EvaluateFunction {
    const auto bound = compiled_for_variables(study)
                           ? std::make_shared<BoundDesign>(*study.compiled)
                           : std::shared_ptr<BoundDesign>();
    return [&study, constraints, square, bound](std::span<const double> x, double& f,
                                                std::span<double> c) {
      const auto at = [&](const Design& design) {
        const Evaluation e = evaluate_in(study, design);
        f = study.over_impacts ? objective_of(study, design) : terms_value(study, e);
        if (square) f *= f;
        for (std::size_t k = 0; k < constraints.size(); ++k)
          c[k] = constraint_value(constraints[k], e);
      };
      try {
        if (const Design* design = bound ? bound->at(x) : nullptr) return at(*design);
      } catch (const std::exception&) {  // the JSON path below decides
      }
      try {
        at(design_at(study, x).design);
      } catch (const std::exception&) {
        // InputError or std::invalid_argument: no valid design here.
        f = kPenalty;
        std::fill(c.begin(), c.end(), kPenalty);
      }
    };
  };
  problem.evaluate = make_evaluate();
  problem.fork = make_evaluate;
  return problem;
}

namespace {

std::optional<Evaluation> outputs_of(const Study& study, const io::DesignFile& design,
                                     std::string* why) {
  try {
    return evaluate_in(study, design);
  } catch (const std::invalid_argument& e) {
    if (why) *why = e.what();
    return std::nullopt;
  }
}

// The objective (in the minimised form) and the signed constraint values at
// one point, as the search's evaluate functions give them.
struct PointValues {
  double objective = kPenalty;
  std::vector<double> constraints;
};

PointValues searched_values(const optimizer::Problem& problem, std::span<const double> x) {
  PointValues v;
  v.constraints.assign(problem.constraints.size(), kPenalty);
  problem.evaluate(x, v.objective, v.constraints);
  return v;
}

// The same numbers for the printed design read again: its evaluation as
// `evaluate` gives it (std::nullopt: refused), with the search's arithmetic.
PointValues reread_values(const Study& study, const io::DesignFile& reread,
                          const std::optional<Evaluation>& e) {
  const std::vector<ProblemConstraint> constraints = expand_constraints(study);
  PointValues v;
  v.constraints.assign(constraints.size(), kPenalty);
  if (!e) return v;
  try {
    v.objective = study.over_impacts ? objective_of(study, reread) : terms_value(study, *e);
  } catch (const std::exception&) {
    v.objective = kPenalty;
  }
  if (minimizes_square(study)) v.objective *= v.objective;
  for (std::size_t k = 0; k < constraints.size(); ++k)
    v.constraints[k] = constraint_value(constraints[k], *e);
  return v;
}

bool same_bits(double a, double b) {
  return std::bit_cast<std::uint64_t>(a) == std::bit_cast<std::uint64_t>(b);
}

// The reported (not minimised) form of an objective value.
double reported_objective(const Study& study, double minimised) {
  return minimizes_square(study) ? std::sqrt(minimised) : minimised;
}

// "" when the search's numbers at its best point are, bit for bit, those of
// the printed design read again and of the summary; else what differs.
std::string compare_values(const Study& study, const optimizer::Summary& summary,
                           const PointValues& searched, const PointValues& reread) {
  std::string differs;
  const auto add = [&](const std::string& what) {
    differs += (differs.empty() ? "" : "; ") + what;
  };
  const double searched_objective = reported_objective(study, searched.objective);
  if (!same_bits(searched.objective, reread.objective) ||
      !same_bits(summary.objective, searched_objective)) {
    add(fmt::format("objective {} (the search) against {} (the printed design)",
                    io::exact(summary.objective),
                    io::exact(reported_objective(study, reread.objective))));
  }
  const std::vector<ProblemConstraint> constraints = expand_constraints(study);
  for (std::size_t k = 0; k < constraints.size(); ++k) {
    if (!same_bits(searched.constraints[k], reread.constraints[k])) {
      add(fmt::format("`{}` off its limit by {} (the search) against {} (the printed design)",
                      constraint_name(constraints[k]), io::exact(searched.constraints[k]),
                      io::exact(reread.constraints[k])));
    }
  }
  return differs;
}

}  // namespace

io::Json printed_design(const Study& study, std::span<const double> x, const io::DesignFile& at_x) {
  io::Json printed = document_at(study, x);
  // Notes about the starting design, not this one.
  for (const char* key : {"$schema", "description", "reference"}) printed.erase(key);
  // The impact the study evaluated, written out: a command's default impact
  // need not be the study's.
  const auto impact = at_x.provenance.find("impact/from_butt_m");
  if (impact == at_x.provenance.end() || impact->second.starts_with("default")) {
    if (!printed.contains("impact") || !printed["impact"].is_object())
      printed["impact"] = io::Json::object();
    printed["impact"]["from_butt_m"] = at_x.design.impact_from_butt_m;
  }
  // The model the study evaluated with, when the file's own would be another.
  const std::string own = printed.contains("fidelity") && printed["fidelity"].is_string()
                              ? printed["fidelity"].get<std::string>()
                              : std::string("auto");
  bool same_model = false;
  try {
    same_model = resolve_fidelity(own, at_x.design) == study.fidelity;
  } catch (const std::invalid_argument&) {
  }
  if (!same_model) printed["fidelity"] = std::string(to_string(study.fidelity));
  return printed;
}

void check_can_optimize(const Study& study) {
  if (study.objective.empty())
    throw io::InputError(study.source, "/objective", "missing: optimize needs an objective");
  for (std::size_t i = 0; i < study.variables.size(); ++i) {
    const StudyVariable& v = study.variables[i];
    if (!(v.min < v.max)) {
      throw io::InputError(study.source, "/variables/" + std::to_string(i),
                           "optimize needs a range: give \"min\" < \"max\" (the values span only " +
                               io::significant(v.min) + ")");
    }
    // A bound the design cannot take at all, its other inputs as given (a
    // mass of -1 kg): the search would meet it only as an infeasible corner.
    // A sweep walks such a range and says where each point is refused.
    for (const auto& [side, bound] : {std::pair{"min", v.min}, std::pair{"max", v.max}}) {
      io::Json document = study.design_document;
      document[io::Json::json_pointer(v.pointer)] = bound;
      try {
        io::read_design(document, study.design_source);
      } catch (const io::InputError& e) {
        if (e.pointer() != v.pointer) continue;  // another input's, or several together
        throw io::InputError(study.source, "/variables/" + std::to_string(i),
                             std::string(side) + " " + io::exact(bound) + " is no value of " +
                                 v.pointer +
                                 " (the design's other inputs as given): " + e.detail());
      }
    }
  }
}

OptimizationResult run_optimization(const Study& study) {
  check_can_optimize(study);
  const optimizer::Problem problem = make_problem(study);
  optimizer::Summary summary = minimize(problem, study.options);
  if (minimizes_square(study)) {
    summary.objective = std::sqrt(summary.objective);
    for (double& value : summary.history) value = std::sqrt(value);
  }
  io::DesignFile start = design_at(study, problem.start);  // valid: read_study checked it
  // A point whose design is invalid carries only the penalty: the start
  // (valid, and evaluated first) then stands for the search's answer.
  std::string why;
  std::optional<io::DesignFile> best;
  try {
    best.emplace(design_at(study, summary.x));
  } catch (const io::InputError& e) {
    why = e.detail();
    summary.x = problem.start;
    best.emplace(start);
  }
  OptimizationResult r{std::move(summary), problem.start, std::move(start), std::move(*best)};
  // Without an impact spread the objective is a function of the outputs:
  // each design is evaluated once (the modal model in the loop costs
  // hundreds of microseconds an evaluation).
  const auto undefined = [&](const io::DesignFile& design,
                             const std::optional<Evaluation>& outputs) {
    return study.over_impacts || !outputs ? objective_undefined(study, design)
                                          : terms_undefined(study, *outputs);
  };
  // The start as the study's file describes it (read, not the search's
  // binding: the postcondition below holds the binding to the reader).
  r.start_outputs = outputs_of(study, r.start, nullptr);
  if (!undefined(r.start, r.start_outputs)) {
    r.start_objective =
        study.over_impacts ? objective_of(study, r.start) : terms_value(study, *r.start_outputs);
  }

  // The postcondition: the design the report prints, read back by the reader
  // `evaluate` uses and evaluated as `evaluate` evaluates it, is the design
  // the search evaluated. Everything reported about the best design comes
  // from that re-read design.
  r.best_document = printed_design(study, r.summary.x, r.best);
  const std::string printed_source = study.source + " (its printed best design)";
  std::optional<Evaluation> reread_outputs;
  bool read_again = false;
  try {
    r.best = io::read_design(
        io::parse_json(r.best_document.dump(2, ' ', false, io::Json::error_handler_t::replace),
                       printed_source),
        printed_source);
    read_again = true;
    reread_outputs = io::evaluate_design_file(r.best, "", study.modal_tolerance);
  } catch (const std::invalid_argument& e) {
    // A refusal of the design read again is its answer (the objective has no
    // value there); a printed design that cannot be read is the defect.
    if (!read_again) why = std::string("the printed best design cannot be read: ") + e.what();
  }
  const PointValues searched = searched_values(problem, r.summary.x);
  const PointValues reread = reread_values(study, r.best, reread_outputs);
  r.inconsistency = compare_values(study, r.summary, searched, reread);
  if (!r.inconsistency.empty()) {
    r.summary.objective = reported_objective(study, reread.objective);
    r.inconsistency =
        "the search's own evaluation of its best design differs from the printed "
        "design's, evaluated again as `sweetspot evaluate` does (a defect of "
        "sweetspot; the report gives the printed design's values): " +
        r.inconsistency;
  }
  r.best_outputs = reread_outputs;
  if (why.empty()) why = undefined(r.best, r.best_outputs).value_or("");

  for (const ProblemConstraint& pc : expand_constraints(study)) {
    ConstraintReport c;
    c.name = constraint_name(pc);
    c.unit = pc.source->output->unit;
    c.limit = limit_of(pc);
    c.tolerance = tolerance_at(*pc.source, c.limit);
    c.value = r.best_outputs ? pc.source->output->value(*r.best_outputs) : std::nullopt;
    if (c.value) {
      const double signed_excess = constraint_value(pc, *r.best_outputs);
      const bool equality = pc.which == ProblemConstraint::kEquals;
      c.violation = equality ? std::abs(signed_excess) : std::max(0.0, signed_excess);
      c.satisfied = c.violation <= c.tolerance;
      c.active =
          equality || std::abs(signed_excess) <=
                          std::max(c.tolerance, kActiveFraction * std::max(1.0, std::abs(c.limit)));
    } else {
      c.violation = std::numeric_limits<double>::infinity();
    }
    r.constraints.push_back(std::move(c));
  }
  const bool all_met = std::all_of(r.constraints.begin(), r.constraints.end(),
                                   [](const ConstraintReport& c) { return c.satisfied; });
  r.outcome = !why.empty() ? Outcome::kNoValue : all_met ? Outcome::kOptimum : Outcome::kInfeasible;
  r.no_value = why;
  return r;
}

}  // namespace sweetspot::studies
