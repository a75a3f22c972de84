#include "studies/sweep.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <memory>

#include "io/format.hpp"
#include "io/input_error.hpp"
#include "io/parallel.hpp"
#include "io/rows.hpp"
#include "studies/design_binding.hpp"
#include "studies/thread_mode_cache.hpp"
#include "sweetspot/evaluate.hpp"
#include "sweetspot/kernels.hpp"

namespace sweetspot::studies {

std::span<const std::string_view> rigid_outcome_outputs() {
  static constexpr std::string_view kNames[] = {
      "effective_mass_kg",   "apparent_cor",      "rebound_speed_m_s", "impulse_N_s",
      "peak_impact_force_N", "wrist_force_ratio", "peak_wrist_force_N"};
  return kNames;
}

namespace {

// One thread's share of a sweep: points by index in grid order (the first
// variable fastest), each evaluated into its CSV row and its plot values.
class SweepWorker {
 public:
  SweepWorker(const Study& study, const std::vector<double>& second, const SweepOptions& options,
              const io::RowWriter& rows)
      : study_(study), rows_(rows), second_(second), document_(study.design_document) {
    const bool share_rows = options.share_rows;
    for (const StudyVariable& variable : study.variables) pointers_.emplace_back(variable.pointer);
    if (options.compiled && compiled_for_variables(study)) bound_.emplace(*study.compiled);
    outcome_only_ =
        options.outcome_only && study.fidelity == Fidelity::kRigid &&
        std::all_of(study.sweep_outputs.begin(), study.sweep_outputs.end(),
                    [](const io::OutputSpec* o) {
                      const auto names = rigid_outcome_outputs();
                      return std::find(names.begin(), names.end(), o->name) != names.end();
                    });
    if (study.variables[0].values.size() <= kCachedTexts) {
      for (const double value : study.variables[0].values)
        rows_.number(0, value, first_text_.emplace_back());
    }
    // The impact point as read_design() reads it: "/impact/from_tip_<unit>" or
    // "/impact/from_butt_<unit>", converted by the same factor.
    const std::string_view pointer = study.variables[0].pointer;
    if (share_rows && study.fidelity == Fidelity::kRigid && pointer.starts_with("/impact/")) {
      const std::string_view key = pointer.substr(std::string_view("/impact/").size());
      if (const auto f = io::unit_scale(key, "from_tip", io::Dimension::kLength))
        impact_ = Impact{true, *f};
      if (const auto f = io::unit_scale(key, "from_butt", io::Dimension::kLength))
        impact_ = Impact{false, *f};
    }
  }

  // Appends point p's row to `text` and its outputs to `values`.
  void point(std::size_t p, std::string& text, std::optional<double>* values) {
    const std::size_t n0 = study_.variables[0].values.size();
    const std::size_t row = p / n0;
    const double v = study_.variables[0].values[p % n0];
    // The point's evaluation, in this worker's one Evaluation (no copy per point).
    const Evaluation* e = nullptr;
    std::string error;
    if (impact_ && shared_ && shared_row_ == row) e = shared_at(v);
    if (!e) e = evaluate_bound(v, second_[row], row);
    if (!e) {
      try {
        e = evaluate_here(v, second_[row], row);
      } catch (const std::exception& ex) {
        error = ex.what();
      }
    }
    // The variables' text repeats along the grid: written once, copied after.
    if (p % n0 < first_text_.size()) {
      text += first_text_[p % n0];
    } else {
      rows_.number(0, v, text);
    }
    std::size_t column = 1;
    if (study_.variables.size() == 2) {
      if (second_text_row_ != row) {
        second_text_.clear();
        rows_.number(1, second_[row], second_text_);
        second_text_row_ = row;
      }
      text += second_text_;
      ++column;
    }
    for (std::size_t k = 0; k < study_.sweep_outputs.size(); ++k) {
      values[k] = e ? study_.sweep_outputs[k]->value(*e) : std::nullopt;
      rows_.number(column++, values[k], text);
    }
    rows_.text(column, error.empty() ? std::nullopt : std::optional<std::string_view>(error), text);
    rows_.end_row(text);
  }

 private:
  struct Impact {
    bool from_tip;
    io::UnitScale to_si;
  };

  // The point set on the study's compiled design and evaluated; nullptr
  // when the binding cannot vouch for it or it fails (evaluate_here() then
  // reads it from JSON and says why).
  const Evaluation* evaluate_bound(double v, double y, std::size_t row) {
    if (!bound_) return nullptr;
    const double values[2] = {v, y};
    try {
      const Design* design = bound_->at(std::span<const double>(values, pointers_.size()));
      if (!design) return nullptr;
      if (!(outcome_only_ && evaluate_rigid_outcome(*design, evaluation_)))
        evaluation_ = evaluate(
            *design, study_.fidelity,
            {.rel_tol = study_.modal_tolerance, .modes = &thread_mode_cache(), .validated = true});
      share_row(*design, row);
      return &evaluation_;
    } catch (const std::exception&) {
      return nullptr;
    }
  }

  // The point read and evaluated on its own.
  const Evaluation* evaluate_here(double v, double y, std::size_t row) {
    document_[pointers_[0]] = v;
    if (pointers_.size() == 2) document_[pointers_[1]] = y;
    const io::DesignFile design = io::read_design_lean(document_, study_.design_source);
    try {
      evaluation_ = evaluate_in(study_, design);
    } catch (const std::invalid_argument& e) {
      // Read again with the key map, to name the user's key ("/ball/diameter_cm").
      io::rethrow_in(io::read_design(document_, study_.design_source), e);
    }
    share_row(design.design, row);
    return &evaluation_;
  }

