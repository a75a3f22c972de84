#include "evaluate_many.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <atomic>
#include <cmath>
#include <cstring>
#include <exception>
#include <limits>
#include <memory>
#include <mutex>
#include <optional>
#include <stdexcept>

#include "io/design_reader.hpp"
#include "io/format.hpp"
#include "io/input_error.hpp"
#include "io/outputs.hpp"
#include "io/parallel.hpp"
#include "studies/catalogue_header.hpp"
#include "studies/design_binding.hpp"
#include "studies/rigid_columns.hpp"
#include "studies/thread_mode_cache.hpp"
#include "sweetspot/evaluate.hpp"

namespace sweetspot::python {
namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
// Rows tried as the template the columns are bound to (as a catalogue tries its shapes').
constexpr std::size_t kTemplateAttempts = 4;

double value_at(const Column& column, std::size_t row) {
  return column.data[static_cast<std::ptrdiff_t>(row) * column.stride];
}

std::string row_name(std::size_t row) { return fmt::format("row {}", row); }

class Rows {
 public:
  Rows(const io::Json& base, std::span<const Column> columns, const ManyOptions& options,
       std::span<double* const> outputs, RowErrors& errors)
      : base_(base),
        columns_(columns),
        options_(options),
        outputs_(outputs),
        errors_(errors),
        pointers_(column_pointers(columns)),
        bad_column_(columns.size() + 1) {
    for (const std::string& pointer : pointers_) overrides_.emplace_back(pointer);
    wanted_ = options.outputs;
    if (wanted_.empty()) {
      for (std::size_t k = 0; k < io::output_specs().size(); ++k) wanted_.push_back(k);
    }
    for (const Column& column : columns) views_.push_back({column.data, column.stride});
    const auto fidelity = base.find("fidelity");
    base_fidelity_ = fidelity != base.end() && fidelity->is_string() ? fidelity->get<std::string>()
                                                                     : std::string("auto");
  }

  // The base with the columns bound, read with the values of one of the
  // first rows that reads (none: every row takes the JSON path).
  void compile(std::size_t rows) {
    for (std::size_t row = 0; row < std::min(rows, kTemplateAttempts); ++row) {
      try {
        const io::Json document = document_at(row);
        auto compiled = studies::CompiledDesign::compile(
            io::describe_design(document, row_name(row)), pointers_);
        if (!compiled) return;  // a column no binding sets
        compiled_ = std::make_unique<const studies::CompiledDesign>(std::move(*compiled));
        compile_columns();
        return;
      } catch (const std::exception&) {
        // Not this row: try the next one.
      }
    }
  }

  void run(std::size_t from, std::size_t to) {
    if (rigid_) {
      // The kernel's blocks, then the rows it leaves, one by one.
      constexpr std::size_t kChunk = 4096;
      std::vector<unsigned char> answered(kChunk);
      for (std::size_t begin = from; begin < to; begin += kChunk) {
        const std::size_t end = std::min(to, begin + kChunk);
        rigid_->run(views_, begin, end, rigid_wanted_, outputs_, answered);
        // Rarely any: memchr skips to each (a byte at a time was 5 % of a million rows).
        const unsigned char* const first = answered.data();
        const unsigned char* const last = first + (end - begin);
        for (const unsigned char* left = first;
             (left = static_cast<const unsigned char*>(std::memchr(left, 0, last - left)));
             ++left) {
          const std::size_t row = begin + static_cast<std::size_t>(left - first);
          run_rows(row, row + 1);
        }
      }
      return;
    }
    run_rows(from, to);
  }

  void run_rows(std::size_t from, std::size_t to) {
    std::optional<studies::BoundDesign> bound;
    if (compiled_) bound.emplace(*compiled_);
    std::vector<double> values(columns_.size());
    for (std::size_t row = from; row < to; ++row) {
      bool finite = true;
      for (std::size_t j = 0; j < columns_.size(); ++j) {
        values[j] = value_at(columns_[j], row);
        finite = finite && std::isfinite(values[j]);
      }
      if (bound && finite && evaluate_bound(*bound, values, row)) continue;
      evaluate_general(row);
    }
  }

  // The first column found at fault for every row, as a catalogue's header
  // is refused: the design has no such field, or the base holds a value on its path.
  void check_columns() const {
    const std::size_t j = bad_column_.load();
    if (j >= columns_.size()) return;
    throw io::InputError("columns", "",
                         fmt::format("column {} {}: {}", j + 1, studies::shown(columns_[j].field),
                                     bad_column_detail_));
  }

 private:
  io::Json document_at(std::size_t row) const {
    io::Json document = base_;
    for (std::size_t j = 0; j < columns_.size(); ++j) {
      const double value = value_at(columns_[j], row);
      if (!std::isfinite(value)) {
        throw io::InputError(row_name(row), pointers_[j],
                             fmt::format("expected a finite number, got {}", value));
      }
      try {
        overrides_[j].apply(document, value);
      } catch (const io::PathError& e) {
        note_bad_column(j, e.detail());
        throw io::InputError(row_name(row), e.pointer(), e.detail());
      } catch (const io::Json::exception&) {
        note_bad_column(j, "the base design holds a value on its path that is not an object");
        throw io::InputError(row_name(row), pointers_[j],
                             "the base design holds a value on its path that is not an object");
      }
    }
    return document;
  }

  bool evaluate_bound(studies::BoundDesign& bound, const std::vector<double>& values,
                      std::size_t row) const {
    const Design* design = bound.at(values);
    if (!design) return false;
    try {
      const Fidelity fidelity = resolve_fidelity(
          options_.fidelity.empty() ? std::string_view(base_fidelity_) : options_.fidelity,
          *design);
      write(row, evaluate(*design, fidelity,
                          {.rel_tol = options_.modal_tolerance,
                           .modes = &studies::thread_mode_cache(),
                           .validated = true}));
      return true;
    } catch (const std::exception&) {
      return false;  // the JSON path says why
    }
  }

