#include "studies/batch.hpp"

#include <fmt/format.h>
#include <unistd.h>

#include <algorithm>
#include <array>
#include <cerrno>
#include <charconv>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <map>
#include <memory>
#include <span>
#include <stdexcept>
#include <vector>

#include "io/csv.hpp"
#include "io/design_fields.hpp"
#include "io/design_reader.hpp"
#include "io/input_error.hpp"
#include "io/outputs.hpp"
#include "io/parallel.hpp"
#include "io/rows.hpp"
#include "studies/catalogue_header.hpp"
#include "studies/design_binding.hpp"
#include "studies/thread_mode_cache.hpp"
#include "sweetspot/evaluate.hpp"
#include "sweetspot/frame_modes.hpp"

namespace sweetspot::studies {
namespace {

// A cell's text in a row's error, in single quotes: the error column is a CSV
// field, where a double quote would be written twice ("got ""VS5""").
std::string shown_cell(std::string_view text) {
  return "'" + io::one_line(io::valid_utf8(text)) + "'";
}

// A row of the catalogue, and what becomes of it. The rows of a chunk are
// reused from chunk to chunk (start()), keeping their strings' memory.
struct Row {
  std::size_t line = 0;
  std::string text;
  std::string name;
  std::string error;
  // A design column (from 1) the header names wrongly, found by this row:
  // the design has no such field, or the base holds a value where it leads.
  std::size_t bad_column = 0;
  std::string bad_column_detail;
  std::vector<std::string> passed;  // the cells passed through
  std::optional<double> key;        // the sort output's value
  std::string out;                  // the row's text, when sorted

  // The row read at `line_number` as `record` (taken, and left holding
  // the former row's text), nothing else of a former row kept.
  void start(std::size_t line_number, std::string& record) {
    line = line_number;
    text.swap(record);
    name.clear();
    error.clear();
    bad_column = 0;
    bad_column_detail.clear();
    passed.clear();
    key.reset();
    out.clear();
  }
};

// What a row evaluates to, in a slot each thread reuses: a row is written as
// soon as it is evaluated, so its evaluation (some 700 bytes) is never kept
// in the chunk.
struct Outcome {
  std::optional<Evaluation> evaluation;
  std::optional<io::DesignFile> file;  // the design as read, for complete JSON rows
};

// The most of a row's text a reused Row keeps between chunks.
constexpr std::size_t kKeptRowBytes = 4096;

// A CSV row's design compiled once per thread for each set of filled cells
// (the rows' shape): the base with those columns is read once, the columns
// bound to it (design_binding.hpp), and every later row of that shape only
// sets numbers on a typed design. A row the binding cannot vouch for (a bad
// cell, a value the reader or the core refuses) goes the JSON path, which
// writes the same error row as ever.
struct Shape {
  std::unique_ptr<const CompiledDesign> compiled;
  std::optional<BoundDesign> bound;
  std::optional<std::string> name;  // the base's name, when the row gives none
  std::string fidelity;             // the design's "fidelity"
  int attempts = 0;                 // rows of this shape whose template could not be read
};
// Rows of a shape tried as its template before the shape is left to the JSON path.
constexpr int kTemplateAttempts = 4;
// A row's shape is a bit per design column.
constexpr std::size_t kMaxCompiledColumns = 64;

class Evaluator {
 public:
  Evaluator(const std::string& source, const BatchOptions& options, bool csv, Header header)
      : source_(source),
        options_(options),
        csv_(csv),
        header_(std::move(header)),
        shapes_(static_cast<std::size_t>(std::max(1, options.threads))),
        records_(shapes_.size()) {
    for (const DesignColumn& column : header_.design) {
      pointers_.push_back(field_to_pointer(column.field));
      columns_.emplace_back(pointers_.back());  // read_header checked the path
      kinds_.push_back(column.field == "name"        ? CellKind::kName
                       : is_text_field(column.field) ? CellKind::kText
                                                     : CellKind::kNumber);
    }
  }

  const Header& header() const { return header_; }

