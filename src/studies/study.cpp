#include "studies/study.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <limits>
#include <string>

#include "io/design_fields.hpp"
#include "io/input_error.hpp"
#include "studies/design_binding.hpp"
#include "studies/thread_mode_cache.hpp"
#include "sweetspot/evaluate.hpp"
#include "sweetspot/kernels.hpp"

namespace sweetspot::studies {
namespace {

// Default grid resolution of a sweep variable, and the limits of a grid
// (points per variable, and in all: a sweep streams, but time is finite).
constexpr int kDefaultGridPoints = 21;
constexpr double kMaxGridPoints = 1e7;
constexpr double kMaxGridTotal = 1e8;

const io::OutputSpec* read_output_name(io::ObjectReader& r, std::string_view key) {
  const auto name = r.string(key);
  if (!name) r.fail("", "missing \"" + std::string(key) + "\" (an output of sweetspot evaluate)");
  const io::OutputSpec* output = io::find_output(*name);
  if (!output) {
    std::string known;
    for (const io::OutputSpec& o : io::output_specs())
      known += (known.empty() ? "" : ", ") + std::string(o.name);
    r.fail(key, "unknown output \"" + *name + "\" (known: " + known + ")");
  }
  return output;
}

const io::Json& array_at(io::ObjectReader& r, std::string_view key, bool required) {
  static const io::Json kEmpty = io::Json::array();
  const io::Json* list = r.child(key);
  if (!list) {
    if (required) r.fail("", "missing \"" + std::string(key) + "\"");
    return kEmpty;
  }
  if (!list->is_array()) r.fail(key, "expected an array, got " + io::brief(*list));
  return *list;
}

// The grid point as the decimal it stands for: lo + (hi - lo) i / (n - 1) in
// binary is 0.30000000000000004 for 0.1 + 0.4 * 2 / 4; the nearest double to
// its 15-digit decimal is taken when it lies within a few rounding errors.
double decimal_grid_point(double lo, double hi, double x) {
  const double decimal = std::strtod(fmt::format("{:.15g}", x).c_str(), nullptr);
  const double slack = 4 * std::numeric_limits<double>::epsilon() *
                       std::max({std::fabs(lo), std::fabs(hi), std::fabs(x)});
  if (std::fabs(decimal - x) <= slack && decimal >= lo && decimal <= hi) return decimal;
  return x;
}

std::vector<double> linspace(double lo, double hi, int points) {
  std::vector<double> values(points);
  for (int i = 0; i < points; ++i) {
    values[i] =
        points == 1 || i == 0 ? lo
        : i == points - 1
            ? hi
            : decimal_grid_point(lo, hi, lo + (hi - lo) * static_cast<double>(i) / (points - 1));
  }
  return values;
}

// A variable may name a quantity in another unit than the design file used
// (/strings/tension_lb over a design giving tension_N; /impact/from_tip_cm
// over from_tip_m): the design's value is rewritten in the variable's unit,
// so the study varies it in the unit it names. Another form of the quantity
// (from_butt for from_tip) is not converted. False when there is no such value.
bool respell_in_unit(io::Json& design, const io::Json::json_pointer& pointer) {
  if (pointer.empty() || !design.contains(pointer.parent_pointer())) return false;
  io::Json& parent = design.at(pointer.parent_pointer());
  if (!parent.is_object()) return false;
  const std::string key = pointer.back();
  for (const io::Dimension dimension : io::kAllDimensions) {
    for (const std::string& spelling : io::spellings("", dimension)) {
      if (key.size() <= spelling.size() || !key.ends_with(spelling)) continue;
      const std::string base = key.substr(0, key.size() - spelling.size());
      const double to_si = *io::unit_factor(key, base, dimension);
      for (const std::string& other : spellings(base, dimension)) {
        const auto it = parent.find(other);
        if (other == key || it == parent.end() || !it->is_number()) continue;
        const double value = it->get<double>() * *unit_factor(other, base, dimension) / to_si;
        if (!std::isfinite(value)) return false;
        parent.erase(other);
        parent[key] = value;
        return true;
      }
    }
  }
  // A quantity the field table spells in keys of its own (headsize_sq_in and
  // headsize_cm2, angular_speed_rad_s and _rpm): another of its row's keys, by
  // the scales the reader applies. A place in points head-light is a form
  // (it needs the length), not a unit.
  std::string object = pointer.parent_pointer().to_string();
  object = io::design_object_of(object.empty() ? object : object.substr(1));
  const auto spelled = io::find_spelling(object, key);
  const auto is_unit = [](std::string_view k) { return !k.ends_with("_pts_hl"); };
  if (!spelled || !is_unit(key)) return false;
  for (const std::string& other : io::spellings_of(*spelled->field)) {
    const auto it = parent.find(other);
    if (other == key || it == parent.end() || !it->is_number() || !is_unit(other)) continue;
    const auto from = io::find_spelling(object, other);
    const double si = from->scale.to_si(it->get<double>());
    const io::UnitScale& to = spelled->scale;
    const double value =
        to.power_of_ten != 0 ? io::shift_decimal(si, -to.power_of_ten) : si / to.factor;
    if (!std::isfinite(value)) return false;
    parent.erase(other);
    parent[key] = value;
    return true;
  }
  return false;
}

StudyVariable read_variable(io::ObjectReader& r, io::Json& design, int grid_points) {
  StudyVariable v;
  const auto path = r.string("path");
  if (!path)
    r.fail("", "missing \"path\" (a JSON pointer into the design, e.g. /implement/mass_kg)");
  v.pointer = *path;
  io::Json::json_pointer pointer;
  try {
    pointer = io::Json::json_pointer(v.pointer);
  } catch (const io::Json::exception&) {
    r.fail("path", "\"" + v.pointer + "\" is not a JSON pointer (it starts with /)");
  }
  if (v.pointer.rfind("/reference", 0) == 0)
    r.fail("path", "\"" + v.pointer + "\" is a published value, not an input");
  // nlohmann's contains() throws for a token that cannot index an array
  // ("/point_masses//x"): such a path is not in the design.
  const auto holds = [&] {
    try {
      return design.contains(pointer);
    } catch (const io::Json::exception&) {
      return false;
    }
  };
  if (!v.pointer.empty() && !holds()) {
    try {
      respell_in_unit(design, pointer);
    } catch (const io::Json::exception&) {
    }
  }
  if (v.pointer.empty() || !holds()) {
    r.fail("path", "\"" + v.pointer + "\" is not in the design");
  }
  if (!design.at(pointer).is_number()) {
    r.fail("path",
           "\"" + v.pointer + "\" is " + io::brief(design.at(pointer)) + ", expected a number");
  }
  const double current = design.at(pointer).get<double>();
  const io::Json& values = array_at(r, "values", false);
  if (r.child("values") && values.empty()) {
    r.fail("values",
           "expected at least one value (leave \"values\" out for an even grid from min to max)");
  }
  const auto value_pointer = [&](std::size_t k) {
    return r.pointer() + "/values/" + std::to_string(k);
  };
  for (std::size_t k = 0; k < values.size(); ++k) {
    if (!values[k].is_number() || !std::isfinite(values[k].get<double>())) {
      throw io::InputError(r.source(), value_pointer(k),
                           "expected a finite number, got " + io::brief(values[k]));
    }
    v.values.push_back(values[k].get<double>());
  }
  const auto min = r.number("min");
  const auto max = r.number("max");
  if (v.values.empty() || min || max) {
    if (!min || !max) r.fail("", "missing \"min\" and \"max\" (the variable's bounds)");
    if (!(*min < *max)) {
      r.fail("min", "must be < max, got min " + io::brief(*min) + " and max " + io::brief(*max));
    }
    v.min = *min;
    v.max = *max;
    // Values outside the bounds would evaluate designs the study rules out.
    for (std::size_t k = 0; k < v.values.size(); ++k) {
      if (!(v.values[k] >= v.min && v.values[k] <= v.max)) {
        throw io::InputError(r.source(), value_pointer(k),
                             "must lie within [min, max] = [" + io::brief(v.min) + ", " +
                                 io::brief(v.max) + "], got " + io::brief(v.values[k]));
      }
    }
  } else {
    v.min = *std::min_element(v.values.begin(), v.values.end());
    v.max = *std::max_element(v.values.begin(), v.values.end());
  }
  const auto points = r.number("points");
  if (points && !(*points >= 1 && *points <= kMaxGridPoints && *points == std::floor(*points))) {
    r.fail("points", "must be a whole number in [1, 1e7], got " + io::brief(*points));
  }
  if (v.values.empty())
    v.values = linspace(v.min, v.max, points ? static_cast<int>(*points) : grid_points);
  const auto start = r.number("start");
  if (start && !(*start >= v.min && *start <= v.max)) {
    r.fail("start", "must lie within [min, max] = [" + io::brief(v.min) + ", " + io::brief(v.max) +
                        "], got " + io::brief(*start));
  }
  v.start =
      start ? *start : (current >= v.min && current <= v.max ? current : 0.5 * (v.min + v.max));
  r.finish({"path", "min", "max", "start", "points", "values"});
  return v;
}

ObjectiveTerm read_term(io::ObjectReader& r, bool allow_spread) {
  ObjectiveTerm term;
  term.output = read_output_name(r, "output");
  const auto goal = r.string("goal").value_or("minimize");
  if (goal == "minimize")
    term.goal = Goal::kMinimize;
  else if (goal == "maximize")
    term.goal = Goal::kMaximize;
  else if (goal == "target")
    term.goal = Goal::kTarget;
  else
    r.fail("goal", "expected \"minimize\", \"maximize\" or \"target\", got \"" + goal + "\"");
  const auto target = r.number("target");
  if (term.goal == Goal::kTarget && !target) r.fail("", "goal \"target\" needs a \"target\" value");
  if (term.goal != Goal::kTarget && target) r.fail("target", "only goal \"target\" takes a target");
  term.target = target.value_or(0.0);
  term.weight = r.number("weight").value_or(1.0);
  if (!(term.weight > 0)) r.fail("weight", "must be > 0, got " + io::brief(term.weight));
  std::vector<std::string> keys{"output", "goal", "target", "weight"};
  if (allow_spread) keys.insert(keys.end(), {"over_impacts", "terms"});
  r.finish(keys);
  return term;
}

ImpactSpread read_spread(io::ObjectReader& r) {
  ImpactSpread spread;
  const io::Json* range = r.child("from_tip_m");
  if (!range || !range->is_array() || range->size() != 2 || !(*range)[0].is_number() ||
      !(*range)[1].is_number()) {
    r.fail("from_tip_m", "expected [nearest, farthest] impact distances from the tip in m");
  }
  spread.from_tip_lo_m = (*range)[0].get<double>();
  spread.from_tip_hi_m = (*range)[1].get<double>();
  if (!(spread.from_tip_lo_m >= 0)) {
    throw io::InputError(
        r.source(), r.pointer() + "/from_tip_m/0",
        "the nearest impact must be >= 0 m from the tip, got " + io::brief((*range)[0]) + " m");
  }
  if (!(spread.from_tip_lo_m < spread.from_tip_hi_m)) {
    throw io::InputError(r.source(), r.pointer() + "/from_tip_m/1",
                         "the farthest impact must be farther from the tip than the nearest (" +
                             io::brief((*range)[0]) + " m), got " + io::brief((*range)[1]) + " m");
  }
  const double points = r.number("points").value_or(8);
  if (!(points >= 2 && points <= 1000 && points == std::floor(points))) {
    r.fail("points", "must be a whole number in [2, 1000], got " + io::brief(points));
  }
  spread.points = static_cast<int>(points);
  const auto reduce = r.string("reduce").value_or("max");
  if (reduce == "max")
    spread.reduce = ImpactSpread::Reduce::kMax;
  else if (reduce == "mean")
    spread.reduce = ImpactSpread::Reduce::kMean;
  else
    r.fail("reduce", "expected \"max\" or \"mean\", got \"" + reduce + "\"");
  r.finish({"from_tip_m", "points", "reduce"});
  return spread;
}

double term_value(const ObjectiveTerm& term, const Evaluation& e) {
  const auto value = term.output->value(e);
  if (!value) return kPenalty;
  switch (term.goal) {
    case Goal::kMinimize:
      return term.weight * *value;
    case Goal::kMaximize:
      return -term.weight * *value;
    case Goal::kTarget:
      return term.weight * (*value - term.target) * (*value - term.target);
  }
  return kPenalty;
}

}  // namespace

double terms_value(const Study& study, const Evaluation& e) {
  double sum = 0.0;
  for (const ObjectiveTerm& term : study.objective) sum += term_value(term, e);
  return sum;
}

namespace {

// What the steps of read_study share: the study being filled, the reader of
// the study file's top level and the file's name for messages.
struct StudyReading {
  Study& study;
  io::ObjectReader& top;
  const std::string& source;
};

void read_names(StudyReading& in) {
  in.study.name = in.top.string("name").value_or(in.source);
  in.study.question = in.top.string("question").value_or("");
  in.top.string("description");
  in.top.string("$schema");
}

// The design, a file path (relative to the study's folder) or inline; true
// when the design gives no impact (the default impact applies).
bool read_design_reference(StudyReading& in, const std::string& folder) {
  Study& study = in.study;
  const io::Json* design = in.top.child("design");
  if (!design) in.top.fail("design", "missing: a design file path or an inline design");
  if (design->is_string()) {
    const std::string path = (std::filesystem::path(folder) / design->get<std::string>()).string();
    try {
      study.design_document = io::read_json_file(path);
    } catch (const io::InputError& e) {
      throw io::InputError(in.source, "/design",
                           "cannot read the design: " + std::string(e.what()));
    }
    study.design_source = path;
  } else if (design->is_object()) {
    study.design_document = *design;
    study.design_source = in.source + " (inline design)";
  } else {
    in.top.fail("design", "expected a path or an inline design object, got " + io::brief(*design));
  }
  // The design must be valid as written.
  const io::DesignFile as_written = io::read_design(study.design_document, study.design_source);
  const auto impact = as_written.provenance.find("impact/from_butt_m");
  return impact != as_written.provenance.end() && impact->second.starts_with("default");
}

int read_grid_points(StudyReading& in) {
  int grid_points = kDefaultGridPoints;
  if (const io::Json* grid = in.top.child("grid")) {
    io::ObjectReader g(*grid, "/grid", "grid", in.source, nullptr);
    const auto points = g.number("points");
    if (points && !(*points >= 1 && *points <= kMaxGridPoints && *points == std::floor(*points))) {
      g.fail("points", "must be a whole number in [1, 1e7], got " + io::brief(*points));
    }
    if (points) grid_points = static_cast<int>(*points);
    g.finish({"points"});
  }
  return grid_points;
}

void read_variables(StudyReading& in, int grid_points) {
  Study& study = in.study;
  const io::Json& variables = array_at(in.top, "variables", true);
  if (variables.empty()) in.top.fail("variables", "expected at least one variable");
  if (variables.size() > 64)
    in.top.fail("variables", "at most 64 variables, got " + std::to_string(variables.size()));
  for (std::size_t i = 0; i < variables.size(); ++i) {
    io::ObjectReader r(variables[i], "/variables/" + std::to_string(i), "", in.source, nullptr);
    study.variables.push_back(read_variable(r, study.design_document, grid_points));
    for (std::size_t j = 0; j < i; ++j) {
      if (study.variables[j].pointer == study.variables[i].pointer) {
        r.fail("path", "repeats /variables/" + std::to_string(j) + "/path");
      }
    }
  }
  // The grid a sweep walks (its first two variables) must be finite in time.
  double total = 1.0;
  for (std::size_t i = 0; i < std::min<std::size_t>(2, study.variables.size()); ++i) {
    total *= static_cast<double>(study.variables[i].values.size());
  }
  if (total > kMaxGridTotal) {
    in.top.fail("variables", "a grid of " + io::brief(total) + " points is more than 1e8");
  }
}

std::optional<ImpactSpread> read_over_impacts(io::ObjectReader& r, const std::string& source) {
  const io::Json* spread = r.child("over_impacts");
  if (!spread) return std::nullopt;
  io::ObjectReader s(*spread, "/objective/over_impacts", "", source, nullptr);
  return read_spread(s);
}

// The objective: one term, or "terms" summed; either over a spread of impacts.
void read_objective(StudyReading& in) {
  Study& study = in.study;
  const io::Json* objective = in.top.child("objective");
  if (!objective) return;
  io::ObjectReader r(*objective, "/objective", "", in.source, nullptr);
  if (r.has("terms")) {
    const io::Json& terms = array_at(r, "terms", true);
    if (terms.empty()) r.fail("terms", "expected at least one term");
    for (std::size_t i = 0; i < terms.size(); ++i) {
      io::ObjectReader t(terms[i], "/objective/terms/" + std::to_string(i), "", in.source, nullptr);
      study.objective.push_back(read_term(t, false));
    }
    study.over_impacts = read_over_impacts(r, in.source);
    r.finish({"terms", "over_impacts"});
  } else {
    study.over_impacts = read_over_impacts(r, in.source);
    study.objective.push_back(read_term(r, true));
  }
  if (!study.over_impacts) return;
  for (std::size_t i = 0; i < study.variables.size(); ++i) {
    if (study.variables[i].pointer.starts_with("/impact")) {
      throw io::InputError(
          in.source, "/variables/" + std::to_string(i) + "/path",
          "the impact point cannot be a variable of a study over a spread of impacts");
    }
  }
}

StudyConstraint read_constraint(io::ObjectReader& r) {
  StudyConstraint c;
  c.output = read_output_name(r, "output");
  c.min = r.number("min");
  c.max = r.number("max");
  c.equals = r.number("equals");
  if (!c.min && !c.max && !c.equals) r.fail("", "give \"min\", \"max\" or \"equals\"");
  if (c.equals && (c.min || c.max)) r.fail("equals", "give either \"equals\" or \"min\"/\"max\"");
  if (c.min && c.max && !(*c.min <= *c.max)) {
    r.fail("min", "must be <= max, got min " + io::brief(*c.min) + " and max " + io::brief(*c.max));
  }
  c.tolerance = r.number("tolerance");
  if (c.tolerance && !(*c.tolerance > 0))
    r.fail("tolerance", "must be > 0, got " + io::brief(*c.tolerance));
  r.finish({"output", "min", "max", "equals", "tolerance"});
  return c;
}

void read_constraints(StudyReading& in) {
  const io::Json& constraints = array_at(in.top, "constraints", false);
  for (std::size_t i = 0; i < constraints.size(); ++i) {
    io::ObjectReader r(constraints[i], "/constraints/" + std::to_string(i), "", in.source, nullptr);
    in.study.constraints.push_back(read_constraint(r));
  }
}

void read_tolerances(StudyReading& in) {
  optimizer::OptimizeOptions& o = in.study.options;
  const io::Json* tolerances = in.top.child("tolerances");
  if (!tolerances) return;
  io::ObjectReader t(*tolerances, "/tolerances", "", in.source, nullptr);
  const auto positive = [&](std::string_view key, double fallback) {
    const auto value = t.number(key);
    if (value && !(*value > 0)) t.fail(key, "must be > 0, got " + io::brief(*value));
    return value.value_or(fallback);
  };
  o.x_tolerance_rel = positive("x_rel", o.x_tolerance_rel);
  o.f_tolerance_rel = positive("f_rel", o.f_tolerance_rel);
  o.max_seconds = positive("max_seconds", o.max_seconds);
  if (const auto max_evaluations = t.number("max_evaluations")) {
    if (!(*max_evaluations >= 1 && *max_evaluations <= 1e9 &&
          *max_evaluations == std::floor(*max_evaluations))) {
      t.fail("max_evaluations",
             "must be a whole number in [1, 1e9], got " + io::brief(*max_evaluations));
    }
    o.max_evaluations = static_cast<int>(*max_evaluations);
  }
  t.finish({"x_rel", "f_rel", "max_evaluations", "max_seconds"});
  if (const std::string why = o.validate(); !why.empty()) {
    throw io::InputError(in.source, "/tolerances", why);
  }
}

// The optimiser's algorithm, local algorithm, seed and tolerances.
void read_algorithm_options(StudyReading& in) {
  optimizer::OptimizeOptions& o = in.study.options;
  if (const auto algorithm = in.top.string("algorithm")) o.algorithm = *algorithm;
  if (!optimizer::is_known_algorithm(o.algorithm)) {
    in.top.fail("algorithm",
                "unknown algorithm \"" + o.algorithm +
                    "\" (auto, or an NLopt name such as LD_SLSQP, LN_COBYLA, GN_ISRES)");
  }
  if (const auto local = in.top.string("local_algorithm")) o.local_algorithm = *local;
  if (!optimizer::is_known_algorithm(o.local_algorithm)) {
    in.top.fail("local_algorithm", "unknown algorithm \"" + o.local_algorithm + "\"");
  }
  if (const auto seed = in.top.number("seed")) {
    if (!(*seed >= 0 && *seed <= 4294967295.0 && *seed == std::floor(*seed))) {
      in.top.fail("seed", "must be a whole number in [0, 4294967295], got " + io::brief(*seed));
    }
    o.seed = static_cast<unsigned long>(*seed);
  }
  read_tolerances(in);
}

// The outputs a sweep writes.
void read_sweep_outputs(StudyReading& in, bool default_impact) {
  Study& study = in.study;
  const io::Json& outputs = array_at(in.top, "outputs", false);
  for (std::size_t i = 0; i < outputs.size(); ++i) {
    const std::string at = "/outputs/" + std::to_string(i);
    if (!outputs[i].is_string() || !io::find_output(outputs[i].get<std::string>())) {
      throw io::InputError(
          in.source, at,
          "expected the name of an output of sweetspot evaluate, got " + io::brief(outputs[i]));
    }
    const io::OutputSpec* output = io::find_output(outputs[i].get<std::string>());
    // Each output once, as each variable's path once: a repeat is a column twice.
    const auto seen = std::find(study.sweep_outputs.begin(), study.sweep_outputs.end(), output);
    if (seen != study.sweep_outputs.end()) {
      throw io::InputError(in.source, at,
                           "repeats /outputs/" +
                               std::to_string(seen - study.sweep_outputs.begin()) + " (" +
                               io::brief(outputs[i]) + "): give each output once");
    }
    study.sweep_outputs.push_back(output);
  }
  // A sweep of a design that gives no impact says where the default hit.
  const io::OutputSpec* impact_output = io::find_output("impact_from_tip_m");
  if (default_impact && !study.sweep_outputs.empty() &&
      std::find(study.sweep_outputs.begin(), study.sweep_outputs.end(), impact_output) ==
          study.sweep_outputs.end()) {
    study.sweep_outputs.push_back(impact_output);
  }
}

// Every output the study asks for: swept, in the objective, constrained.
std::vector<const io::OutputSpec*> outputs_used(const Study& study) {
  std::vector<const io::OutputSpec*> used = study.sweep_outputs;
  for (const ObjectiveTerm& t : study.objective) used.push_back(t.output);
  for (const StudyConstraint& c : study.constraints) used.push_back(c.output);
  return used;
}

// "auto": the cheapest model that answers the design and every output used.
Fidelity auto_fidelity(const Study& study) {
  Fidelity fidelity =
      needed_fidelity(io::read_design(study.design_document, study.design_source).design);
  for (const io::OutputSpec* o : outputs_used(study)) {
    if (o->needs_response && fidelity != Fidelity::kCollision) fidelity = Fidelity::kResponse;
    if (o->needs_modes && fidelity == Fidelity::kRigid) fidelity = Fidelity::kModal;
  }
  return fidelity;
}

void read_fidelity(StudyReading& in) {
  Study& study = in.study;
  const std::string fidelity = in.top.string("fidelity").value_or("auto");
  std::optional<Fidelity> asked;
  try {
    asked = parse_fidelity(fidelity);
  } catch (const std::invalid_argument& e) {
    in.top.fail("fidelity", e.what());
  }
  study.fidelity = asked ? *asked : auto_fidelity(study);
  for (const io::OutputSpec* o : outputs_used(study)) {
    const bool too_low = (o->needs_response && study.fidelity != Fidelity::kResponse &&
                          study.fidelity != Fidelity::kCollision) ||
                         (o->needs_modes && study.fidelity == Fidelity::kRigid);
    if (too_low) {
      in.top.fail("fidelity", "\"" + fidelity + "\" cannot give " + std::string(o->name) +
                                  "; use \"auto\" or a higher fidelity");
    }
  }
  if (const auto tolerance = in.top.number("modal_tolerance")) {
    if (!(*tolerance >= kMinRelTol && *tolerance <= kMaxRelTol)) {
      in.top.fail("modal_tolerance", "must be in [1e-08, 0.1], got " + io::brief(*tolerance));
    }
    study.modal_tolerance = *tolerance;
  }
}

// The start must be a valid design the study's model evaluates, and every
// impact of a spread must hit the implement there (an impact off it has no
// value and would only ever be the optimizer's penalty).
void check_start(const Study& study, const std::string& source) {
  std::vector<double> start;
  for (const StudyVariable& v : study.variables) start.push_back(v.start);
  io::DesignFile at_start = [&] {
    try {
      return design_at(study, start);
    } catch (const io::InputError& e) {
      throw io::InputError(source, "/variables",
                           "the start point is not a valid design: " + std::string(e.what()));
    }
  }();
  try {
    try {
      evaluate_in(study, at_start);
    } catch (const std::invalid_argument& e) {
      io::rethrow_in(at_start, e);
    }
  } catch (const io::InputError& e) {
    // A start the model cannot answer (a ball squeezed past its radius at the
    // start's speed) is the study's to move: its variables' start.
    if (!e.model_refused()) throw;
    throw io::InputError(source, "/variables",
                         "the model cannot answer the start point: " + std::string(e.what()) +
                             "; give each variable a start it answers");
  }
  if (!study.over_impacts) return;
  const double length_m = at_start.design.implement.length_m();
  if (study.over_impacts->from_tip_hi_m > length_m) {
    throw io::InputError(source, "/objective/over_impacts/from_tip_m/1",
                         "the farthest impact, " + io::brief(study.over_impacts->from_tip_hi_m) +
                             " m from the tip, is off the implement, which is " +
                             io::brief(length_m) + " m long (at the start); expected at most " +
                             io::brief(length_m) + " m");
  }
}

// The design compiled for fast evaluation at the variables' pointers, when it can be.
void compile_design(Study& study) {
  std::vector<std::string> pointers;
  for (const StudyVariable& v : study.variables) pointers.push_back(v.pointer);
  if (auto compiled = CompiledDesign::compile(
          io::describe_design(study.design_document, study.design_source), pointers)) {
    study.compiled = std::make_shared<const CompiledDesign>(std::move(*compiled));
  }
}

}  // namespace

Study read_study(const io::Json& document, const std::string& source, const std::string& folder) {
  Study study;
  study.source = source;
  io::ObjectReader top(document, "", "", source, nullptr);
  StudyReading in{study, top, source};
  read_names(in);
  const bool default_impact = read_design_reference(in, folder);
  read_variables(in, read_grid_points(in));
  read_objective(in);
  read_constraints(in);
  read_algorithm_options(in);
  read_sweep_outputs(in, default_impact);
  read_fidelity(in);
  top.finish({"$schema", "name", "question", "description", "design", "variables", "objective",
              "constraints", "algorithm", "local_algorithm", "seed", "tolerances", "grid",
              "outputs", "fidelity", "modal_tolerance"});
  check_start(study, source);
  compile_design(study);
  return study;
}

Study load_study(const std::string& path) {
  const std::string folder = std::filesystem::path(path).parent_path().string();
  return read_study(io::read_json_file(path), io::input_name(path), folder.empty() ? "." : folder);
}

Evaluation evaluate_in(const Study& study, const io::DesignFile& design) {
  return evaluate_in(study, design.design);
}

Evaluation evaluate_in(const Study& study, const Design& design) {
  return evaluate(design, study.fidelity,
                  {.rel_tol = study.modal_tolerance, .modes = &thread_mode_cache()});
}

bool compiled_for_variables(const Study& study) {
  if (!study.compiled || study.compiled->bindings().size() != study.variables.size()) return false;
  for (std::size_t i = 0; i < study.variables.size(); ++i) {
    if (study.compiled->bindings()[i].pointer != study.variables[i].pointer) return false;
  }
  return true;
}

io::Json document_at(const Study& study, std::span<const double> x) {
  io::Json document = study.design_document;
  for (std::size_t i = 0; i < study.variables.size(); ++i) {
    document[io::Json::json_pointer(study.variables[i].pointer)] = x[i];
  }
  return document;
}

io::DesignFile design_at(const Study& study, std::span<const double> x) {
  return io::read_design(document_at(study, x), study.design_source);
}

namespace {

// Impact k of a spread, from the tip.
double spread_from_tip(const ImpactSpread& spread, int k) {
  return spread.from_tip_lo_m +
         (spread.from_tip_hi_m - spread.from_tip_lo_m) * k / (spread.points - 1);
}

// Impact k of a spread, from the butt of an implement `length_m` long.
double spread_from_butt(const ImpactSpread& spread, double length_m, int k) {
  return length_m - spread_from_tip(spread, k);
}

}  // namespace

std::optional<std::string> terms_undefined(const Study& study, const Evaluation& e) {
  for (const ObjectiveTerm& term : study.objective) {
    if (!term.output->value(e)) {
      return std::string(term.output->name) +
             " has no finite value (the physics puts it at infinity)";
    }
  }
  return std::nullopt;
}

double tolerance_at(const StudyConstraint& c, double limit) {
  return c.tolerance ? *c.tolerance : kDefaultConstraintTolerance * std::max(1.0, std::abs(limit));
}

std::optional<std::string> objective_undefined(const Study& study, const io::DesignFile& design) {
  try {
    if (!study.over_impacts) return terms_undefined(study, evaluate_in(study, design));
    const ImpactSpread& spread = *study.over_impacts;
    Design d = design.design;
    const double L = d.implement.length_m();
    for (int k = 0; k < spread.points; ++k) {
      const double x = spread_from_butt(spread, L, k);
      if (!(x >= 0.0 && x <= L)) {
        return "the impact " + io::brief(spread_from_tip(spread, k)) +
               " m from the tip is off the implement, which is " + io::brief(L) + " m long";
      }
      d.impact_from_butt_m = x;
      if (auto why = terms_undefined(
              study, evaluate(d, study.fidelity,
                              {.rel_tol = study.modal_tolerance, .modes = &thread_mode_cache()})))
        return why;
    }
  } catch (const std::invalid_argument& e) {
    return std::string(e.what());
  }
  return std::nullopt;
}

double objective_of(const Study& study, const io::DesignFile& design) {
  return objective_of(study, design.design);
}

double objective_of(const Study& study, const Design& design) {
  if (!study.over_impacts) return terms_value(study, evaluate_in(study, design));
  const ImpactSpread& spread = *study.over_impacts;
  Design d = design;
  const double L = d.implement.length_m();
  const auto from_butt = [&](int k) { return spread_from_butt(spread, L, k); };
  // The rigid model at many impacts shares everything but the impact (ImpactSweep).
  std::optional<ImpactSweep> rigid;
  if (study.fidelity == Fidelity::kRigid && impact_sweep_answers(d)) rigid.emplace(d);
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
          value = terms_value(
              study, evaluate(d, study.fidelity,
                              {.rel_tol = study.modal_tolerance, .modes = &thread_mode_cache()}));
        } catch (const std::invalid_argument&) {
        }
      }
    }
    reduced = spread.reduce == ImpactSpread::Reduce::kMax ? std::max(reduced, value)
                                                          : reduced + value / spread.points;
  }
  return reduced;
}

// Minimising a non-negative output with a kink where its signed form changes
// sign (|F_w|) is minimising its square, which is smooth there: gradient
// methods then apply. The reported objective is the output itself.

}  // namespace sweetspot::studies