  // The row as the JSON document the columns write over the base, read as
  // `sweetspot evaluate --batch` reads a row: the message names the key.
  void evaluate_general(std::size_t row) const {
    const std::string where = row_name(row);
    try {
      const io::Json document = document_at(row);
      const io::DesignFile design = io::read_design_lean(document, where);
      try {
        const Fidelity fidelity = resolve_fidelity(
            options_.fidelity.empty() ? std::string_view(design.fidelity) : options_.fidelity,
            design.design);
        write(row, evaluate(design.design, fidelity,
                            {.rel_tol = options_.modal_tolerance,
                             .modes = &studies::thread_mode_cache()}));
      } catch (const std::invalid_argument& e) {
        io::rethrow_in(io::read_design(document, where), e);  // with the key map
      }
    } catch (const io::InputError& e) {
      fail(row, e.what());
      const bool shape_fault = e.shape_fault();
      for (std::size_t j = 0; shape_fault && j < pointers_.size(); ++j) {
        if (pointers_[j] == e.pointer() || pointers_[j].starts_with(e.pointer() + "/")) {
          note_bad_column(j, e.detail());
          break;
        }
      }
    } catch (const std::exception& e) {
      fail(row, io::InputError(where, "", e.what()).what());
    }
  }

  void write(std::size_t row, const Evaluation& evaluation) const {
    const std::span<const io::OutputSpec> specs = io::output_specs();
    for (std::size_t k = 0; k < wanted_.size(); ++k)
      outputs_[k][row] = specs[wanted_[k]].value(evaluation).value_or(kNaN);
  }

  // The column-wise path, where the rows are rigid evaluations of a paper
  // racquet and every output wanted is one it answers.
  void compile_columns() {
    const Fidelity fidelity =
        resolve_fidelity(options_.fidelity.empty() ? std::string_view(base_fidelity_)
                                                   : std::string_view(options_.fidelity),
                         compiled_->description().design);
    if (fidelity != Fidelity::kRigid) return;
    const std::span<const io::OutputSpec> specs = io::output_specs();
    const std::span<const std::string_view> answers = studies::rigid_column_outputs();
    std::vector<std::size_t> wanted;
    for (const std::size_t k : wanted_) {
      const auto at = std::find(answers.begin(), answers.end(), specs[k].name);
      if (at == answers.end()) return;
      wanted.push_back(static_cast<std::size_t>(at - answers.begin()));
    }
    auto rigid = studies::RigidColumns::compile(*compiled_);
    if (!rigid) return;
    rigid_ = std::make_unique<const studies::RigidColumns>(*rigid);
    rigid_wanted_ = std::move(wanted);
  }

  void fail(std::size_t row, std::string message) const {
    for (double* output : outputs_) output[row] = kNaN;
    const std::lock_guard<std::mutex> lock(errors_mutex_);
    errors_.emplace_back(row, io::one_line(message));
  }

  void note_bad_column(std::size_t j, const std::string& detail) const {
    std::size_t none = columns_.size() + 1;
    if (bad_column_.compare_exchange_strong(none, columns_.size() + 2)) {
      bad_column_detail_ = detail;
      bad_column_.store(j);
    }
  }

  const io::Json& base_;
  std::span<const Column> columns_;
  const ManyOptions& options_;
  std::span<double* const> outputs_;
  RowErrors& errors_;
  mutable std::mutex errors_mutex_;
  std::vector<std::string> pointers_;
  std::vector<io::FieldOverride> overrides_;
  std::string base_fidelity_;
  std::unique_ptr<const studies::CompiledDesign> compiled_;
  std::vector<std::size_t> wanted_;  // indices into io::output_specs(), one per output
  std::vector<studies::ColumnView> views_;
  std::unique_ptr<const studies::RigidColumns> rigid_;
  std::vector<std::size_t> rigid_wanted_;  // indices into studies::rigid_column_outputs()
  // The column at fault (none: columns.size() + 1; being written: + 2).
  mutable std::atomic<std::size_t> bad_column_;
  mutable std::string bad_column_detail_;
};

}  // namespace

std::vector<std::string> column_pointers(std::span<const Column> columns) {
  // The names as a catalogue's header line, checked by the catalogue's own rules.
  std::string line;
  for (const Column& column : columns) {
    if (!line.empty()) line += ',';
    line += io::csv_field(column.field);
  }
  if (columns.empty()) throw io::InputError("columns", "", "expected at least one column");
  const studies::Header header = studies::read_header(line, "columns", {}, "columns");
  std::vector<std::string> pointers;
  for (const studies::DesignColumn& column : header.design) {
    if (studies::is_text_field(column.field)) {
      throw io::InputError(
          "columns", "",
          fmt::format("{}: holds text, expected a field that holds a number", column.label));
    }
    pointers.push_back(studies::field_to_pointer(column.field));
  }
  return pointers;
}

void evaluate_columns(const io::Json& base, std::span<const Column> columns, std::size_t rows,
                      const ManyOptions& options, std::span<double* const> outputs,
                      RowErrors& errors) {
  errors.clear();
  Rows evaluator(base, columns, options, outputs, errors);
  evaluator.compile(rows);
  io::for_blocks(rows, options.threads,
                 [&](std::size_t, std::size_t from, std::size_t to) { evaluator.run(from, to); });
  evaluator.check_columns();
}

}  // namespace sweetspot::python