  // Evaluates a row on thread `thread` (< options.threads). JSON output
  // takes the JSON path, which keeps the design as read (its inputs and
  // their provenance).
  void evaluate_row(Row& row, Outcome& outcome, std::size_t thread) const {
    outcome.evaluation.reset();
    outcome.file.reset();
    if (!csv_) {
      evaluate_general(row, outcome, nullptr);
      return;
    }
    io::CsvRecord& record = records_[thread];
    io::split_csv(row.text, header_.count, record);
    const bool whole = record.error.empty() && record.count == header_.count;
    if (whole) {
      for (const std::size_t k : header_.passed) row.passed.emplace_back(record.fields[k]);
    }
    if (whole && options_.compiled && options_.format != io::Format::kJson &&
        header_.design.size() <= kMaxCompiledColumns &&
        evaluate_compiled(row, outcome, record, thread)) {
      return;
    }
    evaluate_general(row, outcome, &record);
  }

 private:
  // The row set on its shape's compiled design; false (and the row as it
  // was) when the JSON path must read it.
  bool evaluate_compiled(Row& row, Outcome& outcome, const io::CsvRecord& record,
                         std::size_t thread) const {
    const std::vector<std::string_view>& cells = record.fields;
    std::uint64_t mask = 0;
    const std::string_view* name_cell = nullptr;
    std::array<double, kMaxCompiledColumns> values;
    std::size_t count = 0;
    for (std::size_t j = 0; j < header_.design.size(); ++j) {
      const std::string_view& cell = cells[header_.design[j].cell];
      if (cell.empty()) continue;
      mask |= std::uint64_t{1} << j;
      if (kinds_[j] == CellKind::kName) {
        name_cell = &cell;
        continue;
      }
      if (kinds_[j] == CellKind::kText) return false;
      const char* end = cell.data() + cell.size();
      const auto [stop, error] = std::from_chars(cell.data(), end, values[count]);
      if (error != std::errc() || stop != end) return false;
      ++count;
    }
    Shape& shape = shapes_[thread][mask];
    if (!shape.bound && !compile_shape(shape, cells, values, row.line)) return false;
    const Design* design = shape.bound->at(std::span<const double>(values.data(), count));
    if (!design) return false;
    try {
      const Fidelity fidelity = resolve_fidelity(
          options_.fidelity.empty() ? std::string_view(shape.fidelity) : options_.fidelity,
          *design);
      outcome.evaluation.emplace(evaluate(
          *design, fidelity,
          {.rel_tol = options_.modal_tolerance, .modes = &thread_mode_cache(), .validated = true}));
    } catch (const std::exception&) {
      outcome.evaluation.reset();
      return false;
    }
    row.name = name_cell    ? *name_cell
               : shape.name ? *shape.name
                            : fmt::format("{}:{}", source_, row.line);
    return true;
  }

  // Reads this row's document as the template of its shape and binds the
  // filled columns to it; false when it cannot (the row is then read as JSON).
  bool compile_shape(Shape& shape, const std::vector<std::string_view>& cells,
                     std::span<const double> values, std::size_t line) const {
    if (shape.attempts >= kTemplateAttempts) return false;
    ++shape.attempts;
    try {
      io::Json document = options_.base ? *options_.base : io::Json::object();
      std::vector<std::string> pointers;
      bool named = false;
      for (std::size_t j = 0; j < header_.design.size(); ++j) {
        const std::string_view cell = cells[header_.design[j].cell];
        if (cell.empty()) continue;
        if (kinds_[j] == CellKind::kName) {
          document["name"] = std::string(cell);
          named = true;
          continue;
        }
        columns_[j].apply(document, values[pointers.size()]);
        pointers.push_back(pointers_[j]);
      }
      const std::string where = fmt::format("{}:{}", source_, line);
      auto compiled = CompiledDesign::compile(io::describe_design(document, where), pointers);
      if (!compiled) {
        shape.attempts =
            kTemplateAttempts;  // a column no binding sets: every row of the shape reads JSON
        return false;
      }
      shape.compiled = std::make_unique<const CompiledDesign>(std::move(*compiled));
      shape.bound.emplace(*shape.compiled);
      const auto name = document.find("name");
      if (!named && name != document.end()) shape.name = name->get<std::string>();
      const auto fidelity = document.find("fidelity");
      shape.fidelity = fidelity == document.end() ? "auto" : fidelity->get<std::string>();
      return true;
    } catch (const std::exception&) {
      return false;
    }
  }

  // A cell's problem in a row's error: the column is named when it is not
  // the field itself (a mapped column).
  std::string cell_problem(std::size_t j, const std::string& what) const {
    const DesignColumn& column = header_.design[j];
    if (header_.names[column.cell] == column.field) return what;
    return fmt::format("column {}: {}", shown_cell(header_.names[column.cell]), what);
  }

