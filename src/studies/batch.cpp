#include "studies/batch.hpp"

#include <array>
#include <charconv>
#include <cstdint>
#include <map>
#include <memory>
#include <span>
#include <vector>

#include <fmt/format.h>

#include "sweetspot/evaluate.hpp"
#include "sweetspot/frame_modes.hpp"
#include "io/design_reader.hpp"
#include "io/input_error.hpp"
#include "io/outputs.hpp"
#include "io/parallel.hpp"
#include "studies/design_binding.hpp"

namespace sweetspot::io {
namespace {

// Splits one CSV record (RFC 4180 quoting within the line).
std::vector<std::string> split_csv(const std::string& line) {
  std::vector<std::string> fields(1);
  bool quoted = false;
  for (std::size_t i = 0; i < line.size(); ++i) {
    const char c = line[i];
    if (quoted) {
      if (c == '"' && i + 1 < line.size() && line[i + 1] == '"') {
        fields.back() += '"';
        ++i;
      } else if (c == '"') {
        quoted = false;
      } else {
        fields.back() += c;
      }
    } else if (c == '"') {
      quoted = true;
    } else if (c == ',') {
      fields.emplace_back();
    } else if (c != '\r') {
      fields.back() += c;
    }
  }
  return fields;
}

struct Row {
  std::size_t line = 0;
  std::string text;
  std::string name;
  std::optional<Evaluation> evaluation;
  std::string error;
};

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
// A row's shape is a bit per column.
constexpr std::size_t kMaxCompiledColumns = 64;

class Evaluator {
 public:
  Evaluator(const std::string& source, const BatchOptions& options, std::vector<std::string> header)
      : source_(source), options_(options), header_(std::move(header)),
        shapes_(static_cast<std::size_t>(std::max(1, options.threads))) {
    for (const std::string& field : header_) {
      pointers_.push_back(field_to_pointer(field));
      std::optional<FieldOverride> column;
      try {
        if (!Json::json_pointer(pointers_.back()).empty()) column.emplace(pointers_.back());
      } catch (const Json::exception&) {
      }
      columns_.push_back(std::move(column));
    }
  }

  // Evaluates a row on thread `thread` (< options.threads).
  void evaluate_row(Row& row, std::size_t thread) const {
    if (options_.compiled && options_.csv_input && header_.size() <= kMaxCompiledColumns &&
        evaluate_compiled(row, thread)) {
      return;
    }
    evaluate_general(row);
  }

 private:
  // The row set on its shape's compiled design; false (and the row as it
  // was) when the JSON path must read it.
  bool evaluate_compiled(Row& row, std::size_t thread) const {
    const std::vector<std::string> cells = split_csv(row.text);
    if (cells.size() != header_.size()) return false;
    std::uint64_t mask = 0;
    std::size_t name_cell = cells.size();
    std::array<double, kMaxCompiledColumns> values{};
    std::size_t count = 0;
    for (std::size_t k = 0; k < cells.size(); ++k) {
      if (cells[k].empty()) continue;
      mask |= std::uint64_t{1} << k;
      if (header_[k] == "name") {
        name_cell = k;
        continue;
      }
      if (!columns_[k]) return false;
      const char* end = cells[k].data() + cells[k].size();
      const auto [stop, error] = std::from_chars(cells[k].data(), end, values[count]);
      if (error != std::errc() || stop != end) return false;
      ++count;
    }
    Shape& shape = shapes_[thread][mask];
    if (!shape.bound && !compile_shape(shape, cells, values, row.line)) return false;
    const Design* design = shape.bound->at(std::span<const double>(values.data(), count));
    if (!design) return false;
    try {
      const Fidelity fidelity = resolve_fidelity(
          options_.fidelity.empty() ? std::string_view(shape.fidelity) : options_.fidelity, *design);
      row.evaluation = evaluate(*design, fidelity, options_.modal_tolerance);
    } catch (const std::exception&) {
      row.evaluation.reset();
      return false;
    }
    row.name = name_cell < cells.size()  ? cells[name_cell]
               : shape.name              ? *shape.name
                                         : fmt::format("{}:{}", source_, row.line);
    return true;
  }

