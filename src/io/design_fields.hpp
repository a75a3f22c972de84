#pragma once

// The fields of a design file, in one table: for each object of the file
// ("implement", "implement/point_masses/N", ...) the stems it holds, how each
// is spelled (a stem plus one unit suffix of a Dimension, a plain key, or a
// list of keys for a quantity given in several forms), its SI key, its
// default and valid range in words (the range refers to the core's constant),
// and what it depends on. The reader's lists of expected keys, its
// unknown-key messages and the test that the schema and docs/design-files.md agree
// with the reader come from it.

#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "io/json_reader.hpp"

namespace sweetspot::io {

// A key that spells a field in a form of its own (balance_cm, headsize_sq_in),
// with its conversion to SI as the reader applies it.
struct KeySpelling {
  std::string_view key;
  UnitScale scale = {};
};

struct DesignField {
  std::string_view object;  // "" (the document), "implement", "implement/sections/N", ...
  std::string_view stem;    // "mass"; with no dimension and no keys, the key itself
  std::optional<Dimension> dimension;  // the stem takes one unit suffix of it
  std::vector<KeySpelling> keys;       // else: the keys that spell it (balance_cm, ...)
  std::string_view si_key;             // the key the core's name and the writer use
  std::string_view default_value;      // in words, "" when required or none
  std::string_view range;              // in words, naming the core's constant
  std::string_view depends_on;         // what must be given with it, "" when nothing
  // The default in SI when the field has a number for it (the core's), which
  // the schema gives as "default" of the SI key and the reader applies.
  std::optional<double> default_si = std::nullopt;
};

// Every field of a design file.
const std::vector<DesignField>& design_fields();

// Every key that spells `field` (its stem with each unit suffix, or its keys).
std::vector<std::string> spellings_of(const DesignField& field);

// A key of the table with the field it spells and its conversion to SI.
struct FieldSpelling {
  const DesignField* field = nullptr;
  UnitScale scale;
};

// The field of `object` ("implement/point_masses/N") that `key` spells, with
// the conversion the reader applies to it (mass_g: 10^-3; balance_cm: 10^-2;
// headsize_sq_in: 0.0254^2); std::nullopt when the table holds no such key.
// The reader, the writer and the binding of sweeps, studies and catalogues
// all convert through it.
std::optional<FieldSpelling> find_spelling(std::string_view object, std::string_view key);

// The SI key of the field `stem` of `object` (the key the writer writes).
// Throws std::logic_error for a field the table does not hold: a writer or a
// binding that names one is a programming error, caught by the first test.
const std::string& si_key(std::string_view object, std::string_view stem);

// Every key accepted in `object` ("implement/point_masses/N"), in the
// table's order, each unit spelling included.
const std::vector<std::string>& design_keys(std::string_view object);

// The table's object for an ObjectReader's canonical path: the list indices
// become N ("implement/point_masses/2" -> "implement/point_masses/N").
std::string design_object_of(std::string_view canonical);

// Why the JSON pointer `pointer` ("/implement/weight_g") names no field of
// a design file: unknown_key_detail() for its first key that the table does
// not hold in its object (objects the table does not list, such as
// "reference", are not checked); "" when it may name one. A catalogue's
// column is checked with it once, whatever its cells hold.
std::string design_path_problem(std::string_view pointer);

}  // namespace sweetspot::io