  // The JSON path: the row written over the base document and read again.
  void evaluate_general(Row& row, Outcome& outcome, const io::CsvRecord* record) const {
    const std::string where = fmt::format("{}:{}", source_, row.line);
    try {
      io::Json document = options_.base ? *options_.base : io::Json::object();
      if (record) {
        const io::CsvRecord& cells = *record;
        if (!cells.error.empty()) throw io::InputError(where, "", "not CSV: " + cells.error);
        if (cells.count != header_.count) {
          throw io::InputError(where, "",
                               fmt::format("expected {} fields as in the header, got {}",
                                           header_.count, cells.count));
        }
        for (const DesignColumn& column : header_.design) {
          // A row that fails still shows its own name.
          if (column.field == "name") row.name = cells.fields[column.cell];
        }
        for (std::size_t j = 0; j < header_.design.size(); ++j) {
          const DesignColumn& column = header_.design[j];
          const std::string_view text = cells.fields[column.cell];
          if (text.empty()) continue;  // the base's value stands
          if (is_text_field(column.field)) {
            document[io::Json::json_pointer(pointers_[j])] = std::string(text);
            continue;
          }
          const std::string_view cell = trimmed(text);
          double number = 0.0;
          const auto [end, error] = std::from_chars(cell.data(), cell.data() + cell.size(), number);
          io::Json value = number;
          if (error != std::errc() || end != cell.data() + cell.size() || cell.empty()) {
            // A lead's clock or a gauge by its word ("3/9", "throat", "16L"), as
            // --set and the design file take it; the design read says if it is one.
            if (cell.empty() || !takes_a_word(column.field)) {
              throw io::InputError(where, pointers_[j],
                                   cell_problem(j, "expected a number, got " + shown_cell(text)));
            }
            value = std::string(cell);
          } else if (!std::isfinite(number)) {
            throw io::InputError(
                where, pointers_[j],
                cell_problem(j, "expected a finite number, got " + shown_cell(text)));
          }
          try {
            columns_[j].apply(document, std::move(value));
          } catch (const io::PathError& e) {
            row.bad_column = j + 1;
            row.bad_column_detail = e.detail();
            throw io::InputError(where, e.pointer(), cell_problem(j, e.detail()));
          } catch (const io::Json::exception&) {
            row.bad_column = j + 1;
            row.bad_column_detail =
                "the base design holds a value on its path that is not an object";
            throw io::InputError(where, pointers_[j], row.bad_column_detail);
          }
        }
      } else {
        const io::Json patch = io::parse_json(row.text, where);
        // A row that fails still shows its own name, as a CSV row does.
        if (patch.is_object()) {
          const auto name = patch.find("name");
          if (name != patch.end() && name->is_string()) row.name = name->get<std::string>();
        }
        io::override_fields(document, patch);
      }
      if (options_.format == io::Format::kJson) {
        // The design with its inputs' provenance, for a row as complete as `evaluate`'s.
        io::DesignFile design = io::read_design(document, where);
        row.name = design.name;
        outcome.evaluation =
            io::evaluate_design_file(design, options_.fidelity, options_.modal_tolerance);
        outcome.file = std::move(design);
        return;
      }
      const io::DesignFile design = io::read_design_lean(document, where);
      row.name = design.name;
      try {
        const Fidelity fidelity = resolve_fidelity(
            options_.fidelity.empty() ? std::string_view(design.fidelity) : options_.fidelity,
            design.design);
        outcome.evaluation =
            evaluate(design.design, fidelity,
                     {.rel_tol = options_.modal_tolerance, .modes = &thread_mode_cache()});
      } catch (const std::invalid_argument& e) {
        io::rethrow_in(io::read_design(document, where),
                       e);  // with the key map, to name the user's key
      }
    } catch (const io::InputError& e) {
      outcome.evaluation.reset();
      outcome.file.reset();
      row.error = e.what();
      for (std::size_t j = 0; csv_ && j < pointers_.size(); ++j) {
        // A value the model refuses at a mapped column's field names the column too.
        const DesignColumn& column = header_.design[j];
        if (pointers_[j] == e.pointer() && header_.names[column.cell] != column.field &&
            !e.detail().starts_with("column ")) {
          row.error = io::InputError(e.source(), e.pointer(), cell_problem(j, e.detail())).what();
        }
      }
      const bool shape_fault = e.shape_fault();
      if (csv_ && !row.bad_column && shape_fault) {
        // A field the design does not have, or a number where the design has
        // an object or a list, is the header's fault, not the row's.
        for (std::size_t j = 0; j < pointers_.size(); ++j) {
          if (pointers_[j] == e.pointer() || pointers_[j].starts_with(e.pointer() + "/")) {
            row.bad_column = j + 1;
            row.bad_column_detail = e.detail();
            break;
          }
        }
      }
    } catch (const std::exception& e) {
      outcome.evaluation.reset();
      outcome.file.reset();
      row.error = io::InputError(where, "", e.what()).what();
    }
  }

