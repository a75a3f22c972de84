#pragma once

// Many designs from columns of numbers (`sweetspot.evaluate_many`): a base
// design and, for each column, a design field by the dotted name a
// catalogue's header uses ("implement.mass_kg") and its values. Each row is
// evaluated as `sweetspot evaluate --batch` evaluates a CSV row: the columns
// checked once as a catalogue's header (studies/catalogue_header.hpp), bound
// once to the base (studies/design_binding.hpp), the frame's modes shared
// through the thread's ModeCache, and a row the binding cannot vouch for
// read as a JSON document, which names what is wrong. No Python object is
// touched: the caller releases the GIL.

#include <cstddef>
#include <span>
#include <string>
#include <utility>
#include <vector>

#include "io/json_reader.hpp"

namespace sweetspot::python {

struct Column {
  std::string field;             // "implement.mass_kg"
  const double* data = nullptr;  // row i at data[i * stride]
  std::ptrdiff_t stride = 1;     // in doubles; 0 for one value for every row
};

struct ManyOptions {
  std::string fidelity;  // rigid, modal, response, collision or auto; empty: the base's own
  double modal_tolerance = 1e-6;
  int threads = 1;
  // The outputs wanted, as indices into io::output_specs(); empty: every one.
  std::vector<std::size_t> outputs;
};

// The columns checked as a catalogue's header, with the pointer each sets.
// Throws InputError naming "columns".
std::vector<std::string> column_pointers(std::span<const Column> columns);

// The rows that failed, each with its message, in no particular order.
using RowErrors = std::vector<std::pair<std::size_t, std::string>>;

// Evaluates `rows` rows; outputs[k][i] is the k-th output wanted (of
// io::output_specs(), every one when options.outputs is empty) at row i (NaN
// when null or the row failed); errors holds each failed row with its message. Rigid rows of a
// design in the paper's parametrisation whose outputs are all among studies::rigid_column_outputs()
// go through the column-wise kernel (studies/rigid_columns.hpp), a block at a time. Throws
// InputError naming "columns" for a column no design has (a field of another form of the implement,
// a number where the base holds an object).
void evaluate_columns(const io::Json& base, std::span<const Column> columns, std::size_t rows,
                      const ManyOptions& options, std::span<double* const> outputs,
                      RowErrors& errors);

}  // namespace sweetspot::python