  // The row's design kept for the next points when only the impact changes along it.
  void share_row(const Design& design, std::size_t row) {
    if (impact_ && impact_sweep_answers(design)) {
      shared_.emplace(design);
      shared_row_ = row;
      length_m_ = design.implement.length_m();
    }
  }

  // The same point from the row's design, or nullptr when only reading it
  // on its own can say what is wrong (off the implement, not finite).
  const Evaluation* shared_at(double v) {
    const double si = impact_->to_si.to_si(v);
    const double from_butt = impact_->from_tip ? length_m_ - si : si;
    if (!(si >= 0.0 && si <= length_m_)) return nullptr;
    evaluation_ = shared_->at(from_butt);
    for (const io::OutputSpec* o : study_.sweep_outputs) {
      if (const auto value = o->value(evaluation_); value && !std::isfinite(*value)) return nullptr;
    }
    return &evaluation_;
  }

  const Study& study_;
  const io::RowWriter& rows_;  // how a point's row is written
  const std::vector<double>& second_;
  io::Json document_;  // this thread's copy, the variables set in place
  std::vector<io::Json::json_pointer> pointers_;
  std::optional<Impact> impact_;
  std::optional<BoundDesign> bound_;  // empty: every point read from JSON
  Evaluation evaluation_;             // the current point's
  bool outcome_only_ = false;         // the outputs are rigid_outcome()'s alone
  // The first variable's values as CSV text (when there are at most
  // kCachedTexts of them), and ",second" for the current row.
  static constexpr std::size_t kCachedTexts = 100000;
  std::vector<std::string> first_text_;  // each value's cell, when there are few
  std::string second_text_;
  std::size_t second_text_row_ = static_cast<std::size_t>(-1);
  std::optional<ImpactSweep> shared_;
  std::size_t shared_row_ = 0;
  double length_m_ = 0.0;
};

}  // namespace

std::vector<io::Plot> run_sweep(const Study& study, std::ostream& out,
                                const std::function<void(std::size_t, std::size_t)>& progress,
                                const SweepOptions& options) {
  if (study.variables.size() > 2) {
    throw io::InputError(
        study.source, "/variables",
        "a sweep takes one or two variables, got " + std::to_string(study.variables.size()));
  }
  if (study.sweep_outputs.empty())
    throw io::InputError(study.source, "/outputs", "missing: the outputs to sweep");
  const StudyVariable& first = study.variables[0];
  const std::vector<double> second =
      study.variables.size() == 2 ? study.variables[1].values : std::vector<double>{NAN};
  const std::size_t total = first.values.size() * second.size();
  const std::size_t outputs = study.sweep_outputs.size();
  const bool keep = total <= kMaxPlotPoints;

  const std::unique_ptr<io::RowWriter> rows = io::row_writer(options.format);
  std::vector<std::string> names;
  for (const StudyVariable& variable : study.variables) names.emplace_back(variable.pointer);
  for (const io::OutputSpec* o : study.sweep_outputs) names.emplace_back(o->name);
  names.emplace_back("error");
  std::string header;
  rows->header(std::move(names), header);
  out << header;

  // Axes and keys in a reader's words and units (io/plot.hpp), never the pointers.
  const io::AxisQuantity x_axis = io::pointer_axis(first.pointer);
  const std::optional<io::AxisQuantity> key_axis =
      study.variables.size() == 2 ? std::optional(io::pointer_axis(study.variables[1].pointer))
                                  : std::nullopt;
  std::vector<io::Plot> plots;
  std::vector<double> y_factors;
  for (const io::OutputSpec* o : study.sweep_outputs) {
    const io::AxisQuantity y_axis = output_axis(*o);
    y_factors.push_back(y_axis.factor);
    plots.push_back(io::Plot{fmt::format("{}: {}", study.name, y_axis.label),
                             x_axis.label,
                             y_axis.label,
                             std::pair{first.min * x_axis.factor, first.max * x_axis.factor},
                             std::nullopt,
                             {},
                             {},
                             {}});
  }
  const int threads = std::max(1, options.threads);
  std::vector<SweepWorker> workers;
  for (int t = 0; t < threads; ++t) workers.emplace_back(study, second, options, *rows);
  std::vector<std::string> texts(threads);
  std::vector<std::optional<double>> values(kSweepChunkPoints * outputs);
  for (std::size_t begin = 0; begin < total; begin += kSweepChunkPoints) {
    const std::size_t count = std::min(kSweepChunkPoints, total - begin);
    for (std::string& text : texts) text.clear();
    io::for_blocks(count, threads, [&](std::size_t t, std::size_t from, std::size_t to) {
      for (std::size_t i = from; i < to; ++i)
        workers[t].point(begin + i, texts[t], &values[i * outputs]);
    });
    for (const std::string& text : texts) out << text;
    if (keep) {
      for (std::size_t i = 0; i < count; ++i) {
        const std::size_t p = begin + i;
        if (p % first.values.size() == 0) {
          for (std::size_t k = 0; k < outputs; ++k) {
            plots[k].series.push_back(io::PlotSeries{
                key_axis ? fmt::format(
                               "{} {}{}", key_axis->name,
                               io::significant(second[p / first.values.size()] * key_axis->factor),
                               key_axis->unit.empty() ? "" : " " + key_axis->unit)
                         : io::output_axis(*study.sweep_outputs[k]).label,
                {},
                {}});
          }
        }
        for (std::size_t k = 0; k < outputs; ++k) {
          const double y_factor = y_factors[k];
          const auto& y = values[i * outputs + k];
          plots[k].series.back().x.push_back(first.values[p % first.values.size()] * x_axis.factor);
          plots[k].series.back().y.push_back(y ? std::optional(*y * y_factor) : std::nullopt);
        }
      }
    }
    progress(begin + count, total);
  }
  if (!keep) plots.clear();
  return plots;
}

}  // namespace sweetspot::studies