  const std::string& source_;
  const BatchOptions& options_;
  bool csv_;
  Header header_;
  std::vector<std::string> pointers_;
  std::vector<io::FieldOverride> columns_;
  // What each design column's cells hold.
  enum class CellKind { kName, kText, kNumber };
  std::vector<CellKind> kinds_;
  mutable std::vector<std::map<std::uint64_t, Shape>> shapes_;  // per thread
  mutable std::vector<io::CsvRecord> records_;                  // per thread: the row's fields
};

// A row: in CSV through `csv` (io/rows.hpp), in JSON Lines as evaluate's
// own object for the design (outputs nested as evaluate writes them), with
// the line, the error and the columns passed through.
void write_row(const Row& row, const Outcome& outcome, const Header& header, io::Format format,
               const io::RowWriter& csv, std::string& out) {
  const std::optional<Evaluation>& evaluation = outcome.evaluation;
  if (format == io::Format::kJson) {
    io::Json j = evaluation && outcome.file ? evaluation_json(*outcome.file, *evaluation)
                                            : io::Json::object();
    j["line"] = row.line;
    if (!evaluation) {
      j["error"] = row.error;
      if (!row.name.empty()) j["name"] = row.name;
    }
    if (!header.passed.empty() && !row.passed.empty()) {
      io::Json& columns = j["columns"];
      columns = io::Json::object();
      for (std::size_t i = 0; i < header.passed.size(); ++i)
        columns[header.names[header.passed[i]]] = row.passed[i];
    }
    out += j.dump(-1, ' ', false, io::Json::error_handler_t::replace);
    out += "\n";
    return;
  }
  std::size_t column = 0;
  csv.number(column++, static_cast<double>(row.line), out);
  csv.text(column++, row.name, out);
  for (std::size_t i = 0; i < header.passed.size(); ++i) {
    csv.text(column++,
             i < row.passed.size() ? std::optional<std::string_view>(row.passed[i]) : std::nullopt,
             out);
  }
  for (const io::OutputSpec& o : io::output_specs())
    csv.number(column++, evaluation ? o.value(*evaluation) : std::nullopt, out);
  csv.text(column, row.error.empty() ? std::nullopt : std::optional<std::string_view>(row.error),
           out);
  csv.end_row(out);
}

// A sorted catalogue's rows, in bounded memory: each row's text goes to a
// temporary file as it is written, and only its sort key, its place in the
// input and where its text lies are kept (32 bytes a row; with --top N, only
// the best N, in a heap). The file is unlinked as soon as it is made, so that
// nothing is left behind however the process ends.
class SortedRows {
 public:
  SortedRows(bool descending, std::size_t top) : descending_(descending), top_(top) {
    const char* dir = std::getenv("TMPDIR");
    std::string name = std::string(dir && *dir ? dir : "/tmp") + "/sweetspot-sort-XXXXXX";
    fd_ = ::mkstemp(name.data());
    if (fd_ < 0) {
      throw std::runtime_error(
          fmt::format("cannot make a temporary file to sort the rows in {}: {}",
                      name.substr(0, name.rfind('/')), std::strerror(errno)));
    }
    ::unlink(name.c_str());
  }
  ~SortedRows() { ::close(fd_); }
  SortedRows(const SortedRows&) = delete;
  SortedRows& operator=(const SortedRows&) = delete;

  // A row's text, with its key (none: failed or null, written last).
  void add(std::optional<double> key, std::string_view text) {
    const Kept row{key.value_or(0.0), next_++, written_, static_cast<std::uint32_t>(text.size()),
                   key.has_value()};
    if (top_ > 0 && rows_.size() == top_ && !before(row, rows_.front()))
      return;  // not among the best
    append(text);
    rows_.push_back(row);
    if (top_ == 0) return;
    std::push_heap(rows_.begin(), rows_.end(), Before{this});
    if (rows_.size() > top_) {
      std::pop_heap(rows_.begin(), rows_.end(), Before{this});
      rows_.pop_back();
    }
  }

