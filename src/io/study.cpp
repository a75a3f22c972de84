#include "sweetspot/io/study.hpp"

#include <algorithm>
#include <cmath>
#include <filesystem>

#include <fmt/format.h>

#include "sweetspot/evaluate.hpp"
#include "sweetspot/io/input_error.hpp"
#include "sweetspot/io/parallel.hpp"

namespace sweetspot::io {
namespace {

// Default grid resolution of a sweep variable, and the limits of a grid
// (points per variable, and in all: a sweep streams, but time is finite).
constexpr int kDefaultGridPoints = 21;
constexpr double kMaxGridPoints = 1e7;
constexpr double kMaxGridTotal = 1e8;
// A target met to this fraction counts as reached.
constexpr double kTargetReached = 1e-4;
// A constraint within this fraction of its limit counts as active.
constexpr double kActiveFraction = 1e-4;

const OutputSpec* read_output_name(ObjectReader& r, std::string_view key) {
  const auto name = r.string(key);
  if (!name) r.fail("", "missing \"" + std::string(key) + "\" (an output of sweetspot evaluate)");
  const OutputSpec* output = find_output(*name);
  if (!output) {
    std::string known;
    for (const OutputSpec& o : output_specs()) known += (known.empty() ? "" : ", ") + std::string(o.name);
    r.fail(key, "unknown output \"" + *name + "\" (known: " + known + ")");
  }
  return output;
}

const Json& array_at(ObjectReader& r, std::string_view key, bool required) {
  static const Json kEmpty = Json::array();
  const Json* list = r.child(key);
  if (!list) {
    if (required) r.fail("", "missing \"" + std::string(key) + "\"");
    return kEmpty;
  }
  if (!list->is_array()) r.fail(key, "expected an array, got " + brief(*list));
  return *list;
}

std::vector<double> linspace(double lo, double hi, int points) {
  std::vector<double> values(points);
  for (int i = 0; i < points; ++i) {
    values[i] = points == 1 ? lo : lo + (hi - lo) * static_cast<double>(i) / (points - 1);
  }
  return values;
}

StudyVariable read_variable(ObjectReader& r, const Json& design, int grid_points) {
  StudyVariable v;
  const auto path = r.string("path");
  if (!path) r.fail("", "missing \"path\" (a JSON pointer into the design, e.g. /implement/mass_kg)");
  v.pointer = *path;
  Json::json_pointer pointer;
  try {
    pointer = Json::json_pointer(v.pointer);
  } catch (const Json::exception&) {
    r.fail("path", "\"" + v.pointer + "\" is not a JSON pointer (it starts with /)");
  }
  if (v.pointer.rfind("/reference", 0) == 0) r.fail("path", "\"" + v.pointer + "\" is a published value, not an input");
  if (v.pointer.empty() || !design.contains(pointer)) {
    r.fail("path", "\"" + v.pointer + "\" is not in the design");
  }
  if (!design.at(pointer).is_number()) {
    r.fail("path", "\"" + v.pointer + "\" is " + brief(design.at(pointer)) + ", expected a number");
  }
  const double current = design.at(pointer).get<double>();
  const Json& values = array_at(r, "values", false);
  for (std::size_t i = 0; i < values.size(); ++i) {
    if (!values[i].is_number() || !std::isfinite(values[i].get<double>())) {
      r.fail("values", "expected finite numbers, got " + brief(values[i]) + " at index " + std::to_string(i));
    }
    v.values.push_back(values[i].get<double>());
  }
  const auto min = r.number("min");
  const auto max = r.number("max");
  if (v.values.empty() || min || max) {
    if (!min || !max) r.fail("", "missing \"min\" and \"max\" (the variable's bounds)");
    if (!(*min < *max)) {
      r.fail("min", "must be < max, got min " + brief(Json(*min)) + " and max " + brief(Json(*max)));
    }
    v.min = *min;
    v.max = *max;
  } else {
    v.min = *std::min_element(v.values.begin(), v.values.end());
    v.max = *std::max_element(v.values.begin(), v.values.end());
  }
  const auto points = r.number("points");
  if (points && !(*points >= 1 && *points <= kMaxGridPoints && *points == std::floor(*points))) {
    r.fail("points", "must be a whole number in [1, 1e7], got " + brief(Json(*points)));
  }
  if (v.values.empty()) v.values = linspace(v.min, v.max, points ? static_cast<int>(*points) : grid_points);
  const auto start = r.number("start");
  if (start && !(*start >= v.min && *start <= v.max)) {
    r.fail("start", "must lie within [min, max] = [" + brief(Json(v.min)) + ", " + brief(Json(v.max)) +
                        "], got " + brief(Json(*start)));
  }
  v.start = start ? *start : (current >= v.min && current <= v.max ? current : 0.5 * (v.min + v.max));
  r.finish({"path", "min", "max", "start", "points", "values"});
  return v;
}

ObjectiveTerm read_term(ObjectReader& r, bool allow_spread) {
  ObjectiveTerm term;
  term.output = read_output_name(r, "output");
  const auto goal = r.string("goal").value_or("minimize");
  if (goal == "minimize") term.goal = Goal::kMinimize;
  else if (goal == "maximize") term.goal = Goal::kMaximize;
  else if (goal == "target") term.goal = Goal::kTarget;
  else r.fail("goal", "expected \"minimize\", \"maximize\" or \"target\", got \"" + goal + "\"");
  const auto target = r.number("target");
  if (term.goal == Goal::kTarget && !target) r.fail("", "goal \"target\" needs a \"target\" value");
  if (term.goal != Goal::kTarget && target) r.fail("target", "only goal \"target\" takes a target");
  term.target = target.value_or(0.0);
  term.weight = r.number("weight").value_or(1.0);
  if (!(term.weight > 0)) r.fail("weight", "must be > 0, got " + brief(Json(term.weight)));
  std::vector<std::string> keys{"output", "goal", "target", "weight"};
  if (allow_spread) keys.insert(keys.end(), {"over_impacts", "terms"});
  r.finish(keys);
  return term;
}

ImpactSpread read_spread(ObjectReader& r) {
  ImpactSpread spread;
  const Json* range = r.child("from_tip_m");
  if (!range || !range->is_array() || range->size() != 2 || !(*range)[0].is_number() ||
      !(*range)[1].is_number()) {
    r.fail("from_tip_m", "expected [nearest, farthest] impact distances from the tip in m");
  }
  spread.from_tip_lo_m = (*range)[0].get<double>();
  spread.from_tip_hi_m = (*range)[1].get<double>();
  if (!(spread.from_tip_lo_m >= 0 && spread.from_tip_lo_m < spread.from_tip_hi_m)) {
    r.fail("from_tip_m", "expected 0 <= nearest < farthest, got " + brief(*range));
  }
  const double points = r.number("points").value_or(8);
  if (!(points >= 2 && points <= 1000 && points == std::floor(points))) {
    r.fail("points", "must be a whole number in [2, 1000], got " + brief(Json(points)));
  }
  spread.points = static_cast<int>(points);
  const auto reduce = r.string("reduce").value_or("max");
  if (reduce == "max") spread.reduce = ImpactSpread::Reduce::kMax;
  else if (reduce == "mean") spread.reduce = ImpactSpread::Reduce::kMean;
  else r.fail("reduce", "expected \"max\" or \"mean\", got \"" + reduce + "\"");
  r.finish({"from_tip_m", "points", "reduce"});
  return spread;
}

double term_value(const ObjectiveTerm& term, const Evaluation& e) {
  const auto value = term.output->value(e);
  if (!value) return kPenalty;
  switch (term.goal) {
    case Goal::kMinimize: return term.weight * *value;
    case Goal::kMaximize: return -term.weight * *value;
    case Goal::kTarget: return term.weight * (*value - term.target) * (*value - term.target);
  }
  return kPenalty;
}

double terms_value(const Study& study, const Evaluation& e) {
  double sum = 0.0;
  for (const ObjectiveTerm& term : study.objective) sum += term_value(term, e);
  return sum;
}

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
std::string bound_hit(const StudyVariable& v, double x) {
  const double slack = 1e-6 * (v.max - v.min);
  return x <= v.min + slack ? "min" : x >= v.max - slack ? "max" : "";
}

std::string goal_phrase(const ObjectiveTerm& term) {
  switch (term.goal) {
    case Goal::kMinimize: return "lowest";
    case Goal::kMaximize: return "highest";
    case Goal::kTarget: return fmt::format("closest to {}", significant(term.target));
  }
  return "";
}

}  // namespace

Study read_study(const Json& document, const std::string& source, const std::string& folder) {
  Study study;
  study.source = source;
  ObjectReader top(document, "", "", source, nullptr);
  study.name = top.string("name").value_or(source);
  study.question = top.string("question").value_or("");
  top.string("description");
  top.string("$schema");

  const Json* design = top.child("design");
  if (!design) top.fail("design", "missing: a design file path or an inline design");
  if (design->is_string()) {
    const std::string path = (std::filesystem::path(folder) / design->get<std::string>()).string();
    try {
      study.design_document = read_json_file(path);
    } catch (const InputError& e) {
      throw InputError(source, "/design", "cannot read the design: " + std::string(e.what()));
    }
    study.design_source = path;
  } else if (design->is_object()) {
    study.design_document = *design;
    study.design_source = source + " (inline design)";
  } else {
    top.fail("design", "expected a path or an inline design object, got " + brief(*design));
  }
  // The design must be valid as written.
  read_design(study.design_document, study.design_source);

  int grid_points = kDefaultGridPoints;
  if (const Json* grid = top.child("grid")) {
    ObjectReader g(*grid, "/grid", "grid", source, nullptr);
    const auto points = g.number("points");
    if (points && !(*points >= 1 && *points <= kMaxGridPoints && *points == std::floor(*points))) {
      g.fail("points", "must be a whole number in [1, 1e7], got " + brief(Json(*points)));
    }
    if (points) grid_points = static_cast<int>(*points);
    g.finish({"points"});
  }

  const Json& variables = array_at(top, "variables", true);
  if (variables.empty()) top.fail("variables", "expected at least one variable");
  if (variables.size() > 64) top.fail("variables", "at most 64 variables, got " + std::to_string(variables.size()));
  for (std::size_t i = 0; i < variables.size(); ++i) {
    ObjectReader r(variables[i], "/variables/" + std::to_string(i), "", source, nullptr);
    study.variables.push_back(read_variable(r, study.design_document, grid_points));
    for (std::size_t j = 0; j < i; ++j) {
      if (study.variables[j].pointer == study.variables[i].pointer) {
        r.fail("path", "repeats /variables/" + std::to_string(j) + "/path");
      }
    }
  }

  double total = 1.0;
  for (std::size_t i = 0; i < std::min<std::size_t>(2, study.variables.size()); ++i) {
    total *= static_cast<double>(study.variables[i].values.size());
  }
  if (total > kMaxGridTotal) {
    top.fail("variables", "a grid of " + brief(Json(total)) + " points is more than 1e8");
  }

  if (const Json* objective = top.child("objective")) {
    ObjectReader r(*objective, "/objective", "", source, nullptr);
    if (r.has("terms")) {
      const Json& terms = array_at(r, "terms", true);
      if (terms.empty()) r.fail("terms", "expected at least one term");
      for (std::size_t i = 0; i < terms.size(); ++i) {
        ObjectReader t(terms[i], "/objective/terms/" + std::to_string(i), "", source, nullptr);
        study.objective.push_back(read_term(t, false));
      }
      if (const Json* spread = r.child("over_impacts")) {
        ObjectReader s(*spread, "/objective/over_impacts", "", source, nullptr);
        study.over_impacts = read_spread(s);
      }
      r.finish({"terms", "over_impacts"});
    } else {
      if (const Json* spread = r.child("over_impacts")) {
        ObjectReader s(*spread, "/objective/over_impacts", "", source, nullptr);
        study.over_impacts = read_spread(s);
      }
      study.objective.push_back(read_term(r, true));
    }
    if (study.over_impacts) {
      for (std::size_t i = 0; i < study.variables.size(); ++i) {
        if (study.variables[i].pointer.starts_with("/impact")) {
          throw InputError(source, "/variables/" + std::to_string(i) + "/path",
                           "the impact point cannot be a variable of a study over a spread of impacts");
        }
      }
    }
  }

  const Json& constraints = array_at(top, "constraints", false);
  for (std::size_t i = 0; i < constraints.size(); ++i) {
    ObjectReader r(constraints[i], "/constraints/" + std::to_string(i), "", source, nullptr);
    StudyConstraint c;
    c.output = read_output_name(r, "output");
    c.min = r.number("min");
    c.max = r.number("max");
    c.equals = r.number("equals");
    if (!c.min && !c.max && !c.equals) r.fail("", "give \"min\", \"max\" or \"equals\"");
    if (c.equals && (c.min || c.max)) r.fail("equals", "give either \"equals\" or \"min\"/\"max\"");
    if (c.min && c.max && !(*c.min <= *c.max)) {
      r.fail("min", "must be <= max, got min " + brief(Json(*c.min)) + " and max " + brief(Json(*c.max)));
    }
    const double scale = std::max(1.0, std::abs(c.equals.value_or(c.max.value_or(c.min.value_or(0.0)))));
    c.tolerance = r.number("tolerance").value_or(c.equals ? 1e-6 * scale : 1e-9 * scale);
    if (!(c.tolerance > 0)) r.fail("tolerance", "must be > 0, got " + brief(Json(c.tolerance)));
    r.finish({"output", "min", "max", "equals", "tolerance"});
    study.constraints.push_back(c);
  }

  OptimizeOptions& o = study.options;
  if (const auto algorithm = top.string("algorithm")) o.algorithm = *algorithm;
  if (!is_known_algorithm(o.algorithm)) {
    top.fail("algorithm", "unknown algorithm \"" + o.algorithm +
                              "\" (auto, or an NLopt name such as LD_SLSQP, LN_COBYLA, GN_ISRES)");
  }
  if (const auto local = top.string("local_algorithm")) o.local_algorithm = *local;
  if (!is_known_algorithm(o.local_algorithm)) {
    top.fail("local_algorithm", "unknown algorithm \"" + o.local_algorithm + "\"");
  }
  if (const auto seed = top.number("seed")) {
    if (!(*seed >= 0 && *seed <= 4294967295.0 && *seed == std::floor(*seed))) {
      top.fail("seed", "must be a whole number in [0, 4294967295], got " + brief(Json(*seed)));
    }
    o.seed = static_cast<unsigned long>(*seed);
  }
  if (const Json* tolerances = top.child("tolerances")) {
    ObjectReader t(*tolerances, "/tolerances", "", source, nullptr);
    o.x_tolerance_rel = t.number("x_rel").value_or(o.x_tolerance_rel);
    o.f_tolerance_rel = t.number("f_rel").value_or(o.f_tolerance_rel);
    if (const auto max_evaluations = t.number("max_evaluations")) {
      o.max_evaluations = static_cast<int>(std::clamp(*max_evaluations, 0.0, 1e9));
    }
    o.max_seconds = t.number("max_seconds").value_or(o.max_seconds);
    t.finish({"x_rel", "f_rel", "max_evaluations", "max_seconds"});
    if (const std::string why = o.validate(); !why.empty()) {
      throw InputError(source, "/tolerances", why);
    }
  }

  const Json& outputs = array_at(top, "outputs", false);
  for (std::size_t i = 0; i < outputs.size(); ++i) {
    const std::string at = "/outputs/" + std::to_string(i);
    if (!outputs[i].is_string() || !find_output(outputs[i].get<std::string>())) {
      throw InputError(source, at, "expected the name of an output of sweetspot evaluate, got " + brief(outputs[i]));
    }
    study.sweep_outputs.push_back(find_output(outputs[i].get<std::string>()));
  }
  const std::string fidelity = top.string("fidelity").value_or("auto");
  if (fidelity == "modal") {
    study.fidelity = Fidelity::kModal;
  } else if (fidelity == "response") {
    study.fidelity = Fidelity::kResponse;
  } else if (fidelity == "auto") {
    std::vector<const OutputSpec*> used = study.sweep_outputs;
    for (const ObjectiveTerm& t : study.objective) used.push_back(t.output);
    for (const StudyConstraint& c : study.constraints) used.push_back(c.output);
    study.fidelity = needed_fidelity(read_design(study.design_document, study.design_source).design);
    for (const OutputSpec* o : used) {
      if (o->needs_response) study.fidelity = Fidelity::kResponse;
      if (o->needs_modes && study.fidelity == Fidelity::kRigid) study.fidelity = Fidelity::kModal;
    }
  } else if (fidelity != "rigid") {
    top.fail("fidelity", "expected \"rigid\", \"modal\", \"response\" or \"auto\", got \"" + fidelity + "\"");
  }
  {
    std::vector<const OutputSpec*> used = study.sweep_outputs;
    for (const ObjectiveTerm& t : study.objective) used.push_back(t.output);
    for (const StudyConstraint& c : study.constraints) used.push_back(c.output);
    for (const OutputSpec* o : used) {
      const bool too_low = (o->needs_response && study.fidelity != Fidelity::kResponse) ||
                           (o->needs_modes && study.fidelity == Fidelity::kRigid);
      if (too_low) {
        top.fail("fidelity", "\"" + fidelity + "\" cannot give " + std::string(o->name) +
                                 "; use \"auto\" or a higher fidelity");
      }
    }
  }
  if (const auto tolerance = top.number("modal_tolerance")) {
    if (!(*tolerance >= kMinRelTol && *tolerance <= kMaxRelTol)) {
      top.fail("modal_tolerance", "must be in [1e-8, 0.1], got " + brief(Json(*tolerance)));
    }
    study.modal_tolerance = *tolerance;
  }
  top.finish({"$schema", "name", "question", "description", "design", "variables", "objective",
              "constraints", "algorithm", "local_algorithm", "seed", "tolerances", "grid", "outputs",
              "fidelity", "modal_tolerance"});

  // The start must be a valid design.
  std::vector<double> start;
  for (const StudyVariable& v : study.variables) start.push_back(v.start);
  DesignFile at_start = [&] {
    try {
      return design_at(study, start);
    } catch (const InputError& e) {
      throw InputError(source, "/variables", "the start point is not a valid design: " + std::string(e.what()));
    }
  }();
  if (study.fidelity == Fidelity::kModal) {
    try {
      evaluate_in(study, at_start);
    } catch (const std::invalid_argument& e) {
      rethrow_in(at_start, e);
    }
  }
  return study;
}

Study load_study(const std::string& path) {
  const std::string folder = std::filesystem::path(path).parent_path().string();
  return read_study(read_json_file(path), path, folder.empty() ? "." : folder);
}

Evaluation evaluate_in(const Study& study, const DesignFile& design) {
  return evaluate(design.design, study.fidelity, study.modal_tolerance);
}

DesignFile design_at(const Study& study, std::span<const double> x) {
  Json document = study.design_document;
  for (std::size_t i = 0; i < study.variables.size(); ++i) {
    document[Json::json_pointer(study.variables[i].pointer)] = x[i];
  }
  return read_design(document, study.design_source);
}

double objective_of(const Study& study, const DesignFile& design) {
  if (!study.over_impacts) return terms_value(study, evaluate_in(study, design));
  const ImpactSpread& spread = *study.over_impacts;
  Design d = design.design;
  const double L = d.implement.length_m();
  const auto from_butt = [&](int k) {
    return L - (spread.from_tip_lo_m + (spread.from_tip_hi_m - spread.from_tip_lo_m) * k / (spread.points - 1));
  };
  // The rigid model at many impacts shares everything but the impact (ImpactSweep).
  std::optional<ImpactSweep> rigid;
  if (study.fidelity == Fidelity::kRigid && !d.cor_rigid && !d.strings) rigid.emplace(d);
  double reduced = spread.reduce == ImpactSpread::Reduce::kMax ? -kPenalty : 0.0;
  for (int k = 0; k < spread.points; ++k) {
    const double x = from_butt(k);
    double value = kPenalty;  // an impact off the implement keeps the penalty
    if (x >= 0.0 && x <= L) {
      if (rigid) {
        value = terms_value(study, rigid->at(x));
      } else {
        d.impact_from_butt_m = x;
        try {
          value = terms_value(study, evaluate(d, study.fidelity, study.modal_tolerance));
        } catch (const std::invalid_argument&) {
        }
      }
    }
    reduced = spread.reduce == ImpactSpread::Reduce::kMax ? std::max(reduced, value) : reduced + value / spread.points;
  }
  return reduced;
}

// Minimising a non-negative output with a kink where its signed form changes
// sign (|F_w|) is minimising its square, which is smooth there: gradient
// methods then apply. The reported objective is the output itself.
bool minimizes_square(const Study& study) {
  return study.objective.size() == 1 && study.objective[0].goal == Goal::kMinimize &&
         study.objective[0].output->kinked && !study.over_impacts;
}

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
  problem.evaluate = [&study, constraints, square](std::span<const double> x, double& f,
                                                   std::span<double> c) {
    try {
      const DesignFile design = design_at(study, x);
      const Evaluation e = evaluate_in(study, design);
      f = study.over_impacts ? objective_of(study, design) : terms_value(study, e);
      if (square) f *= f;
      for (std::size_t k = 0; k < constraints.size(); ++k) c[k] = constraint_value(constraints[k], e);
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

std::string optimization_report(const Study& study, const OptimizationResult& r, Format format,
                                bool with_timing) {
  const Evaluation start = evaluate_in(study, r.start);
  const Evaluation best = evaluate_in(study, r.best);
  const ObjectiveTerm& lead = study.objective.front();
  const auto lead_value = [&](const Evaluation& e) { return lead.output->value(e); };

  if (format == Format::kJson) {
    Json j;
    j["name"] = study.name;
    j["best_design"] = design_to_json(r.best);
    j["objective_value"] = r.summary.objective;
    j["start_objective_value"] = r.start_objective;
    j["feasible"] = r.summary.feasible;
    j["evaluations"] = r.summary.evaluations;
    j["termination"] = r.summary.termination;
    j["algorithm"] = r.summary.algorithm;
    j["seconds"] = r.summary.seconds;
    Json& variables = j["variables"];
    for (std::size_t i = 0; i < study.variables.size(); ++i) {
      const StudyVariable& v = study.variables[i];
      variables.push_back({{"path", v.pointer}, {"min", v.min}, {"max", v.max}, {"start", r.start_x[i]},
                           {"best", r.summary.x[i]},
                           {"at_bound", bound_hit(v, r.summary.x[i])}});
    }
    j["constraints"] = Json::array();
    for (const ConstraintReport& c : r.constraints) {
      j["constraints"].push_back({{"constraint", c.name},
                                  {"value", std::isnan(c.value) ? Json(nullptr) : Json(c.value)},
                                  {"satisfied", c.satisfied},
                                  {"active", c.active}});
    }
    for (const OutputSpec& o : output_specs()) {
      const auto a = o.value(start), b = o.value(best);
      j["outputs_start"][std::string(o.name)] = a ? Json(*a) : Json(nullptr);
      j["outputs_best"][std::string(o.name)] = b ? Json(*b) : Json(nullptr);
    }
    return j.dump(2) + "\n";
  }
  if (format == Format::kCsv) {
    std::string csv = "output,start,best\n";
    for (const OutputSpec& o : output_specs()) {
      const auto a = o.value(start), b = o.value(best);
      csv += fmt::format("{},{},{}\n", o.name, a ? exact(*a) : "", b ? exact(*b) : "");
    }
    return csv;
  }
  // Markdown: the answer in a sentence, then the numbers.
  std::string changes;
  for (std::size_t i = 0; i < study.variables.size(); ++i) {
    const StudyVariable& v = study.variables[i];
    const double x = r.summary.x[i];
    const std::string hit = bound_hit(v, x);
    changes += fmt::format("{}`{}` = {}{}", changes.empty() ? "" : ", ", v.pointer, significant(x, 4),
                           hit == "min" ? " (its lower bound)" : hit == "max" ? " (its upper bound)" : "");
  }
  std::string active;
  for (const ConstraintReport& c : r.constraints) {
    if (c.active) active += (active.empty() ? "" : ", ") + c.name;
  }
  const auto best_lead = lead_value(best);
  const auto start_lead = lead_value(start);
  std::string md = fmt::format("# {}\n\n", md_cell(study.name));
  if (!study.question.empty()) md += "**Question.** " + study.question + "\n\n";
  md += fmt::format("**Answer.** The {} `{}`{} is {} {} (the starting design gives {}), with {}.{}{}\n\n",
                    goal_phrase(lead), lead.output->name,
                    study.over_impacts ? fmt::format(" ({} over impacts {}–{} m from the tip)",
                                                     study.over_impacts->reduce == ImpactSpread::Reduce::kMax ? "worst case" : "mean",
                                                     significant(study.over_impacts->from_tip_lo_m),
                                                     significant(study.over_impacts->from_tip_hi_m))
                                       : std::string(),
                    study.over_impacts ? significant(r.summary.objective, 4)
                                       : (best_lead ? significant(*best_lead, 4) : std::string("—")),
                    lead.output->unit,
                    study.over_impacts ? significant(r.start_objective, 4)
                                       : (start_lead ? significant(*start_lead, 4) : std::string("—")),
                    changes,
                    active.empty() ? " No constraint is active." : " Active constraints: " + active + ".",
                    r.summary.feasible ? "" : " **No feasible design was found; this is the least infeasible.**");
  if (lead.goal == Goal::kTarget && study.objective.size() == 1 && !study.over_impacts && best_lead &&
      std::abs(*best_lead - lead.target) > kTargetReached * std::max(1.0, std::abs(lead.target))) {
    md += fmt::format("The target {} cannot be reached within the variables' bounds: {} {} is as close as "
                      "these designs get.\n\n",
                      significant(lead.target), significant(*best_lead, 4), lead.output->unit);
  }
  md += "## Variables\n\n| path | min | max | start | best |\n|---|---:|---:|---:|---:|\n";
  for (std::size_t i = 0; i < study.variables.size(); ++i) {
    const StudyVariable& v = study.variables[i];
    md += fmt::format("| `{}` | {} | {} | {} | {} |\n", v.pointer, significant(v.min), significant(v.max),
                      significant(r.start_x[i]), significant(r.summary.x[i]));
  }
  if (!r.constraints.empty()) {
    md += "\n## Constraints\n\n| constraint | value at the optimum | satisfied | active |\n|---|---:|---|---|\n";
    for (const ConstraintReport& c : r.constraints) {
      md += fmt::format("| `{}` | {} | {} | {} |\n", c.name,
                        std::isnan(c.value) ? std::string("—") : significant(c.value), c.satisfied ? "yes" : "**no**",
                        c.active ? "yes" : "no");
    }
  }
  md += fmt::format("\n## Search\n\nObjective (minimised form) {} after {} evaluations; {}; NLopt termination: {}.{}\n",
                    significant(r.summary.objective), r.summary.evaluations, r.summary.algorithm,
                    r.summary.termination,
                    with_timing ? fmt::format(" Wall time {:.2f} ms.", r.summary.seconds * 1e3) : std::string());
  md += "\n## Outputs, start and optimum\n\n| output | start | optimum | unit |\n|---|---:|---:|---|\n";
  for (const OutputSpec& o : output_specs()) {
    const auto a = o.value(start), b = o.value(best);
    md += fmt::format("| `{}` | {} | {} | {} |\n", o.name, a ? significant(*a) : "—", b ? significant(*b) : "—", o.unit);
  }
  md += "\nThe best design as a design file (`sweetspot evaluate` accepts it):\n\n```json\n" +
        design_to_json(r.best).dump(2) + "\n```\n";
  return md;
}

Plot convergence_plot(const Study& study, const OptimizationResult& r) {
  PlotSeries series{"best objective so far", {}, {}, "lines lw 2"};
  for (std::size_t i = 0; i < r.summary.history.size(); ++i) {
    series.x.push_back(static_cast<double>(i + 1));
    const double value = r.summary.history[i];
    series.y.push_back(std::abs(value) < kPenalty / 10 ? std::optional(value) : std::nullopt);
  }
  return Plot{"Convergence: " + study.name, "evaluation (including difference gradients)",
              fmt::format("objective ({})", study.objective.front().output->name), std::nullopt,
              std::nullopt, {series}, {}, {}};
}

namespace {

// One thread's share of a sweep: points by index in grid order (the first
// variable fastest), each evaluated into its CSV row and its plot values.
class SweepWorker {
 public:
  SweepWorker(const Study& study, const std::vector<double>& second, bool share_rows)
      : study_(study), second_(second), document_(study.design_document) {
    for (const StudyVariable& variable : study.variables) pointers_.emplace_back(variable.pointer);
    // The impact point as read_design() reads it: "/impact/from_tip_<unit>" or
    // "/impact/from_butt_<unit>", converted by the same factor.
    const std::string_view pointer = study.variables[0].pointer;
    if (share_rows && study.fidelity == Fidelity::kRigid && pointer.starts_with("/impact/")) {
      const std::string_view key = pointer.substr(std::string_view("/impact/").size());
      if (const auto f = unit_factor(key, "from_tip", Dimension::kLength)) impact_ = Impact{true, *f};
      if (const auto f = unit_factor(key, "from_butt", Dimension::kLength)) impact_ = Impact{false, *f};
    }
  }

  // Appends point p's CSV row to `text` and its outputs to `values`.
  void point(std::size_t p, std::string& text, std::optional<double>* values) {
    const std::size_t n0 = study_.variables[0].values.size();
    const std::size_t row = p / n0;
    const double v = study_.variables[0].values[p % n0];
    std::optional<Evaluation> e;
    std::string error;
    if (impact_ && shared_ && shared_row_ == row) e = shared_at(v);
    if (!e) {
      try {
        e = evaluate_here(v, second_[row], row);
      } catch (const std::exception& ex) {
        error = ex.what();
      }
    }
    text += exact(v);
    if (study_.variables.size() == 2) text += "," + exact(second_[row]);
    for (std::size_t k = 0; k < study_.sweep_outputs.size(); ++k) {
      values[k] = e ? study_.sweep_outputs[k]->value(*e) : std::nullopt;
      text += ",";
      if (values[k]) text += exact(*values[k]);
    }
    text += "," + csv_field(error) + "\n";
  }

 private:
  struct Impact {
    bool from_tip;
    double to_si;
  };

  // The point read and evaluated on its own; the row's design kept for the
  // next points when only the impact changes along it.
  Evaluation evaluate_here(double v, double y, std::size_t row) {
    document_[pointers_[0]] = v;
    if (pointers_.size() == 2) document_[pointers_[1]] = y;
    const DesignFile design = read_design_lean(document_, study_.design_source);
    Evaluation e = evaluate_in(study_, design);
    if (impact_ && !design.design.cor_rigid && !design.design.strings) {
      shared_.emplace(design.design);
      shared_row_ = row;
      length_m_ = design.design.implement.length_m();
    }
    return e;
  }

  // The same point from the row's design, or std::nullopt when only reading
  // it on its own can say what is wrong (off the implement, not finite).
  std::optional<Evaluation> shared_at(double v) const {
    const double si = v * impact_->to_si;
    const double from_butt = impact_->from_tip ? length_m_ - si : si;
    if (!(si >= 0.0 && si <= length_m_)) return std::nullopt;
    Evaluation e = shared_->at(from_butt);
    for (const OutputSpec* o : study_.sweep_outputs) {
      if (const auto value = o->value(e); value && !std::isfinite(*value)) return std::nullopt;
    }
    return e;
  }

  const Study& study_;
  const std::vector<double>& second_;
  Json document_;  // this thread's copy, the variables set in place
  std::vector<Json::json_pointer> pointers_;
  std::optional<Impact> impact_;
  std::optional<ImpactSweep> shared_;
  std::size_t shared_row_ = 0;
  double length_m_ = 0.0;
};

}  // namespace

std::vector<Plot> run_sweep(const Study& study, std::ostream& csv,
                            const std::function<void(std::size_t, std::size_t)>& progress,
                            const SweepOptions& options) {
  if (study.variables.size() > 2) {
    throw InputError(study.source, "/variables", "a sweep takes one or two variables, got " +
                                                     std::to_string(study.variables.size()));
  }
  if (study.sweep_outputs.empty()) throw InputError(study.source, "/outputs", "missing: the outputs to sweep");
  const StudyVariable& first = study.variables[0];
  const std::vector<double> second =
      study.variables.size() == 2 ? study.variables[1].values : std::vector<double>{NAN};
  const std::size_t total = first.values.size() * second.size();
  const std::size_t outputs = study.sweep_outputs.size();
  const bool keep = total <= kMaxPlotPoints;

  csv << first.pointer;
  if (study.variables.size() == 2) csv << "," << study.variables[1].pointer;
  for (const OutputSpec* o : study.sweep_outputs) csv << "," << o->name;
  csv << ",error\n";

  std::vector<Plot> plots;
  for (const OutputSpec* o : study.sweep_outputs) {
    plots.push_back(Plot{fmt::format("{}: {}", study.name, o->name), first.pointer,
                         fmt::format("{} ({})", o->name, o->unit.empty() ? "dimensionless" : o->unit),
                         std::pair{first.min, first.max}, std::nullopt, {}, {}, {}});
  }
  const int threads = std::max(1, options.threads);
  std::vector<SweepWorker> workers;
  for (int t = 0; t < threads; ++t) workers.emplace_back(study, second, options.share_rows);
  std::vector<std::string> texts(threads);
  std::vector<std::optional<double>> values(kSweepChunkPoints * outputs);
  for (std::size_t begin = 0; begin < total; begin += kSweepChunkPoints) {
    const std::size_t count = std::min(kSweepChunkPoints, total - begin);
    for (std::string& text : texts) text.clear();
    for_blocks(count, threads, [&](std::size_t t, std::size_t from, std::size_t to) {
      for (std::size_t i = from; i < to; ++i) workers[t].point(begin + i, texts[t], &values[i * outputs]);
    });
    for (const std::string& text : texts) csv << text;
    if (keep) {
      for (std::size_t i = 0; i < count; ++i) {
        const std::size_t p = begin + i;
        if (p % first.values.size() == 0) {
          for (std::size_t k = 0; k < outputs; ++k) {
            plots[k].series.push_back(PlotSeries{
                study.variables.size() == 2
                    ? fmt::format("{} = {}", study.variables[1].pointer, significant(second[p / first.values.size()]))
                    : std::string(study.sweep_outputs[k]->name),
                {},
                {}});
          }
        }
        for (std::size_t k = 0; k < outputs; ++k) {
          plots[k].series.back().x.push_back(first.values[p % first.values.size()]);
          plots[k].series.back().y.push_back(values[i * outputs + k]);
        }
      }
    }
    progress(begin + count, total);
  }
  if (!keep) plots.clear();
  return plots;
}

}  // namespace sweetspot::io
