#include "reports/optimization_report.hpp"

#include <cmath>

#include <fmt/format.h>

namespace sweetspot::io {
namespace {

// A target met to this fraction counts as reached.
constexpr double kTargetReached = 1e-4;

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

}  // namespace sweetspot::io