  // Every row kept, best first (rows with equal keys in input order).
  void write(std::ostream& out) {
    flush();
    std::sort(rows_.begin(), rows_.end(), Before{this});
    std::string text;
    for (const Kept& row : rows_) {
      text.resize(row.length);
      for (std::size_t done = 0; done < row.length;) {
        const ssize_t n = ::pread(fd_, text.data() + done, row.length - done,
                                  static_cast<off_t>(row.offset + done));
        if (n < 0 && errno == EINTR) continue;
        if (n <= 0) {
          throw std::runtime_error(
              fmt::format("cannot read back the sorted rows' temporary file: {}",
                          n < 0 ? std::strerror(errno) : "it ended early"));
        }
        done += static_cast<std::size_t>(n);
      }
      out << text;
    }
  }

 private:
  struct Kept {  // 32 bytes
    double key;
    std::uint64_t order;   // the row's place in the input
    std::uint64_t offset;  // where its text starts in the file
    std::uint32_t length;  // a row is far below 4 GiB: a line is at most 1 MiB
    bool has_key;
  };
  static_assert(sizeof(Kept) == 32);

  // Whether `a` is written before `b`: keyed rows first, by key in the asked
  // direction, then in input order.
  bool before(const Kept& a, const Kept& b) const {
    if (a.has_key != b.has_key) return a.has_key;
    if (a.has_key && a.key != b.key) return descending_ ? a.key > b.key : a.key < b.key;
    return a.order < b.order;
  }
  struct Before {
    const SortedRows* rows;
    bool operator()(const Kept& a, const Kept& b) const { return rows->before(a, b); }
  };

  void append(std::string_view text) {
    buffer_ += text;
    written_ += text.size();
    if (buffer_.size() >= (std::size_t{1} << 20)) flush();
  }
  void flush() {
    for (std::size_t done = 0; done < buffer_.size();) {
      const ssize_t n = ::write(fd_, buffer_.data() + done, buffer_.size() - done);
      if (n < 0 && errno == EINTR) continue;
      if (n < 0) {
        throw std::runtime_error(
            fmt::format("cannot write the sorted rows' temporary file: {}", std::strerror(errno)));
      }
      done += static_cast<std::size_t>(n);
    }
    buffer_.clear();
  }

