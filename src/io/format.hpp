#pragma once

// Writers for one evaluated design: Markdown for people, JSON and CSV for
// programs. All output names come from outputs.hpp.

#include <optional>
#include <string>
#include <string_view>

#include "io/design_reader.hpp"
#include "sweetspot/evaluate.hpp"

namespace sweetspot::io {

enum class Format { kMarkdown, kJson, kCsv };

// "md", "json" or "csv"; std::nullopt otherwise.
std::optional<Format> parse_format(std::string_view text);

// `value` with `digits` significant digits, no exponent for everyday magnitudes.
std::string significant(double value, int digits = 6);
// Shortest text that reads back to exactly `value` (for CSV and JSON).
std::string exact(double value);
// exact(value) appended to `out` (no temporary string: the CSV writers' loop).
void append_exact(std::string& out, double value);
// Text for a Markdown table cell (pipes escaped).
std::string md_cell(std::string_view text);
// A CSV field, quoted when it holds a comma, quote or newline.
std::string csv_field(std::string_view text);

// {"name", "inputs": {canonical name: {"value", "provenance"}}, "outputs": {...},
//  "notes": {output: why null}}.
Json evaluation_json(const DesignFile& design, const Evaluation& evaluation);

// The whole evaluation in `format`.
// In Markdown, `answer` (a paragraph of plain sentences, reports/summary.hpp)
// comes right after the title, before the tables.
std::string evaluation_report(const DesignFile& design, const Evaluation& evaluation, Format format,
                              std::string_view answer = {});

}  // namespace sweetspot::io
