#include "reports/optimization_report.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <vector>

#include "io/format.hpp"
#include "reports/html_page.hpp"
#include "reports/html_report.hpp"

namespace sweetspot::reports {
namespace {

// A target met to this fraction counts as reached.
constexpr double kTargetReached = 1e-4;

std::string bound_hit(const studies::StudyVariable& v, double x) {
  const double slack = 1e-6 * (v.max - v.min);
  return x <= v.min + slack ? "min" : x >= v.max - slack ? "max" : "";
}

std::string goal_phrase(const studies::ObjectiveTerm& term) {
  switch (term.goal) {
    case studies::Goal::kMinimize:
      return "lowest";
    case studies::Goal::kMaximize:
      return "highest";
    case studies::Goal::kTarget:
      return fmt::format("closest to {}", io::significant(term.target));
  }
  return "";
}

const char* outcome_name(studies::Outcome outcome) {
  switch (outcome) {
    case studies::Outcome::kOptimum:
      return "optimum";
    case studies::Outcome::kInfeasible:
      return "infeasible";
    case studies::Outcome::kNoValue:
      return "no_value";
  }
  return "";
}

std::optional<double> output_value(const io::OutputSpec& o, const std::optional<Evaluation>& e) {
  return e ? o.value(*e) : std::nullopt;
}

std::string with_unit(double value, std::string_view unit, int digits = 6) {
  return unit.empty() ? io::significant(value, digits)
                      : io::significant(value, digits) + " " + std::string(unit);
}

// "`swingweight_kg_cm2 <= 100` is 234 kg cm^2, outside its limit by 134 (tolerance 0.0001)".
std::string violated(const studies::ConstraintReport& c) {
  if (!c.value) return fmt::format("`{}` has no value", c.name);
  return fmt::format("`{}` is {}, outside its limit by {} (tolerance {})", c.name,
                     with_unit(*c.value, c.unit, 4), io::significant(c.violation, 4),
                     io::significant(c.tolerance));
}

// The answer in sentences, names of outputs and paths in backticks: the
// answer itself, then (when a target is out of reach) a note saying so.
std::vector<std::string> answer_paragraphs(const studies::Study& study,
                                           const studies::OptimizationResult& r) {
  const std::optional<Evaluation>& start = r.start_outputs;
  const std::optional<Evaluation>& best = r.best_outputs;
  const studies::ObjectiveTerm& lead = study.objective.front();
  std::string changes;
  for (std::size_t i = 0; i < study.variables.size(); ++i) {
    const studies::StudyVariable& v = study.variables[i];
    const double x = r.summary.x[i];
    const std::string hit = bound_hit(v, x);
    // In the unit the file writes the variable in, read from its key.
    const std::string_view unit = io::unit_of_key(v.pointer.substr(v.pointer.rfind('/') + 1));
    changes += fmt::format("{}`{}` = {}{}{}{}", changes.empty() ? "" : ", ", v.pointer,
                           io::significant(x, 4), unit.empty() ? "" : " ", unit,
                           hit == "min"   ? " (its lower bound)"
                           : hit == "max" ? " (its upper bound)"
                                          : "");
  }
  std::string active;
  for (const studies::ConstraintReport& c : r.constraints) {
    if (c.active) active += (active.empty() ? "" : ", ") + c.name;
  }
  const auto best_lead = output_value(*lead.output, best);
  const auto start_lead = output_value(*lead.output, start);
  const std::string spread =
      study.over_impacts
          ? fmt::format(" ({} over impacts {}–{} m from the tip)",
                        study.over_impacts->reduce == studies::ImpactSpread::Reduce::kMax
                            ? "worst case"
                            : "mean",
                        io::significant(study.over_impacts->from_tip_lo_m),
                        io::significant(study.over_impacts->from_tip_hi_m))
          : std::string();
  // The lead output at the best design and at the start: over a spread of
  // impacts, the objective turned back into the output (a maximised output
  // is minimised as its negative; a weight divided out), as the sentence names
  // it; with several terms or a target, the objective itself.
  const auto over_spread = [&](double objective) {
    if (study.objective.size() != 1 || lead.goal == studies::Goal::kTarget)
      return io::significant(objective, 4);
    const double sign = lead.goal == studies::Goal::kMaximize ? -1.0 : 1.0;
    return io::significant(sign * objective / lead.weight, 4);
  };
  const std::string best_text = study.over_impacts
                                    ? over_spread(r.summary.objective)
                                    : (best_lead ? io::significant(*best_lead, 4) : "—");
  const std::string start_text =
      study.over_impacts ? (r.start_objective ? over_spread(*r.start_objective) : "no value")
                         : (start_lead ? io::significant(*start_lead, 4) : "no value");
  std::vector<std::string> paragraphs(1);
  std::string& answer = paragraphs.front();
  switch (r.outcome) {
    case studies::Outcome::kOptimum:
      answer = fmt::format(
          "The {} `{}`{} is {} {} (the starting design gives {}), with {}.{}", goal_phrase(lead),
          lead.output->name, spread, best_text, lead.output->unit, start_text, changes,
          active.empty() ? " No constraint is active." : " Active constraints: " + active + ".");
      break;
    case studies::Outcome::kInfeasible: {
      std::string broken;
      for (const studies::ConstraintReport& c : r.constraints) {
        if (!c.satisfied) broken += (broken.empty() ? "" : "; ") + violated(c);
      }
      answer = fmt::format(
          "No design meets the constraints; the least violating one is {}, where {}. "
          "Its `{}`{} is {} {} (the starting design gives {}).",
          changes, broken, lead.output->name, spread, best_text, lead.output->unit, start_text);
      break;
    }
    case studies::Outcome::kNoValue:
      answer = fmt::format(
          "No valid design was found: no design the search reached gives `{}`{} a "
          "value. At the last one it kept, {}, {}.",
          lead.output->name, spread, changes, r.no_value);
      break;
  }
  if (r.outcome == studies::Outcome::kOptimum && lead.goal == studies::Goal::kTarget &&
      study.objective.size() == 1 && !study.over_impacts && best_lead &&
      std::abs(*best_lead - lead.target) > kTargetReached * std::max(1.0, std::abs(lead.target))) {
    paragraphs.push_back(fmt::format(
        "The target {} cannot be reached within the variables' bounds: {} {} is as close as "
        "these designs get.",
        io::significant(lead.target), io::significant(*best_lead, 4), lead.output->unit));
  }
  if (!r.inconsistency.empty()) {
    std::string sentence = r.inconsistency;
    sentence[0] = static_cast<char>(std::toupper(static_cast<unsigned char>(sentence[0])));
    paragraphs.push_back("**Internal error.** " + sentence + ".");
  }
  return paragraphs;
}

}  // namespace

std::string optimization_report(const studies::Study& study, const studies::OptimizationResult& r,
                                io::Format format, bool with_timing) {
  const std::optional<Evaluation>& start = r.start_outputs;
  const std::optional<Evaluation>& best = r.best_outputs;
  const bool has_value = r.outcome != studies::Outcome::kNoValue;

  if (format == io::Format::kJson) {
    io::Json j;
    j["name"] = study.name;
    j["outcome"] = outcome_name(r.outcome);
    if (r.outcome == studies::Outcome::kNoValue) j["no_value_reason"] = r.no_value;
    j["best_design"] = r.best_document;
    if (!r.inconsistency.empty()) j["inconsistency"] = r.inconsistency;
    j["objective_value"] = has_value ? io::Json(r.summary.objective) : io::Json(nullptr);
    j["start_objective_value"] =
        r.start_objective ? io::Json(*r.start_objective) : io::Json(nullptr);
    j["feasible"] = r.outcome == studies::Outcome::kOptimum;
    j["evaluations"] = r.summary.evaluations;
    j["termination"] = r.summary.termination_text();
    j["algorithm"] = r.summary.algorithm;
    j["seconds"] = r.summary.seconds;
    io::Json& variables = j["variables"];
    for (std::size_t i = 0; i < study.variables.size(); ++i) {
      const studies::StudyVariable& v = study.variables[i];
      variables.push_back({{"path", v.pointer},
                           {"min", v.min},
                           {"max", v.max},
                           {"start", r.start_x[i]},
                           {"best", r.summary.x[i]},
                           {"at_bound", bound_hit(v, r.summary.x[i])}});
    }
    j["constraints"] = io::Json::array();
    for (const studies::ConstraintReport& c : r.constraints) {
      j["constraints"].push_back(
          {{"constraint", c.name},
           {"value", c.value ? io::Json(*c.value) : io::Json(nullptr)},
           {"limit", c.limit},
           {"tolerance", c.tolerance},
           {"violation", c.value ? io::Json(c.violation) : io::Json(nullptr)},
           {"satisfied", c.satisfied},
           {"active", c.active}});
    }
    for (const io::OutputSpec& o : io::output_specs()) {
      const auto a = output_value(o, start), b = output_value(o, best);
      j["outputs_start"][std::string(o.name)] = a ? io::Json(*a) : io::Json(nullptr);
      j["outputs_best"][std::string(o.name)] = b ? io::Json(*b) : io::Json(nullptr);
    }
    return j.dump(2, ' ', false, io::Json::error_handler_t::replace) + "\n";
  }
  if (format == io::Format::kCsv) {
    std::string csv = "output,start,best\n";
    for (const io::OutputSpec& o : io::output_specs()) {
      const auto a = output_value(o, start), b = output_value(o, best);
      csv += fmt::format("{},{},{}\n", o.name, a ? io::exact(*a) : "", b ? io::exact(*b) : "");
    }
    return csv;
  }
  // Markdown: the answer in a sentence, then the numbers.
  std::string md = fmt::format("# {}\n\n", io::md_cell(study.name));
  if (!study.question.empty()) md += "**Question.** " + io::terminal_text(study.question) + "\n\n";
  const std::vector<std::string> answer = answer_paragraphs(study, r);
  md += "**Answer.** " + io::terminal_text(answer.front()) + "\n\n";
  for (std::size_t k = 1; k < answer.size(); ++k) md += io::terminal_text(answer[k]) + "\n\n";
  md += "## Variables\n\n| path | min | max | start | best |\n|---|---:|---:|---:|---:|\n";
  for (std::size_t i = 0; i < study.variables.size(); ++i) {
    const studies::StudyVariable& v = study.variables[i];
    md += fmt::format("| `{}` | {} | {} | {} | {} |\n", v.pointer, io::significant(v.min),
                      io::significant(v.max), io::significant(r.start_x[i]),
                      io::significant(r.summary.x[i]));
  }
  if (!r.constraints.empty()) {
    md +=
        "\n## Constraints\n\nA constraint is met when its value lies within its tolerance of the "
        "limit (the "
        "study's, or 10⁻⁶ of the limit's size, at least 10⁻⁶).\n\n"
        "| constraint | value at the best design | tolerance | outside the limit by | satisfied | "
        "active |\n"
        "|---|---:|---:|---:|---|---|\n";
    for (const studies::ConstraintReport& c : r.constraints) {
      md += fmt::format("| `{}` | {} | {} | {} | {} | {} |\n", c.name,
                        c.value ? io::significant(*c.value) : "—", io::significant(c.tolerance),
                        c.value ? io::significant(c.violation) : "—",
                        c.satisfied ? "yes" : "**no**", c.active ? "yes" : "no");
    }
  }
  md += fmt::format(
      "\n## Search\n\nObjective (minimised form) {} after {} evaluations; {}; termination: "
      "{}.{}\n",
      has_value ? io::significant(r.summary.objective) : std::string("—"), r.summary.evaluations,
      r.summary.algorithm, r.summary.termination_text(),
      with_timing ? fmt::format(" Wall time {:.2f} ms.", r.summary.seconds * 1e3) : std::string());
  md +=
      "\n## Outputs, start and optimum\n\n| output | start | optimum | unit "
      "|\n|---|---:|---:|---|\n";
  for (const io::OutputSpec& o : io::output_specs()) {
    const auto a = output_value(o, start), b = output_value(o, best);
    md += fmt::format("| `{}` | {} | {} | {} |\n", o.name, a ? io::significant(*a) : "—",
                      b ? io::significant(*b) : "—", o.unit);
  }
  md += std::string(r.outcome == studies::Outcome::kOptimum ? "\nThe best design"
                    : r.outcome == studies::Outcome::kInfeasible
                        ? "\nThe least violating design"
                        : "\nThe last design the search kept") +
        " as a design file (`sweetspot evaluate` accepts it):\n\n```json\n" +
        r.best_document.dump(2, ' ', false, io::Json::error_handler_t::replace) + "\n```\n";
  return md;
}

io::Plot convergence_plot(const studies::Study& study, const studies::OptimizationResult& r) {
  // One objective term is plotted as the output itself, in its unit: the
  // minimised form of a target is weight (value - target)^2, whose square
  // root is the distance from the target (the COP-node gap, not its square).
  const bool single = study.objective.size() == 1;
  const studies::ObjectiveTerm* term = single ? &study.objective.front() : nullptr;
  const io::AxisQuantity axis = io::output_axis(*study.objective.front().output);
  std::string y_label = "objective (weighted sum of the terms, minimised form)";
  if (single) {
    const std::string over = !study.over_impacts ? ""
                             : study.over_impacts->reduce == studies::ImpactSpread::Reduce::kMax
                                 ? ", the worst of the impacts"
                                 : ", mean over the impacts";
    y_label = term->goal == studies::Goal::kTarget
                  ? fmt::format("{}{}: distance from its target {}{}", axis.label, over,
                                io::significant(term->target * axis.factor),
                                axis.unit.empty() ? "" : " " + axis.unit)
                  : axis.label + over;
  }
  const auto shown = [&](double value) {
    if (!single) return value;
    switch (term->goal) {
      case studies::Goal::kMinimize:
        return value / term->weight * axis.factor;
      case studies::Goal::kMaximize:
        return -value / term->weight * axis.factor;
      case studies::Goal::kTarget:
        return std::sqrt(std::max(0.0, value / term->weight)) * axis.factor;
    }
    return value;
  };
  io::PlotSeries objective{single ? "best so far" : "best objective so far", {}, {}, "lines lw 2"};
  for (std::size_t i = 0; i < r.summary.history.size(); ++i) {
    objective.x.push_back(static_cast<double>(i + 1));
    const double value = r.summary.history[i];
    objective.y.push_back(std::abs(value) < studies::kPenalty / 10 ? std::optional(shown(value))
                                                                   : std::nullopt);
  }
  io::Plot plot{"Convergence: " + study.name,
                "evaluation (including difference gradients)",
                y_label,
                std::nullopt,
                std::nullopt,
                {objective},
                {},
                {}};
  // Where the best-so-far curve is not: it rises when maximising.
  if (single && term->goal == studies::Goal::kMaximize) plot.key_position = "bottom right";
  if (!r.constraints.empty()) {
    // Beside the objective, on its own logarithmic axis: how far the best
    // point is outside its worst limit (the line ends where every limit holds).
    io::PlotSeries violation{
        "its worst constraint violation (right axis)", {}, {}, "lines lw 2 dt 2"};
    violation.right_axis = true;
    for (std::size_t i = 0; i < r.summary.violation_history.size(); ++i) {
      violation.x.push_back(static_cast<double>(i + 1));
      const double value = r.summary.violation_history[i];
      violation.y.push_back(value > 0 && value < studies::kPenalty / 10 ? std::optional(value)
                                                                        : std::nullopt);
    }
    plot.series.push_back(std::move(violation));
    plot.y2_label = "constraint violation (multiples of its tolerance; <= 1 is met)";
    plot.log_y2 = true;
  }
  return plot;
}

namespace {

// An output's words and unit as the design page shows them ("peak wrist
// force", "N"), from its axis label.
std::pair<std::string, std::string> words_and_unit(const io::AxisQuantity& axis) {
  const std::size_t open = axis.label.rfind(" (");
  if (open == std::string::npos) return {axis.label, ""};
  return {axis.label.substr(0, open), axis.label.substr(open + 2, axis.label.size() - open - 3)};
}

// Where the design file puts the point mass a variable's path sets the mass
// of ("/implement/point_masses/1/mass_g"), in words ("at 3 and 9 o'clock",
// "5 cm from the tip"); "" when the path sets its place, or is not a lead's.
std::string lead_place(const io::Json& design, const std::string& pointer) {
  constexpr std::string_view kLead = "/implement/point_masses/";
  if (!pointer.starts_with(kLead)) return "";
  const std::size_t slash = pointer.find('/', kLead.size());
  if (slash == std::string::npos) return "";
  const std::string key = pointer.substr(slash + 1);
  if (key.starts_with("from_") || key.starts_with("clock") || key.starts_with("off_axis"))
    return "";
  const io::Json::json_pointer entry_at(pointer.substr(0, slash));
  if (!design.contains(entry_at) || !design.at(entry_at).is_object()) return "";
  const io::Json& entry = design.at(entry_at);
  const auto hour = [](const io::Json& h) {
    return h.is_number() ? io::significant(h.get<double>(), 3) : std::string();
  };
  if (const auto clock = entry.find("clock"); clock != entry.end()) {
    if (clock->is_string()) {
      const std::string place = clock->get<std::string>();
      return place == "throat"   ? "at the throat"
             : place == "handle" ? "at the handle"
             : place == "butt"   ? "under the butt cap"
             : place == "grip"   ? "under the grip"
                                 : "";
    }
    if (clock->is_number()) return "at " + hour(*clock) + " o'clock";
    if (clock->is_array() && !clock->empty()) {
      std::string hours;
      for (std::size_t k = 0; k < clock->size(); ++k)
        hours += (k == 0 ? "" : k + 1 == clock->size() ? " and " : ", ") + hour((*clock)[k]);
      return "at " + hours + " o'clock" + (clock->size() > 1 ? ", each" : "");
    }
    return "";
  }
  for (const auto& [name, value] : entry.items()) {
    if (!value.is_number()) continue;
    for (const std::string_view end : {"from_tip", "from_butt"}) {
      if (!name.starts_with(end)) continue;
      const std::string_view unit = io::unit_of_key(name);
      return fmt::format("{} {} from the {}", io::significant(value.get<double>(), 4), unit,
                         end == "from_tip" ? "tip" : "butt");
    }
  }
  return "";
}

std::string variables_html(const studies::Study& study, const studies::OptimizationResult& r) {
  std::string html =
      "<div class=\"table-wrap\"><table id=\"variables\" class=\"side-by-side\"><thead><tr>"
      "<th>variable (unit)</th><th class=\"num\">min</th><th class=\"num\">max</th>"
      "<th class=\"num\">start</th><th class=\"num\">best</th></tr></thead><tbody>\n";
  // Each value in the reader's unit, the file's value under it.
  for (std::size_t i = 0; i < study.variables.size(); ++i) {
    const studies::StudyVariable& v = study.variables[i];
    const io::AxisQuantity axis = io::pointer_axis(v.pointer);
    auto [words, unit] = words_and_unit(axis);
    if (const std::string place = lead_place(study.design_document, v.pointer); !place.empty())
      words += ", " + place;
    const auto cell = [&](double x) {
      return fmt::format("<td class=\"num\">{}<span class=\"si\">{}</span></td>",
                         io::significant(x * axis.factor, 4), io::significant(x, 6));
    };
    const std::string hit = bound_hit(v, r.summary.x[i]);
    html += fmt::format(
        "<tr id=\"var-{}\"><td>{}{}<div class=\"means\"><code>{}</code></div>{}</td>{}{}{}{}"
        "</tr>\n",
        i + 1, html_escape(words), unit.empty() ? "" : " (" + html_escape(unit) + ")",
        html_escape(v.pointer),
        hit.empty()    ? ""
        : hit == "min" ? "<div class=\"means\">best at its lower bound</div>"
                       : "<div class=\"means\">best at its upper bound</div>",
        cell(v.min), cell(v.max), cell(r.start_x[i]), cell(r.summary.x[i]));
  }
  return html + "</tbody></table></div>\n";
}

std::string constraints_html(const studies::OptimizationResult& r) {
  if (r.constraints.empty()) return "<p>The study has no constraints.</p>\n";
  std::string html =
      "<p>A constraint is met when its value lies within its tolerance of the limit.</p>\n"
      "<div class=\"table-wrap\"><table id=\"constraints\"><thead><tr><th>constraint</th>"
      "<th class=\"num\">value at the best design</th><th class=\"num\">tolerance</th>"
      "<th class=\"num\">outside the limit by</th><th>met</th><th>active</th></tr></thead>"
      "<tbody>\n";
  for (const studies::ConstraintReport& c : r.constraints) {
    html += fmt::format(
        "<tr><td><code>{}</code></td><td class=\"num\">{}</td><td class=\"num\">{}</td>"
        "<td class=\"num\">{}</td><td>{}</td><td>{}</td></tr>\n",
        html_escape(c.name), c.value ? html_escape(with_unit(*c.value, c.unit)) : "—",
        io::significant(c.tolerance), c.value ? io::significant(c.violation) : "—",
        c.satisfied ? "yes" : "<strong>no</strong>", c.active ? "yes" : "no");
  }
  return html + "</tbody></table></div>\n";
}

// The convergence plot and the numbers behind it: the evaluations at which
// the best so far improved (the plotted curve is flat in between).
std::string convergence_html(const studies::Study& study, const studies::OptimizationResult& r) {
  io::Plot plot = convergence_plot(study, r);
  // No key: on a phone's narrow layout it covers the curves or the axis
  // label; the caption says which line is which.
  plot.key_position = "off";
  plot.title = "Convergence: " + plot_text_for_html(study.name);
  std::string html = html_figure(
      plot, "plot-convergence",
      "Solid: the best objective found so far after each evaluation of the design (" +
          html_escape(r.summary.algorithm) + ")" +
          (r.constraints.empty() ? std::string()
                                 : "; dashed, on the right axis: how far the best design is "
                                   "outside its worst constraint, in multiples of its tolerance") +
          ".");
  const io::PlotSeries& curve = plot.series.front();
  html += fmt::format(
      "<details><summary>The numbers behind this plot</summary><p>The evaluations at which the "
      "best so far improved, of {}.</p><div class=\"table-wrap\"><table id=\"convergence\">"
      "<thead><tr><th class=\"num\">evaluation</th><th class=\"num\">{}</th></tr></thead>"
      "<tbody>\n",
      r.summary.evaluations, html_escape(plot.y_label));
  std::string last;  // as shown: an improvement in the seventh digit is not listed
  for (std::size_t i = 0; i < curve.x.size(); ++i) {
    if (!curve.y[i] || io::significant(*curve.y[i], 6) == last) continue;
    last = io::significant(*curve.y[i], 6);
    html += fmt::format("<tr><td class=\"num\">{:.0f}</td><td class=\"num\">{}</td></tr>\n",
                        curve.x[i], last);
  }
  return html + "</tbody></table></div></details>\n";
}

std::string outputs_html(const studies::OptimizationResult& r) {
  std::string html =
      "<div class=\"table-wrap\"><table id=\"outputs\"><thead><tr><th>quantity</th>"
      "<th class=\"num\">start</th><th class=\"num\">optimum</th><th>unit</th></tr></thead>"
      "<tbody>\n";
  for (const io::OutputSpec& o : io::output_specs()) {
    const auto a = output_value(o, r.start_outputs), b = output_value(o, r.best_outputs);
    if (!a && !b) continue;
    const io::AxisQuantity axis = output_axis(o);
    const std::string words = words_and_unit(axis).first;
    // In a player's units (g, cm, kg·cm², ms), as the comparison page gives them.
    const io::PeopleUnit people = io::people_unit(o.unit, o.name);
    const std::string unit(people.unit);
    const auto cell = [&](const std::optional<double>& v) {
      return v ? fmt::format("<td class=\"num\">{}</td>", io::significant(*v * people.factor, 4))
               : std::string("<td class=\"num\">—</td>");
    };
    html += fmt::format(
        "<tr id=\"out-{}\"><td>{}<div class=\"means\"><code>{}</code></div></td>{}{}<td>{}</td>"
        "</tr>\n",
        o.name, html_escape(words), o.name, cell(a), cell(b), html_escape(unit));
  }
  return html + "</tbody></table></div>\n";
}

}  // namespace

std::string optimization_html(const studies::Study& study, const studies::OptimizationResult& r) {
  std::string html = html_page_open(study.name, "");
  html += "<section id=\"answer\"><h2>The answer</h2>\n";
  if (!study.question.empty())
    html += "<p class=\"question\"><strong>Question.</strong> " + html_escape(study.question) +
            "</p>\n";
  html += "<div class=\"answer\">\n";
  for (const std::string& paragraph : answer_paragraphs(study, r))
    html += "<p>" + html_with_code(paragraph) + "</p>\n";
  html += "</div></section>\n";

  html +=
      "<section id=\"variables-section\"><h2>What the search could change</h2>\n"
      "<p>Each value in a player's units, the value as the files write it under it.</p>\n" +
      variables_html(study, r) + "<h3>Constraints</h3>\n" + constraints_html(r) + "</section>\n";

  html += "<section id=\"search\"><h2>The search</h2>\n" + convergence_html(study, r) +
          fmt::format("<p>{} evaluations; {}; termination: {}.</p>\n", r.summary.evaluations,
                      html_escape(r.summary.algorithm), html_escape(r.summary.termination_text())) +
          "</section>\n";

  const char* best_name = r.outcome == studies::Outcome::kOptimum ? "the best design"
                          : r.outcome == studies::Outcome::kInfeasible
                              ? "the least violating design"
                              : "the last design the search kept";
  html += fmt::format("<section id=\"outputs-section\"><h2>Start and {}</h2>\n", best_name);
  // Drawn under names that tell them apart (both carry the study's design's).
  io::DesignFile start = r.start, best = r.best;
  start.name = "start";
  best.name = r.outcome == studies::Outcome::kOptimum ? "best" : "found";
  std::vector<DrawnRacquet> drawn;
  const std::string best_title =
      std::string(1, static_cast<char>(std::toupper(best_name[0]))) + (best_name + 1);
  if (r.start_outputs) drawn.push_back({&start, &*r.start_outputs, "The starting design"});
  if (r.best_outputs) drawn.push_back({&best, &*r.best_outputs, best_title});
  html +=
      "<p>Both from above, tip on the left, to one scale: the balance point (triangle), the "
      "hand-held COP (red dot), the node (blue diamond, when the frame's stiffness is known), "
      "the lead (orange) and the ball at the impact.</p>\n";
  if (!drawn.empty()) html += racquets_to_scale_html(drawn, "drawing");
  html += "<h3>Every output</h3>\n" + outputs_html(r);
  html += fmt::format(
      "<details><summary>{} as a design file (<code>sweetspot evaluate</code> accepts it)"
      "</summary><pre id=\"best-design\">{}</pre></details>\n</section>\n",
      best_title,
      html_escape(r.best_document.dump(2, ' ', false, io::Json::error_handler_t::replace)));
  return html + html_page_close("Computed by sweetspot from <code>" + html_escape(study.source) +
                                "</code>, after R. Cross, \"Center of percussion of hand-held "
                                "implements\", Am. J. Phys. 72 (2004). Positions are measured "
                                "from the tip of the racquet.");
}

}  // namespace sweetspot::reports
