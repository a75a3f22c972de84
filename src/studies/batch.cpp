#include "studies/batch.hpp"

#include <charconv>
#include <vector>

#include <fmt/format.h>

#include "sweetspot/evaluate.hpp"
#include "sweetspot/frame_modes.hpp"
#include "io/design_reader.hpp"
#include "io/input_error.hpp"
#include "io/outputs.hpp"
#include "io/parallel.hpp"

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

class Evaluator {
 public:
  Evaluator(const std::string& source, const BatchOptions& options, std::vector<std::string> header)
      : source_(source), options_(options), header_(std::move(header)) {
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

  void evaluate_row(Row& row) const {
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

 private:
  const std::string& source_;
  const BatchOptions& options_;
  std::vector<std::string> header_;
  std::vector<std::string> pointers_;
  std::vector<std::optional<FieldOverride>> columns_;  // empty: not a JSON pointer
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
    out += ",";
    if (value) out += exact(*value);
  }
  out += ",";
  out += csv_field(row.error);
  out += "\n";
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
        evaluator.evaluate_row(chunk[i]);
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