  // Reads this row's document as the template of its shape and binds the
  // filled columns to it; false when it cannot (the row is then read as JSON).
  bool compile_shape(Shape& shape, const std::vector<std::string>& cells, std::span<const double> values,
                     std::size_t line) const {
    if (shape.attempts >= kTemplateAttempts) return false;
    ++shape.attempts;
    try {
      Json document = options_.base ? *options_.base : Json::object();
      std::vector<std::string> pointers;
      bool named = false;
      for (std::size_t k = 0; k < cells.size(); ++k) {
        if (cells[k].empty()) continue;
        if (header_[k] == "name") {
          document["name"] = cells[k];
          named = true;
          continue;
        }
        columns_[k]->apply(document, values[pointers.size()]);
        pointers.push_back(pointers_[k]);
      }
      const std::string where = fmt::format("{}:{}", source_, line);
      auto compiled = CompiledDesign::compile(describe_design(document, where), pointers);
      if (!compiled) {
        shape.attempts = kTemplateAttempts;  // a column no binding sets: every row of the shape reads JSON
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

  // The JSON path: the row written over the base document and read again.
  void evaluate_general(Row& row) const {
    const std::string where = fmt::format("{}:{}", source_, row.line);
    try {
      Json document = options_.base ? *options_.base : Json::object();
      if (options_.csv_input) {
        const std::vector<std::string> cells = split_csv(row.text);
        if (cells.size() != header_.size()) {
          throw InputError(where, "", fmt::format("expected {} fields as in the header, got {}",
                                                  header_.size(), cells.size()));
        }
        for (std::size_t k = 0; k < cells.size(); ++k) {
          if (cells[k].empty()) continue;  // the base's value stands
          if (header_[k] == "name") {
            document["name"] = cells[k];
            continue;
          }
          if (!columns_[k]) throw InputError(where, pointers_[k], "not a JSON pointer");
          double value = 0.0;
          const auto [end, error] = std::from_chars(cells[k].data(), cells[k].data() + cells[k].size(), value);
          if (error != std::errc() || end != cells[k].data() + cells[k].size()) {
            throw InputError(where, pointers_[k], "expected a number, got \"" + cells[k] + "\"");
          }
          columns_[k]->apply(document, value);
        }
      } else {
        override_fields(document, parse_json(row.text, where));
      }
      const DesignFile design = read_design_lean(document, where);
      row.name = design.name;
      try {
        const Fidelity fidelity = resolve_fidelity(
            options_.fidelity.empty() ? std::string_view(design.fidelity) : options_.fidelity, design.design);
        row.evaluation = evaluate(design.design, fidelity, options_.modal_tolerance);
      } catch (const std::invalid_argument& e) {
        rethrow_in(read_design(document, where), e);  // with the key map, to name the user's key
      }
    } catch (const InputError& e) {
      row.error = e.what();
    } catch (const std::exception& e) {
      row.error = where + ": " + e.what();
    }
  }

  const std::string& source_;
  const BatchOptions& options_;
  std::vector<std::string> header_;
  std::vector<std::string> pointers_;
  std::vector<std::optional<FieldOverride>> columns_;  // empty: not a JSON pointer
  mutable std::vector<std::map<std::uint64_t, Shape>> shapes_;  // per thread
};

void write_row(const Row& row, Format format, std::string& out) {
  if (format == Format::kJson) {
    Json j{{"line", row.line}};
    if (row.evaluation) {
      j["name"] = row.name;
      for (const OutputSpec& o : output_specs()) {
        const auto value = o.value(*row.evaluation);
        j["outputs"][std::string(o.name)] = value ? Json(*value) : Json(nullptr);
      }
    } else {
      j["error"] = row.error;
    }
    out += j.dump(-1, ' ', false, Json::error_handler_t::replace);
    out += "\n";
    return;
  }
  out += std::to_string(row.line);
  out += ",";
  out += csv_field(row.name);
  for (const OutputSpec& o : output_specs()) {
    const auto value = row.evaluation ? o.value(*row.evaluation) : std::nullopt;
    out += ',';
    if (value) append_exact(out, *value);
  }
  out += ',';
  if (!row.error.empty()) out += csv_field(row.error);
  out += '\n';
}

}  // namespace

std::string field_to_pointer(const std::string& field) {
  std::string pointer = "/";
  for (const char c : field) pointer += c == '.' ? '/' : c;
  return pointer;
}

BatchSummary run_batch(std::istream& in, const std::string& source, const BatchOptions& options,
                       std::ostream& out) {
  std::vector<std::string> header;
  std::size_t line_number = 0;
  std::string line;
  if (options.csv_input) {
    if (!std::getline(in, line)) throw InputError(source, "", "the file is empty, expected a CSV header");
    ++line_number;
    header = split_csv(line);
    for (const std::string& field : header) {
      if (field.empty()) throw InputError(source + ":1", "", "an empty column name in the header");
    }
  }
  if (options.format == Format::kCsv) {
    out << "line,name";
    for (const OutputSpec& o : output_specs()) out << "," << o.name;
    out << ",error\n";
  }
  const Evaluator evaluator(source, options, header);
  BatchSummary summary;
  std::vector<Row> chunk;
  chunk.reserve(kBatchChunkRows);
  std::vector<std::string> texts(std::max(1, options.threads));
  const auto flush = [&] {
    // Rows are read, evaluated and formatted by the threads, each into its
    // own block of text; the blocks are written in order.
    for (std::string& text : texts) text.clear();
    for_blocks(chunk.size(), options.threads, [&](std::size_t t, std::size_t from, std::size_t to) {
      for (std::size_t i = from; i < to; ++i) {
        evaluator.evaluate_row(chunk[i], t);
        write_row(chunk[i], options.format, texts[t]);
      }
    });
    for (const std::string& text : texts) out << text;
    for (const Row& row : chunk) {
      ++summary.rows;
      if (!row.error.empty()) ++summary.failed;
    }
    chunk.clear();
  };
  while (std::getline(in, line)) {
    ++line_number;
    if (line.find_first_not_of(" \t\r") == std::string::npos) continue;
    chunk.push_back(Row{line_number, line, {}, std::nullopt, {}});
    if (chunk.size() == kBatchChunkRows) flush();
  }
  if (!chunk.empty()) flush();
  return summary;
}

bool is_csv_catalogue(const std::string& path) {
  return path.size() >= 4 && path.compare(path.size() - 4, 4, ".csv") == 0;
}

}  // namespace sweetspot::io
