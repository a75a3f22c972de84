#pragma once

// Study files: what to change (design fields addressed by JSON pointer, with
// bounds), what to minimise, under which constraints; run as an optimisation
// (`sweetspot optimize`) or as a grid of what-ifs (`sweetspot sweep`).
// The format is documented in docs/studies.md.

#include <memory>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include "io/design_reader.hpp"
#include "io/outputs.hpp"
#include "optimizer/optimize.hpp"
#include "sweetspot/evaluate.hpp"

namespace sweetspot::studies {

class CompiledDesign;

// Stands in for an output the physics puts at infinity (or a design a
// variable made invalid) inside an objective or constraint: large, finite.
inline constexpr double kPenalty = 1e12;

struct StudyVariable {
  std::string pointer;  // JSON pointer into the design, e.g. "/implement/mass_kg"
  double min = 0.0;
  double max = 0.0;
  double start = 0.0;  // "start", else the design's value if inside the bounds, else the middle
  std::vector<double> values;  // sweep: the grid along this variable
};

enum class Goal { kMinimize, kMaximize, kTarget };

struct ObjectiveTerm {
  const io::OutputSpec* output = nullptr;
  Goal goal = Goal::kMinimize;
  double target = 0.0;  // for kTarget: the term is weight * (value - target)^2
  double weight = 1.0;
};

// Players do not hit one point: evaluate the objective at `points` impacts
// evenly spread from `from_tip_lo_m` to `from_tip_hi_m` and reduce.
struct ImpactSpread {
  double from_tip_lo_m = 0.0;
  double from_tip_hi_m = 0.0;
  int points = 2;
  enum class Reduce { kMax, kMean } reduce = Reduce::kMax;
};

// A constraint's default tolerance, relative to its limit: 1e-6 max(1, |limit|).
inline constexpr double kDefaultConstraintTolerance = 1e-6;

struct StudyConstraint {
  const io::OutputSpec* output = nullptr;
  std::optional<double> min, max, equals;
  // How far outside a limit still counts as on it, in the output's unit;
  // std::nullopt: kDefaultConstraintTolerance max(1, |limit|) for each limit.
  std::optional<double> tolerance;
};

// The tolerance `c` is judged by at `limit` (one of its min, max, equals).
double tolerance_at(const StudyConstraint& c, double limit);

struct Study {
  std::string source;  // the study file
  std::string name;
  std::string question;      // optional: the question in a coach's words
  io::Json design_document;  // the design as written, variables set by pointer
  std::string design_source;
  std::vector<StudyVariable> variables;
  std::vector<ObjectiveTerm> objective;
  std::optional<ImpactSpread> over_impacts;
  std::vector<StudyConstraint> constraints;
  optimizer::OptimizeOptions options;
  std::vector<const io::OutputSpec*> sweep_outputs;  // outputs a sweep writes
  // The model every evaluation uses: "fidelity" rigid, modal or auto (the
  // default: modal exactly when an objective, constraint or swept output needs
  // the modes), and the hand-held modes' relative frequency error.
  Fidelity fidelity = Fidelity::kRigid;
  double modal_tolerance = 1e-6;
  // The design with the variables bound (design_binding.hpp), compiled when
  // the study is read: evaluations set numbers on a typed design instead of
  // reading the JSON again. Null when a variable cannot be bound.
  std::shared_ptr<const CompiledDesign> compiled;
};

// Whether the study's compiled design binds exactly its variables, in order.
bool compiled_for_variables(const Study& study);

// Evaluates `design` with the study's fidelity. Throws like evaluate().
Evaluation evaluate_in(const Study& study, const io::DesignFile& design);
Evaluation evaluate_in(const Study& study, const Design& design);

// Reads a study file; `design` paths are relative to the study's folder.
// Throws InputError naming the study file and the JSON path.
Study load_study(const std::string& path);
Study read_study(const io::Json& document, const std::string& source, const std::string& folder);

// The study's design document with the variables set to x (the numbers at
// their pointers, nothing else changed): what design_at() reads.
io::Json document_at(const Study& study, std::span<const double> x);

// The design with the variables set to x. Throws InputError when x makes it invalid.
io::DesignFile design_at(const Study& study, std::span<const double> x);

// The objective (to minimise) of a design: the weighted terms, reduced over
// the impact spread when the study has one.
double objective_of(const Study& study, const io::DesignFile& design);
double objective_of(const Study& study, const Design& design);

// The study's objective terms for one evaluation (kPenalty for an output at infinity).
double terms_value(const Study& study, const Evaluation& evaluation);

// Why the study's objective has no value for `design` (a model that refuses
// it, an output at infinity, an impact of the spread off the implement), or
// std::nullopt when it has one. Where objective_of returns kPenalty, this
// says why; a penalty is never a result.
std::optional<std::string> objective_undefined(const Study& study, const io::DesignFile& design);
// The same for a study without an impact spread, from the design's
// evaluation at the study's fidelity (its objective is a function of it).
std::optional<std::string> terms_undefined(const Study& study, const Evaluation& evaluation);

}  // namespace sweetspot::studies