  bool descending_;
  std::size_t top_;
  int fd_ = -1;
  std::vector<Kept> rows_;  // with top_, a heap whose front is the worst kept
  std::uint64_t next_ = 0;
  std::uint64_t written_ = 0;
  std::string buffer_;
};

}  // namespace

BatchSummary run_batch(std::istream& in, const std::string& source, const BatchOptions& options,
                       std::ostream& out) {
  io::LineReader reader(in, source, kMaxBatchLineBytes);
  std::string line;
  // The first line that is not blank: the CSV header, or the first design.
  bool have_line = false;
  while (reader.next(line)) {
    if (!trimmed(line).empty()) {
      have_line = true;
      break;
    }
  }
  bool csv = options.input == CatalogueFormat::kCsv;
  if (options.input == CatalogueFormat::kAuto) csv = have_line && !trimmed(line).starts_with('{');
  Header header;
  const std::string header_at = fmt::format("{}:{}", source, reader.line_number());
  // A catalogue with no row at all is a mistake (the wrong file, an empty
  // pipe), not a catalogue of nothing.
  if (!have_line) {
    throw io::InputError(source, "",
                         csv ? "the file is empty, expected a CSV header"
                             : "the file is empty, expected one design per line (JSON Lines)");
  }
  if (!csv && !options.map.empty()) {
    throw io::InputError(options.map_source, "",
                         "a column map is for a CSV catalogue, and " + source +
                             " is JSON Lines (expected its rows to name design fields themselves)");
  }
  const io::OutputSpec* sort_by = nullptr;
  if (!options.sort_output.empty()) {
    sort_by = io::find_output(options.sort_output);
    if (!sort_by) throw std::invalid_argument("sort_output: no output " + options.sort_output);
  }
  if (csv) {
    io::complete_record(reader, line);
    header = read_header(line, header_at, options.map, options.map_source);
  }
  const std::unique_ptr<io::RowWriter> csv_rows = io::row_writer(io::Format::kCsv);
  // The output's header, held back until the first rows show no column at
  // fault (a column the base cannot take is found only on a row): a refused
  // catalogue writes nothing, not a header.
  std::string header_text;
  const auto write_header = [&] {
    out << header_text;
    header_text.clear();
  };
  if (options.format == io::Format::kCsv) {
    // A column passed through keeps its name, which must not be one of the output's own.
    std::vector<std::string_view> own{"line", "name", "error"};
    for (const io::OutputSpec& o : io::output_specs()) own.push_back(o.name);
    for (const std::size_t k : header.passed) {
      if (std::find(own.begin(), own.end(), header.names[k]) != own.end()) {
        throw io::InputError(
            header_at, "",
            fmt::format("column {} {}: passed through, it would repeat the output's "
                        "own column {}: map it onto a design field, or rename it",
                        k + 1, shown(header.names[k]), shown(header.names[k])));
      }
    }
    std::vector<std::string> names{"line", "name"};
    for (const std::size_t k : header.passed) names.push_back(header.names[k]);
    for (const io::OutputSpec& o : io::output_specs()) names.emplace_back(o.name);
    names.emplace_back("error");
    csv_rows->header(std::move(names), header_text);
  }
  const Evaluator evaluator(source, options, csv, std::move(header));
  BatchSummary summary;
  // The chunk's rows: the first `rows` of `chunk`, whose Rows are reused.
  std::vector<Row> chunk;
  std::size_t rows = 0;
  std::size_t chunk_bytes = 0;
  chunk.reserve(kBatchChunkRows);
  std::vector<std::string> texts(std::max(1, options.threads));
  std::vector<Outcome> outcomes(texts.size());  // per thread
  std::optional<SortedRows> kept;               // with sort_by
  if (sort_by) kept.emplace(options.descending, options.top);
  const auto flush = [&] {
    // Rows are read, evaluated and formatted by the threads, each into its
    // own block of text (or, sorted, its own row); the blocks are written in order.
    for (std::string& text : texts) text.clear();
    const std::span<Row> read(chunk.data(), rows);
    io::for_blocks(
        read.size(), options.threads, [&](std::size_t t, std::size_t from, std::size_t to) {
          for (std::size_t i = from; i < to; ++i) {
            Row& row = read[i];
            Outcome& outcome = outcomes[t];
            evaluator.evaluate_row(row, outcome, t);
            if (sort_by) {
              if (outcome.evaluation) row.key = sort_by->value(*outcome.evaluation);
              write_row(row, outcome, evaluator.header(), options.format, *csv_rows, row.out);
            } else {
              write_row(row, outcome, evaluator.header(), options.format, *csv_rows, texts[t]);
            }
          }
        });
    for (const Row& row : read) {
      if (!row.bad_column) continue;
      const DesignColumn& column = evaluator.header().design[row.bad_column - 1];
      throw io::InputError(header_at, "",
                           fmt::format("{}: {}", column.label, row.bad_column_detail));
    }
    if (sort_by) {
      for (const Row& row : read) kept->add(row.key, row.out);
    } else {
      write_header();
      for (const std::string& text : texts) out << text;
    }
    for (Row& row : read) {
      ++summary.rows;
      if (!row.error.empty()) ++summary.failed;
      // A long line's memory is not kept for the rows to come.
      if (row.text.capacity() > kKeptRowBytes) row = Row();
    }
    rows = 0;
    chunk_bytes = 0;
    if (options.progress) options.progress(summary.rows, reader.bytes_read());
  };
  // In JSON Lines the first line read is the first design.
  bool pending = have_line && !csv;
  for (;;) {
    if (!pending && !reader.next(line)) break;
    pending = false;
    const std::size_t line_number = reader.line_number();
    if (trimmed(line).empty()) continue;
    if (csv) io::complete_record(reader, line);
    if (csv && io::blank_record(line)) continue;  // the empty last row a spreadsheet exports
    chunk_bytes += line.size();
    if (rows == chunk.size()) chunk.emplace_back();
    chunk[rows++].start(line_number, line);
    if (rows == kBatchChunkRows || chunk_bytes >= kBatchChunkBytes) flush();
  }
  if (rows > 0) flush();
  write_header();  // a catalogue of no rows: the header alone
  if (sort_by) {
    kept->write(out);
  }
  return summary;
}

CatalogueFormat catalogue_format(const std::string& path) {
  const auto ends_with = [&](std::string_view suffix) {
    return std::string_view(path).ends_with(suffix);
  };
  if (ends_with(".csv")) return CatalogueFormat::kCsv;
  if (ends_with(".jsonl") || ends_with(".ndjson") || ends_with(".json"))
    return CatalogueFormat::kJsonLines;
  return CatalogueFormat::kAuto;
}

}  // namespace sweetspot::studies
