#pragma once

// A catalogue's header and its column map: which column sets which design
// field (a dotted path such as implement.mass_g, or a column mapped onto
// one), which are passed through to the output, checked once for the whole
// file. The rows are read by studies/batch.cpp.

#include <cstddef>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "io/json_reader.hpp"

namespace sweetspot::studies {

// At most this many CSV columns (docs/catalogues.md, "Input limits").
inline constexpr std::size_t kMaxBatchColumns = 1000;

// Catalogue column name -> design field ("weight" -> "implement.mass_g").
using ColumnMap = std::vector<std::pair<std::string, std::string>>;

// A column that sets a design field.
struct DesignColumn {
  std::size_t cell = 0;  // its index among the record's fields
  std::string field;     // "implement.mass_g"
  std::string label;     // for messages: "column 7 'weight' (mapped to implement.mass_g)"
};

struct Header {
  std::size_t count = 0;             // fields in every record
  std::vector<DesignColumn> design;  // the columns that set design fields
  std::vector<std::size_t> passed;   // the columns passed through, in order
  std::vector<std::string> names;    // every column's name as the file gives it
};

// The header `line` (named `where` in messages), checked once: every column
// a design field (or, with a map, mapped onto one or passed through), none
// given twice, in two units or forms, or inside another; every column of the
// map in the header. Throws InputError naming `where` or `map_source`.
Header read_header(std::string_view line, const std::string& where, const ColumnMap& map,
                   const std::string& map_source);

// Fields given together (a header's columns, the command line's --set
// items), each a design field: none given twice, in two units or forms, or
// inside another. Throws InputError naming `where` and the fields' labels.
void check_fields_together(const std::vector<DesignColumn>& fields, const std::string& where);

// Why the dotted path `field` ("implement.mass_g") names no field of a
// design, "" when it may name one.
std::string design_field_problem(std::string_view field);

// Columns that hold text, not numbers.
bool is_text_field(std::string_view field);

// A number or a word: a lead's clock ("throat", "3/9") or a trade gauge
// ("16L"), as the design file and --set take them.
bool takes_a_word(std::string_view field);

// A column map written inline, "weight=implement.mass_g,length=implement.length_in".
// Throws InputError naming `source` and the item for an item without '=', an
// empty name or field, or a column mapped twice.
ColumnMap parse_column_map(std::string_view text, const std::string& source);

// A column map from a JSON object {"weight": "implement.mass_g", ...}.
// Throws InputError naming `source` and the key for anything else.
ColumnMap column_map_from_json(const io::Json& map, const std::string& source);

// "implement.point_masses.0.mass_g" -> "/implement/point_masses/0/mass_g".
std::string field_to_pointer(const std::string& field);

// `text` without the blanks (spaces, tabs) around it.
std::string_view trimmed(std::string_view text);

// A cell or column name quoted for a message, shortened like brief().
std::string shown(std::string_view text);

}  // namespace sweetspot::studies
